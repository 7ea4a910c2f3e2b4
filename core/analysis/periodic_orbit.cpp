#include "core/analysis/periodic_orbit.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/analysis/checked_run.h"
#include "core/analysis/monodromy.h"
#include "core/run/deadline.h"

namespace vibro {
namespace {

Model started_at(const Model& model, const Vec& x) {
  Model m = model;
  for (int i = 0; i < m.size(); ++i) {
    m.pellets[i].phi0 = x[2 * i];
    m.pellets[i].dphi0 = x[2 * i + 1];
  }
  return m;
}

Vec final_state(const RunResult& run) {
  Vec y(2 * run.summary.final.size());
  for (std::size_t i = 0; i < run.summary.final.size(); ++i) {
    y[2 * i] = run.summary.final[i].phi;
    y[2 * i + 1] = run.summary.final[i].dphi;
  }
  return y;
}

// The run of the map alone: no shadow, no branches.
RunResult map_run(const Model& model, const SimOptions& options, double t_end, const Vec& x,
                  bool keep_path) {
  SimOptions o = options;
  o.t_end = t_end;
  o.check = false;
  o.keep_path = keep_path;
  o.record.clear();
  o.stops.clear();
  o.max_samples = 0;
  return simulate(started_at(model, x), o);
}

// The options with what is left of `deadline` as their deadline.
SimOptions until(SimOptions options, const Deadline& deadline) {
  if (!deadline.never()) options.deadline_ms = deadline.left_ms();
  return options;
}

// Central differences of the map, where the saltations do not reach: steps of 1e-6 rad and
// 1e-6 rad/s per unit of the scene's time scale. Its runs share options.deadline_ms.
Mat differenced_jacobian(const Model& model, const SimOptions& options, double t_end,
                         const Vec& x) {
  const Deadline deadline = Deadline::in_ms(options.deadline_ms);
  const double speed = speed_scale(model);
  Mat J(x.size(), x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    const double h = 1e-6 * (k % 2 ? speed : 1.0);
    Vec xp = x, xm = x;
    xp[k] += h;
    xm[k] -= h;
    J.col(k) = (final_state(map_run(model, until(options, deadline), t_end, xp, false)) -
                final_state(map_run(model, until(options, deadline), t_end, xm, false))) /
               (2.0 * h);
  }
  return J;
}

double tolerance_for(const SimOptions& options) { return std::max(1e-10, 100.0 * options.rtol); }

std::string number(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

}  // namespace

Model at_phase(const Model& model, double theta) {
  Model m = model;
  for (Pellet& p : m.pellets)
    if (p.force.active()) p.force.psi += p.force.Omega * theta;
  return m;
}

double forcing_period(const Model& model) {
  for (const Pellet& p : model.pellets)
    if (p.force.active() && p.force.Omega > 0.0) return kTwoPi / p.force.Omega;
  return 0.0;
}

namespace {

// The simulated time of the run to the guess and of the search, each held to limits.t_end as a
// scene's run is: each Newton iteration maps the state over `periods` forcing periods of T s.
std::optional<FieldError> check_simulated_time(const OrbitSpec& spec, double T,
                                               const Limits& limits) {
  const auto over = [&](const char* field, const std::string& what, double s) {
    return FieldError{std::string("periodic_orbit.") + field,
                      what + " would last " + shortest_text(s) +
                          " s of simulated time, over the limit of " + shortest_text(limits.t_end) +
                          " s"};
  };
  if (spec.guess.empty() && spec.transient * T > limits.t_end)
    return over("transient", "the run to the starting guess (transient periods)",
                spec.transient * T);
  const double search = (spec.max_iterations + 1.0) * spec.periods * T;
  if (search > limits.t_end)
    return over("max_iterations", "the search ((max_iterations + 1) × periods forcing periods)",
                search);
  return std::nullopt;
}

}  // namespace

std::optional<FieldError> validate_orbit(const Model& model, const OrbitSpec& spec,
                                         const Limits& limits) {
  const double T = forcing_period(model);
  if (T == 0.0)
    return FieldError{
        "model.pellets",
        "a periodic orbit needs a periodic force: no pellet has F0 ≠ 0 and Omega > 0"};
  for (int i = 0; i < model.size(); ++i) {
    const Forcing& f = model.pellets[i].force;
    // A constant force (Omega = 0, F0 cos psi) repeats with every period.
    if (!f.active() || f.Omega == 0.0) continue;
    const double cycles = f.Omega * T / kTwoPi;
    if (!(f.Omega > 0.0) || std::abs(cycles - std::round(cycles)) > 1e-9 * cycles)
      return FieldError{"model.pellets[" + std::to_string(i) + "].Omega",
                        "every force must repeat with the first forced pellet's period 2π/Ω: Omega "
                        "must be a whole multiple of it"};
  }
  for (std::size_t l = 0; l < model.limiters.size(); ++l)
    if (model.limiters[l].mobile)
      return FieldError{"model.limiters[" + std::to_string(l) + "].mobile",
                        "periodic orbits are sought with fixed limiters only: a mobile limiter's "
                        "armed state is not part of the section's state"};
  if (spec.periods < 1 || spec.periods > limits.orbit_periods)
    return FieldError{"periodic_orbit.periods",
                      "expected a whole number of forcing periods from 1 to " +
                          std::to_string(limits.orbit_periods)};
  if (spec.transient < 0 || spec.transient > limits.orbit_transient)
    return FieldError{"periodic_orbit.transient",
                      "expected a whole number of forcing periods from 0 to " +
                          std::to_string(limits.orbit_transient)};
  if (!spec.guess.empty() && static_cast<int>(spec.guess.size()) != model.size())
    return FieldError{"periodic_orbit.guess", "expected one {\"phi\", \"dphi\"} per pellet (" +
                                                  std::to_string(model.size()) + "), got " +
                                                  std::to_string(spec.guess.size())};
  for (std::size_t i = 0; i < spec.guess.size(); ++i)
    if (auto e = validate_state("periodic_orbit.guess[" + std::to_string(i) + "]",
                                spec.guess[i].phi, spec.guess[i].dphi))
      return e;
  if (spec.max_iterations < 1 || spec.max_iterations > limits.orbit_iterations)
    return FieldError{"periodic_orbit.max_iterations", "expected a whole number from 1 to " +
                                                           std::to_string(limits.orbit_iterations)};
  return check_simulated_time(spec, T, limits);
}

MapPoint stroboscopic_map(const Model& model, const SimOptions& options, int periods,
                          const Vec& x) {
  const Deadline deadline = Deadline::in_ms(options.deadline_ms);
  MapPoint p;
  const double t_end = periods * forcing_period(model);
  p.x = x;
  p.run = map_run(model, options, t_end, x, true);
  p.ok = p.run.stats.termination == Termination::completed;
  p.image = final_state(p.run);
  if (!p.ok) return p;
  const PathJacobian J = path_jacobian(started_at(model, x), p.run.path, options.rtol, deadline);
  p.run.path.clear();
  if (J.out_of_time) {
    p.ok = false;
    p.run.stats.termination = Termination::deadline;
    p.run.stats.message =
        "took longer than its deadline of " + number(options.deadline_ms) + " ms with its Jacobian";
  } else if (J.unsupported.empty()) {
    p.jacobian = J.matrix;
  } else {
    p.exact = false;
    p.jacobian_note =
        "central differences of the map: the saltation matrices do not cover " + J.unsupported;
    p.jacobian = differenced_jacobian(model, until(options, deadline), t_end, x);
  }
  return p;
}

Vec orbit_residual(const MapPoint& p) {
  Vec r = p.image - p.x;
  for (Eigen::Index k = 0; k < r.size(); k += 2) r[k] = wrap_angle(r[k]);
  return r;
}

double residual_norm(const Model& model, const Vec& r) {
  const double time = time_scale(model);
  double n = 0.0;
  for (Eigen::Index k = 0; k < r.size(); ++k)
    n = std::max(n, std::abs(r[k]) * (k % 2 ? time : 1.0));
  return n;
}

namespace {

// The state the search starts from: the guess, or the scene's start after spec.transient periods
// (none, with orbit.message saying why, where that run failed).
std::optional<Vec> starting_state(const Model& model, const SimOptions& options,
                                  const OrbitSpec& spec, PeriodicOrbit& orbit) {
  const int n = model.size();
  Vec x(2 * n);
  if (!spec.guess.empty()) {
    for (int i = 0; i < n; ++i) x.segment(2 * i, 2) << spec.guess[i].phi, spec.guess[i].dphi;
    return x;
  }
  for (int i = 0; i < n; ++i) x.segment(2 * i, 2) << model.pellets[i].phi0, model.pellets[i].dphi0;
  if (spec.transient <= 0) return x;
  const RunResult warmup = map_run(model, options, orbit.t0, x, false);
  if (warmup.stats.termination != Termination::completed) {
    orbit.message = "the run that gives the starting guess " + warmup.stats.message;
    return std::nullopt;
  }
  return final_state(warmup);
}

// Newton's method on x − P(x) from p, damped (the map is only piecewise smooth, and a full step
// may cross onto another sequence of events), until the residual is under `tol`, a step fails to
// reduce it, or the iterations or the deadline run out. Returns the last map point; counts the
// iterations in orbit.iterations.
MapPoint newton(const Model& model, const SimOptions& options, const Deadline& deadline,
                const OrbitSpec& spec, double tol, MapPoint p, PeriodicOrbit& orbit) {
  const int n = model.size();
  double norm = residual_norm(model, orbit_residual(p));
  for (orbit.iterations = 0; p.ok && norm > tol && orbit.iterations < spec.max_iterations;
       ++orbit.iterations) {
    if (deadline.left_ms() <= 0.0) {
      orbit.message =
          "the search took longer than its deadline of " + number(options.deadline_ms) + " ms";
      break;
    }
    const Mat A = p.jacobian - Mat::Identity(2 * n, 2 * n);
    const Vec dx = A.fullPivLu().solve(-orbit_residual(p));
    if (!dx.allFinite()) break;
    bool accepted = false;
    for (double lambda = 1.0; lambda >= 1.0 / 256.0 && !accepted; lambda /= 2.0) {
      MapPoint trial =
          stroboscopic_map(model, until(options, deadline), spec.periods, p.x + lambda * dx);
      const double trial_norm = trial.ok ? residual_norm(model, orbit_residual(trial)) : INFINITY;
      if (trial_norm < (1.0 - 1e-4 * lambda) * norm) {
        p = std::move(trial);
        norm = trial_norm;
        accepted = true;
      }
    }
    if (!accepted) break;
  }
  orbit.residual = norm;
  return p;
}

// The converged orbit's multipliers, stability and events over one return (times from t0).
void describe(const MapPoint& p, const OrbitSpec& spec, PeriodicOrbit& orbit) {
  orbit.exact_jacobian = p.exact;
  orbit.jacobian_note = p.jacobian_note;
  const Eigen::EigenSolver<Mat> eig(p.jacobian, false);
  for (Eigen::Index k = 0; k < eig.eigenvalues().size(); ++k)
    orbit.multipliers.push_back(eig.eigenvalues()[k]);
  std::sort(orbit.multipliers.begin(), orbit.multipliers.end(),
            [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  orbit.stable = std::all_of(orbit.multipliers.begin(), orbit.multipliers.end(),
                             [](auto m) { return std::abs(m) < 1.0; });
  int impacts = 0;
  for (Event e : p.run.events) {
    if (e.kind == EventKind::limiter || e.kind == EventKind::collision) ++impacts;
    e.t += orbit.t0;
    e.t_accumulation += orbit.t0;
    orbit.events.push_back(std::move(e));
  }
  orbit.impacts_per_period = static_cast<double>(impacts) / spec.periods;
}

// The check: the orbit run with the shadow at a tighter tolerance must return to itself, with
// its events vouched for and no near miss that could change them (orbit.admissible).
void check_admissible(const Model& model, SimOptions check, const OrbitSpec& spec, const Vec& x,
                      double tol, PeriodicOrbit& orbit) {
  check.t_end = spec.periods * orbit.period;
  check.check = true;
  check.record.clear();
  check.stops.clear();
  const RunResult run = simulate(started_at(model, x), check);
  orbit.stats = run.stats;
  const double returned =
      residual_norm(model, orbit_residual({x, final_state(run), {}, true, {}, {}, true}));
  if (run.stats.termination != Termination::completed) {
    orbit.message = "the check run " + run.stats.message;
  } else if (run.graze) {
    orbit.message = "the orbit grazes: a near miss at t = " + number(orbit.t0 + run.graze->t) +
                    " s may add or remove an event, so the motion is at a grazing bifurcation and "
                    "not vouched for";
  } else if (run.stats.trusted_until < check.t_end * (1.0 - 1e-12)) {
    orbit.message = "the check run vouches for its events only up to t = " +
                    number(orbit.t0 + run.stats.trusted_until) + " s";
  } else if (returned > 10.0 * tol) {
    orbit.message = "the check run returns " + number(returned) + " away from the orbit";
  } else {
    orbit.admissible = true;
  }
}

}  // namespace

PeriodicOrbit find_periodic_orbit(const Model& model, const SimOptions& options,
                                  const OrbitSpec& spec) {
  // options.deadline_ms bounds the whole search: each map's run gets what is left of it.
  const Deadline deadline = Deadline::in_ms(options.deadline_ms);
  PeriodicOrbit orbit;
  orbit.periods = spec.periods;
  orbit.period = forcing_period(model);
  orbit.t0 = spec.guess.empty() ? spec.transient * orbit.period : 0.0;
  const std::optional<Vec> x = starting_state(model, until(options, deadline), spec, orbit);
  if (!x) return orbit;
  const double tol = tolerance_for(options);
  const MapPoint p =
      newton(model, options, deadline, spec, tol,
             stroboscopic_map(model, until(options, deadline), spec.periods, *x), orbit);
  for (int i = 0; i < model.size(); ++i) orbit.state.push_back({p.x[2 * i], p.x[2 * i + 1]});
  if (!p.ok) {
    orbit.message = "the map's run " + p.run.stats.message;
    return orbit;
  }
  orbit.converged = orbit.residual <= tol;
  if (!orbit.converged) {
    if (orbit.message.empty())
      orbit.message = "Newton's method stopped after " + std::to_string(orbit.iterations) +
                      " iterations with the state returning " + number(orbit.residual) +
                      " away (needed " + number(tol) +
                      "): no periodic motion near the guess, or one the map's events make "
                      "nonsmooth there";
    return orbit;
  }
  describe(p, spec, orbit);
  check_admissible(model, until(options, deadline), spec, p.x, tol, orbit);
  return orbit;
}

std::variant<OrbitReturn, FieldError> orbit_return(const Model& model, const SimOptions& options,
                                                   const PeriodicOrbit& orbit) {
  if (!orbit.converged)
    return FieldError{"periodic_orbit", "no periodic motion to draw: " + orbit.message};
  OrbitReturn once{model, options};
  for (int i = 0; i < once.model.size(); ++i) {
    once.model.pellets[i].phi0 = orbit.state[i].phi;
    once.model.pellets[i].dphi0 = orbit.state[i].dphi;
  }
  once.options.t_end = orbit.periods * orbit.period;
  return once;
}

}  // namespace vibro
