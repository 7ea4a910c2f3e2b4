#include "core/run/polish.h"

#include <cmath>

namespace vibro {

void RootPolisher::polish(const MotionInterval& interval, const Crossing& c, Stepper& stepper,
                          double a, double b, double& t, Vec& y_out) {
  const Watch& w = interval.watches()[c.watch];
  const std::vector<Body>& bodies = interval.bodies();
  Vec& y = scratch_;
  double value = 0.0, slope = 0.0, curvature = 0.0;
  if (follows_motion(w.kind)) {
    stepper.precise_state(t, y);
    const Closing at = closing(w, model_, law_, bodies, t, y, /*with_curvature=*/true);
    value = at.value;
    slope = at.rate;
    curvature = at.curvature;
  } else {
    auto g_dense = [&](double tt) {
      stepper.dense(tt, y);
      return evaluate(w, model_, bodies, tt, y);
    };
    const double delta = 1e-3 * (t - a);
    const double before = g_dense(t - delta), at = g_dense(t), after = g_dense(t + delta);
    slope = (after - before) / (2.0 * delta);
    curvature = (after - 2.0 * at + before) / (delta * delta);
    stepper.precise_state(t, y);
    value = evaluate(w, model_, bodies, t, y);
  }
  // The root nearest t of the quadratic (a straight line for a speed, whose curvature the state
  // does not give).
  const double disc = slope * slope - 2.0 * curvature * value;
  if (!(disc >= 0.0)) return;
  const double dt = -2.0 * value / (slope + std::copysign(std::sqrt(disc), slope));
  if (!std::isfinite(dt) || std::abs(curvature * dt) > 0.1 * std::abs(slope)) return;
  if (!(t + dt >= a && t + dt <= b)) return;  // the root lies in this step: no correction leaves it
  const SegmentDynamics& f = interval.dynamics();
  y_out = y;
  f.rhs(t, y_out, y);
  y = y_out + 0.5 * dt * y;
  midpoint_rate_.resize(y_out.size());
  f.rhs(t + 0.5 * dt, y, midpoint_rate_);
  y_out += dt * midpoint_rate_;
  t += dt;
}

}  // namespace vibro
