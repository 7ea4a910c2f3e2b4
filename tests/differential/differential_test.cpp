// The bounded property tests of issue 9: random scenes (scene_gen.h) run under every method
// must list the same events at tight tolerances (a), the same events at rtol and rtol/10 (b),
// and keep the physics (c). Each property checks a fixed number of scenes from a fixed seed,
// so CI is reproducible and the file runs in well under a minute; set VIBRO_DIFF_SEED=<n> in
// the environment to draw other scenes (RC_PARAMS is not read: the count and the seed are
// fixed here). A failure prints the shrunk scene as JSON, ready for `vibro simulate -`.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/detail/TestListenerAdapter.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <sstream>

#include "core/run/validate.h"
#include "tests/differential/checks.h"

namespace vibro::differential {
namespace {

std::uint64_t seed() {
  const char* s = std::getenv("VIBRO_DIFF_SEED");
  return s ? std::strtoull(s, nullptr, 10) : 20240901;
}

// The share of each property's scenes to check, VIBRO_DIFF_FRACTION in (0, 1] (default 1): the
// sanitized suite (scripts/sanitize.sh) checks a quarter, where it looks for memory errors on the
// same code paths at twenty times the cost per scene.
int scaled(int scenes) {
  const char* s = std::getenv("VIBRO_DIFF_FRACTION");
  const double f = s ? std::strtod(s, nullptr) : 1.0;
  if (!(f > 0.0 && f <= 1.0)) return scenes;
  return std::max(1, static_cast<int>(f * scenes));
}

// Checks `property` on `scenes` scenes, as RC_GTEST_PROP does but with the count and the seed
// set here instead of from RC_PARAMS. A silent listener: RapidCheck's own would print an
// RC_PARAMS="reproduce=..." line that this check does not read.
template <typename Property>
void check(int scenes, Property property) {
  rc::detail::TestParams params;
  params.seed = seed();
  params.maxSuccess = scaled(scenes);
  params.maxSize = rc::kNominalSize;
  params.maxDiscardRatio = 10;
  rc::detail::TestMetadata metadata;
  metadata.id = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  metadata.description = metadata.id;
  rc::detail::TestListenerAdapter silent;
  const auto result =
      rc::detail::checkProperty(rc::detail::toProperty(property), metadata, params, silent);
  if (!result.template is<rc::detail::SuccessResult>()) {
    std::ostringstream message;
    rc::detail::printResultMessage(result, message);
    FAIL() << message.str() << "\n(seed " << params.seed << ")";
  }
}

// A random scene. validate_model accepts every one by construction; the guard discards any it
// would refuse should its rules grow.
RandomScene valid_scene() {
  RandomScene scene = *gen_scene();
  RC_PRE(!validate_model(scene.model));
  return scene;
}

// (a) and (b) compare what the runs vouch for: the events before their stats.trusted_until.
// An ill-conditioned event (a grazing impact, a stick test at its threshold, events nearly at
// one instant, a difference an earlier one amplified) may still come out otherwise under
// another method before the check noticed it: the shadow run shares the method's bias. Those
// are counted in docs/ACCURACY.md; a disagreement that no conditioning explains, or an impact
// at round-off speed, is a bug and fails.
bool explained(const Finding& f) {
  return f.cause != Cause::unexplained && f.cause != Cause::round_off_impact &&
         f.cause != Cause::regrouped;
}

TEST(Differential, MethodsAgreeAtTightTolerances) {
  check(300, [] {
    SceneRuns runs(valid_scene(), /*trust_horizon=*/true);
    for (double rtol : {1e-11, 1e-12}) {
      RC_PRE(!incomplete(runs, rtol));
      if (auto f = methods_disagree(runs, rtol); f && !explained(*f)) RC_FAIL(describe(*f));
    }
  });
}

TEST(Differential, EachMethodAgreesWithATenthOfItsTolerance) {
  check(200, [] {
    SceneRuns runs(valid_scene(), /*trust_horizon=*/true);
    for (double rtol : {1e-9, 1e-10, 1e-11}) RC_PRE(!incomplete(runs, rtol));
    for (Method m : kMethods)
      for (double rtol : {1e-9, 1e-10})
        if (auto f = rtol_disagrees(runs, m, rtol); f && !explained(*f)) RC_FAIL(describe(*f));
  });
}

// A sweep's runs pass a frictionless pellet's reversals (docs/MODEL.md, "Events"): on random
// scenes made frictionless, every other event they vouch for is the one the listing run finds.
TEST(Differential, PassingFrictionlessReversalsKeepsEveryOtherEvent) {
  check(150, [] {
    RandomScene scene = *gen_scene();
    scene.model.alpha0 = 0.0;
    scene.model.mu_s.reset();
    RC_PRE(!validate_model(scene.model));
    SceneRuns runs(scene, /*trust_horizon=*/true);
    RC_PRE(!incomplete(runs, 1e-10));
    for (Method m : {Method::taylor, Method::dop853})
      if (auto f = passed_reversals_disagree(runs, m, 1e-10); f && !explained(*f))
        RC_FAIL(describe(*f));
  });
}

TEST(Differential, EveryRunKeepsThePhysics) {
  check(300, [] {
    SceneRuns runs(valid_scene());
    RC_PRE(!incomplete(runs, 1e-10));
    for (Method m : kMethods)
      if (auto f = physics_fails(runs, m, 1e-10)) RC_FAIL(describe(*f));
  });
}

}  // namespace
}  // namespace vibro::differential
