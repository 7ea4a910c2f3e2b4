#include "core/analysis/grazing_orbit.h"

#include <Eigen/LU>
#include <cmath>
#include <numbers>

#include "core/analysis/periodic_orbit.h"

namespace vibro {

Model without_limiter(Model m, int l) {
  m.limiters.erase(m.limiters.begin() + l);
  return m;
}

namespace {

// One return from the impact to the next, in unknowns w: the state just before the impact with
// speeds times the time scale, the pellet's angle (on the limiter) replaced by the impact's time
// over the time scale, so that a unit of each moves the motion alike.
class ImpactReturn {
 public:
  ImpactReturn(const Model& model, const SimOptions& options, int periods,
               const GrazingImpact& impact)
      : free_(without_limiter(model, impact.limiter)),
        options_(options),
        span_(periods * forcing_period(model)),
        impact_(impact),
        angle_(model.limiters[impact.limiter].angle),
        k_(model.limiters[impact.limiter].k),
        scale_(time_scale(model)) {}

  Vec unknowns(const Vec& before, double time) const {
    Vec w = before;
    for (Eigen::Index k = 1; k < w.size(); k += 2) w[k] *= scale_;
    w[2 * impact_.pellet] = time / scale_;
    return w;
  }
  double time(const Vec& w) const { return w[2 * impact_.pellet] * scale_; }
  Vec before(const Vec& w) const {
    Vec s = w;
    for (Eigen::Index k = 1; k < s.size(); k += 2) s[k] /= scale_;
    s[2 * impact_.pellet] = angle_;
    return s;
  }
  Vec after(const Vec& w) const {
    Vec s = before(w);
    s[2 * impact_.pellet + 1] *= -k_;
    return s;
  }

  // The state before the impact one return later minus the one before it (speeds times the time
  // scale, angles modulo 2π); none where the run fails.
  std::optional<Vec> residual(const Vec& w) const {
    const std::optional<Vec> back = run_from(at_phase(free_, time(w)), options_, after(w), span_);
    if (!back) return std::nullopt;
    Vec r = *back - before(w);
    for (Eigen::Index k = 0; k < r.size(); k += 2)
      r[k] = std::remainder(r[k], 2.0 * std::numbers::pi);
    for (Eigen::Index k = 1; k < r.size(); k += 2) r[k] *= scale_;
    return r;
  }

  // The state on the section after the impact (the model's next t ≡ 0 mod the span).
  std::optional<Vec> on_section(const Vec& w) const {
    const double t = time(w);
    const double dt = span_ * std::ceil(t / span_) - t;
    return run_from(at_phase(free_, t), options_, after(w), dt);
  }

 private:
  const Model free_;
  const SimOptions& options_;
  const double span_;
  const GrazingImpact impact_;
  const double angle_, k_, scale_;
};

// The residual's Jacobian in w by central differences (steps of 1e-7: the unknowns are O(1e-3)
// to O(1) and the runs' error is far below), or none where a run fails.
std::optional<Mat> differenced(const ImpactReturn& ret, const Vec& w) {
  constexpr double h = 1e-7;
  Mat J(w.size(), w.size());
  for (Eigen::Index k = 0; k < w.size(); ++k) {
    Vec up = w, down = w;
    up[k] += h;
    down[k] -= h;
    const std::optional<Vec> ru = ret.residual(up), rd = ret.residual(down);
    if (!ru || !rd) return std::nullopt;
    J.col(k) = (*ru - *rd) / (2.0 * h);
  }
  return J;
}

}  // namespace

std::optional<ImpactingOrbit> impacting_orbit(const Model& model, const SimOptions& options,
                                              int periods, const GrazingImpact& impact, double time,
                                              const Vec& before, double tol) {
  const ImpactReturn ret(model, options, periods, impact);
  Vec w = ret.unknowns(before, time);
  for (int it = 0;; ++it) {
    const std::optional<Vec> r = ret.residual(w);
    if (!r || !r->allFinite()) return std::nullopt;
    if (r->lpNorm<Eigen::Infinity>() <= 0.01 * tol) break;
    if (it == 16) return std::nullopt;
    const std::optional<Mat> J = differenced(ret, w);
    if (!J) return std::nullopt;
    const Vec dw = J->fullPivLu().solve(-*r);
    if (!dw.allFinite()) return std::nullopt;
    w += dw;
  }
  const std::optional<Vec> x = ret.on_section(w);
  const double speed = ret.before(w)[2 * impact.pellet + 1];
  if (!x || !(speed * impact.side > 0.0)) return std::nullopt;
  return ImpactingOrbit{*x, ret.time(w), speed, ret.before(w)};
}

}  // namespace vibro
