// The crossing finder (core/events/crossing_finder.h) on steps whose states are analytic
// functions of time, served through StepView as a dense output or as exact polynomials. The
// watch is a limiter watch of one pellet at target 0, so its value is g(t) = −φ(t) and its rate
// −φ'(t): each test gives g and g', and the state is built from them. Gravity, forcing and
// friction are nil, so the curvature the model gives the watch is 0.
#include "core/events/crossing_finder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "core/events/polynomial_roots.h"

namespace vibro {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// One step [t0, t1] of a single pellet whose watch value is g(t): φ = −g, φ' = −g'. With
// `poly` set, g is the polynomial Σ poly[k]·(t − t0)^k, also served as StepPolynomials.
class ToyStep : public StepView {
 public:
  ToyStep(double t0, double t1, std::function<double(double)> g, std::function<double(double)> rate)
      : t0_(t0), t1_(t1), g_(std::move(g)), rate_(std::move(rate)) {}

  // A step whose g is the polynomial c in τ = t − t0, served as polynomials when `serve`.
  static ToyStep polynomial(double t0, double t1, std::vector<double> c, bool serve) {
    std::vector<double> dc(c.size(), 0.0);
    for (std::size_t k = 1; k < c.size(); ++k) dc[k - 1] = k * c[k];
    ToyStep step(
        t0, t1, [c, t0](double t) { return polynomial_value(c, t - t0); },
        [dc, t0](double t) { return polynomial_value(dc, t - t0); });
    if (serve) step.serve(c, dc);
    return step;
  }

  double t_prev() const override { return t0_; }
  double t() const override { return t1_; }
  void dense(double t, Vec& out) const override { out = state(t); }
  const StepPolynomials* polynomials() const override { return served_ ? &poly_ : nullptr; }

  Vec state(double t) const {
    Vec y(3);
    y << -g_(t), -rate_(t), 0.0;
    return y;
  }
  double g(double t) const { return g_(t); }

 private:
  // φ = −g, φ' = −g', work 0, as polynomials of one degree.
  void serve(const std::vector<double>& c, const std::vector<double>& dc) {
    const std::size_t n = c.size();
    coefficients_.assign(3 * n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      coefficients_[k] = -c[k];
      coefficients_[n + k] = -dc[k];
    }
    poly_ = {t0_, static_cast<int>(n) - 1, coefficients_};
    served_ = true;
  }

  double t0_, t1_;
  std::function<double(double)> g_, rate_;
  std::vector<double> coefficients_;
  StepPolynomials poly_;
  bool served_ = false;
};

struct Finder {
  Model model = [] {
    Model m;
    m.g = 0.0;
    m.R = 1.0;
    m.pellets = {Pellet{.m = 1.0}};
    m.limiters = {Limiter{.angle = 0.0}};
    return m;
  }();
  std::vector<Body> bodies = {Body{.members = {0}, .s = 1}};
  std::vector<Watch> watches = {Watch{
      .kind = WatchKind::limiter, .body = 0, .pellet = 0, .limiter = 0, .target = 0.0, .side = 1}};
  CrossingFinder finder;

  // Starts at the step's start and searches it at `inside` evenly spaced samples and its end.
  std::vector<Crossing> search(const ToyStep& step, int inside) {
    begin(step);
    return next(step, inside);
  }
  // Starts an interval at the step's start, at rtol 1e-9.
  void begin(const ToyStep& step) {
    finder.start(watches, model, bodies, step.t_prev(), step.state(step.t_prev()), 1e-9, 1e-12);
  }
  // Searches a step that follows the last one.
  std::vector<Crossing> next(const ToyStep& step, int inside) {
    std::vector<double> times;
    std::vector<Vec> states;
    const double a = step.t_prev(), b = step.t();
    for (int k = 1; k <= inside + 1; ++k) {
      times.push_back(k == inside + 1 ? b : a + (b - a) * k / (inside + 1));
      states.push_back(step.state(times.back()));
    }
    return finder.find(watches, model, bodies, step, times, states, 1e-12 * (1.0 + b));
  }
};

// The reported time is the right end of a bracket refined to round-off: the watch is at or below
// zero there and positive a few ulps before.
void expect_root_to_round_off(const ToyStep& step, double t) {
  EXPECT_LE(step.g(t), 0.0) << t;
  EXPECT_GT(step.g(t - 8.0 * kEps * std::max(1.0, std::abs(t))), 0.0) << t;
}

TEST(CrossingFinder, FindsTheRootOfASineToRoundOff) {
  Finder f;
  auto g = [](double t) { return std::sin(t); };
  auto rate = [](double t) { return std::cos(t); };
  // Steps of 0.5 from 0.1: none crosses before the one that holds π.
  const ToyStep first(0.1, 0.6, g, rate);
  EXPECT_TRUE(f.search(first, 3).empty());
  std::vector<Crossing> found;
  double t = 0.6;
  for (; t < 4.0 && found.empty(); t += 0.5) found = f.next(ToyStep(t, t + 0.5, g, rate), 3);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].watch, 0);
  EXPECT_NEAR(found[0].t, std::numbers::pi, 4.0 * kEps * std::numbers::pi);
  expect_root_to_round_off(ToyStep(t - 0.5, t, g, rate), found[0].t);
  EXPECT_FALSE(f.finder.first_graze());
}

TEST(CrossingFinder, AParabolaThatGrazesZeroIsANearMissNotACrossing) {
  // A minimum of 1e-11 at t = 0.4, within the watch's error at rtol 1e-9 (about 1e-8).
  Finder f;
  const ToyStep step = ToyStep::polynomial(0.0, 1.0, {0.16 + 1e-11, -0.8, 1.0}, false);
  EXPECT_TRUE(f.search(step, 3).empty());
  const std::optional<Graze>& graze = f.finder.first_graze();
  ASSERT_TRUE(graze);
  EXPECT_EQ(graze->of, Graze::Of::limiter);
  EXPECT_NEAR(graze->t, 0.4, 1e-9);
  EXPECT_NEAR(graze->value, 1e-11, 1e-15);
  EXPECT_LT(graze->earliest, graze->t);
}

TEST(CrossingFinder, AParabolaClearOfZeroIsNeitherCrossingNorNearMiss) {
  Finder f;
  const ToyStep step = ToyStep::polynomial(0.0, 1.0, {0.16 + 1e-3, -0.8, 1.0}, false);
  EXPECT_TRUE(f.search(step, 3).empty());
  EXPECT_FALSE(f.finder.first_graze());
}

TEST(CrossingFinder, FindsTheFirstOfTwoRootsInsideOneStepFromItsEndsAlone) {
  // g = (t − 0.3)(t − 0.7): positive at both ends of the step, no sample inside. The rates at
  // the ends (closing, then opening) locate the minimum between, below zero.
  Finder f;
  const ToyStep step = ToyStep::polynomial(0.0, 1.0, {0.21, -1.0, 1.0}, false);
  const std::vector<Crossing> found = f.search(step, 0);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0].t, 0.3, 4.0 * kEps);
  expect_root_to_round_off(step, found[0].t);
}

TEST(CrossingFinder, FindsARootAtTheStepsEnd) {
  Finder f;
  const ToyStep step = ToyStep::polynomial(0.0, 1.0, {1.0, -1.0}, false);
  const std::vector<Crossing> found = f.search(step, 3);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].t, 1.0);
}

TEST(CrossingFinder, AWatchThatStartsOnItsRootArmsOnlyOnceItIsPositive) {
  // g = t(1 − t) ... starting at 0: not an event at the start; the fall at 1 is.
  Finder f;
  EXPECT_TRUE(f.search(ToyStep::polynomial(0.0, 0.5, {0.0, 1.0, -1.0}, false), 3).empty());
  const std::vector<Crossing> found =
      f.next(ToyStep::polynomial(0.5, 1.5, {0.25, 0.0, -1.0}, false), 3);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0].t, 1.0, 4.0 * kEps);
}

TEST(CrossingFinder, AStepIsCalmWhereTheWatchStaysFartherFromZeroThanItMoves) {
  Finder f;
  const ToyStep far = ToyStep::polynomial(0.0, 1.0, {1.0, 0.1}, false);
  f.begin(far);
  EXPECT_TRUE(f.finder.calm(f.watches, f.model, f.bodies, 0.0, 1.0, far.state(1.0)));
  EXPECT_TRUE(f.next(far, 0).empty());
  // 1 falling to 0.1 moves farther than it stays from zero: its samples are searched, and it
  // reaches zero at 1.11, in the next step.
  const ToyStep near = ToyStep::polynomial(0.0, 1.0, {1.0, -0.9}, false);
  f.begin(near);
  EXPECT_FALSE(f.finder.calm(f.watches, f.model, f.bodies, 0.0, 1.0, near.state(1.0)));
  EXPECT_TRUE(f.next(near, 3).empty());
}

// The seam: the same cubic, rising at both ends of the step and dipping below zero between
// (roots near 0.29 and 0.94). Sampled at its ends, its rates give no hint; served as polynomials,
// its roots are isolated between its turning points (0.1 and 0.7).
const std::vector<double> kDippingCubic = {0.05, 0.21, -1.2, 1.0};

TEST(CrossingFinder, APolynomialStepServesTheRootsItsSamplesStepOver) {
  Finder sampled;
  EXPECT_TRUE(sampled.search(ToyStep::polynomial(0.0, 1.0, kDippingCubic, false), 0).empty());

  Finder served;
  const ToyStep step = ToyStep::polynomial(0.0, 1.0, kDippingCubic, true);
  const std::vector<Crossing> found = served.search(step, 0);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_GT(found[0].t, 0.1);
  EXPECT_LT(found[0].t, 0.7);
  expect_root_to_round_off(step, found[0].t);
}

TEST(CrossingFinder, APolynomialStepAndItsDenseOutputAgreeOnTwoRootsInOneStep) {
  for (bool serve : {false, true}) {
    SCOPED_TRACE(serve ? "polynomials" : "dense output");
    Finder f;
    const ToyStep step = ToyStep::polynomial(0.0, 1.0, {0.21, -1.0, 1.0}, serve);
    const std::vector<Crossing> found = f.search(step, 0);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_NEAR(found[0].t, 0.3, 4.0 * kEps);
  }
}

TEST(CrossingFinder, APolynomialStepReportsItsNearMissAtTheMinimum) {
  Finder f;
  const ToyStep step = ToyStep::polynomial(0.0, 1.0, {0.16 + 1e-11, -0.8, 1.0}, true);
  EXPECT_TRUE(f.search(step, 0).empty());
  ASSERT_TRUE(f.finder.first_graze());
  EXPECT_NEAR(f.finder.first_graze()->t, 0.4, 1e-12);
  EXPECT_NEAR(f.finder.first_graze()->value, 1e-11, 1e-15);
}

// Every watch linear and armed on a step given as polynomials: the step needs no samples, and a
// root in the second of two such steps is found from the track the first left at its end.
TEST(CrossingFinder, AStepItsPolynomialsServeIsSearchedAtItsEndAlone) {
  Finder f;
  const ToyStep sampled = ToyStep::polynomial(0.0, 1.0, {1.0, -0.5}, false);
  f.begin(sampled);
  EXPECT_FALSE(f.finder.served_by_polynomials(f.watches, f.bodies, sampled));
  const ToyStep first = ToyStep::polynomial(0.0, 1.0, {1.0, -0.5}, true);
  EXPECT_TRUE(f.finder.served_by_polynomials(f.watches, f.bodies, first));
  EXPECT_TRUE(f.next(first, 0).empty());
  const ToyStep second = ToyStep::polynomial(1.0, 2.0, {0.5, -0.25, -1.0}, true);
  EXPECT_TRUE(f.finder.served_by_polynomials(f.watches, f.bodies, second));
  const std::vector<Crossing> found = f.next(second, 0);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0].t, 1.0 + (-0.25 + std::sqrt(0.0625 + 2.0)) / 2.0, 1e-14);
  expect_root_to_round_off(second, found[0].t);
}

// A watch that starts on its root is not armed: its step is sampled until it is positive.
TEST(CrossingFinder, AnUnarmedWatchIsNotServedByPolynomials) {
  Finder f;
  const ToyStep step = ToyStep::polynomial(0.0, 1.0, {0.0, 1.0, -2.0}, true);
  f.begin(step);
  EXPECT_FALSE(f.finder.served_by_polynomials(f.watches, f.bodies, step));
}

// (τ − 0.1)(τ − 0.2)···(τ − 0.8): seven turning points, the first root at 0.1, found with the
// Bernstein coefficients' sign changes pruning the turning points' search.
TEST(PolynomialRoots, FindsTheFirstRootOfAPolynomialWithManyTurningPoints) {
  std::vector<double> c = {1.0};
  for (int r = 1; r <= 8; ++r) {
    std::vector<double> next(c.size() + 1, 0.0);
    for (std::size_t k = 0; k < c.size(); ++k) {
      next[k] -= 0.1 * r * c[k];
      next[k + 1] += c[k];
    }
    c = next;
  }
  const auto b = first_polynomial_crossing(c, 1.0);
  ASSERT_TRUE(b);
  EXPECT_NEAR(b->hi, 0.1, 1e-14);
  EXPECT_LE(b->hi - b->lo, 4.0 * kEps);
  // Short of the first root: no crossing, and no minimum before it.
  PolynomialMinima minima;
  EXPECT_FALSE(first_polynomial_crossing(c, 0.09, &minima));
  EXPECT_EQ(minima.count, 0);
}

TEST(PolynomialRoots, TheFirstCrossingsBracketIsRoundOffWide) {
  const std::vector<double> c = {0.21, -1.0, 1.0};  // (τ − 0.3)(τ − 0.7)
  const auto b = first_polynomial_crossing(c, 1.0);
  ASSERT_TRUE(b);
  EXPECT_GT(b->p_lo, 0.0);
  EXPECT_LE(b->p_hi, 0.0);
  EXPECT_LE(b->hi - b->lo, 4.0 * kEps);
  EXPECT_NEAR(b->hi, 0.3, 4.0 * kEps);
}

// Roots anywhere in the step, near its ends, of a line, of a steep and of a flattening approach
// ((r − τ)(1 + aτ + bτ²) on [0, h], factors positive there): the bracket holds r and is
// round-off wide, however the secants approach it (from one side, past it, or landing on it).
TEST(PolynomialRoots, EveryRootsBracketHoldsItToRoundOff) {
  const double h = 0.08;
  int cases = 0;
  for (double r :
       {1e-9 * h, 1e-6 * h, 0.013 * h, 0.31 * h, 0.5 * h, 0.77 * h, 0.999 * h, (1.0 - 1e-9) * h}) {
    for (double a : {-10.0, 0.0, 3.0, 40.0}) {
      for (double q : {-100.0, 0.0, 150.0, 2000.0}) {
        // Positive on [0, h]: 1 + a·τ + q·τ² at both ends and at its vertex.
        auto factor = [&](double t) { return 1.0 + a * t + q * t * t; };
        const double vertex = q != 0.0 ? -a / (2.0 * q) : -1.0;
        if (!(factor(0.0) > 0.0 && factor(h) > 0.0) ||
            (vertex > 0.0 && vertex < h && !(factor(vertex) > 0.0)))
          continue;
        const std::vector<double> c = {r, r * a - 1.0, r * q - a, -q};
        const auto b = first_polynomial_crossing(c, h);
        ASSERT_TRUE(b) << "r " << r << ", a " << a << ", q " << q;
        EXPECT_GT(b->p_lo, 0.0);
        EXPECT_LE(b->p_hi, 0.0);
        EXPECT_LE(b->hi - b->lo, 4.0 * kEps * b->hi) << "r " << r << ", a " << a << ", q " << q;
        // The root to within its condition: p's round-off over its slope at r.
        const double slack = 8.0 * kEps * (r + std::abs(r * a) + std::abs(r * q)) + 4.0 * kEps * r;
        EXPECT_LE(b->lo, r + slack) << "r " << r << ", a " << a << ", q " << q;
        EXPECT_GE(b->hi, r - slack) << "r " << r << ", a " << a << ", q " << q;
        ++cases;
      }
    }
  }
  EXPECT_GT(cases, 80);
}

// (τ − 0.5)² + 0.3 on [0, 1]: the crude bound 0.55 − 1 − 1 proves nothing, its quadratic part
// proves it above 0.06 (its Bernstein coefficients (0.55, 0.05, 0.55) would not), never above
// its minimum 0.3; with a cubic term the quadratic part's bound leaves the Bernstein
// coefficients to prove it positive; the dipping cubic is not.
TEST(PolynomialRoots, ABoundProvesAStepClearOfZeroWithoutIsolatingRoots) {
  EXPECT_TRUE(stays_above(std::vector<double>{0.55, -1.0, 1.0}, 1.0, 0.0));
  EXPECT_TRUE(stays_above(std::vector<double>{0.55, -1.0, 1.0}, 1.0, 0.06));
  EXPECT_FALSE(stays_above(std::vector<double>{0.55, -1.0, 1.0}, 1.0, 0.31));
  EXPECT_TRUE(stays_above(std::vector<double>{0.55, -1.0, 1.0, 0.3}, 1.0, 0.0));
  EXPECT_TRUE(stays_above(std::vector<double>{1.0, 0.1}, 1.0, 0.5));
  EXPECT_FALSE(stays_above(kDippingCubic, 1.0, 0.0));
  EXPECT_FALSE(stays_above(std::vector<double>{0.21, -1.0, 1.0}, 1.0, 0.0));  // two roots
}

// The end value and rate the finder takes in one pass are polynomial_value's and
// polynomial_rate's, to the bit, at every length and either parity.
TEST(PolynomialRoots, ValueAndRateInOnePassAreTheSeparateOnesBitForBit) {
  std::vector<double> c;
  for (int n = 0; n <= 20; ++n) {
    for (double tau : {0.0, 1e-3, 0.37, -0.2, 1.7}) {
      const ValueAndRate both = polynomial_value_and_rate(c, tau);
      EXPECT_EQ(both.value, polynomial_value(c, tau)) << "n = " << n << ", tau = " << tau;
      EXPECT_EQ(both.rate, polynomial_rate(c, tau)) << "n = " << n << ", tau = " << tau;
    }
    c.push_back(std::sin(1.3 * n + 0.2) / (1.0 + n));
  }
}

// stays_above's end value and rate, taken beside its first bound, are polynomial_value_and_rate's
// to the bit, and its verdict the three-argument one's, whatever the verdict.
TEST(PolynomialRoots, TheBoundsEndValueAndRateAreTheOnePassOnes) {
  std::vector<double> c;
  for (int n = 0; n <= 20; ++n) {
    for (double h : {1e-3, 0.37, 1.7}) {
      for (double level : {-1.0, 0.0, 0.5}) {
        ValueAndRate end{-7.0, -7.0};
        const bool above = stays_above(c, h, level, end);
        EXPECT_EQ(above, stays_above(c, h, level)) << "n = " << n << ", h = " << h;
        const ValueAndRate both = polynomial_value_and_rate(c, h);
        EXPECT_EQ(end.value, both.value) << "n = " << n << ", h = " << h;
        EXPECT_EQ(end.rate, both.rate) << "n = " << n << ", h = " << h;
      }
    }
    c.push_back(std::sin(1.3 * n + 0.2) / (1.0 + n));
  }
}

TEST(PolynomialRoots, ATouchOfZeroIsAMinimumNotACrossing) {
  const std::vector<double> c = {0.25 + 1e-13, -1.0, 1.0};  // (τ − 0.5)² + 1e-13
  PolynomialMinima minima;
  EXPECT_FALSE(first_polynomial_crossing(c, 1.0, &minima));
  ASSERT_EQ(minima.count, 1);
  EXPECT_NEAR(minima.at[0].tau, 0.5, 1e-12);
  EXPECT_NEAR(minima.at[0].value, 1e-13, 1e-16);
  EXPECT_NEAR(minima.at[0].half_curvature, 1.0, 1e-12);
}

TEST(PolynomialRoots, FindsTheFirstOfTwoRootsOfACubicBetweenItsTurningPoints) {
  const auto b = first_polynomial_crossing(kDippingCubic, 1.0);
  ASSERT_TRUE(b);
  EXPECT_GT(b->lo, 0.1);
  EXPECT_LT(b->hi, 0.7);
  EXPECT_LE(b->hi - b->lo, 4.0 * kEps);
  // The second root, past the minimum at 0.7, is not the first.
  EXPECT_FALSE(first_polynomial_crossing(kDippingCubic, 0.25));
}

}  // namespace
}  // namespace vibro
