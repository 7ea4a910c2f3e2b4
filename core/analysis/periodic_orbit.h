// Periodic motions on the stroboscopic section (API.md, "Periodic motions and their stability"):
// a state at t = k·T that returns to itself after `periods` forcing periods, found by Newton's
// method on P(x) − x with the exact Jacobian of the map (core/analysis/monodromy.h), and its
// Floquet multipliers. The map is the simulator itself, so an orbit obeys every limiter, collision
// and stick test; docs/ORBITS.md says how it is found and checked.
#pragma once

#include <complex>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/integrators/ode.h"
#include "core/model/model.h"
#include "core/run/limits.h"
#include "core/run/result.h"
#include "core/run/sim_options.h"
#include "core/run/validate.h"

namespace vibro {

struct OrbitSpec {
  int periods = 1;                // forcing periods until the state returns
  int transient = 100;            // periods of the scene's own run that give the starting guess
  std::vector<PhasePoint> guess;  // one per pellet; given, it replaces the run's guess
  // With a guess, per limiter: armed at the section (MODEL.md, "Periodic motions with a mobile
  // limiter"); empty: as the model's limiters start. Without one, the run's armed set at its end.
  std::vector<bool> armed;
  int max_iterations = 40;
};

// Why an orbit cannot be sought, naming the field ("periodic_orbit.periods", ...); periods,
// transient and max_iterations are held to `limits` (orbit_periods, orbit_transient,
// orbit_iterations).
std::optional<FieldError> validate_orbit(const Model& model, const OrbitSpec& spec,
                                         const Limits& limits = {});

// The forcing period T of a model whose forces share one, s (the first forced pellet's 2π/Ω).
double forcing_period(const Model& model);

// The model seen from time theta: every force's phase advanced by Ω·theta, so that its t = 0 is
// the original's t = theta. A section at another phase of the forcing is a section of it.
Model at_phase(const Model& model, double theta);

// The model with its limiters armed at the start as `armed` says (one per limiter): the state of
// the mobile limiters on a section, which a periodic motion returns to with its continuous state.
Model armed_as(const Model& model, const std::vector<bool>& armed);
// The limiters armed as the model starts (a fixed one always).
std::vector<bool> armed_at_start(const Model& model);

// The state (phi, dphi per pellet) dt after x in the model m run from its t = 0 (no check), with
// the limiters armed then in `armed` when given; none where the run does not reach its end.
std::optional<Vec> run_from(const Model& m, const SimOptions& options, const Vec& x, double dt,
                            std::vector<bool>* armed = nullptr);

// The stroboscopic map over `periods` forcing periods from x (phi, dphi per pellet) with the
// limiters armed as the model starts, and its Jacobian (unset, with the reason, where the path
// holds what it does not differentiate). The armed set is fixed on the section: a run that ends
// with another one is no return (not ok), since no periodic motion passes through it.
struct MapPoint {
  Vec x, image;  // 2N
  Mat jacobian;  // 2N × 2N, exact (saltation) or, failing that, central differences
  bool exact = true;
  std::string jacobian_note;  // why it is not exact
  RunResult run;              // the run from x, with its events
  bool ok = true;             // the run reached its end
};
MapPoint stroboscopic_map(const Model& model, const SimOptions& options, int periods, const Vec& x);

// Why x is no state of the scene's motion on the section (MODEL.md, "A fixed point never crosses
// a limiter"), or nothing if it is one: a pellet's angle beyond a fixed limiter that acts on it,
// on the side the pellet did not start on (the run from x would be a motion the scene's pellet
// never reaches, on the far side of the limiter), or two pellets in the other order than they
// start in, along the turn a fixed limiter acting on both closes or around the circle (they never
// pass each other). A pellet on a limiter's angle, in x or at the scene's start, is on the side
// its motion puts it on, as the simulator takes a start there: away from where it moves, or, at
// rest, where its free acceleration presses it against the limiter.
std::optional<std::string> off_own_side(const Model& model, const Vec& x);

// How far from the unit circle a multiplier must be to count as inside or outside it: the
// accuracy of the map's Jacobian (the tolerance the orbit is converged to). Within it a
// multiplier is neutral: an area-preserving map's lie on the circle to round-off.
double multiplier_band(const SimOptions& options);
// Whether every multiplier lies inside the unit circle by more than `band`.
bool inside_unit_circle(const std::vector<std::complex<double>>& multipliers, double band);
// Whether the multipliers leave the motion neutral, neither stable nor unstable: none outside the
// unit circle by more than `band`, and one within `band` of it (an area-preserving map's, or the
// multiplier 1 of a pellet friction holds wherever it stopped).
bool neutral_within(const std::vector<std::complex<double>>& multipliers, double band);

// The residual P(x) − x with angles compared modulo 2π, and its size with speeds scaled by
// sqrt(R/g) (rad).
Vec orbit_residual(const MapPoint& p);
double residual_norm(const Model& model, const Vec& r);

struct PeriodicOrbit {
  bool converged = false;
  std::string message;  // what failed, or why the orbit is not vouched for
  int periods = 1;
  double period = 0.0;  // T, s
  double t0 = 0.0;      // the section time of `state`, s
  std::vector<PhasePoint> state;
  std::vector<bool> armed;  // per limiter, at the section: the same after every return
  int iterations = 0;
  double residual = 0.0;                          // rad, speeds scaled by sqrt(R/g)
  std::vector<std::complex<double>> multipliers;  // eigenvalues of the monodromy matrix
  bool stable = false;                            // all multipliers inside the unit circle
  bool neutral = false;                           // not stable, not unstable: neutral_within
  bool exact_jacobian = true;
  std::string jacobian_note;
  double impacts_per_period = 0.0;  // limiter impacts and collisions
  // Every pellet at rest on the section and no event over the return: the motion has come to
  // rest (a rest state is a fixed point of the map; a pellet friction holds wherever it stopped
  // has the multiplier 1 of that continuum of rest states, one on a limiter 0).
  bool at_rest = false;
  // The motion checked as a physical one: a run of the orbit at tighter tolerance returns to it,
  // its events are vouched for, and no near miss (a grazing) makes its sequence uncertain.
  bool admissible = false;
  std::vector<Event> events;  // over one return, times from t0
  Stats stats;                // of the check run
};

// Runs the scene for spec.transient periods (or takes spec.guess) and corrects the state by
// Newton's method. Call validate_orbit first.
PeriodicOrbit find_periodic_orbit(const Model& model, const SimOptions& options,
                                  const OrbitSpec& spec);

// One return of a found periodic motion as a run to make: the model started on the orbit's state
// and armed set and the options of a run over its periods. The section time t0 is a whole number of
// every force's periods, so the forces' phases are those of t = 0 and the run starts there.
struct OrbitReturn {
  Model model;
  SimOptions options;
};
// An orbit that was not found is an error naming "periodic_orbit" with the reason.
std::variant<OrbitReturn, FieldError> orbit_return(const Model& model, const SimOptions& options,
                                                   const PeriodicOrbit& orbit);

}  // namespace vibro
