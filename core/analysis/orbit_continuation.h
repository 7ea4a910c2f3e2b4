// Continuation of a periodic motion in one parameter (API.md, "Periodic motions and their
// stability"): pseudo-arclength on the stroboscopic map, so that folds are passed, with the
// bifurcations on the way detected and located: fold (a multiplier through +1), period
// doubling (through −1), Neimark–Sacker (a complex pair through the unit circle) and grazing
// (an impact speed reaching zero: the motion's impacts change). docs/ORBITS.md says how.
#pragma once

#include <atomic>
#include <complex>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/analysis/periodic_orbit.h"
#include "core/model/model.h"
#include "core/run/sim_options.h"
#include "core/run/validate.h"

namespace vibro {

struct ContinuationSpec {
  std::string parameter;  // a path of core/model/parameter.h
  double to = 0.0;        // the value to reach
  int max_points = 200;   // branch points at most
};

// States on the branch are on the stroboscopic section t = k·T of the sweep's diagrams, so that a
// branch draws over them. (The continuation itself may follow the motion at another phase of the
// forcing, away from its impacts, where the map is smooth.)
struct BranchPoint {
  double value = 0.0;
  std::vector<PhasePoint> state;
  std::vector<std::complex<double>> multipliers;  // largest modulus first
  bool stable = false;  // every multiplier inside the unit circle (inside_unit_circle)
  double impacts_per_period = 0.0;
  // Not stable and not unstable: a multiplier on the unit circle within the band the stability is
  // decided to, none outside it (neutral_within). Neither stable nor neutral: unstable.
  bool neutral = false;
};

enum class BifurcationKind { fold, period_doubling, neimark_sacker, grazing };
std::string_view bifurcation_kind_name(BifurcationKind kind);  // "fold", "period_doubling", ...

struct Bifurcation {
  BifurcationKind kind = BifurcationKind::fold;
  double value = 0.0;
  std::vector<PhasePoint> state;
  // A period doubling: the doubled motion it sheds (`periods` twice the branch's), found a little
  // past it, where the branch is unstable: continue from there to follow the doubled branch.
  // Empty when it was not found.
  std::optional<double> doubled_value;
  std::vector<PhasePoint> doubled_state;
  // A grazing: whether the branch came to it from the side where its motion has the impact that
  // vanishes there (true) or from the side without it (false).
  std::optional<bool> approached_impacting;
};

struct OrbitBranch {
  std::vector<BranchPoint> points;  // in the order followed, the start first
  std::vector<Bifurcation> bifurcations;
  bool reached = false;  // the branch got to `to`
  std::string message;   // why it stopped before, if it did
};

// Why a continuation cannot run, naming the field ("periodic_orbit.continuation.parameter", ...);
// max_points is held to limits.branch_points, the model at `to` to the limits of a scene's.
std::optional<FieldError> validate_continuation(const Model& model, const ContinuationSpec& spec,
                                                const Limits& limits = {});

// Follows `start` (a converged orbit of `model`) toward spec.to. `progress` is told the share of
// the way done (0 to 1); `cancel`, once set, stops it after the point in hand.
OrbitBranch continue_orbit(const Model& model, const SimOptions& options,
                           const PeriodicOrbit& start, const ContinuationSpec& spec,
                           const std::function<void(double done)>& progress = {},
                           const std::atomic<bool>* cancel = nullptr);

}  // namespace vibro
