// Impacts at one instant: momentum and Newton's restitution law at every collision, limiter
// restitution, mobile limiters, and cascades resolved in bounded work.
#include "core/events/impacts.h"

#include <gtest/gtest.h>

#include <random>

#include "scenes.h"

namespace vibro {
namespace {

TEST(Collide, ConservesMomentumAndObeysRestitution) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> mass(1e-4, 10.0), speed(-50.0, 50.0), k(0.0, 1.0);
  for (int trial = 0; trial < 1000; ++trial) {
    const double mi = mass(rng), mj = mass(rng), kc = k(rng);
    double vi = speed(rng), vj = speed(rng);
    const double vi0 = vi, vj0 = vj;
    collide(mi, mj, kc, vi, vj);
    const double scale = (mi + mj) * (std::abs(vi0) + std::abs(vj0));
    EXPECT_NEAR(mi * vi + mj * vj, mi * vi0 + mj * vj0, 1e-13 * scale);
    EXPECT_NEAR(vj - vi, -kc * (vj0 - vi0), 1e-12 * (std::abs(vi0) + std::abs(vj0)));
  }
}

TEST(Collide, EqualMassesElasticSwapSpeeds) {
  double a = 3.0, b = -1.0;
  collide(0.2, 0.2, 1.0, a, b);
  EXPECT_DOUBLE_EQ(a, -1.0);
  EXPECT_DOUBLE_EQ(b, 3.0);
}

// The state of pellets at angles phi, moving at speeds v.
Vec state(const std::vector<double>& v, const std::vector<double>& phi) {
  Vec y = Vec::Zero(3 * static_cast<int>(v.size()));
  for (int i = 0; i < static_cast<int>(v.size()); ++i) {
    y[phi_index(i)] = phi[i];
    y[dphi_index(i)] = v[i];
  }
  return y;
}

// Pellets at the bottom, moving at speeds v.
Vec speeds(const std::vector<double>& v) { return state(v, std::vector<double>(v.size(), 0.0)); }

Model two_pellets_and_limiters() {
  Model m = testing::one_pellet(0.0, 0.0, 0.0);
  m.pellets.push_back(m.pellets[0]);
  m.limiters = {{0.5, 0.5, true, 1, {}}, {-0.5, 0.8, false, -1, {}}};
  return m;
}

TEST(ResolveImpacts, LimiterReversesWithRestitution) {
  Model m = two_pellets_and_limiters();
  Vec y = state({4.0, 0.0}, {-0.5, 0.2});
  std::vector<bool> armed = {true, true};
  auto events = resolve_impacts(m, y, armed, {{0, 1, +1}}, {});
  // Pellet 0 lies on the phi > angle side of limiter 1 and moves away from it: no impact.
  EXPECT_TRUE(events.empty());
  y = state({-4.0, 0.0}, {-0.5, 0.2});
  events = resolve_impacts(m, y, armed, {{0, 1, +1}}, {});
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, EventKind::limiter);
  EXPECT_DOUBLE_EQ(y[dphi_index(0)], 0.8 * 4.0);
  EXPECT_EQ(y[phi_index(0)], -0.5);  // angles are left as they are
}

TEST(ResolveImpacts, MobileLimiterDisarmsAndIsRearmedByItsPartner) {
  Model m = two_pellets_and_limiters();
  Vec y = state({4.0, 0.0}, {0.5, 0.0});
  std::vector<bool> armed = {true, true};
  resolve_impacts(m, y, armed, {{0, 0, -1}}, {});
  EXPECT_DOUBLE_EQ(y[dphi_index(0)], -2.0);
  EXPECT_FALSE(armed[0]);
  // While disarmed, a pellet passes it.
  y = state({4.0, 0.0}, {0.5, 0.0});
  auto none = resolve_impacts(m, y, armed, {{0, 0, -1}}, {});
  EXPECT_TRUE(none.empty());
  EXPECT_DOUBLE_EQ(y[dphi_index(0)], 4.0);
  // An impact on limiter 1 (its rearm_by) arms it again.
  y = state({-1.0, 0.0}, {-0.5, 0.0});
  resolve_impacts(m, y, armed, {{0, 1, +1}}, {});
  EXPECT_TRUE(armed[0]);
}

TEST(ResolveImpacts, PelletsOnTwoSidesOfALimiterDoNotCollide) {
  Model m = two_pellets_and_limiters();
  m.limiters[0].mobile = false;
  m.limiters[0].rearm_by = -1;
  Vec y = state({3.0, -2.0}, {0.5, 0.5});  // both run into limiter 0 from its two sides
  std::vector<bool> armed = {true, true};
  auto events = resolve_impacts(m, y, armed, {{0, 0, -1}, {1, 0, +1}}, {{0, 1}});
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].kind, EventKind::limiter);
  EXPECT_EQ(events[1].kind, EventKind::limiter);
  EXPECT_DOUBLE_EQ(y[dphi_index(0)], -1.5);
  EXPECT_DOUBLE_EQ(y[dphi_index(1)], 1.0);
}

TEST(ResolveImpacts, SqueezedLightPelletEndsInBoundedWorkAsAPlasticGroup) {
  Model m = testing::one_pellet(0.0, 0.0, 0.0);
  m.pellets.push_back(m.pellets[0]);
  m.pellets[0].m = 1.0;
  m.pellets[1].m = 1e-4;
  m.limiters = {{0.5, 1.0, false, -1, {}}};
  m.k_c = 1.0;
  Vec y = state({2.0, 2.0}, {0.5, 0.5});  // heavy pellet behind, light one against the limiter
  std::vector<bool> armed = {true};
  auto events = resolve_impacts(m, y, armed, {{1, 0, -1}}, {{0, 1}});
  ASSERT_FALSE(events.empty());
  EXPECT_LE(events.size(), 4u);
  // The limit of the cascade: the group stops against the limiter.
  EXPECT_DOUBLE_EQ(y[dphi_index(0)], 0.0);
  EXPECT_DOUBLE_EQ(y[dphi_index(1)], 0.0);
  EXPECT_GT(events.back().impacts_resolved, 0);
}

// Two impacts closing on one pellet at an instant (from both sides, or from behind while it
// strikes a limiter): their order decides what they leave, and is decided below the tolerance.
// One impact, or impacts on different pellets, have no order to decide.
TEST(SharedByClosings, NamesThePelletTwoImpactsCloseOn) {
  Model m = testing::one_pellet(0.0, 0.0, 0.0);
  m.pellets.push_back(m.pellets[0]);
  m.pellets.push_back(m.pellets[0]);
  m.limiters = {{0.5, 1.0, false, -1, {}}};
  const std::vector<bool> armed = {true};
  const std::vector<PairContact> both_sides = {{0, 1}, {1, 2}};
  EXPECT_EQ(shared_by_closings(m, speeds({1.0, 0.0, -1.0}), armed, {}, both_sides, 1e-13), 1);
  EXPECT_EQ(shared_by_closings(m, speeds({1.0, 0.0, 0.0}), armed, {}, both_sides, 1e-13), -1);
  EXPECT_EQ(shared_by_closings(m, speeds({1.0, 1.0, 1.0}), armed, {}, both_sides, 1e-13), -1);
  // Pellet 1 strikes the limiter (it lies below it, side −1) while pellet 0 strikes it.
  const std::vector<LimiterContact> at_limiter = {{1, 0, -1}};
  EXPECT_EQ(shared_by_closings(m, speeds({2.0, 1.0, 0.0}), armed, at_limiter, {{0, 1}}, 1e-13), 1);
  EXPECT_EQ(shared_by_closings(m, speeds({2.0, 1.0, 0.0}), {false}, at_limiter, {{0, 1}}, 1e-13),
            -1);
  EXPECT_EQ(shared_by_closings(m, speeds({2.0, -1.0, 0.0}), armed, at_limiter, {{0, 1}}, 1e-13),
            -1);
  // Pellet 0 strikes pellet 1 while pellet 2 strikes the limiter: no pellet takes both.
  EXPECT_EQ(shared_by_closings(m, speeds({1.0, 0.0, 1.0}), armed, {{2, 0, -1}}, {{0, 1}}, 1e-13),
            -1);
}

}  // namespace
}  // namespace vibro
