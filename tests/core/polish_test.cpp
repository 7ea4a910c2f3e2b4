// Event roots are polished on a precise state (core/run/simulate.cpp, Simulation::polish): the
// long chains of impacts where a root's small error repeats at every impact show it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/analysis/checked_run.h"
#include "scenes.h"

namespace vibro {
namespace {

// Pellet 4 pressed by a force of 1 N onto pellet 3, 2e-9 rad from it at the bottom of a circle
// of 1.9 mm, bounces on it elastically 10,067 times in 14 ms, each flight 1.4e-6 s inside steps
// of up to 3 ms (two other pellets swing far away). Each root's error repeats at every bounce:
// DOP853 at rtol 1e-6 to 1e-8 put the 10,000th bounce 4e-7 s late, DOPRI5 at rtol 1e-6 listed
// 10,093 events and Radau IIA 3,711 (trust scan, seed 11, scene 259). Every method at rtol 1e-6
// and 1e-8 lists the reference's events, at times within 1e-7 s of it (1.2e-8 s at worst).
TEST(Polish, TenThousandBouncesOfAnElasticPairKeepTheirTimes) {
  Model model;
  model.R = 0.0018839204526546504;
  model.friction = FrictionLaw::bilateral;
  model.k_c = 1.0;
  model.limiters = {
      Limiter{.angle = -0.3021582625387551, .k = 0.0, .pellets = {2, 3}},
      Limiter{.angle = -2.9979796944364527, .k = 0.5395717620849609, .mobile = true, .rearm_by = 0},
      Limiter{.angle = 0.648226725130737, .k = 0.16356945037841797}};
  model.pellets = {Pellet{.m = 0.015810444929436916,
                          .phi0 = -0.16805145732231733,
                          .force = {0.17453284119739795, 17.1422536460621, 4.563197364537905}},
                   Pellet{.m = 9.966984123721339,
                          .phi0 = 8.650561079208629,
                          .dphi0 = -79.9026492423013,
                          .force = {288.48548895759836, 4.135341168010528, 1.2619988036585739}},
                   Pellet{.m = 0.2554616686570595, .phi0 = 0.0},
                   Pellet{.m = 0.05078787033519329,
                          .phi0 = 2e-09,
                          .force = {0.9985496183907803, 2.5383555829351945, 3.813014846024848}}};
  SimOptions o;
  o.t_end = 0.01873089362510622;
  o.method = Method::dop853;
  o.rtol = 1e-13;
  o.atol = 1e-16;
  o.check = false;
  const RunResult ref = simulate(model, o);
  ASSERT_EQ(ref.stats.termination, Termination::completed);
  ASSERT_GT(ref.events.size(), 10000u);
  for (Method m : {Method::dopri5, Method::dop853, Method::radau5, Method::automatic}) {
    for (double rtol : {1e-6, 1e-8}) {
      SCOPED_TRACE(testing::method_at(m, rtol));
      o.method = m;
      o.rtol = rtol;
      o.atol = 1e-3 * rtol;
      const RunResult run = simulate(model, o);
      ASSERT_EQ(run.events.size(), ref.events.size());
      double worst = 0.0;
      for (std::size_t k = 0; k < run.events.size(); ++k) {
        ASSERT_EQ(run.events[k].kind, ref.events[k].kind) << "event " << k;
        ASSERT_EQ(run.events[k].pellets, ref.events[k].pellets) << "event " << k;
        worst = std::max(worst, std::abs(run.events[k].t - ref.events[k].t));
      }
      EXPECT_LT(worst, 1e-7);
    }
  }
}

}  // namespace
}  // namespace vibro
