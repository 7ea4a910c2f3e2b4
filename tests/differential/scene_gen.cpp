#include "tests/differential/scene_gen.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <mutex>
#include <numbers>
#include <optional>
#include <ostream>

#include "io/scene_json.h"

namespace vibro::differential {
namespace {

using std::numbers::pi;

// A number in [0, 1] that shrinks toward 0. Drawn at RapidCheck's nominal size: gen::inRange
// scales its range with the size, which would make the first scenes of a check all alike.
double unit() {
  constexpr int kSteps = 1 << 20;
  return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, kSteps + 1)) / double(kSteps);
}
double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
double log_uniform(double lo, double hi) { return lo * std::pow(hi / lo, unit()); }

// An index drawn with the given weights; shrinks toward 0, so the simplest option goes first.
int choose(std::initializer_list<int> weights) {
  int total = 0;
  for (int w : weights) total += w;
  int x = *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, total));
  int i = 0;
  for (int w : weights) {
    if (x < w) return i;
    x -= w;
    ++i;
  }
  return i - 1;
}

Limiter gen_limiter(int index, int limiters, int pellets) {
  Limiter l;
  l.angle = uniform(-pi, pi);
  switch (choose({3, 1, 1})) {
    case 0:
      l.k = unit();
      break;
    case 1:
      l.k = 1.0;
      break;
    default:
      l.k = 0.0;
      break;
  }
  if (limiters >= 2 && choose({2, 1}) == 1) {
    l.mobile = true;
    l.rearm_by = (index + 1 + choose({1, 1, 1}) % (limiters - 1)) % limiters;
  }
  if (pellets >= 2 && choose({3, 1}) == 1) {
    for (int p = 0; p < pellets; ++p)
      if (choose({1, 1}) == 1) l.pellets.push_back(p);
    if (l.pellets.empty()) l.pellets.push_back(index % pellets);
  }
  return l;
}

// The angle where a pellet at rest has a_free = r·capacity at t = 0 (|r| ≤ 1: inside the
// friction cone, it sticks; otherwise it slides off at once), on the lower half where
// cos φ > 0. With f = F(0)/(m g) the condition f − sin φ = r·mu_s·cos φ reads
// sqrt(1 + A²)·sin(φ + atan A) = f with A = r·mu_s. Empty when no such angle exists.
std::optional<double> cone_angle(double f, double r, double mu_s) {
  const double A = r * mu_s;
  const double s = f / std::sqrt(1.0 + A * A);
  if (std::abs(s) > 1.0) return std::nullopt;
  return std::asin(s) - std::atan(A);
}

Pellet gen_pellet(const Model& m, int index) {
  Pellet p;
  p.m = log_uniform(0.01, 10.0);
  if (choose({1, 1}) == 1) {
    p.force.F0 = p.m * m.g * uniform(0.0, 3.0);
    p.force.Omega = log_uniform(0.1, 1e4);
    p.force.psi = uniform(0.0, 2.0 * pi);
  }
  const double v_scale = std::sqrt(m.g / m.R);
  const double winding = kTwoPi * std::array{0, 1, -1}[choose({4, 1, 1})];
  bool may_move = true;
  enum { free, rest_by_cone, at_limiter, touching };
  int where = choose({3, 2, 1, 1});
  if (where == at_limiter && m.limiters.empty()) where = free;
  if (where == touching && index == 0) where = free;
  switch (where) {
    case free:
      p.phi0 = uniform(-pi, pi) + winding;
      break;
    case rest_by_cone: {
      const double f = p.force.F0 * std::cos(p.force.psi) / (p.m * m.g);
      const auto phi = cone_angle(f, uniform(-3.0, 3.0), m.mu_static());
      p.phi0 = (phi ? *phi : uniform(-pi, pi)) + winding;
      may_move = false;
      break;
    }
    case at_limiter:
      p.phi0 = m.limiters[choose({1, 1, 1}) % m.limiters.size()].angle;
      break;
    case touching:  // just clear of validate_model's 1e-9 floor, or a little more
      p.phi0 = m.pellets[index - 1].phi0 + (choose({1, 1}) == 0 ? 2e-9 : 1e-6);
      break;
  }
  if (may_move && choose({2, 1}) == 0) {
    const double sign = choose({1, 1}) == 0 ? 1.0 : -1.0;
    p.dphi0 = sign * log_uniform(0.03, 10.0) * v_scale;
  }
  return p;
}

// Pellets are point masses and must start apart (validate_model: 1e-9 rad): a pellet that
// lands on another (shrinking pulls angles to the same end of their range) is moved off it.
// The bound sits between that floor and the 2e-9 of "touching" pellets, which round-off in
// wrap_angle brings a little below 2e-9.
void separate(Model& m) {
  for (int i = 1; i < m.size(); ++i) {
    for (int tries = 0; tries < 8; ++tries) {
      bool clash = false;
      for (int j = 0; j < i; ++j)
        clash = clash || std::abs(wrap_angle(m.pellets[i].phi0 - m.pellets[j].phi0)) < 1.5e-9;
      if (!clash) break;
      m.pellets[i].phi0 += 1e-6;
    }
  }
}

}  // namespace

RandomScene scene_at(std::uint64_t seed, long i) {
  static std::mutex generating;
  std::lock_guard lock(generating);
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(i);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return gen_scene()(rc::Random(z), rc::kNominalSize).value();
}

rc::Gen<RandomScene> gen_scene() {
  return rc::gen::exec([] {
    RandomScene s;
    Model& m = s.model;
    m.R = log_uniform(1e-3, 10.0);
    m.friction = choose({1, 1}) == 0 ? FrictionLaw::paper : FrictionLaw::bilateral;
    m.alpha0 = choose({1, 4}) == 0 ? 0.0 : uniform(0.0, 0.5);
    if (choose({2, 1}) == 1) m.mu_s = m.mu() + 0.5 * unit();
    switch (choose({1, 1, 3})) {
      case 0:
        m.k_c = 1.0;
        break;
      case 1:
        m.k_c = 0.0;
        break;
      default:
        m.k_c = unit();
        break;
    }
    const int pellets = 1 + choose({1, 1, 1, 1});
    const int limiters = choose({1, 2, 2, 2});
    for (int l = 0; l < limiters; ++l) m.limiters.push_back(gen_limiter(l, limiters, pellets));
    for (int i = 0; i < pellets; ++i) m.pellets.push_back(gen_pellet(m, i));
    separate(m);

    // A few time scales, and no more than 40 periods of the fastest forcing: every forcing
    // period can hold a stick and a release, and its steps.
    s.t_end = uniform(0.5, 5.0) * time_scale(m);
    for (const Pellet& p : m.pellets)
      if (p.force.active()) s.t_end = std::min(s.t_end, 40.0 * kTwoPi / p.force.Omega);
    return s;
  });
}

SimOptions run_options(const RandomScene& scene, Method method, double rtol) {
  SimOptions o;
  o.t_end = scene.t_end;
  o.method = method;
  o.rtol = rtol;
  o.atol = 1e-12;   // API.md's default: the instrument runs scenes as a user would
  o.check = false;  // the engine's own shadow run: the instrument compares runs itself
  o.max_events = 20000;
  o.max_steps = 2000000;
  o.deadline_ms = 2000.0;
  return o;
}

Scene to_scene(const RandomScene& scene, Method method, double rtol,
               const std::string& description) {
  Scene s;
  s.description = description;
  s.model = scene.model;
  const SimOptions o = run_options(scene, method, rtol);
  s.sim.t_end = o.t_end;
  s.sim.method = o.method;
  s.sim.rtol = o.rtol;
  s.sim.atol = o.atol;
  TimePlot time;
  for (int i = 0; i < scene.model.size(); ++i) time.pellets.push_back(i);
  s.figure.plots = {time};
  return s;
}

std::string scene_json_text(const RandomScene& scene, Method method, double rtol,
                            const std::string& description) {
  return scene_to_json(to_scene(scene, method, rtol, description)).dump(2);
}

void showValue(const RandomScene& scene, std::ostream& os) {
  os << scene_json_text(scene, Method::automatic, 1e-11);
}

}  // namespace vibro::differential
