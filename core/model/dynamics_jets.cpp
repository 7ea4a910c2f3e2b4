// The Taylor coefficients of SegmentDynamics (core/model/dynamics.h): the same equations as its
// right-hand side, term by term, as normalized series in τ = t − t0.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "core/integrators/series.h"
#include "core/model/dynamics.h"

namespace vibro {

using integrators::add_cosine_series;
using integrators::product_coefficient;

namespace {

// A body's series up to this order live on the stack (the Taylor method asks for 30 at most);
// longer ones in SegmentDynamics::jet_scratch_.
constexpr std::size_t kStackTerms = 32;
// The series a body's jets need, in units of n1 doubles: {cos u, sin u} pairs (2), j·u[j] pairs
// (2), v², the body's force, the normal force, one member's force and that force less friction's,
// and v in pairs {v[j], v[j]} (2).
constexpr std::size_t kJetSeries = 11;

// Two doubles that add and multiply lane by lane, each lane exactly as a double does (IEEE,
// no contraction): two sums kept side by side are the two sums, bit for bit, at one instruction
// per step for both. Loaded and stored unaligned.
typedef double Pair __attribute__((vector_size(16), aligned(8), may_alias));

// Coefficient k >= 1 of S = sin u and C = cos u into CS[k] = {C[k], S[k]}, from
// ju[j] = {j·u[j], j·u[j]} (j = 1..k) and CS up to k − 1: integrators::sin_cos_coefficient's
// sums, term for term and in the same order, both in one pass.
void sin_cos_pair(const Pair* ju, Pair* CS, int k) {
  Pair sc = {0.0, 0.0};  // {Σ j·u[j]·C[k−j], Σ j·u[j]·S[k−j]}
  int j = 1;
  for (; j < k; j += 2) {  // two terms per pass, added one after the other
    sc += ju[j] * CS[k - j];
    sc += ju[j + 1] * CS[k - j - 1];
  }
  if (j == k) sc += ju[j] * CS[0];
  CS[k] = Pair{-sc[1] / k, sc[0] / k};
}

// Coefficients k and k + 1 of the product v·g, from vv[j] = {v[j], v[j]}: each summed over j
// ascending as integrators::product_coefficient does, in the two lanes of one pass (lane 1's
// last term, j = k + 1, added after it).
Pair product_pair(const Pair* vv, const double* g, int k) {
  auto g_pair = [&](int j) {  // {g[k − j], g[k − j + 1]}, copied out of the doubles
    Pair x;
    std::memcpy(&x, g + (k - j), sizeof x);
    return x;
  };
  Pair sum = {0.0, 0.0};
  int j = 0;
  for (; j < k; j += 2) {  // two terms per pass, added one after the other
    sum += vv[j] * g_pair(j);
    sum += vv[j + 1] * g_pair(j + 1);
  }
  if (j == k) sum += vv[j] * g_pair(j);
  sum[1] += vv[k + 1][0] * g[0];
  return sum;
}

}  // namespace

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
// Each series is computed by the same operations in the same order as the right-hand side's
// terms; the shortcuts below (a series that is zero, a term that is zero) change no bit.
void SegmentDynamics::body_jets(std::size_t b, double t0, int order, std::span<double> out) const {
  const Body& body = bodies_[b];
  const std::size_t n1 = static_cast<std::size_t>(order) + 1;
  double* const state = out.data();
  auto component = [&](int i) { return state + static_cast<std::size_t>(i) * n1; };
  const int L = body.leader();
  const double* const u = component(phi_index(L));
  const double* const v = component(dphi_index(L));
  std::array<double, kJetSeries * kStackTerms> stack;
  double* scratch = stack.data();
  if (n1 > kStackTerms) {
    jet_scratch_.resize(kJetSeries * n1);
    scratch = jet_scratch_.data();
  }
  Pair* const CS = reinterpret_cast<Pair*>(scratch);  // n1 pairs
  Pair* const ju = reinterpret_cast<Pair*>(scratch + 2 * n1);
  double* const Q = scratch + 4 * n1;
  double* const F = scratch + 5 * n1;
  double* const N = scratch + 6 * n1;
  double* const Fi = scratch + 7 * n1;
  double* const G = scratch + 8 * n1;
  Pair* const vv = reinterpret_cast<Pair*>(scratch + 9 * n1);
  auto add_force = [&](int i, double* into) {
    const Forcing& f = model_.pellets[i].force;
    if (f.active())
      add_cosine_series(f.F0, f.Omega, f.Omega * t0 + f.psi, order, std::span<double>(into, n1));
  };
  std::fill(F, F + n1, 0.0);
  for (int i : body.members) add_force(i, F);
  const double R = law_.R, gR = law_.gR, mu = law_.mu, M = mass_[b], damping = damping_[b];
  const int s = body.s, side = normal_side_[b];
  const double sigma = law_.paper ? 1.0 : side;  // n = R·σ·(v² + gR·cos u)
  // Without friction v² and n enter neither the motion nor the work, unless a damper's power
  // needs v²: they stay 0.
  const bool damped = std::any_of(body.members.begin(), body.members.end(),
                                  [&](int i) { return model_.pellets[i].c != 0.0; });
  const bool squares = mu != 0.0 || damped;
  if (!squares) std::fill(Q, Q + n1, 0.0);
  if (mu == 0.0) std::fill(N, N + n1, 0.0);
  const double S0 = std::sin(u[0]), C0 = std::cos(u[0]);
  CS[0] = Pair{C0, S0};
  const bool alone = body.members.size() == 1;  // its force is the body's
  double* const phi = component(phi_index(L));
  double* const dphi = component(dphi_index(L));
  for (int k = 0; k < order; ++k) {
    if (k > 0) {
      const double juk = k * u[k];
      ju[k] = Pair{juk, juk};
      sin_cos_pair(ju, CS, k);
    }
    const double Sk = CS[k][1], Ck = CS[k][0];
    if (squares) Q[k] = product_coefficient({v, n1}, {v, n1}, k);
    double acc = law_.paper ? F[k] / (M * R) - s * mu * Q[k] - gR * (Sk + s * mu * Ck)
                            : F[k] / (M * R) - gR * Sk - s * mu * side * (Q[k] + gR * Ck);
    acc -= damping * v[k];
    if (mu != 0.0) N[k] = R * sigma * (Q[k] + gR * Ck);
    if (alone) {
      phi[k + 1] = dphi[k] / (k + 1);
      dphi[k + 1] = acc / (k + 1);
      continue;
    }
    for (int i : body.members) {
      component(phi_index(i))[k + 1] = component(dphi_index(i))[k] / (k + 1);
      component(dphi_index(i))[k + 1] = acc / (k + 1);
    }
  }
  for (int j = 0; j < order; ++j) vv[j] = Pair{v[j], v[j]};
  for (int i : body.members) {
    if (!alone) {
      std::fill(Fi, Fi + n1, 0.0);
      add_force(i, Fi);
    }
    const double* const Fm = alone ? F : Fi;
    const Pellet& p = model_.pellets[i];
    const double ms_mu = p.m * s * mu, damper = p.m * R * R * p.c;  // damper·v² is its power
    // Without friction n is 0 and G is the force itself: Fm[k] − (±0) is Fm[k] (never −0).
    const double* g = Fm;
    if (mu != 0.0) {
      for (int k = 0; k < order; ++k) G[k] = Fm[k] - ms_mu * N[k];
      g = G;
    }
    double* const w = component(work_index(i));
    // Coefficient k of the work's rate over k + 1. Without v² (no friction, no damper)
    // damper·Q[k] is a zero that changes nothing.
    auto rate = [&](int k, double product) {
      return squares ? (R * product - damper * Q[k]) / (k + 1) : R * product / (k + 1);
    };
    int k = 0;
    for (; k + 1 < order; k += 2) {
      const Pair product = product_pair(vv, g, k);
      w[k + 1] = rate(k, product[0]);
      w[k + 2] = rate(k + 1, product[1]);
    }
    if (k < order) w[k + 1] = rate(k, product_coefficient({v, n1}, {g, n1}, k));
  }
}

}  // namespace vibro
