// A saved result reads back as what was saved (`vibro plot` draws it without running anything):
// a sweep's runs and points to the bit, where JSON holds them; a branch with its bifurcations.
// What is not a saved result is refused naming the field.
#include "io/saved_results.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "io/orbit_json.h"
#include "io/sweep_json.h"

namespace vibro {
namespace {

using nlohmann::json;

SweepResult two_runs() {
  SweepResult result;
  for (int k = 0; k < 2; ++k) {
    SweepRun run;
    run.value = 3.0 + 1.0 / 3.0 * k;
    run.value2 = 0.25 * k;
    run.start = k;
    run.direction = k == 0 ? 1 : -1;
    run.period = 2 + k;
    run.impacts_per_period = 1.5;
    run.sticks = k == 1;
    run.trusted = k == 0;
    run.trusted_until = 12.5;
    run.termination = k == 0 ? Termination::completed : Termination::deadline;
    run.message = k == 0 ? "" : "stopped";
    if (k == 0) run.lyapunov = -0.125;
    for (int i = 0; i < 3 + k; ++i)
      run.points.emplace_back(0, 0.1 * i, 1.0 / 7.0 * i, -2.0 / 3.0, 0.5, k - 1, i != 1);
    result.runs.push_back(run);
  }
  result.runs[1].points[2].dphi = std::numeric_limits<double>::quiet_NaN();  // JSON: null
  return result;
}

TEST(SavedResults, ASweepReadsBackAsItWasWritten) {
  SweepSpec spec;
  spec.axis.parameter = "model.pellets[0].Omega";
  const SweepResult sent = two_runs();
  const auto read = read_sweep_result(json::parse(sweep_result_json(spec, sent).dump()));
  ASSERT_TRUE(std::holds_alternative<SweepResult>(read)) << std::get<FieldError>(read).message;
  const SweepResult& back = std::get<SweepResult>(read);
  ASSERT_EQ(back.runs.size(), 2u);
  for (std::size_t r = 0; r < 2; ++r) {
    const SweepRun& a = sent.runs[r];
    const SweepRun& b = back.runs[r];
    EXPECT_EQ(a.value, b.value);
    EXPECT_EQ(a.value2, b.value2);
    EXPECT_EQ(a.start, b.start);
    EXPECT_EQ(a.direction, b.direction);
    EXPECT_EQ(a.period, b.period);
    EXPECT_EQ(a.sticks, b.sticks);
    EXPECT_EQ(a.trusted, b.trusted);
    EXPECT_EQ(a.termination, b.termination);
    EXPECT_EQ(a.message, b.message);
    EXPECT_EQ(a.lyapunov, b.lyapunov);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i) {
      const SectionPoint &p = a.points[i], &q = b.points[i];
      EXPECT_EQ(p.t, q.t);
      EXPECT_EQ(p.phi, q.phi);
      EXPECT_TRUE(p.dphi == q.dphi || (std::isnan(p.dphi) && std::isnan(q.dphi)));
      EXPECT_EQ(p.phase, q.phase);
      EXPECT_EQ(p.limiter, q.limiter);
      EXPECT_EQ(p.trusted, q.trusted);
    }
  }
}

TEST(SavedResults, ColumnsNotDrawnFromArePassedOverAndBrokenOnesNamed) {
  json j = sweep_result_json(SweepSpec{}, two_runs());
  j["points"]["attractor"] = json::array();  // a column a newer writer adds
  EXPECT_TRUE(std::holds_alternative<SweepResult>(read_sweep_result(j)));
  json short_column = j;
  short_column["points"]["t"].erase(0);
  auto read = read_sweep_result(short_column);
  ASSERT_TRUE(std::holds_alternative<FieldError>(read));
  EXPECT_EQ(std::get<FieldError>(read).field, "points.t");
  json far_run = j;
  far_run["points"]["run"][0] = 7;
  read = read_sweep_result(far_run);
  ASSERT_TRUE(std::holds_alternative<FieldError>(read));
  EXPECT_EQ(std::get<FieldError>(read).field, "points.run");
  read = read_sweep_result(json{{"orbit", 1}});
  ASSERT_TRUE(std::holds_alternative<FieldError>(read));
  EXPECT_EQ(std::get<FieldError>(read).field, "result");
}

TEST(SavedResults, ABranchReadsBackWithItsBifurcations) {
  OrbitResult sent;
  for (int k = 0; k < 3; ++k)
    sent.branch.points.push_back(
        {5.0 + 0.1 * k, {{0.25, -1.0 / 3.0}}, {{0.5, 0.25}, {-1.25, 0.0}}, k != 1, 2.0});
  sent.branch.bifurcations.push_back(
      {BifurcationKind::period_doubling, 5.15, {{0.25, -0.5}}, std::nullopt, {}});
  sent.branch.bifurcations.push_back(
      {BifurcationKind::grazing, 5.2, {{0.3, 0.0}}, std::nullopt, {}, false});
  sent.branch.message = "a fold ahead";
  // Neutral: its multipliers lie on the unit circle. A branch saved without "neutral" is judged
  // by them (point 3), one that says it is read as it says (point 4).
  sent.branch.points.push_back({5.3, {{0.25, 0.0}}, {{0.6, 0.8}, {0.6, -0.8}}, false, 0.0, true});
  sent.branch.points.push_back({5.4, {{0.25, 0.0}}, {{0.5, 0.0}, {0.4, 0.0}}, false, 0.0, true});
  json saved = json::parse(orbit_result_json(sent).dump());
  EXPECT_EQ(saved["branch"][3]["neutral"], true);
  saved["branch"][3].erase("neutral");
  const auto read = read_orbit_branch(saved, 1e-10);
  ASSERT_TRUE(std::holds_alternative<OrbitBranch>(read)) << std::get<FieldError>(read).message;
  const OrbitBranch& back = std::get<OrbitBranch>(read);
  ASSERT_EQ(back.points.size(), 5u);
  EXPECT_TRUE(back.points[4].neutral);
  EXPECT_EQ(back.points[1].value, 5.1);
  EXPECT_FALSE(back.points[1].stable);
  EXPECT_FALSE(back.points[1].neutral);
  EXPECT_FALSE(back.points[3].stable);
  EXPECT_TRUE(back.points[3].neutral);
  EXPECT_EQ(back.points[2].state[0].dphi, -1.0 / 3.0);
  EXPECT_EQ(back.points[0].multipliers[1], std::complex<double>(-1.25, 0.0));
  ASSERT_EQ(back.bifurcations.size(), 2u);
  EXPECT_EQ(back.bifurcations[0].kind, BifurcationKind::period_doubling);
  EXPECT_EQ(back.bifurcations[0].approached_impacting, std::nullopt);
  EXPECT_EQ(back.bifurcations[1].approached_impacting, false);  // a grazing says its side
  EXPECT_EQ(back.message, "a fold ahead");
  json not_boolean = orbit_result_json(sent);
  not_boolean["branch"][2]["neutral"] = "yes";
  const auto refused_neutral = read_orbit_branch(not_boolean, 1e-10);
  ASSERT_TRUE(std::holds_alternative<FieldError>(refused_neutral));
  EXPECT_EQ(std::get<FieldError>(refused_neutral).field, "branch[2].neutral");
  json wrong = orbit_result_json(sent);
  wrong["bifurcations"][0]["kind"] = "cusp";
  const auto refused = read_orbit_branch(wrong, 1e-10);
  ASSERT_TRUE(std::holds_alternative<FieldError>(refused));
  EXPECT_EQ(std::get<FieldError>(refused).field, "bifurcations[0].kind");
}

}  // namespace
}  // namespace vibro
