#include "core/analysis/periodic_orbit.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/analysis/checked_run.h"
#include "core/analysis/monodromy.h"
#include "core/events/event_tolerances.h"
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

// The side of a limiter's angle (+1 above it, −1 below) that pellet i lies on when it is at that
// angle with speed v, decided from its motion as the simulator decides it for a start there
// (start_side, core/events/snap.cpp): away from where it moves, or, at rest, where its free
// acceleration (at the model's t = 0) presses it against the limiter.
int side_on_angle(const Model& model, int i, double phi, double v) {
  if (v != 0.0) return v > 0.0 ? -1 : 1;
  return free_acceleration(model, i, 0.0, phi) > 0.0 ? -1 : 1;
}

// Whether the angle phi lies on one of lim's angles θ + 2πk, to the simulator's tolerance for a
// start there.
bool on_copy(const Model& model, const Limiter& lim, double phi) {
  return std::abs(wrap_angle(phi - lim.angle)) <= event_tolerances(model).start_on_limiter;
}

// The copy θ + 2πk of a fixed limiter's angle just below the turn pellet i of the scene lives in
// (it never passes the limiter): the one below its start phi0, or, for a start on a copy, that
// copy or the one below it by the side its motion puts it on (side_on_angle).
double home_below(const Model& model, int i, const Limiter& lim) {
  const Pellet& p = model.pellets[i];
  const double turns = (p.phi0 - lim.angle) / kTwoPi;
  if (!on_copy(model, lim, p.phi0)) return lim.angle + kTwoPi * std::floor(turns);
  const double on = std::round(turns);
  return lim.angle + kTwoPi * (side_on_angle(model, i, p.phi0, p.dphi0) > 0 ? on : on - 1.0);
}

// Why pellet i at the unwrapped angle phi lies beyond a fixed limiter that acts on it, seen from
// its start: outside its home turn (home_below), which a run never leaves, or, given its speed v,
// on an end of it with a motion that puts it on the far side (side_on_angle: a run from there
// takes it so). Without v, an end of the turn is in it. The simulator holds a pellet in that turn
// too (home_side, core/events/snap.cpp).
std::optional<std::string> beyond_limiter(const Model& model, int i, double phi,
                                          std::optional<double> v = std::nullopt) {
  for (std::size_t l = 0; l < model.limiters.size(); ++l) {
    const Limiter& lim = model.limiters[l];
    if (lim.mobile || !lim.acts_on(i)) continue;
    const double below = home_below(model, i, lim), above = below + kTwoPi;
    const bool inside = phi >= below && phi <= above;
    const int side = v && on_copy(model, lim, phi) ? side_on_angle(model, i, phi, *v) : 0;
    const bool far_at_end =
        (side < 0 && std::abs(phi - below) < 1.0) || (side > 0 && std::abs(phi - above) < 1.0);
    if (inside && !far_at_end) continue;
    return "pellet " + std::to_string(i + 1) + " at φ = " + number(phi) + " rad" +
           (inside ? " on the far side of" : ", beyond") + " limiter " + std::to_string(l + 1) +
           " (" + number(lim.angle) +
           " rad) from where it starts (φ0 = " + number(model.pellets[i].phi0) +
           " rad): a motion the scene's pellet never reaches";
  }
  return std::nullopt;
}

// How far pellet i at the unwrapped angle phi lies along its home turn of limiter lim
// (home_below; in [0, 2π] where it stays in that turn).
double along_turn(const Model& model, int i, const Limiter& lim, double phi) {
  return phi - home_below(model, i, lim);
}

// Why pellets i and j at angles phi_i, phi_j lie in the other order than they start in, along the
// turn a fixed limiter acting on both closes (pellets never pass each other, nor that limiter:
// such a state is a motion of the scene with the pellets swapped, which its pellets never reach).
std::optional<std::string> swapped(const Model& model, int i, int j, double phi_i, double phi_j) {
  for (const Limiter& lim : model.limiters) {
    if (lim.mobile || !lim.acts_on(i) || !lim.acts_on(j)) continue;
    const double start_i = along_turn(model, i, lim, model.pellets[i].phi0);
    const double start_j = along_turn(model, j, lim, model.pellets[j].phi0);
    if (start_i == start_j) return std::nullopt;
    // Touching (equal places) keeps the order.
    const double u_i = along_turn(model, i, lim, phi_i), u_j = along_turn(model, j, lim, phi_j);
    if (start_i < start_j ? u_i <= u_j : u_i >= u_j) return std::nullopt;
    return "pellets " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
           " in the other order than they start in (φ = " + number(phi_i) + " and " +
           number(phi_j) + " rad): they never pass each other, so a motion the scene never reaches";
  }
  return std::nullopt;
}

// Why the pellets at the angles of x lie in another order around the circle than they start in
// (they never pass each other): going round from each pellet to the next in the start's order,
// the gaps add up to 2π once the order is kept, and to a further 2π for every pellet out of it.
// Pellets at one place, within 1e-9 rad, may stand in either order.
std::optional<std::string> out_of_circle_order(const Model& model, const Vec& x) {
  const int n = model.size();
  if (n < 3) return std::nullopt;  // two pellets are in both orders around a circle
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  auto around = [](double phi) { return phi - kTwoPi * std::floor(phi / kTwoPi); };
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return around(model.pellets[a].phi0) < around(model.pellets[b].phi0);
  });
  for (int k = 0; k < n; ++k)  // starts at one place: no order to keep between them
    if (around(model.pellets[order[(k + 1) % n]].phi0 - model.pellets[order[k]].phi0) < 1e-9)
      return std::nullopt;
  double turns = 0.0;
  for (int k = 0; k < n; ++k) {
    const double gap = around(x[2 * order[(k + 1) % n]] - x[2 * order[k]]);
    turns += gap > kTwoPi - 1e-9 ? 0.0 : gap;
  }
  if (turns <= kTwoPi + 1e-9) return std::nullopt;
  return "the pellets in another order around the circle than they start in: they never pass "
         "each other, so a motion the scene never reaches";
}

// Why the map's run from x starts a pellet resting on a limiter from the side it did not start
// on (held there by a limiter it could only reach through it); empty if none does.
std::string rests_on_far_side(const Model& model, const RunResult& run) {
  if (run.path.empty()) return {};
  for (const Body& b : run.path.front().bodies) {
    if (b.mode != Mode::resting || b.limiter < 0 || model.limiters[b.limiter].mobile) continue;
    const int i = b.leader();
    const double start = model.pellets[i].phi0;
    const double angle = model.limiters[b.limiter].angle;
    const double at = run.path.front().y[phi_index(i)];
    const double copy = angle + kTwoPi * std::round((at - angle) / kTwoPi);
    if (start == copy || (start > copy ? 1 : -1) == b.side) continue;
    return "rests pellet " + std::to_string(i + 1) + " against limiter " +
           std::to_string(b.limiter + 1) + " from the side it did not start on";
  }
  return {};
}

// Why the run ends with limiters armed otherwise than the model starts them (no return to the
// section's armed set); empty if it ends with the same.
std::string other_armed_set(const Model& model, const RunResult& run) {
  const std::vector<bool> start = armed_at_start(model);
  for (std::size_t l = 0; l < start.size() && l < run.summary.armed.size(); ++l)
    if (start[l] != run.summary.armed[l])
      return std::string("ends with mobile limiter ") + std::to_string(l) + " " +
             (run.summary.armed[l] ? "armed" : "disarmed") + ", not " +
             (start[l] ? "armed" : "disarmed") + " as at the section";
  return {};
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

// The guess's armed set: one per limiter, a fixed one armed, and only with a guess (without one
// the run to the guess gives it).
std::optional<FieldError> check_armed(const Model& model, const OrbitSpec& spec) {
  if (spec.armed.empty()) return std::nullopt;
  if (spec.guess.empty())
    return FieldError{"periodic_orbit.armed",
                      "goes with a guess: without one the run to the starting guess gives it"};
  if (spec.armed.size() != model.limiters.size())
    return FieldError{"periodic_orbit.armed", "expected one true or false per limiter (" +
                                                  std::to_string(model.limiters.size()) +
                                                  "), got " + std::to_string(spec.armed.size())};
  for (std::size_t l = 0; l < spec.armed.size(); ++l)
    if (!spec.armed[l] && !model.limiters[l].mobile)
      return FieldError{"periodic_orbit.armed[" + std::to_string(l) + "]",
                        "limiter " + std::to_string(l) + " is fixed: it is always armed"};
  return std::nullopt;
}

}  // namespace

Model armed_as(const Model& model, const std::vector<bool>& armed) {
  Model m = model;
  for (std::size_t l = 0; l < m.limiters.size() && l < armed.size(); ++l)
    m.limiters[l].armed = armed[l] || !m.limiters[l].mobile;
  return m;
}

std::vector<bool> armed_at_start(const Model& model) {
  std::vector<bool> armed;
  for (const Limiter& l : model.limiters) armed.push_back(!l.mobile || l.armed);
  return armed;
}

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
  for (std::size_t i = 0; i < spec.guess.size(); ++i)
    if (std::optional<std::string> off =
            beyond_limiter(model, static_cast<int>(i), spec.guess[i].phi))
      return FieldError{"periodic_orbit.guess[" + std::to_string(i) + "].phi", "puts " + *off};
  for (std::size_t i = 0; i < spec.guess.size(); ++i)
    for (std::size_t j = i + 1; j < spec.guess.size(); ++j)
      if (std::optional<std::string> off = swapped(model, static_cast<int>(i), static_cast<int>(j),
                                                   spec.guess[i].phi, spec.guess[j].phi))
        return FieldError{"periodic_orbit.guess[" + std::to_string(j) + "].phi", "puts " + *off};
  if (auto e = check_armed(model, spec)) return e;
  if (spec.max_iterations < 1 || spec.max_iterations > limits.orbit_iterations)
    return FieldError{"periodic_orbit.max_iterations", "expected a whole number from 1 to " +
                                                           std::to_string(limits.orbit_iterations)};
  return check_simulated_time(spec, T, limits);
}

std::optional<std::string> off_own_side(const Model& model, const Vec& x) {
  for (int i = 0; i < model.size(); ++i)
    if (std::optional<std::string> off = beyond_limiter(model, i, x[2 * i], x[2 * i + 1]))
      return off;
  for (int i = 0; i < model.size(); ++i)
    for (int j = i + 1; j < model.size(); ++j)
      if (std::optional<std::string> off = swapped(model, i, j, x[2 * i], x[2 * j])) return off;
  return out_of_circle_order(model, x);
}

double multiplier_band(const SimOptions& options) { return tolerance_for(options); }

bool inside_unit_circle(const std::vector<std::complex<double>>& multipliers, double band) {
  return std::all_of(multipliers.begin(), multipliers.end(),
                     [band](auto m) { return std::abs(m) < 1.0 - band; });
}

bool neutral_within(const std::vector<std::complex<double>>& multipliers, double band) {
  return !inside_unit_circle(multipliers, band) &&
         std::all_of(multipliers.begin(), multipliers.end(),
                     [band](auto m) { return std::abs(m) <= 1.0 + band; });
}

std::optional<Vec> run_from(const Model& m, const SimOptions& options, const Vec& x, double dt,
                            std::vector<bool>* armed) {
  if (armed) *armed = armed_at_start(m);
  if (!(dt > 0.0)) return x;
  SimOptions o = options;
  o.t_end = dt;
  o.check = false;
  o.record.clear();
  o.stops.clear();
  const RunResult run = simulate(started_at(m, x), o);
  if (armed) *armed = run.summary.armed;
  if (run.stats.termination != Termination::completed) return std::nullopt;
  return final_state(run);
}

MapPoint stroboscopic_map(const Model& model, const SimOptions& options, int periods,
                          const Vec& x) {
  const Deadline deadline = Deadline::in_ms(options.deadline_ms);
  MapPoint p;
  const double t_end = periods * forcing_period(model);
  p.x = x;
  p.image = x;
  if (std::optional<std::string> off = off_own_side(model, x)) {
    p.ok = false;
    p.run.stats.message = "starts " + *off;
    return p;
  }
  p.run = map_run(model, options, t_end, x, true);
  p.ok = p.run.stats.termination == Termination::completed;
  p.image = final_state(p.run);
  if (!p.ok) return p;
  if (std::string other = other_armed_set(model, p.run); !other.empty()) {
    p.ok = false;
    p.run.stats.message = other;
    return p;
  }
  if (std::string far = rests_on_far_side(model, p.run); !far.empty()) {
    p.ok = false;
    p.run.stats.message = far;
    return p;
  }
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
// (none, with orbit.message saying why, where that run failed); its armed set in orbit.armed.
std::optional<Vec> starting_state(const Model& model, const SimOptions& options,
                                  const OrbitSpec& spec, PeriodicOrbit& orbit) {
  const int n = model.size();
  Vec x(2 * n);
  orbit.armed = spec.armed.empty() ? armed_at_start(model) : spec.armed;
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
  orbit.armed = warmup.summary.armed;
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
void describe(const MapPoint& p, const OrbitSpec& spec, double band, PeriodicOrbit& orbit) {
  orbit.exact_jacobian = p.exact;
  orbit.jacobian_note = p.jacobian_note;
  const Eigen::EigenSolver<Mat> eig(p.jacobian, false);
  for (Eigen::Index k = 0; k < eig.eigenvalues().size(); ++k)
    orbit.multipliers.push_back(eig.eigenvalues()[k]);
  std::sort(orbit.multipliers.begin(), orbit.multipliers.end(),
            [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  orbit.stable = inside_unit_circle(orbit.multipliers, band);
  orbit.neutral = neutral_within(orbit.multipliers, band);
  int impacts = 0;
  for (Event e : p.run.events) {
    if (e.kind == EventKind::limiter || e.kind == EventKind::collision) ++impacts;
    e.t += orbit.t0;
    e.t_accumulation += orbit.t0;
    orbit.events.push_back(std::move(e));
  }
  orbit.impacts_per_period = static_cast<double>(impacts) / spec.periods;
  bool still = p.run.events.empty();
  for (Eigen::Index k = 1; k < p.x.size(); k += 2) still = still && p.x[k] == 0.0;
  orbit.at_rest = still;
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
  const std::string other = other_armed_set(model, run);
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
  } else if (!other.empty()) {
    orbit.message = "the check run " + other;
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
  // The mobile limiters armed as on the section, for every map and the check.
  const Model section = armed_as(model, orbit.armed);
  const MapPoint p =
      newton(section, options, deadline, spec, tol,
             stroboscopic_map(section, until(options, deadline), spec.periods, *x), orbit);
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
  describe(p, spec, multiplier_band(options), orbit);
  check_admissible(section, until(options, deadline), spec, p.x, tol, orbit);
  return orbit;
}

std::variant<OrbitReturn, FieldError> orbit_return(const Model& model, const SimOptions& options,
                                                   const PeriodicOrbit& orbit) {
  if (!orbit.converged)
    return FieldError{"periodic_orbit", "no periodic motion to draw: " + orbit.message};
  OrbitReturn once{armed_as(model, orbit.armed), options};
  for (int i = 0; i < once.model.size(); ++i) {
    once.model.pellets[i].phi0 = orbit.state[i].phi;
    once.model.pellets[i].dphi0 = orbit.state[i].dphi;
  }
  once.options.t_end = orbit.periods * orbit.period;
  return once;
}

}  // namespace vibro
