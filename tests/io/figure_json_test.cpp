// A scene's print size ("figure": API.md, "Figure size for print"): read with its defaults, its
// pixels set from it, written back, and every bad field named.
#include "io/figure_json.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/scene_json.h"

namespace vibro {
namespace {

using nlohmann::json;

json scene_with(json figure) {
  json scene = json::parse(R"({
    "model": {"R": 0.5, "pellets": [{"m": 0.2, "phi0": 0.1, "dphi0": 1.0}]},
    "t_end": 2.0,
    "plots": [{"kind": "phase", "pellet": 0}],
    "width": 1200, "height": 800
  })");
  scene["figure"] = std::move(figure);
  return scene;
}

std::string field_of(const json& scene, const Limits& limits = {}) {
  const SceneOrError r = scene_from_json(scene, limits);
  if (const FieldError* e = std::get_if<FieldError>(&r)) return e->field;
  return "(accepted)";
}

TEST(FigureJson, APrintSizeSetsThePixelsAndIsWrittenBack) {
  const SceneOrError read = scene_from_json(scene_with({{"width_mm", 85}}));
  ASSERT_TRUE(std::holds_alternative<Scene>(read)) << std::get<FieldError>(read).message;
  const Scene& scene = std::get<Scene>(read);
  ASSERT_TRUE(scene.figure.print);
  const PrintSize& p = *scene.figure.print;
  EXPECT_EQ(p.width_mm, 85.0);
  EXPECT_DOUBLE_EQ(p.height_mm, 85.0 * 2.0 / 3.0);  // two thirds of the width
  EXPECT_EQ(p.font_pt, 8.0);
  EXPECT_EQ(p.dpi, 300.0);
  // 85 mm at 300 dpi: 85 / 25.4 · 300 = 1003.9 px, over the scene's width and height.
  EXPECT_EQ(scene.figure.width, 1004);
  EXPECT_EQ(scene.figure.height, 669);

  const json written = scene_to_json(scene);
  EXPECT_EQ(
      written["figure"],
      (json{
          {"width_mm", 85.0}, {"height_mm", 85.0 * 2.0 / 3.0}, {"font_pt", 8.0}, {"dpi", 300.0}}));
  const SceneOrError again = scene_from_json(written);
  ASSERT_TRUE(std::holds_alternative<Scene>(again));
  EXPECT_EQ(scene_to_json(std::get<Scene>(again)), written);
  // Without a print size the scene keeps its pixels and writes no "figure".
  json plain = scene_with({});
  plain.erase("figure");
  const SceneOrError without = scene_from_json(plain);
  ASSERT_TRUE(std::holds_alternative<Scene>(without));
  EXPECT_FALSE(std::get<Scene>(without).figure.print);
  EXPECT_EQ(std::get<Scene>(without).figure.width, 1200);
  EXPECT_FALSE(scene_to_json(std::get<Scene>(without)).contains("figure"));
}

TEST(FigureJson, EveryBadFieldIsNamed) {
  const struct {
    const char* what;
    json figure;
    const char* field;
  } cases[] = {
      {"not an object", 85, "figure"},
      {"no width", {{"height_mm", 60}}, "figure.width_mm"},
      {"width a string", {{"width_mm", "85mm"}}, "figure.width_mm"},
      {"width below 10 mm", {{"width_mm", 5}}, "figure.width_mm"},
      {"width over 1 m", {{"width_mm", 1200}}, "figure.width_mm"},
      {"height negative", {{"width_mm", 85}, {"height_mm", -60}}, "figure.height_mm"},
      {"font too small", {{"width_mm", 85}, {"font_pt", 2}}, "figure.font_pt"},
      {"font too large", {{"width_mm", 85}, {"font_pt", 100}}, "figure.font_pt"},
      {"dpi too low", {{"width_mm", 85}, {"dpi", 10}}, "figure.dpi"},
      {"a typo", {{"width_mm", 85}, {"dpi_", 300}}, "figure.dpi_"},
      // 170 mm at 1200 dpi: 8031 px, over 4096 a side.
      {"too many pixels", {{"width_mm", 170}, {"dpi", 1200}}, "figure.dpi"},
      // 12 mm at 100 dpi: 47 px, too few for the axes.
      {"too few pixels", {{"width_mm", 12}, {"height_mm", 40}, {"dpi", 100}}, "figure.width_mm"},
  };
  for (const auto& c : cases) EXPECT_EQ(field_of(scene_with(c.figure)), c.field) << c.what;
  // A server's tighter limits hold the pixels too.
  Limits server;
  server.width = server.height = 2100;
  server.pixels = 2100L * 1500L;
  EXPECT_EQ(field_of(scene_with({{"width_mm", 170}, {"dpi", 300}}), server), "(accepted)");
  EXPECT_EQ(field_of(scene_with({{"width_mm", 170}, {"dpi", 600}}), server), "figure.dpi");
}

}  // namespace
}  // namespace vibro
