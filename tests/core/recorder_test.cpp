// The recorder's sample budget (SimOptions::max_samples): past it the branches are thinned, so a
// long run is drawn whole; what is kept is a subset of the unbounded run's samples, with every
// branch's ends.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "core/simulate.h"
#include "tests/core/scenes.h"

namespace vibro {
namespace {

TEST(Recorder, ASampleBudgetThinsTheBranchesAndKeepsTheirEnds) {
  const Scene paper = testing::preset("paper");
  const Model& m = paper.model;
  SimOptions o = paper.sim;
  o.check = false;
  o.record = {true, true};
  const RunResult full = simulate(m, o);
  o.max_samples = 800;
  const RunResult thin = simulate(m, o);

  ASSERT_EQ(full.tracks.size(), thin.tracks.size());
  long kept = 0, all = 0;
  for (std::size_t k = 0; k < full.tracks.size(); ++k) {
    const auto& a = full.tracks[k].branches;
    const auto& b = thin.tracks[k].branches;
    ASSERT_EQ(a.size(), b.size());  // every branch is still there
    for (std::size_t j = 0; j < a.size(); ++j) {
      std::set<std::tuple<double, double, double>> samples;
      for (const Sample& s : a[j].samples) samples.insert({s.t, s.phi, s.dphi});
      for (const Sample& s : b[j].samples) EXPECT_TRUE(samples.count({s.t, s.phi, s.dphi}));
      EXPECT_EQ(b[j].samples.front().t, a[j].samples.front().t);
      EXPECT_EQ(b[j].samples.back().t, a[j].samples.back().t);
      kept += static_cast<long>(b[j].samples.size());
      all += static_cast<long>(a[j].samples.size());
    }
  }
  EXPECT_GT(all, 2 * 800);  // the budget mattered
  EXPECT_LE(kept, 800 + 2);
  EXPECT_GT(kept, 800 / 3);
  // The run itself is the same: thinning only drops samples.
  ASSERT_EQ(full.events.size(), thin.events.size());
  for (std::size_t k = 0; k < full.events.size(); ++k) EXPECT_EQ(full.events[k].t, thin.events[k].t);
}

}  // namespace
}  // namespace vibro
