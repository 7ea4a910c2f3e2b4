// Who touches whom on hand-made states: neighbours around the circle and their winding offsets,
// near-touching pellets snapped onto one place, chains of linked pellets, and when touching
// pellets move on as one body (the press between them against the chatter it would take).
#include "core/events/contacts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "scenes.h"

namespace vibro {
namespace {

Vec angles(const std::vector<double>& phi) {
  Vec y = Vec::Zero(3 * static_cast<int>(phi.size()));
  for (int i = 0; i < static_cast<int>(phi.size()); ++i) y[phi_index(i)] = phi[i];
  return y;
}

TEST(Contacts, NeighboursFollowTheCircleAndTheirGapsLieInOneTurn) {
  // Pellet 2 at −0.5 rad lies at 2π − 0.5 around the circle: the order is 0, 1, 2, and the
  // gap from 1 (2.0) to 2 (−0.5) is 2π − 2.5, the offset 2π winding it into [0, 2π].
  const Vec y = angles({0.1, 2.0, -0.5});
  const std::vector<Neighbours> nb = circular_neighbours(y, 3);
  ASSERT_EQ(nb.size(), 3u);
  EXPECT_EQ(nb[0].behind, 0);
  EXPECT_EQ(nb[0].ahead, 1);
  EXPECT_EQ(nb[0].offset, 0.0);
  EXPECT_EQ(nb[1].behind, 1);
  EXPECT_EQ(nb[1].ahead, 2);
  EXPECT_NEAR(nb[1].offset, kTwoPi, 1e-15);
  EXPECT_EQ(nb[2].behind, 2);
  EXPECT_EQ(nb[2].ahead, 0);
  EXPECT_NEAR(nb[2].offset, 0.0, 1e-15);
  double total = 0.0;
  for (const Neighbours& n : nb) {
    const double gap = y[phi_index(n.ahead)] - y[phi_index(n.behind)] + n.offset;
    EXPECT_GE(gap, 0.0);
    EXPECT_LE(gap, kTwoPi);
    total += gap;
  }
  EXPECT_NEAR(total, kTwoPi, 1e-15);  // the gaps go once around
}

TEST(Contacts, NearTouchingPelletsAreSnappedOntoOnePlaceTheOneAtALimiterStayingPut) {
  const std::vector<PairContact> none;
  // 1e-12 apart with a contact radius of 1e-10: they touch; the one ahead comes to the one behind.
  Vec y = angles({0.3, 0.3 + 1e-12, 1.0});
  std::vector<Neighbours> nb = circular_neighbours(y, 3);
  std::vector<PairContact> pairs;
  std::vector<bool> at_limiter = {false, false, false};
  snap_touching(y, nb, 1e-10, at_limiter, none, pairs);
  EXPECT_EQ(y[phi_index(1)], 0.3);
  EXPECT_EQ(y[phi_index(2)], 1.0);  // far from both: untouched
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0], (PairContact{0, 1}));
  // The one ahead at a limiter: the one behind comes to it.
  y = angles({0.3, 0.3 + 1e-12, 1.0});
  pairs.clear();
  at_limiter = {false, true, false};
  snap_touching(y, nb, 1e-10, at_limiter, none, pairs);
  EXPECT_EQ(y[phi_index(0)], 0.3 + 1e-12);
  // A limiter between them: they never touch.
  y = angles({0.3, 0.3 + 1e-12, 1.0});
  pairs.clear();
  at_limiter = {false, false, false};
  snap_touching(y, nb, 1e-10, at_limiter, {{0, 1}}, pairs);
  EXPECT_TRUE(pairs.empty());
  EXPECT_EQ(y[phi_index(1)], 0.3 + 1e-12);
}

TEST(Contacts, NearTouchingPelletsSnapAlongAChainOntoTheOneAtALimiter) {
  // Three pellets each 1e-12 from the next, the front one at a limiter: all end on its place.
  Vec y = angles({0.3 - 2e-12, 0.3 - 1e-12, 0.3});
  const std::vector<Neighbours> nb = circular_neighbours(y, 3);
  std::vector<PairContact> pairs;
  std::vector<bool> at_limiter = {false, false, true};
  snap_touching(y, nb, 1e-10, at_limiter, {}, pairs);
  EXPECT_EQ(y[phi_index(0)], 0.3);
  EXPECT_EQ(y[phi_index(1)], 0.3);
  EXPECT_EQ(pairs.size(), 2u);
}

TEST(Contacts, ChainsRunBehindToAheadAndARingStartsAheadOfItsLowestPellet) {
  PelletLinks links(5);
  links.link({3, 1});
  links.link({1, 4});
  const std::vector<std::vector<int>> open = chains(links);
  EXPECT_EQ(open, (std::vector<std::vector<int>>{{0}, {3, 1, 4}, {2}}));
  PelletLinks ring(3);
  ring.link({0, 1});
  ring.link({1, 2});
  ring.link({2, 0});
  EXPECT_EQ(chains(ring), (std::vector<std::vector<int>>{{1, 2, 0}}));
}

// Two touching pellets of 0.2 kg on R = 0.5 m at 1 and 1 + w rad/s (parting at w), a force F on
// the one behind pressing them together at p = F/(m R) while both move (friction and gravity
// per mass are the same for both). Parting at w and pressed back at p, they meet again after
// 2w/p, then after k_c times that, and so on: the chatter lasts 2w/(p(1 − k_c)).
std::vector<Body> joined(double w, double F, double chatter_time, double flight = 0.0) {
  Model m = testing::one_pellet(0.1, 0.3, 1.0);
  m.pellets.push_back(m.pellets[0]);
  m.pellets[0].force = {F, 0.0, 0.0};
  m.k_c = 0.5;
  Vec y = angles({0.3, 0.3});
  y[dphi_index(0)] = 1.0;
  y[dphi_index(1)] = 1.0 + w;
  const JoinCriteria criteria{1e-12, chatter_time, flight};
  return join_touching(m, 0.0, y, {{0, 1}}, {}, {}, criteria);
}

TEST(Contacts, PressedPelletsWhoseChatterWouldBeShorterThanTheChatterTimeMoveAsOne) {
  // F = 1 N: p = 1/(0.2·0.5) = 10 rad/s², k_c = 0.5: the chatter lasts 2w/5 s.
  EXPECT_EQ(joined(1e-5, 1.0, 1e-4).size(), 1u);  // 4e-6 s
  EXPECT_EQ(joined(1e-3, 1.0, 1e-4).size(), 2u);  // 4e-4 s
  EXPECT_EQ(joined(1e-3, 1.0, 4.01e-4).size(), 1u);
  EXPECT_EQ(joined(1e-3, 1.0, 3.99e-4).size(), 2u);
}

TEST(Contacts, PressedPelletsWhoseFlightApartIsWithinRoundOffMoveAsOne) {
  // Parting at 1e-3 rad/s against 10 rad/s², they part by w²/(2p) = 5e-8 rad at most.
  EXPECT_EQ(joined(1e-3, 1.0, 0.0, 5.01e-8).size(), 1u);
  EXPECT_EQ(joined(1e-3, 1.0, 0.0, 4.99e-8).size(), 2u);
}

TEST(Contacts, PelletsPulledApartOrNotPressedDoNotJoin) {
  EXPECT_EQ(joined(1e-5, 0.0, 1e-4).size(), 2u);        // no press: the chatter never ends
  EXPECT_EQ(joined(0.0, -1.0, 1e-4).size(), 2u);        // the force pulls the one behind back
  const std::vector<Body> one = joined(0.0, 1.0, 0.0);  // at one speed, pressed
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].members, (std::vector<int>{0, 1}));
}

TEST(Contacts, PelletsOnTwoSidesOfAnArmedLimiterNeverJoin) {
  // Pellet 0 touches the limiter from below: pellet 1, at its place, is across the limiter.
  Model m = testing::one_pellet(0.1, 0.3, 0.0);
  m.pellets.push_back(m.pellets[0]);
  m.limiters = {{0.3, 0.5, false, -1, {}}};
  const Vec y = angles({0.3, 0.3});
  const JoinCriteria criteria{1e-12, 1e-4, 1e-14};
  const std::vector<LimiterContact> below = {{0, 0, -1}};
  EXPECT_EQ(join_touching(m, 0.0, y, {{0, 1}}, below, {true}, criteria).size(), 2u);
  // Disarmed, the limiter parts nothing: at rest, pulled down alike, they join.
  EXPECT_EQ(join_touching(m, 0.0, y, {{0, 1}}, below, {false}, criteria).size(), 1u);
}

}  // namespace
}  // namespace vibro
