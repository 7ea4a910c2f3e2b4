// The Taylor coefficients of SegmentDynamics (core/model/dynamics.h): the same equations as its
// right-hand side, term by term, as normalized series in τ = t − t0.
#include <algorithm>
#include <cmath>

#include "core/integrators/series.h"
#include "core/model/dynamics.h"

namespace vibro {

using integrators::add_cosine_series;
using integrators::product_coefficient;
using integrators::sin_cos_coefficient;

bool SegmentDynamics::taylor_coefficients(double t0, const Vec& y0, int order,
                                          std::span<double> out) const {
  const std::size_t n1 = static_cast<std::size_t>(order) + 1;
  for (Eigen::Index i = 0; i < y0.size(); ++i) {
    const std::span<double> c = out.subspan(static_cast<std::size_t>(i) * n1, n1);
    c[0] = y0[i];
    std::fill(c.begin() + 1, c.end(), 0.0);  // a held body's state stays
  }
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].mode == Mode::sliding) body_jets(b, t0, order, out);
  return true;
}

// A sliding body: its leader's angle u and speed v give every member's acceleration (as
// SlidingLaw::acceleration, its damping C·v last) and, with each member's force, its work rate
// R·v·(F_i − m_i·s·μ·n) − m_i·R²·c_i·v².
// Coefficient k + 1 of each state component is coefficient k of its rate over k + 1.
void SegmentDynamics::body_jets(std::size_t b, double t0, int order, std::span<double> out) const {
  const Body& body = bodies_[b];
  const std::size_t n1 = static_cast<std::size_t>(order) + 1;
  auto component = [&](int i) { return out.subspan(static_cast<std::size_t>(i) * n1, n1); };
  const int L = body.leader();
  const std::span<const double> u = component(phi_index(L)), v = component(dphi_index(L));
  // The body's series: sin u, cos u, v², its total force, the normal force n; then per member
  // its force, and its work's rate.
  jet_scratch_.assign(7 * n1, 0.0);
  const std::span<double> scratch(jet_scratch_);
  const std::span<double> S = scratch.subspan(0, n1), C = scratch.subspan(n1, n1),
                          Q = scratch.subspan(2 * n1, n1), F = scratch.subspan(3 * n1, n1),
                          N = scratch.subspan(4 * n1, n1), Fi = scratch.subspan(5 * n1, n1),
                          G = scratch.subspan(6 * n1, n1);
  auto add_force = [&](int i, std::span<double> into) {
    const Forcing& f = model_.pellets[i].force;
    if (f.active()) add_cosine_series(f.F0, f.Omega, f.Omega * t0 + f.psi, order, into);
  };
  for (int i : body.members) add_force(i, F);
  const double R = law_.R, gR = law_.gR, mu = law_.mu, M = mass_[b], damping = damping_[b];
  const int s = body.s, side = normal_side_[b];
  const double sigma = law_.paper ? 1.0 : side;  // n = R·σ·(v² + gR·cos u)
  // Without friction v² and n enter neither the motion nor the work, unless a damper's power
  // needs v²: they stay 0.
  const bool damped = std::any_of(body.members.begin(), body.members.end(),
                                  [&](int i) { return model_.pellets[i].c != 0.0; });
  const bool squares = mu != 0.0 || damped;
  S[0] = std::sin(u[0]);
  C[0] = std::cos(u[0]);
  for (int k = 0; k < order; ++k) {
    if (k > 0) sin_cos_coefficient(u, S, C, k);
    if (squares) Q[k] = product_coefficient(v, v, k);
    double acc = law_.paper ? F[k] / (M * R) - s * mu * Q[k] - gR * (S[k] + s * mu * C[k])
                            : F[k] / (M * R) - gR * S[k] - s * mu * side * (Q[k] + gR * C[k]);
    acc -= damping * v[k];
    if (mu != 0.0) N[k] = R * sigma * (Q[k] + gR * C[k]);
    for (int i : body.members) {
      component(phi_index(i))[k + 1] = component(dphi_index(i))[k] / (k + 1);
      component(dphi_index(i))[k + 1] = acc / (k + 1);
    }
  }
  const bool alone = body.members.size() == 1;  // its force is the body's
  for (int i : body.members) {
    if (!alone) {
      std::fill(Fi.begin(), Fi.end(), 0.0);
      add_force(i, Fi);
    }
    const std::span<const double> Fm = alone ? F : Fi;
    const Pellet& p = model_.pellets[i];
    const double ms_mu = p.m * s * mu, damper = p.m * R * R * p.c;  // damper·v² is its power
    for (int k = 0; k < order; ++k) G[k] = Fm[k] - ms_mu * N[k];
    const std::span<double> w = component(work_index(i));
    for (int k = 0; k < order; ++k)
      w[k + 1] = (R * product_coefficient(v, G, k) - damper * Q[k]) / (k + 1);
  }
}

}  // namespace vibro
