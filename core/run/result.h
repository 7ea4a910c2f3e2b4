// What a run answers (MODEL.md, "What a run must answer"): events, branches, summary, stats.
// Plain value types: the JSON writer, the renderer and the tests all read these.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/events/event.h"
#include "core/model/motion.h"

namespace vibro {

// A pellet's place in its phase plane.
struct PhasePoint {
  double phi = 0.0;   // rad
  double dphi = 0.0;  // rad/s
};

// One point of a phase trajectory.
struct Sample {
  double t = 0.0;
  double phi = 0.0;
  double dphi = 0.0;
};

// A branch of one pellet's phase trajectory: the motion between two events that touch it
// (the paper's "motion interval"). Numbered from 1 in the order they occur.
struct Branch {
  int index = 1;
  std::vector<Sample> samples;  // increasing t; the first and last are the interval's ends
};

struct PelletTrack {
  int pellet = 0;
  std::vector<Branch> branches;
};

enum class PelletState { sliding, stuck, resting_at_limiter };
std::string_view pellet_state_name(PelletState state);  // "sliding", "stuck", "resting_at_limiter"

struct FinalState {
  double phi = 0.0;   // unwrapped, rad
  double dphi = 0.0;  // rad/s
  PelletState state = PelletState::sliding;
  int limiter = -1;  // the limiter it rests against, if resting_at_limiter
};

struct LastImpact {
  int index = 0;  // 1-based count of impacts (limiter, collision, chatter as one); 0: none
  double t = 0.0;
};

struct Summary {
  // Each listed impact counts once, by its kind: the three add up to the impacts.
  int limiter_impacts = 0;    // listed limiter impacts
  int collisions = 0;         // with a group's plastic stop against a limiter (a cascade's limit)
  int chatter_sequences = 0;  // chatter events, each summing infinitely many impacts
  std::vector<std::vector<int>> impacts_by_limiter;  // [limiter][pellet], listed impacts
  LastImpact last_impact;
  // False while impacts still go on at the end of the run: the last impact is then no answer to
  // the paper's question of when the system stops being vibro-impact.
  bool ends_vibro_impact = true;
  std::vector<FinalState> final;
  std::vector<bool> armed;  // per limiter: armed at the end (a mobile one may be disarmed)
};

enum class Termination {
  completed,          // reached t_end
  event_limit,        // more events than allowed
  step_limit,         // more steps than allowed
  deadline,           // the wall-clock deadline passed
  numerical_failure,  // step-size underflow, non-finite state, implicit solver failure
  cancelled           // SolverOptions::cancelled said so
};
std::string_view termination_name(Termination t);

struct Stats {
  std::string method;  // the method asked for ("auto" reports what it used, e.g. "auto(dop853)")
  double rtol = 0.0, atol = 0.0;
  long steps = 0, rejected = 0, rhs_evals = 0, jac_evals = 0, lu_decomps = 0, stiff_switches = 0;
  // "auto": the steps each explicit method took
  long dopri5_steps = 0, dop853_steps = 0, taylor_steps = 0;
  double wall_ms = 0.0;
  // The largest of the estimates below in one unit: times over sqrt(R/g), angles in rad, the
  // rest relative.
  double error_estimate = 0.0;
  double energy_defect = 0.0;  // relative: E − E0 − work − impact losses, over the scale
  double first_integral_residual = 0.0;  // relative, unforced paper-law intervals; 0 if none
  // Trust (API.md): from the check against a shadow solution at a tighter tolerance, or,
  // with the check off, from the run alone (which does not see event times).
  bool check = true;              // the shadow ran
  std::string check_method;       // the shadow's method and tolerance
  double check_wall_ms = 0.0;     // the shadow's share of wall_ms
  double event_time_error = 0.0;  // s: largest error of the event times
  double state_error = 0.0;       // rad, φ̇ scaled by sqrt(R/g): error of the final state
  double trusted_until = 0.0;     // s: the events are judged converged up to here
  Termination termination = Termination::completed;
  std::string message;  // why the run stopped early, naming time and cause
  double t_reached = 0.0;
};

struct Warning {
  std::string code;  // "negative_normal_force", ...
  std::string message;
  int pellet = -1;
  double t_begin = 0.0, t_end = 0.0;
};

// The state at one of SimOptions::stops.
struct StateAt {
  double t = 0.0;
  std::vector<FinalState> pellets;
};

// The hybrid path of a run, one instant and the motion interval it opens at a time, with the
// bodies and modes the interval followed: what the variational equations
// (core/analysis/monodromy.h) replay. Kept only when SimOptions::keep_path asks.
struct PathSegment {
  double t = 0.0;                   // the instant (0 for the run's start)
  std::vector<Body> bodies_before;  // the bodies that reached it
  std::vector<double> y_before;     // the state there, snapped onto its events (3 per pellet)
  std::vector<Event> events;        // what happened at it, in order
  std::vector<Body> bodies;         // the interval's bodies and modes
  std::vector<int> normal_sides;    // per body: the side of the bilateral law's normal force
  std::vector<double> y;            // the interval's start: the state after the instant
  double t_end = 0.0;               // the interval's end: the next instant, or the run's end
};

// Lyapunov exponents of the run's motion (core/analysis/lyapunov.h).
struct LyapunovSpectrum {
  // 1/s, largest first, one per phase-space dimension (2 per pellet). −infinity for a direction
  // perturbations die in: a pellet held by friction or resting on a limiter keeps no memory of
  // how it got there.
  std::vector<double> exponents;
  double span = 0.0;        // s: the time they are averaged over
  std::string unsupported;  // non-empty: the path holds what the saltations do not cover
};

struct RunResult {
  std::vector<Event> events;
  std::vector<StateAt> stops;  // those reached, in order
  // SimOptions::settle_window: the run ended at its last stop, where its section had settled
  // (repeated with a period over the window), before t_end.
  bool settled = false;
  std::vector<PelletTrack> tracks;  // only the pellets whose branches were asked for
  Summary summary;
  Stats stats;
  std::vector<Warning> warnings;
  // The earliest near miss (core/events/watch.h): the trust ends before it.
  std::optional<Graze> graze;
  std::vector<PathSegment> path;             // SimOptions::keep_path
  std::optional<LyapunovSpectrum> lyapunov;  // SimOptions::lyapunov
};

}  // namespace vibro
