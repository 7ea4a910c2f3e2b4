// Pellets never pass each other: the circular order of the start holds at every instant.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "core/analysis/checked_run.h"
#include "scenes.h"

namespace vibro {
namespace {

// Checks that, at every recorded instant, each pellet's gap to its successor (in the start's
// circular order) stays within [0, 2π] up to round-off.
void expect_order_kept(const Model& m, const RunResult& run, const std::string& what) {
  const int n = m.size();
  std::vector<std::vector<Sample>> flat(n);
  for (const PelletTrack& t : run.tracks)
    for (const Branch& b : t.branches)
      flat[t.pellet].insert(flat[t.pellet].end(), b.samples.begin(), b.samples.end());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto place = [&](int i) {
    double w = std::fmod(m.pellets[i].phi0, kTwoPi);
    return w < 0 ? w + kTwoPi : w;
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return place(a) < place(b); });
  for (int k = 0; k < n; ++k) {
    const int a = order[k], b = order[(k + 1) % n];
    const double offset = [&] {
      const double raw = m.pellets[b].phi0 - m.pellets[a].phi0;
      double g = std::fmod(raw, kTwoPi);
      if (g <= 0) g += kTwoPi;
      return g - raw;
    }();
    ASSERT_EQ(flat[a].size(), flat[b].size());
    for (std::size_t s = 0; s < flat[a].size(); ++s) {
      const double gap = flat[b][s].phi - flat[a][s].phi + offset;
      ASSERT_GE(gap, -1e-9) << what << " pellets " << a << "," << b << " t=" << flat[a][s].t;
      ASSERT_LE(gap, kTwoPi + 1e-9)
          << what << " pellets " << a << "," << b << " t=" << flat[a][s].t;
    }
  }
}

TEST(Order, PresetsKeepThePelletsInOrder) {
  for (const char* name : {"paper", "frictionless-elastic", "mass-ratio", "tiny-radius"}) {
    const Scene scene = testing::preset(name);
    const RunResult run =
        simulate(scene.model, testing::recorded(scene.model, std::min(scene.sim.t_end, 10.0)));
    ASSERT_EQ(run.stats.termination, Termination::completed) << name << ": " << run.stats.message;
    expect_order_kept(scene.model, run, name);
  }
}

TEST(Order, RandomScenesOfUpToEightPelletsKeepTheirOrder) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    Model m;
    m.R = 0.5;
    m.alpha0 = 0.1 * u(rng);
    m.k_c = 0.3 + 0.7 * u(rng);
    const int n = 2 + trial % 7;
    for (int i = 0; i < n; ++i) {
      Pellet p;
      p.m = 0.05 + u(rng);
      p.phi0 = -2.5 + 5.0 * (i + 0.2 + 0.6 * u(rng)) / n;
      p.dphi0 = 12.0 * (u(rng) - 0.5);
      if (i == 0) p.force = {1.0, 3.0, 0.0};
      m.pellets.push_back(p);
    }
    m.limiters = {{2.8, 0.5 + 0.5 * u(rng), false, -1, {}},
                  {-2.8, 0.5 + 0.5 * u(rng), false, -1, {}}};
    const RunResult run = simulate(m, testing::recorded(m, 5.0));
    ASSERT_EQ(run.stats.termination, Termination::completed)
        << "trial " << trial << ": " << run.stats.message;
    EXPECT_TRUE(testing::all_finite(run));
    expect_order_kept(m, run, "trial " + std::to_string(trial));
  }
}

}  // namespace
}  // namespace vibro
