// The scene's "periodic_orbit" (io/orbit_json.h): read strictly with every bad field named, kept
// through the canonical form; and an orbit's result in the shape of API.md, with null where a
// number is not finite.
#include "io/orbit_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "io/scene_json.h"
#include "tests/io/orbit_scene.h"

namespace vibro {
namespace {

using nlohmann::json;

// The shared scene, asking for everything a "periodic_orbit" may hold.
json orbit_scene() {
  json s = testing::impact_oscillator_orbit();
  s["periodic_orbit"]["periods"] = 1;
  s["periodic_orbit"]["transient"] = 50;
  s["periodic_orbit"]["max_iterations"] = 30;
  s["periodic_orbit"]["continuation"] = {
      {"parameter", "model.pellets[0].Omega"}, {"to", 6.5}, {"max_points", 50}};
  return s;
}

std::string field_of(const json& scene) {
  const SceneOrError r = scene_from_json(scene);
  if (const FieldError* e = std::get_if<FieldError>(&r)) return e->field;
  return "(accepted)";
}

// A mobile limiter's armed state: a limiter may start disarmed (a scene started on a motion's
// section), a guess carries the section's armed set, and both read back through the canonical
// form; a fixed limiter cannot be disarmed, and an armed set holds booleans.
TEST(OrbitJson, ArmedStatesOfMobileLimitersAreRead) {
  json s = nlohmann::json::parse(std::string(*preset_json("paper")));
  s["model"]["limiters"][0]["armed"] = false;
  s["periodic_orbit"] = {
      {"periods", 6},
      {"guess", {{{"phi", 1.42}, {"dphi", 3.43}}, {{"phi", 1.13}, {"dphi", 1.1}}}},
      {"armed", {false, true}}};
  const SceneOrError read = scene_from_json(s);
  ASSERT_TRUE(std::holds_alternative<Scene>(read)) << std::get<FieldError>(read).message;
  const Scene& scene = std::get<Scene>(read);
  EXPECT_FALSE(scene.model.limiters[0].armed);
  EXPECT_TRUE(scene.model.limiters[1].armed);
  EXPECT_EQ(scene.periodic_orbit->orbit.armed, (std::vector<bool>{false, true}));
  const json canonical = scene_to_json(scene);
  EXPECT_EQ(canonical["model"]["limiters"][0]["armed"], false);
  EXPECT_FALSE(canonical["model"]["limiters"][1].contains("armed"));
  EXPECT_EQ(canonical["periodic_orbit"]["armed"], json({false, true}));

  json fixed = s;
  fixed["model"]["limiters"][1]["armed"] = false;
  EXPECT_EQ(field_of(fixed), "model.limiters[1].armed");
  json text = s;
  text["periodic_orbit"]["armed"] = {"no", true};
  EXPECT_EQ(field_of(text), "periodic_orbit.armed[0]");
}

TEST(OrbitJson, ASceneAsksForAnOrbitAndItsContinuation) {
  const SceneOrError read = scene_from_json(orbit_scene());
  ASSERT_TRUE(std::holds_alternative<Scene>(read)) << std::get<FieldError>(read).message;
  const Scene& scene = std::get<Scene>(read);
  ASSERT_TRUE(scene.periodic_orbit);
  const OrbitSpec& spec = scene.periodic_orbit->orbit;
  EXPECT_EQ(spec.periods, 1);
  EXPECT_EQ(spec.transient, 50);
  EXPECT_EQ(spec.max_iterations, 30);
  ASSERT_EQ(spec.guess.size(), 1u);
  EXPECT_EQ(spec.guess[0].phi, 0.15);
  EXPECT_EQ(spec.guess[0].dphi, 0.1);
  ASSERT_TRUE(scene.periodic_orbit->continuation);
  EXPECT_EQ(scene.periodic_orbit->continuation->parameter, "model.pellets[0].Omega");
  EXPECT_EQ(scene.periodic_orbit->continuation->to, 6.5);
  EXPECT_EQ(scene.periodic_orbit->continuation->max_points, 50);

  // The canonical form keeps it, and reads back to itself.
  const json canonical = scene_to_json(scene);
  EXPECT_EQ(canonical["periodic_orbit"]["continuation"]["to"], 6.5);
  const SceneOrError again = scene_from_json(canonical);
  ASSERT_TRUE(std::holds_alternative<Scene>(again));
  EXPECT_EQ(scene_to_json(std::get<Scene>(again)).dump(), canonical.dump());
}

TEST(OrbitJson, OmittedFieldsTakeTheDefaults) {
  json s = orbit_scene();
  s["periodic_orbit"] = json::object();
  const Scene scene = std::get<Scene>(scene_from_json(s));
  const OrbitSpec defaults;
  EXPECT_EQ(scene.periodic_orbit->orbit.periods, defaults.periods);
  EXPECT_EQ(scene.periodic_orbit->orbit.transient, defaults.transient);
  EXPECT_TRUE(scene.periodic_orbit->orbit.guess.empty());
  EXPECT_FALSE(scene.periodic_orbit->continuation);
  s.erase("periodic_orbit");
  EXPECT_FALSE(std::get<Scene>(scene_from_json(s)).periodic_orbit);
}

TEST(OrbitJson, EveryBadFieldIsNamed) {
  struct Case {
    json::json_pointer pointer;
    json value;
    std::string field;
  };
  const std::vector<Case> cases = {
      {json::json_pointer("/periodic_orbit/period"), 1, "periodic_orbit.period"},
      {json::json_pointer("/periodic_orbit/periods"), 0, "periodic_orbit.periods"},
      {json::json_pointer("/periodic_orbit/periods"), 1.5, "periodic_orbit.periods"},
      {json::json_pointer("/periodic_orbit/transient"), -1, "periodic_orbit.transient"},
      {json::json_pointer("/periodic_orbit/max_iterations"), "many",
       "periodic_orbit.max_iterations"},
      {json::json_pointer("/periodic_orbit/guess"),
       json::array({{{"phi", 0.1}, {"dphi", 0.0}}, {{"phi", 0.2}, {"dphi", 0.0}}}),
       "periodic_orbit.guess"},
      {json::json_pointer("/periodic_orbit/guess"), json::array({{{"phi", 0.1}}}),
       "periodic_orbit.guess[0].dphi"},
      {json::json_pointer("/periodic_orbit/guess/0/speed"), 1.0, "periodic_orbit.guess[0].speed"},
      {json::json_pointer("/periodic_orbit/guess/0/phi"), "0.1", "periodic_orbit.guess[0].phi"},
      {json::json_pointer("/periodic_orbit/guess"), 0.1, "periodic_orbit.guess"},
      {json::json_pointer("/periodic_orbit/continuation/step"), 0.1,
       "periodic_orbit.continuation.step"},
      {json::json_pointer("/periodic_orbit/continuation/parameter"), nullptr,
       "periodic_orbit.continuation.parameter"},
      {json::json_pointer("/periodic_orbit/continuation/parameter"), "model.pellets[0].mass",
       "periodic_orbit.continuation.parameter"},
      {json::json_pointer("/periodic_orbit/continuation/to"), nullptr,
       "periodic_orbit.continuation.to"},
      {json::json_pointer("/periodic_orbit/continuation/max_points"), 1,
       "periodic_orbit.continuation.max_points"},
      {json::json_pointer("/periodic_orbit"), "yes", "periodic_orbit"},
      {json::json_pointer("/model/pellets/0/F0"), 0.0, "model.pellets"},
  };
  for (const Case& c : cases) {
    json s = orbit_scene();
    s[c.pointer] = c.value;
    EXPECT_EQ(field_of(s), c.field) << c.pointer.to_string() << " = " << c.value.dump();
  }
}

// A result with every kind of entry, and numbers that are not finite.
OrbitResult synthetic_result() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  OrbitResult r;
  PeriodicOrbit& o = r.orbit;
  o.converged = true;
  o.period = 2.0 * M_PI / 6.0;
  o.state = {{0.15, nan}};
  o.multipliers = {{0.5, 0.6}, {0.5, -0.6}};
  o.residual = std::numeric_limits<double>::infinity();
  Event impact;
  impact.t = 1.0;
  impact.kind = EventKind::limiter;
  impact.pellets = {0};
  impact.limiter = 0;
  impact.dphi_before = {-1.0};
  impact.dphi_after = {0.8};
  o.events = {impact};
  r.branch.points = {{6.0, {{0.15, 0.1}}, {{0.5, 0.6}}, true, 1.0},
                     {6.1, {{0.16, 0.1}}, {{0.6, 0.6}}, true, 1.0}};
  r.branch.bifurcations = {
      {BifurcationKind::period_doubling, 6.05, {{0.15, 0.1}}, 6.03, {{0.2, 0.1}}},
      {BifurcationKind::fold, 6.08, {{0.15, 0.1}}, {}, {}}};
  r.branch.message = "the branch left the limits";
  return r;
}

bool has_keys(const json& j, std::initializer_list<const char*> keys) {
  for (const char* k : keys)
    if (!j.contains(k)) {
      ADD_FAILURE() << "no \"" << k << "\" in " << j.dump();
      return false;
    }
  return true;
}

TEST(OrbitJson, TheResultHasTheShapeOfTheApiAndNoNaN) {
  const json j = orbit_result_json(synthetic_result());
  EXPECT_TRUE(has_keys(j, {"orbit", "branch", "bifurcations", "reached", "message"}));
  const json& o = j["orbit"];
  EXPECT_TRUE(
      has_keys(o, {"periods", "t0", "state", "impacts_per_period", "residual", "multipliers",
                   "stable", "neutral", "events", "converged", "admissible", "message",
                   "iterations", "exact_jacobian", "jacobian_note", "period", "stats"}));
  EXPECT_TRUE(o["state"][0]["dphi"].is_null());
  EXPECT_EQ(o["state"][0]["phi"], 0.15);
  EXPECT_TRUE(o["residual"].is_null());
  EXPECT_EQ(o["multipliers"][1], (json{{"re", 0.5}, {"im", -0.6}}));
  EXPECT_EQ(o["events"][0]["kind"], "limiter");
  EXPECT_EQ(o["events"][0]["limiter"], 0);
  ASSERT_EQ(j["branch"].size(), 2u);
  EXPECT_TRUE(has_keys(j["branch"][1], {"value", "state", "multipliers", "stable", "neutral",
                                        "impacts_per_period"}));
  EXPECT_EQ(j["branch"][1]["value"], 6.1);
  ASSERT_EQ(j["bifurcations"].size(), 2u);
  EXPECT_EQ(j["bifurcations"][0]["kind"], "period_doubling");
  EXPECT_EQ(j["bifurcations"][0]["doubled"]["value"], 6.03);
  EXPECT_EQ(j["bifurcations"][0]["doubled"]["state"][0]["phi"], 0.2);
  EXPECT_EQ(j["bifurcations"][1]["kind"], "fold");
  EXPECT_FALSE(j["bifurcations"][1].contains("doubled"));
  EXPECT_TRUE(has_keys(j["bifurcations"][1], {"value", "kind", "state"}));
  EXPECT_EQ(j["reached"], false);
  const std::string text = j.dump();
  EXPECT_EQ(text.find("NaN"), std::string::npos);
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_EQ(text.find("inf"), std::string::npos);
}

// Without continuation the branch and the bifurcations are empty arrays, not absent.
TEST(OrbitJson, AnOrbitAloneHasAnEmptyBranch) {
  OrbitResult r = synthetic_result();
  r.branch = {};
  const json j = orbit_result_json(r);
  EXPECT_TRUE(j["branch"].is_array());
  EXPECT_TRUE(j["branch"].empty());
  EXPECT_TRUE(j["bifurcations"].is_array());
  EXPECT_TRUE(j["bifurcations"].empty());
  EXPECT_EQ(j["message"], "");
}

}  // namespace
}  // namespace vibro

namespace vibro {
namespace {

// The shared scene following the period doubling in the stop's restitution.
json follow_scene() {
  json s = orbit_scene();
  s["periodic_orbit"]["continuation"]["to"] = 5.0;
  s["periodic_orbit"]["continuation"]["follow"] = "period_doubling";
  s["periodic_orbit"]["continuation"]["parameter2"] = {
      {"parameter", "model.limiters[0].k"}, {"from", 0.6}, {"to", 0.9}};
  return s;
}

TEST(OrbitJson, AFollowIsReadKeptAndEveryBadFieldNamed) {
  const SceneOrError r = scene_from_json(follow_scene());
  ASSERT_TRUE(std::holds_alternative<Scene>(r));
  const OrbitRequest& request = *std::get<Scene>(r).periodic_orbit;
  ASSERT_TRUE(request.follow);
  EXPECT_EQ(request.follow->kind, BifurcationKind::period_doubling);
  EXPECT_EQ(request.follow->parameter2, "model.limiters[0].k");
  EXPECT_EQ(request.follow->to, 0.9);
  const json back = orbit_request_to_json(request)["continuation"];
  EXPECT_EQ(back["follow"], "period_doubling");
  EXPECT_EQ(back["parameter2"]["from"], 0.6);

  const std::string c = "periodic_orbit.continuation.";
  const auto without = [](const char* key) {
    json s = follow_scene();
    s["periodic_orbit"]["continuation"].erase(key);
    return s;
  };
  EXPECT_EQ(field_of(without("parameter2")), c + "parameter2");
  EXPECT_EQ(field_of(without("follow")), c + "follow");
  struct Case {
    const char* pointer;
    json value;
    std::string field;
  };
  const std::vector<Case> cases = {
      {"/follow", "neimark_sacker", c + "follow"},
      {"/follow", "cusp", c + "follow"},
      {"/follow", 1, c + "follow"},
      {"/parameter2", 0.5, c + "parameter2"},
      {"/parameter2/parameter", "model.pellets[0].Omega", c + "parameter2.parameter"},
      {"/parameter2/parameter", "model.limiters[3].k", c + "parameter2.parameter"},
      {"/parameter2/parameter", nullptr, c + "parameter2.parameter"},
      {"/parameter2/from", nullptr, c + "parameter2.from"},
      {"/parameter2/from", 0.85, c + "parameter2.from"},
      {"/parameter2/to", 1.5, c + "parameter2.to"},
      {"/parameter2/to", 0.5, c + "parameter2.to"},
      {"/parameter2/count", 10, c + "parameter2.count"},
  };
  for (const Case& k : cases) {
    json s = follow_scene();
    s["periodic_orbit"]["continuation"][json::json_pointer(k.pointer)] = k.value;
    EXPECT_EQ(field_of(s), k.field) << k.pointer << " = " << k.value.dump();
  }
}

TEST(OrbitJson, CurvesAreInTheResultOnlyWhenFollowed) {
  OrbitResult r = synthetic_result();
  EXPECT_FALSE(orbit_result_json(r).contains("curves"));
  r.curves = {{BifurcationKind::grazing, {{0.1, 2.5}, {0.2, NAN}}, true, false, "lost"}};
  const json j = orbit_result_json(r);
  ASSERT_EQ(j["curves"].size(), 1u);
  EXPECT_EQ(j["curves"][0]["kind"], "grazing");
  EXPECT_EQ(j["curves"][0]["points"][0], (json{{"value", 0.1}, {"value2", 2.5}}));
  EXPECT_TRUE(j["curves"][0]["points"][1]["value2"].is_null());
  EXPECT_EQ(j["curves"][0]["message"], "lost");
}

}  // namespace
}  // namespace vibro
