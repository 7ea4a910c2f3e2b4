// The Taylor coefficients of SegmentDynamics (core/model/dynamics.h): the same equations as its
// right-hand side, term by term, as normalized series in τ = t − t0.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

#include "core/integrators/series.h"
#include "core/model/dynamics.h"

namespace vibro {

using integrators::add_cosine_series;
using integrators::cosine_series_factors;
using integrators::product_coefficient;

namespace {

// A body's series up to this order live on the stack (the Taylor method asks for 30 at most);
// longer ones in SegmentDynamics::jet_scratch_.
constexpr std::size_t kStackTerms = 32;
// The series a body's jets need, in units of n1 doubles: {cos u, sin u} pairs (2), v², the body's
// force, the normal force, one member's force and that force less friction's, and v in pairs
// {v[j], v[j]} (2); and one double more, by which the pairs {v[j], v[j]} may be moved to be
// aligned.
constexpr std::size_t kJetSeries = 9;
constexpr std::size_t jet_scratch_size(std::size_t n1) { return kJetSeries * n1 + 1; }

// Two doubles that add and multiply lane by lane, each lane exactly as a double does (IEEE,
// no contraction): two sums kept side by side are the two sums, bit for bit, at one instruction
// per step for both. Aligned to 16 bytes (jet_series lays the pairs out so, in a scratch that is
// aligned): a product of pairs reads one of them from memory as it multiplies.
typedef double Pair __attribute__((vector_size(16), may_alias));

// Coefficient k >= 1 of S = sin u and C = cos u into CS[k] = {C[k], S[k]}, where u' = v:
// S[k] = (1/k) Σ_{i=0..k−1} v[i]·C[k−1−i], C[k] = −(1/k) Σ v[i]·S[k−1−i] (S' = v·C, C' = −v·S;
// integrators::sin_cos_coefficient's sums with j·u[j] = v[j − 1]), both in one pass, from
// vv[i] = {v[i], v[i]} (i < k), CS up to k − 1 and r = 1/k. The two terms whose inputs the
// recursion makes last (v[k − 1], CS[k − 1]) are added last and the others in two partial sums
// beforehand, so that the chain from one coefficient to the next is a few operations, not k.
[[gnu::always_inline]] inline void sin_cos_pair(const Pair* vv, Pair* CS, int k, double r) {
  Pair even = {0.0, 0.0}, odd = {0.0, 0.0};  // the terms i = 1..k − 2
  int i = 1;
  for (; i + 1 < k - 1; i += 2) {
    even += vv[i] * CS[k - 1 - i];
    odd += vv[i + 1] * CS[k - 2 - i];
  }
  if (i < k - 1) even += vv[i] * CS[k - 1 - i];
  Pair sc = even + odd;  // {Σ v[i]·C[k−1−i], Σ v[i]·S[k−1−i]}
  if (k > 1) sc += vv[k - 1] * CS[0];
  sc += vv[0] * CS[k - 1];
  CS[k] = Pair{-sc[1] * r, sc[0] * r};
}

// Coefficients k and k + 1 of the product v·g, from vv[j] = {v[j], v[j]}: each summed over j
// ascending as integrators::product_coefficient does, in the two lanes of one pass (lane 1's
// last term, j = k + 1, added after it).
[[gnu::always_inline]] inline Pair product_pair(const Pair* vv, const double* g, int k) {
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

// f(K) for each K of the sequence, in order, written out.
template <class F, int... K>
[[gnu::always_inline]] inline void call_each(F& f, std::integer_sequence<int, K...>) {
  (f(K), ...);
}

// Calls f(k) for k = 0..count − 1 in order. With kCount > 0 (then count == kCount) the calls are
// written out, k a constant in each: the recursions' loops over j <= k then have constant bounds
// and unroll, the same operations in the same order without the loops' bookkeeping.
template <int kCount, class F>
[[gnu::always_inline]] inline void for_each_k(int count, F& f) {
  if constexpr (kCount > 0)
    call_each(f, std::make_integer_sequence<int, kCount>{});
  else
    for (int k = 0; k < count; ++k) f(k);
}

// What one body's jets read: the model's constants, the body's, and where its series go.
struct BodyJets {
  const Model& model;
  const Body& body;
  const SlidingLaw& law;
  double M, damping;  // the body's mass and damping
  int side;           // its side of the bilateral law's normal force
  double t0;
  int order;
  const double* inverse;  // 1/k for k = 1..order + 1 (integrators::kReciprocal)
  const double* force;    // every pellet's forcing factors F0·Ωᵏ/k!, (order + 1) each
  double* state;          // the components' series, (order + 1) each
  double* scratch;        // jet_scratch_size(order + 1) doubles, aligned to 16 bytes
};

// The series one body's jets work in, laid out in BodyJets::scratch: the pairs at even offsets.
struct JetSeries {
  Pair* CS;    // {cos u, sin u}, n1 pairs
  double* Q;   // v²
  double* F;   // the body's force
  double* N;   // the normal force
  double* Fi;  // one member's force
  double* G;   // that force less friction's
  Pair* vv;    // {v[j], v[j]}, n1 pairs
};

JetSeries jet_series(double* scratch, std::size_t n1) {
  return {reinterpret_cast<Pair*>(scratch),
          scratch + 2 * n1,
          scratch + 3 * n1,
          scratch + 4 * n1,
          scratch + 5 * n1,
          scratch + 6 * n1,
          reinterpret_cast<Pair*>(scratch + 7 * n1 + n1 % 2)};
}

// Adds pellet i's force F0 cos(Ωt + ψ) as a series in τ = t − t0 to into[0..order].
// kOrder: the order as a constant (0: read from in.order).
template <int kOrder>
void add_force(const BodyJets& in, int i, double* into) {
  const Forcing& f = in.model.pellets[i].force;
  const std::size_t n1 = static_cast<std::size_t>(kOrder > 0 ? kOrder : in.order) + 1;
  if (f.active())
    add_cosine_series(std::span<const double>(in.force + static_cast<std::size_t>(i) * n1, n1),
                      f.Omega * in.t0 + f.psi, std::span<double>(into, n1));
}

// Coefficient k of v², the square the motion reads: 0 without friction or a damper (kSquares),
// where v² enters neither the motion nor the work.
template <bool kSquares>
double square(const JetSeries& x, int k) {
  if constexpr (kSquares)
    return x.Q[k];
  else
    return 0.0;
}

// The jets of one sliding body's motion: its leader's angle u and speed v give every member's
// acceleration (as SlidingLaw::acceleration, its damping C·v last); coefficient k + 1 of each
// state component is coefficient k of its rate over k + 1. Leaves v², the normal force and v in
// pairs in x for the work (member_work_jets).
template <bool kFriction, bool kSquares, bool kAlone, int kOrder>
void motion_jets(const BodyJets& in, const JetSeries& x) {
  const Body& body = in.body;
  const int order = kOrder > 0 ? kOrder : in.order;
  const std::size_t n1 = static_cast<std::size_t>(order) + 1;
  auto component = [&](int i) { return in.state + static_cast<std::size_t>(i) * n1; };
  const int L = body.leader();
  const double* const u = component(phi_index(L));
  const double* const v = component(dphi_index(L));
  std::fill(x.F, x.F + n1, 0.0);
  if constexpr (kAlone)
    add_force<kOrder>(in, L, x.F);
  else
    for (int i : body.members) add_force<kOrder>(in, i, x.F);
  const SlidingLaw& law = in.law;
  const double R = law.R, gR = law.gR, mu = law.mu, M = in.M, damping = in.damping;
  const int s = body.s, side = in.side;
  const bool paper = law.paper;
  const double sigma = paper ? 1.0 : side;  // n = R·σ·(v² + gR·cos u)
  x.CS[0] = Pair{std::cos(u[0]), std::sin(u[0])};
  double* const phi = component(phi_index(L));
  double* const dphi = component(dphi_index(L));
  // Coefficient k of every series, and k + 1 of the state's (inlined where it is written out).
  auto coefficient = [&](int k) __attribute__((always_inline)) {
    if (k > 0) sin_cos_pair(x.vv, x.CS, k, in.inverse[k]);
    x.vv[k] = Pair{v[k], v[k]};
    const double Sk = x.CS[k][1], Ck = x.CS[k][0];
    if constexpr (kSquares) x.Q[k] = product_coefficient({v, n1}, {v, n1}, k);
    double acc;
    if constexpr (kFriction) {
      const double v2 = square<kSquares>(x, k);
      acc = paper ? x.F[k] / (M * R) - s * mu * v2 - gR * (Sk + s * mu * Ck)
                  : x.F[k] / (M * R) - gR * Sk - s * mu * side * (v2 + gR * Ck);
    } else {
      acc = x.F[k] / (M * R) - gR * Sk;  // μ = 0: friction's terms are zeros
    }
    if constexpr (kSquares) acc -= damping * v[k];  // 0 without a damper (kSquares false)
    if constexpr (kFriction) x.N[k] = R * sigma * (x.Q[k] + gR * Ck);
    const double r = in.inverse[k + 1];
    if constexpr (kAlone) {
      phi[k + 1] = dphi[k] * r;
      dphi[k + 1] = acc * r;
    } else {
      for (int i : body.members) {
        component(phi_index(i))[k + 1] = component(dphi_index(i))[k] * r;
        component(dphi_index(i))[k + 1] = acc * r;
      }
    }
  };
  for_each_k<kOrder>(order, coefficient);
}

// The jets of member i's work: its rate R·v·(F_i − m_i·s·μ·n) − m_i·R²·c_i·v², from the series
// motion_jets left in x; coefficient k + 1 is coefficient k of the rate over k + 1.
template <bool kFriction, bool kSquares, bool kAlone, int kOrder>
void member_work_jets(const BodyJets& in, const JetSeries& x, int i) {
  const int order = kOrder > 0 ? kOrder : in.order;
  const std::size_t n1 = static_cast<std::size_t>(order) + 1;
  if constexpr (!kAlone) {
    std::fill(x.Fi, x.Fi + n1, 0.0);
    add_force<kOrder>(in, i, x.Fi);
  }
  const double* const Fm = kAlone ? x.F : x.Fi;
  const Pellet& p = in.model.pellets[i];
  const double R = in.law.R, mu = in.law.mu;
  const double ms_mu = p.m * in.body.s * mu, damper = p.m * R * R * p.c;  // damper·v²: its power
  // Without friction n is 0 and G is the force itself: Fm[k] − (±0) is Fm[k] (never −0).
  const double* g = Fm;
  if constexpr (kFriction) {
    for (int k = 0; k < order; ++k) x.G[k] = Fm[k] - ms_mu * x.N[k];
    g = x.G;
  }
  double* const w = in.state + static_cast<std::size_t>(work_index(i)) * n1;
  // Without v² (no friction, no damper) damper·Q[k] is a zero that changes nothing.
  auto rate = [&](int k, double product) {
    if constexpr (kSquares)
      return (R * product - damper * x.Q[k]) * in.inverse[k + 1];
    else
      return R * product * in.inverse[k + 1];
  };
  // The coefficients in pairs k, k + 1 (k = 0, 2, ... while k + 1 < order), then the last one
  // where order is odd.
  auto pair = [&](int half) __attribute__((always_inline)) {
    const int k = 2 * half;
    const Pair product = product_pair(x.vv, g, k);
    w[k + 1] = rate(k, product[0]);
    w[k + 2] = rate(k + 1, product[1]);
  };
  for_each_k<kOrder / 2>(order / 2, pair);
  const double* const v = in.state + static_cast<std::size_t>(dphi_index(in.body.leader())) * n1;
  if (order % 2 == 1) w[order] = rate(order - 1, product_coefficient({v, n1}, {g, n1}, order - 1));
}

// The jets of one sliding body (SegmentDynamics::body_jets), specialised by what the model has,
// decided once per call: kFriction (μ ≠ 0: v² and the normal force enter the motion and the
// work), kSquares (v² is needed: friction or a damper's power), kAlone (one member, whose force
// is the body's). Every variant does the general case's operations in its order; a series the
// general case keeps at zero is read as the literal 0.0, the same value.
template <bool kFriction, bool kSquares, bool kAlone, int kOrder>
void sliding_jets(const BodyJets& in) {
  static_assert(kSquares || !kFriction);
  const JetSeries x = jet_series(in.scratch, static_cast<std::size_t>(in.order) + 1);
  motion_jets<kFriction, kSquares, kAlone, kOrder>(in, x);
  if constexpr (kAlone)
    member_work_jets<kFriction, kSquares, kAlone, kOrder>(in, x, in.body.leader());
  else
    for (int i : in.body.members) member_work_jets<kFriction, kSquares, kAlone, kOrder>(in, x, i);
}

// kOrder: the order as a constant (0: read from in.order), for the orders written out.
template <bool kFriction, bool kSquares, int kOrder>
void sliding_jets_alone_or_not(const BodyJets& in) {
  if (in.body.members.size() == 1)
    sliding_jets<kFriction, kSquares, true, kOrder>(in);
  else
    sliding_jets<kFriction, kSquares, false, kOrder>(in);
}

// The orders whose jets are written out: those of rtol 1e-3 to 1e-14 (Taylor::order_for); the
// others loop.
constexpr int kLowestWritten = 8, kHighestWritten = 21;

using Jets = void (*)(const BodyJets&);

// The written-out jets of orders kLowestWritten + K.
template <bool kFriction, bool kSquares, int... K>
constexpr std::array<Jets, sizeof...(K)> written_jets(std::integer_sequence<int, K...>) {
  return {&sliding_jets_alone_or_not<kFriction, kSquares, kLowestWritten + K>...};
}

template <bool kFriction, bool kSquares>
void sliding_jets_of(const BodyJets& in) {
  static constexpr auto written = written_jets<kFriction, kSquares>(
      std::make_integer_sequence<int, kHighestWritten - kLowestWritten + 1>{});
  if (in.order >= kLowestWritten && in.order <= kHighestWritten)
    written[in.order - kLowestWritten](in);
  else
    sliding_jets_alone_or_not<kFriction, kSquares, 0>(in);
}

}  // namespace

bool SegmentDynamics::taylor_coefficients(double t0, const Vec& y0, int order,
                                          std::span<double> out) const {
  const std::size_t n1 = static_cast<std::size_t>(order) + 1;
  if (force_order_ != order) {
    force_factors_.resize(model_.pellets.size() * n1);
    for (std::size_t i = 0; i < model_.pellets.size(); ++i) {
      const Forcing& f = model_.pellets[i].force;
      cosine_series_factors(f.F0, f.Omega, std::span<double>(force_factors_).subspan(i * n1, n1));
    }
    force_order_ = order;
  }
  for (Eigen::Index i = 0; i < y0.size(); ++i) out[static_cast<std::size_t>(i) * n1] = y0[i];
  // A held body's state stays; a sliding body's jets write every coefficient past the first of
  // its members' components.
  for (const Body& body : bodies_)
    if (body.mode != Mode::sliding)
      for (int p : body.members)
        for (int i = phi_index(p); i <= work_index(p); ++i) {
          const auto c = out.begin() + static_cast<std::ptrdiff_t>(i * n1);
          std::fill(c + 1, c + static_cast<std::ptrdiff_t>(n1), 0.0);
        }
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].mode == Mode::sliding) body_jets(b, t0, order, out);
  return true;
}

// A sliding body: its leader's angle u and speed v give every member's acceleration (as
// SlidingLaw::acceleration, its damping C·v last) and, with each member's force, its work rate
// R·v·(F_i − m_i·s·μ·n) − m_i·R²·c_i·v².
// Coefficient k + 1 of each state component is coefficient k of its rate over k + 1, taken as a
// product with 1/(k + 1) from a table (a multiplication's latency on the recursion's chain, not a
// division's).
// Each series is computed by the same operations in the same order as the right-hand side's
// terms (F/(M·R) divided as SlidingLaw::acceleration divides it), so coefficient 1 is the
// right-hand side to the bit: the event code takes a watch's start from the right-hand side and
// its course from the jets, and a release on the edge of friction's capacity depends on their
// agreement. The shortcuts (a series that is zero, a term that is zero) change no bit.
void SegmentDynamics::body_jets(std::size_t b, double t0, int order, std::span<double> out) const {
  const Body& body = bodies_[b];
  const std::size_t n1 = static_cast<std::size_t>(order) + 1;
  alignas(16) std::array<double, jet_scratch_size(kStackTerms)> stack;
  double* scratch = stack.data();
  const double* inverse = integrators::kReciprocal.data();
  static_assert(kStackTerms < integrators::kReciprocals);
  if (n1 > kStackTerms) {  // the series and the reciprocals 1/k, k <= n1, in the heap
    // One double more than they take, so that the series may start 16-byte aligned.
    jet_scratch_.resize(jet_scratch_size(n1) + n1 + 2);
    scratch = jet_scratch_.data();
    if (reinterpret_cast<std::uintptr_t>(scratch) % 16 != 0) ++scratch;
    double* const tail = scratch + jet_scratch_size(n1);
    for (std::size_t k = 1; k <= n1; ++k) tail[k] = integrators::reciprocal(static_cast<int>(k));
    inverse = tail;
  }
  const BodyTerms& terms = terms_[b];
  const BodyJets in{.model = model_,
                    .body = body,
                    .law = law_,
                    .M = terms.mass,
                    .damping = terms.damping,
                    .side = terms.normal_side,
                    .t0 = t0,
                    .order = order,
                    .inverse = inverse,
                    .force = force_factors_.data(),
                    .state = out.data(),
                    .scratch = scratch};
  const bool damped = std::any_of(body.members.begin(), body.members.end(),
                                  [&](int i) { return model_.pellets[i].c != 0.0; });
  if (law_.mu != 0.0)
    sliding_jets_of<true, true>(in);
  else if (damped)
    sliding_jets_of<false, true>(in);
  else
    sliding_jets_of<false, false>(in);
}

}  // namespace vibro
