// Whether a run can vouch for its events (API.md, "Trust fields"). The run is checked against a
// shadow solution of the same scene at a hundredth of its tolerances, compared event by event:
// where both list the same events, their differences estimate the run's error (the shadow's own
// error is several times smaller), with what round-off does to them from the variational
// equations along the shadow's path; where they list different events, the sequence depends on
// differences below the tolerance, and the run is not trusted from there on.
#pragma once

#include <limits>
#include <vector>

#include "core/model/model.h"
#include "core/run/result.h"
#include "core/run/sim_options.h"

namespace vibro {

// The shadow's options: the same scene, limits and deadline, nothing recorded but its path (where
// its start's shifts are found, compare_runs), not checked itself, at a hundredth of both
// tolerances (down to the smallest the integrators accept) with its longest step halved: DOPRI5
// and DOP853 checked by Taylor, Radau IIA by `auto`, Taylor by itself, and `auto` by itself, on
// DOP853 where it weighs DOPRI5 against DOP853 (rtol 1e-6 and looser).
struct ShadowOptions {
  SimOptions options;
  // The shadow's stepper (make_stepper, core/run/simulate.h): which explicit method its `auto`
  // runs, and its longest step as a share of longest_step(model).
  AutoExplicit auto_explicit = AutoExplicit::by_tolerance;
  double longest_step_scale = 1.0;
};
ShadowOptions check_options(const SimOptions& run);

// The shadow's scene: the run's, its initial speeds 64 ulps faster and the angles of the pellets
// that move 64 ulps ahead. Where the run and its shadow take the same steps (flights cut short by
// events, one step each at any tolerance), they round alike and agree about what round-off,
// amplified by a chaotic chain of impacts, has already moved (DOP853 at rtol 1e-10 and a
// shadow started with it vouched for a turn where a reference listed a collision; ctest
// trust_scene.a_shadow_started_with_the_run_shared_its_chaotic_error). Speeds alone do not move a
// chain that starts at once: a pellet near its limiter strikes it at once, and run and shadow then
// agree far below the round-off a chaotic cascade amplifies
// (Trust.AShadowOfAnImpactAtOnceStrikesARoundOffApart). Rest stays rest, contacts stay contacts,
// and the shadow's answer moves by round-off where the scene does not amplify it. Over trust_scan
// seeds 1-32 (640,000 runs) the angles took the estimates ten times short from 24 to 13 and the
// wrong events vouched for from 8 to 4, with the share trusted to the end unchanged (98.49 %).
// Moving the angles of pellets at rest too broke equilibria (a pellet at rest at the bottom turned
// at 7e-14 s: 2.4 % of the runs lost their trust), and moving the forcing's phase cost 1 %. So
// where every pellet rests nothing moves, and the shadow starts where the run does: a pellet may
// rest where its force balances gravity to round-off, and 4 ulps on it turns at once
// (Trust.AShadowOfPelletsAtRestStartsWhereTheyRest). Over trust_scan seeds 1-4 (7,400 runs of
// scenes at rest) 4 ulps of their resting angles took 50 runs' trust and 64 ulps 300, while
// unmoved no estimate fell below 0.79 of the true error: the start's round-off reaches the
// estimate through the variational shifts (compare_runs) instead.
Model check_model(const Model& model);

// A run's events instant by instant, as runs are compared: the collisions of one instant as one
// collision of every pellet they involve (in index order), the impacts on one limiter as one, the
// other events as listed; within an instant in a fixed order. How a cascade is listed depends on
// which gaps its instant found closed (within the contact distance, one collision of three
// pellets; a hair apart, thirty collisions of alternating pairs), its outcome does not. A merged
// event lists one speed per pellet, in its pellets' order: dphi_before before the instant's first
// impact on that pellet, dphi_after after its last (none where an event merged lists none); its
// t and phi are those of the first event merged (the pellets it merges touch there).
std::vector<Event> by_instant(const std::vector<Event>& events);

struct TrustReport {
  double event_time_error = 0.0;  // s: the largest time difference of the events listed alike
  double state_error = 0.0;       // rad: the final states' difference, φ̇ scaled by sqrt(R/g)
  double trusted_until = 0.0;     // s: a margin before the runs part, or the end
  // Indices into the runs' events by_instant():
  int first_difference = -1;  // the first event listed differently; -1: none
  int unresolved = -1;        // the first event whose times differ by more than a tenth of the time
                              // to its neighbours; -1: none
  // The first event whose instant's collisions leave a pellet at a speed within ten of its errors
  // of zero (whether and when it turns is not resolved); -1: none. The pellet and the speeds the
  // two runs left it at.
  int uncertain_turn = -1;
  int turning_pellet = -1;
  double run_speed = 0.0, shadow_speed = 0.0;
};

// Compares a run with its shadow, instant by instant, the shadow's times taken as they are and
// less what its start 64 ulps ahead moved them (from its path, within budget_ms of wall clock).
// The runs agree on an event when kind, pellets and limiter are the same and the times differ by
// less than a tenth of the time to the neighbouring events; trust ends ten errors before the
// first events that they do not (but not before the last they list alike), or where either run
// stopped. It ends ten errors before a collision that leaves a pellet at a speed within ten
// times the run's and the shadow's difference of zero (TrustPolicy::turn_speed_errors).
TrustReport compare_runs(const Model& model, const RunResult& run, const RunResult& shadow,
                         double budget_ms = std::numeric_limits<double>::infinity());

// Fills the trust fields of `run` (stats and a warning a person reads) from the comparison with
// its shadow, and error_estimate as the largest of the estimates in one unit.
void apply_check(const Model& model, const RunResult& shadow, RunResult& run,
                 double budget_ms = std::numeric_limits<double>::infinity());

// Fills them from the run alone, when the check is turned off: the energy balance and the first
// integral only, which do not see event times.
void apply_unchecked(const Model& model, RunResult& run);

}  // namespace vibro
