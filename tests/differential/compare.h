// Comparing two runs of one scene event by event, and the physics every single run must keep.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "core/model/model.h"
#include "core/run/result.h"

namespace vibro::differential {

// Two runs agree on an event time when |Δt| ≤ factor·rtol·(T0 + t), T0 = sqrt(R/g), rtol the
// looser of the two runs' tolerances, times v/w for an impact at approach speed w below the
// speed scale v = 1/T0 (a slow impact's time is that much less well determined). The global error
// of a tolerance-controlled run grows about linearly in time, and an event time errs by the state's
// error over its speed (about 1/T0 in these units), hence rtol·(T0 + t). The factor is measured
// (README.md in this folder): it is above the 99th percentile of |Δt|/(rtol·(T0 + t)) between the
// explicit methods, and between each and itself at rtol/10, over random scenes listing the same
// events.
struct TimeTolerance {
  static constexpr double kFactor = 1e3;
  double rtol = 1e-9;
  double time_scale = 1.0;
  // What the runs state themselves (stats.event_time_error, with the factor of ten the trust
  // contract allows it to fall short by): a run that vouches for its events is held to the
  // errors it states, however ill-conditioned an event is. 0 when the runs are not checked.
  double stated = 0.0;
  double at(double t) const { return kFactor * rtol * (time_scale + std::abs(t)); }
};

enum class Verdict {
  agree,
  sequence,  // the events differ in kind, pellets or limiter (or one run has more)
  time,      // the same sequence, but an event time differs beyond the tolerance
};
std::string_view verdict_name(Verdict v);  // "agree", "sequence", "time"

struct Comparison {
  Verdict verdict = Verdict::agree;
  std::size_t index = 0;      // the first mismatch, counted in the first run's events
  std::optional<Event> a, b;  // the two runs' events there; empty where a run has none
  double dt = 0.0;            // |Δt| of the mismatch when both events exist
  double tolerance = 0.0;     // the tolerance at that time
  // Over the events matched before the mismatch (or all, if none): the largest
  // |Δt|/(rtol·(T0 + t)), to measure TimeTolerance::kFactor.
  double worst_ratio = 0.0;
};

// Compares the event sequences of two runs of one scene up to t_end. Events at nearly the same
// time (within the tolerance) may come in either order: independent events of two pellets that
// close together are equally right in both. Events within the tolerance of t_end may be missing
// from one run (it ended just before them).
Comparison compare_runs(const RunResult& a, const RunResult& b, const TimeTolerance& tol,
                        double t_end);

// One line: "event 12: dop853 has release [0] at t=1.23, radau5 has collision [0,1] ...".
std::string describe(const Comparison& c, const std::string& name_a, const std::string& name_b);

// "release [0]" or "limiter [1] L2".
std::string event_name(const Event& e);

// A run stopped by its bounds on work (events, steps, wall clock): not a verdict on the physics.
bool stopped_by_budget(const RunResult& run);

// The first physics rule that `run` breaks, in words; empty when it keeps them all:
// finite numbers, completed run, events in time order inside [0, t_end]; momentum conserved
// and Newton's restitution k_c at every pairwise collision; dphi⁺ = −k·dphi⁻ at every limiter
// impact that is not a cascade's plastic limit; the pellet on the limiter's angle; a chatter
// ends at rest; a pellet resting at a limiter is at its angle; the energy balance and the first
// integral within the tolerance's reach; pellets never pass each other (their circular order
// at the end is the initial one).
std::optional<std::string> physics_violation(const Model& model, const RunResult& run,
                                             double t_end);

}  // namespace vibro::differential
