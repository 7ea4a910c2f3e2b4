#include "render/track_window.h"

#include <gtest/gtest.h>

namespace vibro::render {
namespace {

const std::vector<Sample> kSamples{
    {0.0, 0.0, 1.0}, {1.0, 1.0, 1.0}, {2.0, 2.0, 1.0}, {3.0, 3.0, 1.0}};

TEST(ClipToWindow, KeepsInsideSamplesAndInterpolatesTheEdges) {
  const auto clipped = clip_to_window(kSamples, 0.5, 2.25);
  ASSERT_EQ(clipped.size(), 4u);
  EXPECT_DOUBLE_EQ(clipped.front().t, 0.5);
  EXPECT_DOUBLE_EQ(clipped.front().phi, 0.5);
  EXPECT_DOUBLE_EQ(clipped[1].t, 1.0);
  EXPECT_DOUBLE_EQ(clipped.back().t, 2.25);
  EXPECT_DOUBLE_EQ(clipped.back().phi, 2.25);
}

TEST(ClipToWindow, WholeOrNothing) {
  EXPECT_EQ(clip_to_window(kSamples, 0.0, 1e9).size(), 4u);
  EXPECT_TRUE(clip_to_window(kSamples, 5.0, 6.0).empty());
  const auto inside_one_step = clip_to_window(kSamples, 1.2, 1.8);
  ASSERT_EQ(inside_one_step.size(), 2u);
  EXPECT_DOUBLE_EQ(inside_one_step[1].phi, 1.8);
}

// Two branches with a gap between them (a pellet at rest that the run stopped sampling).
const PelletTrack kTrack{
    0,
    {Branch{1, {{0.5, 0.0, 2.0}, {1.0, 1.0, 2.0}}}, Branch{2, {{1.0, 1.0, -1.0}, {1.5, 0.5, -1.0}}},
     Branch{3, {{3.0, 0.5, 0.0}, {4.0, 0.5, 0.0}}}}};

TEST(StateAt, InterpolatesInsideABranch) {
  EXPECT_DOUBLE_EQ(state_at(kTrack, 0.75)->phi, 0.5);
  EXPECT_DOUBLE_EQ(state_at(kTrack, 1.25)->phi, 0.75);
  // At an event the state after it: where the next branch starts.
  EXPECT_DOUBLE_EQ(state_at(kTrack, 1.0)->dphi, -1.0);
}

TEST(StateAt, HoldsThePlaceWhereNoBranchSpansTheTime) {
  EXPECT_DOUBLE_EQ(state_at(kTrack, 2.0)->phi, 0.5);  // between branches
  EXPECT_DOUBLE_EQ(state_at(kTrack, 9.0)->phi, 0.5);  // after the record
  EXPECT_DOUBLE_EQ(state_at(kTrack, 0.0)->phi, 0.0);  // before it
  EXPECT_DOUBLE_EQ(state_at(kTrack, 9.0)->t, 9.0);
  EXPECT_FALSE(state_at(PelletTrack{0, {Branch{1, {}}}}, 1.0));
}

Event event(double t, EventKind kind, std::vector<int> pellets) {
  Event e;
  e.t = t;
  e.kind = kind;
  e.pellets = std::move(pellets);
  return e;
}

TEST(FindImpact, MatchesTimePelletAndMarkedKind) {
  const std::vector<Event> events{event(0.5, EventKind::reversal, {0}),
                                  event(1.0, EventKind::limiter, {1}),
                                  event(1.0, EventKind::collision, {0, 1})};
  const Event* e = find_impact(events, 0, 1.0);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->kind, EventKind::collision);
  EXPECT_EQ(find_impact(events, 1, 1.0)->kind, EventKind::limiter);
  EXPECT_EQ(find_impact(events, 0, 0.5), nullptr);
}

TEST(PanelPellets, TimeAndMechanismPanelsDefaultToEveryPellet) {
  TimePlot time;
  EXPECT_EQ(panel_pellets(time, 3), (std::vector<int>{0, 1, 2}));
  time.pellets = {1};
  EXPECT_EQ(panel_pellets(time, 3), (std::vector<int>{1}));
  PhasePlot phase;
  phase.pellet = 2;
  EXPECT_EQ(panel_pellets(phase, 3), (std::vector<int>{2}));
  MechanismPlot mechanism;
  EXPECT_EQ(panel_pellets(mechanism, 2), (std::vector<int>{0, 1}));
}

TEST(WindowSuffix, NamesARestrictedWindowOnly) {
  TimeWindow spec;
  EXPECT_EQ(window_suffix(spec, 12.0), "");
  spec.t_to = 12.0;
  EXPECT_EQ(window_suffix(spec, 12.0), "");
  spec.t_from = 2.0;
  spec.t_to = 6.5;
  EXPECT_EQ(window_suffix(spec, 12.0), ", t \u2208 [2, 6.5] s");
  spec.t_to = 1e9;
  EXPECT_EQ(window_suffix(spec, 12.0), ", t \u2208 [2, 12] s");
}

}  // namespace
}  // namespace vibro::render
