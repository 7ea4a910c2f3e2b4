// Scene reading: every kind of bad scene is answered with its field named; presets parse; the
// canonical form is stable.
#include "io/scene_json.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/presets.h"

namespace vibro {
namespace {

using nlohmann::json;

json base_scene() {
  return json::parse(R"({
    "model": {"R": 0.5, "alpha0": 0.05,
              "pellets": [{"m": 0.2, "phi0": 0.1, "dphi0": 1.0}, {"m": 0.3, "phi0": -0.2}],
              "limiters": [{"angle": 0.7, "k": 0.5, "mobile": true, "rearm_by": 1},
                           {"angle": -0.7, "k": 0.5}]},
    "t_end": 2.0,
    "plots": [{"kind": "phase", "pellet": 0}, {"kind": "time", "pellets": [0, 1]}]
  })");
}

std::string field_of(const json& scene) {
  const SceneOrError r = scene_from_json(scene);
  if (const FieldError* e = std::get_if<FieldError>(&r)) return e->field;
  return "(accepted)";
}

struct BadCase {
  std::string what;
  json::json_pointer pointer;
  json value;
  std::string field;
};

TEST(SceneJson, TheBaseSceneIsAccepted) { EXPECT_EQ(field_of(base_scene()), "(accepted)"); }

TEST(SceneJson, EveryBadFieldIsNamed) {
  const std::vector<BadCase> cases = {
      {"R zero", json::json_pointer("/model/R"), 0.0, "model.R"},
      {"R negative", json::json_pointer("/model/R"), -1.0, "model.R"},
      {"R a string", json::json_pointer("/model/R"), "half", "model.R"},
      {"alpha0 too big", json::json_pointer("/model/alpha0"), 1.6, "model.alpha0"},
      {"alpha0 negative", json::json_pointer("/model/alpha0"), -0.1, "model.alpha0"},
      {"mu_s below mu", json::json_pointer("/model/mu_s"), 0.01, "model.mu_s"},
      {"g negative", json::json_pointer("/model/g"), -9.81, "model.g"},
      {"k_c over 1", json::json_pointer("/model/k_c"), 1.5, "model.k_c"},
      {"friction unknown", json::json_pointer("/model/friction"), "sticky", "model.friction"},
      {"mass zero", json::json_pointer("/model/pellets/1/m"), 0.0, "model.pellets[1].m"},
      {"mass missing", json::json_pointer("/model/pellets/1"), json{{"phi0", 0.3}},
       "model.pellets[1].m"},
      {"phi0 a bool", json::json_pointer("/model/pellets/0/phi0"), true, "model.pellets[0].phi0"},
      {"dphi0 huge", json::json_pointer("/model/pellets/0/dphi0"), 1e300, "model.pellets[0].dphi0"},
      {"damping negative", json::json_pointer("/model/pellets/1/c"), -0.5, "model.pellets[1].c"},
      {"damping a string", json::json_pointer("/model/pellets/0/c"), "none", "model.pellets[0].c"},
      {"pellets coincide", json::json_pointer("/model/pellets/1/phi0"), 0.1 + 6.283185307179586,
       "model.pellets[1].phi0"},
      {"no pellets", json::json_pointer("/model/pellets"), json::array(), "model.pellets"},
      {"nine pellets", json::json_pointer("/model/pellets"),
       json(std::vector<json>(9, json{{"m", 1}, {"phi0", 0}})), "model.pellets"},
      {"pellet not an object", json::json_pointer("/model/pellets/0"), 3, "model.pellets[0]"},
      {"k over 1", json::json_pointer("/model/limiters/1/k"), 2.0, "model.limiters[1].k"},
      {"angle missing", json::json_pointer("/model/limiters/1"), json{{"k", 0.5}},
       "model.limiters[1].angle"},
      {"rearm_by out of range", json::json_pointer("/model/limiters/0/rearm_by"), 5,
       "model.limiters[0].rearm_by"},
      {"rearm_by itself", json::json_pointer("/model/limiters/0/rearm_by"), 0,
       "model.limiters[0].rearm_by"},
      {"limiters coincide", json::json_pointer("/model/limiters/1/angle"), 0.7 - 6.283185307179586,
       "model.limiters[1].angle"},
      {"limiter pellets out of range", json::json_pointer("/model/limiters/1/pellets"), json{0, 4},
       "model.limiters[1].pellets[1]"},
      {"t_end zero", json::json_pointer("/t_end"), 0.0, "t_end"},
      {"t_end huge", json::json_pointer("/t_end"), 1e9, "t_end"},
      {"t_end a string", json::json_pointer("/t_end"), "10", "t_end"},
      {"method unknown", json::json_pointer("/solver"), json{{"method", "euler"}}, "solver.method"},
      {"rtol too small", json::json_pointer("/solver"), json{{"rtol", 1e-20}}, "solver.rtol"},
      {"atol negative", json::json_pointer("/solver"), json{{"atol", -1.0}}, "solver.atol"},
      {"plot kind unknown", json::json_pointer("/plots/0/kind"), "polar", "plots[0].kind"},
      {"plot pellet out of range", json::json_pointer("/plots/0/pellet"), 2, "plots[0].pellet"},
      {"plot pellets out of range", json::json_pointer("/plots/1/pellets"), json{0, 7},
       "plots[1].pellets[1]"},
      {"plot window empty", json::json_pointer("/plots/0/t_to"), -1.0, "plots[0].t_to"},
      {"plot branch zero", json::json_pointer("/plots/0/branches"), json{0},
       "plots[0].branches[0]"},
      {"phi_range reversed", json::json_pointer("/plots/0/phi_range"), json{1.0, 0.0},
       "plots[0].phi_range"},
      {"dphi_range one number", json::json_pointer("/plots/1/dphi_range"), json{1.0},
       "plots[1].dphi_range"},
      {"phi_range a string", json::json_pointer("/plots/0/phi_range"), json{"a", 1.0},
       "plots[0].phi_range[0]"},
      {"wrap not a boolean", json::json_pointer("/plots/0/wrap"), 1, "plots[0].wrap"},
      {"width zero", json::json_pointer("/width"), 0, "width"},
      {"height over the limit", json::json_pointer("/height"), 100000, "height"},
      {"width fractional", json::json_pointer("/width"), 100.5, "width"},
      {"typo in a key", json::json_pointer("/model/alpah0"), 0.1, "model.alpah0"},
      {"typo in a pellet key", json::json_pointer("/model/pellets/0/dphi"), 0.1,
       "model.pellets[0].dphi"},
      {"unknown top-level key", json::json_pointer("/tend"), 3, "tend"},
  };
  for (const BadCase& c : cases) {
    json scene = base_scene();
    scene[c.pointer] = c.value;
    EXPECT_EQ(field_of(scene), c.field) << c.what;
  }
}

// Limiters at one angle are refused only when both stop some pellet: which one it strikes would
// depend on their order in the list.
TEST(SceneJson, LimitersAtOneAngleMustStopDifferentPellets) {
  json scene = base_scene();
  scene["model"]["limiters"][1] = {{"angle", 0.7}, {"k", 0.9}, {"pellets", {1}}};
  EXPECT_EQ(field_of(scene), "model.limiters[1].angle");
  // Prose counts from 1, as the figures and the event table do; JSON paths from 0.
  const auto error = std::get<FieldError>(scene_from_json(scene));
  EXPECT_NE(error.message.find("coincides with limiter 1 (model.limiters[0])"), std::string::npos)
      << error.message;
  EXPECT_NE(error.message.find("both stop pellet 2"), std::string::npos) << error.message;
  scene["model"]["limiters"][0]["pellets"] = {0};
  EXPECT_EQ(field_of(scene), "(accepted)");
}

TEST(SceneJson, ATypoSuggestsTheFieldItMeant) {
  json scene = base_scene();
  scene["model"]["alpah0"] = 0.1;
  const SceneOrError r = scene_from_json(scene);
  ASSERT_TRUE(std::holds_alternative<FieldError>(r));
  EXPECT_NE(std::get<FieldError>(r).message.find("alpha0"), std::string::npos);
}

// Of the fields as close to the typo as each other, the first in sorted order is suggested,
// whatever order the reader asks for them in ("x" is one edit from both "m" and "c").
TEST(SceneJson, ATypoCloseToTwoFieldsSuggestsTheFirstInSortedOrder) {
  json scene = base_scene();
  scene["model"]["pellets"][0]["x"] = 1.0;
  const SceneOrError r = scene_from_json(scene);
  ASSERT_TRUE(std::holds_alternative<FieldError>(r));
  EXPECT_EQ(std::get<FieldError>(r).field, "model.pellets[0].x");
  EXPECT_EQ(std::get<FieldError>(r).message, "is not a known field here (did you mean \"c\"?)");
}

TEST(SceneJson, TextThatIsNotJsonOrTooDeepIsRefused) {
  auto field = [](std::string_view text) {
    const SceneOrError r = scene_from_text(text);
    return std::holds_alternative<FieldError>(r) ? std::get<FieldError>(r).field : "(accepted)";
  };
  EXPECT_EQ(field("{\"model\": "), "scene");
  EXPECT_EQ(field("[1, 2]"), "scene");
  EXPECT_EQ(field(std::string(100, '[') + std::string(100, ']')), "scene");
  EXPECT_EQ(field(""), "scene");
}

TEST(SceneJson, AnEmptyKeyGivenTwiceIsNamed) {
  // Found by the fuzzer: the empty key twice at the top level was refused with an empty field.
  for (const char* text : {R"({"": 1, "": 2})", R"({"model": {"": {"": 1, "": 2}}})"}) {
    const SceneOrError r = scene_from_text(text);
    ASSERT_TRUE(std::holds_alternative<FieldError>(r)) << text;
    EXPECT_FALSE(std::get<FieldError>(r).field.empty()) << text;
  }
  EXPECT_EQ(std::get<FieldError>(scene_from_text(R"({"": 1, "": 2})")).field, "\"\"");
  EXPECT_EQ(std::get<FieldError>(scene_from_text(R"({"model": {"": {"": 1, "": 2}}})")).field,
            "model.\"\".\"\"");
}

TEST(SceneJson, ASyntaxErrorSaysWhereAndAnOverflowSaysWhat) {
  SceneOrError r = scene_from_text(R"({"model": {"R": 0.5,, }})");
  ASSERT_TRUE(std::holds_alternative<FieldError>(r));
  EXPECT_NE(std::get<FieldError>(r).message.find("at byte 21"), std::string::npos)
      << std::get<FieldError>(r).message;
  r = scene_from_text(R"({"t_end": 1e999})");
  ASSERT_TRUE(std::holds_alternative<FieldError>(r));
  EXPECT_EQ(std::get<FieldError>(r).field, "scene");
  EXPECT_NE(std::get<FieldError>(r).message.find("1e999"), std::string::npos);
}

TEST(SceneJson, EveryPresetParsesAndItsCanonicalFormIsStable) {
  for (const PresetText& p : presets()) {
    const SceneOrError first = scene_from_text(p.json);
    ASSERT_TRUE(std::holds_alternative<Scene>(first))
        << p.name << ": " << std::get<FieldError>(first).field;
    const json canonical = scene_to_json(std::get<Scene>(first));
    const SceneOrError again = scene_from_json(canonical);
    ASSERT_TRUE(std::holds_alternative<Scene>(again)) << p.name;
    EXPECT_EQ(scene_to_json(std::get<Scene>(again)).dump(), canonical.dump()) << p.name;
    EXPECT_EQ(canonical.value("name", ""), std::string(p.name));
  }
}

// A plot's axis limits, wrap and labels survive the canonical form.
TEST(SceneJson, APlotsAxesWrapAndLabelsAreKept) {
  json scene = base_scene();
  scene["plots"][0]["phi_range"] = {-1.5, 2.0};
  scene["plots"][0]["wrap"] = true;
  scene["plots"][0]["labels"] = false;
  scene["plots"][1]["dphi_range"] = {-3.0, 3.0};
  const SceneOrError read = scene_from_json(scene);
  ASSERT_TRUE(std::holds_alternative<Scene>(read));
  const json canonical = scene_to_json(std::get<Scene>(read));
  EXPECT_EQ(canonical["plots"][0]["phi_range"], json({-1.5, 2.0}));
  EXPECT_EQ(canonical["plots"][0]["wrap"], true);
  EXPECT_EQ(canonical["plots"][0]["labels"], false);
  EXPECT_EQ(canonical["plots"][1]["dphi_range"], json({-3.0, 3.0}));
}

// A mechanism panel shows one instant of the run, every pellet: a time in [0, t_end], no pellet
// and no window.
TEST(SceneJson, AMechanismPanelReadsItsTimeWithinTheRun) {
  json scene = base_scene();
  scene["plots"][1] = {{"kind", "mechanism"}, {"t", 1.5}};
  const SceneOrError read = scene_from_json(scene);
  ASSERT_TRUE(std::holds_alternative<Scene>(read)) << std::get<FieldError>(read).field;
  const auto* plot = std::get_if<MechanismPlot>(&std::get<Scene>(read).figure.plots[1]);
  ASSERT_NE(plot, nullptr);
  EXPECT_EQ(plot->t, 1.5);
  EXPECT_EQ(scene_to_json(std::get<Scene>(read))["plots"][1],
            json({{"kind", "mechanism"}, {"t", 1.5}}));
  scene["plots"][1].erase("t");
  EXPECT_EQ(std::get<MechanismPlot>(std::get<Scene>(scene_from_json(scene)).figure.plots[1]).t,
            0.0);
  for (const json& bad : {json(-0.1), json(2.5), json("1")}) {
    scene["plots"][1]["t"] = bad;
    EXPECT_EQ(field_of(scene), "plots[1].t") << bad;
  }
  scene["plots"][1] = {{"kind", "mechanism"}, {"pellet", 0}};
  EXPECT_EQ(field_of(scene), "plots[1].pellet");
  scene["plots"][1] = {{"kind", "mechanism"}, {"t_to", 1.0}};
  EXPECT_EQ(field_of(scene), "plots[1].t_to");
}

TEST(SceneJson, ThePaperPresetStatesItsAssumptionsAndComesFirst) {
  ASSERT_FALSE(presets().empty());
  EXPECT_EQ(presets().front().name, "paper");
  const Scene s = std::get<Scene>(scene_from_text(*preset_json("paper")));
  EXPECT_GE(s.assumptions.size(), 2u);
  EXPECT_EQ(s.model.k_c, 1.0);
  EXPECT_EQ(s.model.pellets.size(), 2u);
  EXPECT_TRUE(s.model.limiters[0].mobile);
}

TEST(SceneJson, DefaultsAreThoseOfTheApi) {
  const Scene s = std::get<Scene>(scene_from_json(
      json::parse(R"({"model": {"R": 1, "pellets": [{"m": 1, "phi0": 0}]}, "t_end": 1})")));
  EXPECT_EQ(s.model.g, 9.81);
  EXPECT_EQ(s.model.friction, FrictionLaw::paper);
  EXPECT_EQ(s.model.k_c, 1.0);
  EXPECT_FALSE(s.model.mu_s.has_value());
  EXPECT_EQ(s.model.pellets[0].force.F0, 0.0);
  EXPECT_EQ(s.model.pellets[0].c, 0.0);
  EXPECT_EQ(s.sim.method, Method::automatic);
  EXPECT_EQ(s.sim.rtol, 1e-9);
  EXPECT_EQ(s.sim.atol, 1e-12);
}

TEST(SceneJson, EveryMethodNameIsRead) {
  for (Method m :
       {Method::dopri5, Method::dop853, Method::radau5, Method::automatic, Method::taylor}) {
    const json j = {{"model", {{"R", 1}, {"pellets", {{{"m", 1}, {"phi0", 0}}}}}},
                    {"t_end", 1},
                    {"solver", {{"method", std::string(method_name(m))}}}};
    const SceneOrError r = scene_from_json(j);
    ASSERT_TRUE(std::holds_alternative<Scene>(r)) << method_name(m);
    EXPECT_EQ(std::get<Scene>(r).sim.method, m);
  }
}

// Damping is read, and echoed only where it is set: undamped scenes echo as before.
TEST(SceneJson, DampingIsReadAndEchoedWhereSet) {
  json scene = base_scene();
  scene["model"]["pellets"][0]["c"] = 0.25;
  const Scene s = std::get<Scene>(scene_from_json(scene));
  EXPECT_EQ(s.model.pellets[0].c, 0.25);
  EXPECT_EQ(s.model.pellets[1].c, 0.0);
  const json echoed = scene_to_json(s);
  EXPECT_EQ(echoed["model"]["pellets"][0]["c"], 0.25);
  EXPECT_FALSE(echoed["model"]["pellets"][1].contains("c"));
  EXPECT_EQ(std::get<Scene>(scene_from_json(echoed)).model.pellets[0].c, 0.25);
}

}  // namespace
}  // namespace vibro
