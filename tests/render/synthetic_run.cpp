#include "synthetic_run.h"

#include <array>
#include <cmath>
#include <numbers>

namespace vibro::testing {
namespace {

constexpr double kDt = 1e-3;

struct State {
  double phi, dphi;
};

State rk4(const Model& model, State s, double damping, double h) {
  const auto f = [&](State x) {
    return State{x.dphi, -(model.g / model.R) * std::sin(x.phi) - damping * x.dphi};
  };
  const State k1 = f(s);
  const State k2 = f({s.phi + 0.5 * h * k1.phi, s.dphi + 0.5 * h * k1.dphi});
  const State k3 = f({s.phi + 0.5 * h * k2.phi, s.dphi + 0.5 * h * k2.dphi});
  const State k4 = f({s.phi + h * k3.phi, s.dphi + h * k3.dphi});
  return {s.phi + h / 6.0 * (k1.phi + 2 * k2.phi + 2 * k3.phi + k4.phi),
          s.dphi + h / 6.0 * (k1.dphi + 2 * k2.dphi + 2 * k3.dphi + k4.dphi)};
}

class Builder {
 public:
  explicit Builder(int pellets) : run_() {
    for (int i = 0; i < pellets; ++i) run_.tracks.push_back({i, {Branch{1, {}}}});
  }
  void sample(int pellet, double t, State s) {
    branches(pellet).back().samples.push_back({t, s.phi, s.dphi});
  }
  // Ends the pellet's branch at `before` and opens the next one at `after`.
  void split(int pellet, double t, State before, State after) {
    sample(pellet, t, before);
    auto& list = branches(pellet);
    list.push_back(Branch{list.back().index + 1, {}});
    sample(pellet, t, after);
  }
  void event(Event e) { run_.events.push_back(std::move(e)); }
  RunResult take() { return std::move(run_); }

 private:
  std::vector<Branch>& branches(int pellet) { return run_.tracks[pellet].branches; }
  RunResult run_;
};

}  // namespace

Model synthetic_model() {
  Model model;
  model.R = 0.5;
  model.alpha0 = 0.05;
  model.pellets = {Pellet{0.2, 0.2, 9.0, {}}, Pellet{0.2, -0.3, -2.0, {}}};
  model.limiters = {Limiter{std::numbers::pi / 4, 0.6, true, 1, {}},
                    Limiter{-std::numbers::pi / 2, 0.6, false, -1, {}}};
  return model;
}

RunResult synthetic_run(const Model& model, double t_end, double damping) {
  const int n = model.size();
  std::vector<State> state;
  for (const Pellet& p : model.pellets) state.push_back({p.phi0, p.dphi0});
  Builder out(n);
  for (int i = 0; i < n; ++i) out.sample(i, 0.0, state[i]);
  for (double t = kDt; t <= t_end + 0.5 * kDt; t += kDt) {
    std::vector<State> next(n);
    for (int i = 0; i < n; ++i) next[i] = rk4(model, state[i], damping, kDt);
    for (int i = 0; i < n; ++i) {
      bool split = false;
      for (int l = 0; l < static_cast<int>(model.limiters.size()) && !split; ++l) {
        const Limiter& lim = model.limiters[l];
        if ((state[i].phi - lim.angle) * (next[i].phi - lim.angle) < 0.0) {
          const State before{lim.angle, next[i].dphi};
          const State after{lim.angle, -lim.k * next[i].dphi};
          out.split(i, t, before, after);
          out.event({t, EventKind::limiter, {i}, l, lim.angle, {before.dphi}, {after.dphi}});
          next[i] = after;
          split = true;
        }
      }
      if (!split && state[i].dphi * next[i].dphi < 0.0) {
        out.split(i, t, next[i], next[i]);
        out.event({t, EventKind::reversal, {i}, -1, next[i].phi, {next[i].dphi}, {next[i].dphi}});
        split = true;
      }
      if (!split) out.sample(i, t, next[i]);
    }
    // Elastic collision of equal masses: the velocities swap where the pellets meet.
    for (int i = 0; i + 1 < n; ++i) {
      const int j = i + 1;
      if ((state[i].phi - state[j].phi) * (next[i].phi - next[j].phi) < 0.0) {
        const double phi = 0.5 * (next[i].phi + next[j].phi);
        const State bi{phi, next[i].dphi}, bj{phi, next[j].dphi};
        const State ai{phi, next[j].dphi}, aj{phi, next[i].dphi};
        out.split(i, t, bi, ai);
        out.split(j, t, bj, aj);
        out.event(
            {t, EventKind::collision, {i, j}, -1, phi, {bi.dphi, bj.dphi}, {ai.dphi, aj.dphi}});
        next[i] = ai;
        next[j] = aj;
      }
    }
    state = next;
  }
  RunResult run = out.take();
  run.stats.t_reached = t_end;
  return run;
}

}  // namespace vibro::testing
