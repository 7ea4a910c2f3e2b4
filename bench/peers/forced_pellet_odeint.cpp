#include <array>
#include <boost/numeric/odeint.hpp>
#include <limits>

#include "peers/forced_pellet_equations.h"
#include "peers/forced_pellet_peer.h"

namespace vibro::bench {

PeerRun odeint_forced_pellet(const Model& model, double t_end, double rtol, double atol) {
  namespace odeint = boost::numeric::odeint;
  using State = std::array<double, 2>;
  ForcedPellet pellet(model);
  PeerRun run;
  auto sys = [&](const State& x, State& dxdt, double t) {
    ++run.rhs_evals;
    dxdt[0] = x[1];
    dxdt[1] = pellet.ddphi(t, x[0], x[1]);
  };
  auto stepper = odeint::make_dense_output(atol, rtol, odeint::runge_kutta_dopri5<State>());
  stepper.initialize(State{model.pellets[0].phi0, model.pellets[0].dphi0}, 0.0, 1e-4);
  State x;
  double g[ForcedPellet::kEvents];
  while (stepper.current_time() < t_end) {
    if (stepper.current_time() + stepper.current_time_step() > t_end) {
      stepper.initialize(State(stepper.current_state()), stepper.current_time(),
                         t_end - stepper.current_time());
    }
    const auto [t0, t1] = stepper.do_step(sys);
    ++run.steps;
    const State& x1 = stepper.current_state();
    pellet.events(x1[0], x1[1], g);
    // The earliest crossing among the functions negative at the step's end, each bisected on
    // the dense output down to round-off of t.
    int which = -1;
    double t_event = std::numeric_limits<double>::infinity();
    for (int i = 0; i < ForcedPellet::kEvents; ++i) {
      if (g[i] > 0.0) continue;
      double lo = t0, hi = t1;
      while (hi - lo > 4.0 * std::numeric_limits<double>::epsilon() * std::abs(hi)) {
        const double mid = 0.5 * (lo + hi);
        double gm[ForcedPellet::kEvents];
        stepper.calc_state(mid, x);
        pellet.events(x[0], x[1], gm);
        (gm[i] > 0.0 ? lo : hi) = mid;
      }
      if (hi < t_event) {
        t_event = hi;
        which = i;
      }
    }
    if (which < 0) continue;
    stepper.calc_state(t_event, x);
    run.failure = pellet.apply(which, t_event, x[0], x[1]);
    if (!run.failure.empty()) return run;
    if (which > 0) run.impact_times.push_back(t_event);
    stepper.initialize(x, t_event, stepper.current_time_step());
  }
  return run;
}

}  // namespace vibro::bench
