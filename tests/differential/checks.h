// The checks of the instrument on one random scene, shared by the property tests, the corpus
// test and the scan: all methods agree at a tight tolerance, each method agrees with itself at
// a tenth of the tolerance, and every run keeps the physics. Runs are made once per (method,
// rtol) and shared between the checks.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "core/integrators/stepper.h"
#include "core/run/result.h"
#include "tests/differential/compare.h"
#include "tests/differential/conditioning.h"
#include "tests/differential/scene_gen.h"

namespace vibro::differential {

inline constexpr std::array kMethods = {Method::dopri5, Method::dop853, Method::radau5,
                                        Method::automatic, Method::taylor};

class SceneRuns {
 public:
  // `trust_horizon`: run with the engine's trust check (a shadow run, SimOptions::check) and
  // compare only the events before the earliest stats.trusted_until of the runs compared: the
  // events a run vouches for must agree; an ill-conditioned scene's later ones need not.
  // `bounded`: the runs stop at a wall-clock deadline (a random scene may be costly); a known
  // scene (the corpus) is run to its end however slow the build (a sanitizer's).
  explicit SceneRuns(RandomScene scene, bool trust_horizon = false, bool bounded = true)
      : scene_(std::move(scene)), trust_horizon_(trust_horizon), bounded_(bounded) {}
  const RandomScene& scene() const { return scene_; }
  bool trust_horizon() const { return trust_horizon_; }
  const RunResult& run(Method method, double rtol);

 private:
  RandomScene scene_;
  bool trust_horizon_;
  bool bounded_;
  std::map<std::pair<Method, double>, RunResult> runs_;
};

enum class FailureClass {
  methods_sequence,      // methods at one tight rtol list different events
  methods_time,          // ... the same events at times beyond the tolerance
  convergence_sequence,  // one method at rtol and rtol/10 lists different events
  convergence_time,      // ... the same events at times beyond the tolerance
  physics,               // a run breaks a physics rule (compare.h)
};
std::string_view class_name(FailureClass c);

struct Finding {
  FailureClass cls = FailureClass::physics;
  Method method = Method::automatic;  // the run that fails (unused by methods_*)
  double rtol = 0.0;
  // What failed, without the numbers that change when a scene shrinks: the class, the method,
  // and the likely cause of a mismatch or the broken rule. Findings with one signature are one
  // failure class.
  std::string signature;
  std::string detail;  // what disagrees, with the margins of the events involved
  // Conditioning (conditioning.h) of the two mismatching events: the smaller event margin and
  // the smaller isolation; and the smallest margin of the events before them in either run.
  double margin = 0.0;
  double isolation = 0.0;
  double earlier_margin = 0.0;
  Cause cause = Cause::unexplained;  // of a mismatch (conditioning.h)
};

// Whether some run of the scene at these settings stopped at its bounds on work; such scenes
// are left out of the checks.
bool incomplete(SceneRuns& runs, double rtol);

// (a) All kMethods at `rtol` list the same events at close times. The signature and the detail
// say which methods agree with which ("dopri5+radau5 | dop853+auto").
std::optional<Finding> methods_disagree(SceneRuns& runs, double rtol);
// (b) `method` at rtol and rtol/10 lists the same events at close times.
std::optional<Finding> rtol_disagrees(SceneRuns& runs, Method method, double rtol);
// A frictionless scene's run of `method` at `rtol` that passes its reversals
// (SolverOptions::frictionless_reversals false, as a sweep's) lists the same events other than
// reversals, at close times, as the run that lists them. For a scene with no friction (alpha0 =
// 0, no mu_s).
std::optional<Finding> passed_reversals_disagree(SceneRuns& runs, Method method, double rtol);
// (c) The run of `method` at `rtol` keeps the physics.
std::optional<Finding> physics_fails(SceneRuns& runs, Method method, double rtol);

// One line per finding, for a failure message or a scene's description.
std::string describe(const Finding& f);

// The check that produced `finding` (its class, method and rtol), made on `scene`; empty when
// the scene passes it or stops at its bounds on work.
std::optional<Finding> check_again(const RandomScene& scene, const Finding& finding);
// Whether `scene` fails that check with the same signature.
bool reproduces(const RandomScene& scene, const Finding& finding);

}  // namespace vibro::differential
