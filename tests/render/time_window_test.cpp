// A φ(t) panel's window that starts where the pellet rests between two branches (issue 31's
// render fuzzer): the panel joins a track's branches into one curve, so the window cuts that
// curve, gaps included. It cut each branch alone, so the curve began at the next sample after
// the window's start, and a window holding one sample got a time axis of no length (its plot
// axes x_lo = x_hi, its transform dividing by zero).
#include <gtest/gtest.h>

#include "render/figure.h"

namespace vibro {
namespace {

// One pellet that moves for 1 s, rests (the run keeps no samples while it does), and is sampled
// again at 5 s and at the end, 10 s.
RunResult resting_run() {
  RunResult run;
  PelletTrack track;
  Branch moving{1, {}};
  for (int i = 0; i <= 10; ++i) moving.samples.push_back({0.1 * i, 0.3 - 0.03 * i, -0.3});
  track.branches = {moving, Branch{2, {{5.0, 0.0, 0.0}, {10.0, 0.0, 0.0}}}};
  run.tracks = {track};
  run.stats.t_reached = 10.0;
  return run;
}

Model one_pellet() {
  Model model;
  model.pellets = {Pellet{0.1, 0.3, -0.3, {}}};
  return model;
}

// The time axis of a φ(t) panel of the resting run over [t_from, t_to].
PlotAxes time_axes(double t_from, double t_to) {
  TimePlot plot;
  plot.t_from = t_from;
  plot.t_to = t_to;
  const RenderResult r =
      render_figure({{plot}, 600, 400}, one_pellet(), resting_run(), ImageFormat::svg);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.plot_axes.size(), 1u);
  return r.plot_axes.empty() ? PlotAxes{} : r.plot_axes[0];
}

TEST(TimeWindow, AWindowStartingInARestStartsTheCurveThere) {
  const PlotAxes a = time_axes(2.0, 10.0);
  EXPECT_DOUBLE_EQ(a.x_lo, 2.0);
  EXPECT_DOUBLE_EQ(a.x_hi, 10.0);
}

TEST(TimeWindow, AWindowHoldingOneSampleHasATimeAxisOfSomeLength) {
  const PlotAxes a = time_axes(10.0, 20.0);
  EXPECT_LT(a.x_lo, a.x_hi);
  EXPECT_LE(a.x_lo, 10.0);
  EXPECT_GE(a.x_hi, 10.0);
}

}  // namespace
}  // namespace vibro
