// Energy: conserved without friction and with elastic impacts; balanced by the work of force
// and friction and the impact losses otherwise.
#include <gtest/gtest.h>

#include <cmath>

#include "core/analysis/checked_run.h"
#include "scenes.h"

namespace vibro {
namespace {

// Total energy at every recorded instant (all tracks sample the same times).
std::vector<double> energies(const Model& m, const RunResult& run) {
  std::vector<std::vector<Sample>> flat;
  for (const PelletTrack& t : run.tracks) {
    flat.emplace_back();
    for (const Branch& b : t.branches)
      flat.back().insert(flat.back().end(), b.samples.begin(), b.samples.end());
  }
  std::vector<double> E(flat.at(0).size(), 0.0);
  for (std::size_t p = 0; p < flat.size(); ++p) {
    EXPECT_EQ(flat[p].size(), E.size());
    for (std::size_t k = 0; k < E.size() && k < flat[p].size(); ++k) {
      EXPECT_EQ(flat[p][k].t, flat[0][k].t);
      E[k] += energy(m, run.tracks[p].pellet, flat[p][k].phi, flat[p][k].dphi);
    }
  }
  return E;
}

TEST(Energy, HoldsWithoutFrictionAndWithElasticImpacts) {
  const Scene scene = testing::preset("frictionless-elastic");
  for (Method method : {Method::dopri5, Method::dop853, Method::radau5, Method::automatic}) {
    const RunResult run =
        simulate(scene.model, testing::recorded(scene.model, scene.sim.t_end, method));
    ASSERT_EQ(run.stats.termination, Termination::completed) << run.stats.message;
    EXPECT_GE(run.summary.limiter_impacts, 10);
    EXPECT_GE(run.summary.collisions, 3);
    const std::vector<double> E = energies(scene.model, run);
    double scale = 0.0;
    for (const Pellet& p : scene.model.pellets) scale += p.m * scene.model.g * scene.model.R;
    double worst = 0.0;
    for (double e : E) worst = std::max(worst, std::abs(e - E.front()) / scale);
    // Radau IIA's embedded estimate is less tight than the explicit pairs' at equal rtol.
    const double bound = method == Method::radau5 ? 1e-7 : 1e-8;
    EXPECT_LT(worst, bound) << method_name(method);
    EXPECT_LT(run.stats.energy_defect, bound) << method_name(method);
  }
}

TEST(Energy, BalanceDefectIsSmallWithFrictionForcingAndImpacts) {
  const Scene scene = testing::preset("paper");
  SimOptions o = scene.sim;
  o.t_end = 8.0;
  const RunResult run = simulate(scene.model, o);
  ASSERT_EQ(run.stats.termination, Termination::completed) << run.stats.message;
  EXPECT_LT(run.stats.energy_defect, 1e-7);
  EXPECT_GT(run.stats.energy_defect, 0.0);
}

}  // namespace
}  // namespace vibro
