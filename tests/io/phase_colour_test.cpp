// A phase portrait's "colour": "branch" (the default), "one" or "time" (long steady-state runs),
// read strictly and written back; another value is refused naming the field.
#include <gtest/gtest.h>

#include "io/presets.h"
#include "io/scene_json.h"

namespace vibro {
namespace {

using nlohmann::json;

std::variant<Scene, FieldError> with_colour(const json& colour) {
  json scene = json::parse(*preset_json("impact-oscillator"));
  scene["plots"] = json::array({{{"kind", "phase"}, {"pellet", 0}, {"colour", colour}}});
  return scene_from_text(scene.dump());
}

TEST(PhaseColour, ReadStrictlyAndWrittenBack) {
  const Scene timed = std::get<Scene>(with_colour("time"));
  EXPECT_EQ(std::get<PhasePlot>(timed.figure.plots[0]).colours, PhaseColours::time);
  EXPECT_EQ(scene_to_json(timed)["plots"][0]["colour"], "time");
  const Scene one = std::get<Scene>(with_colour("one"));
  EXPECT_EQ(std::get<PhasePlot>(one.figure.plots[0]).colours, PhaseColours::one);
  for (const json& wrong : {json("teal"), json(1)}) {
    const auto read = with_colour(wrong);
    ASSERT_TRUE(std::holds_alternative<FieldError>(read)) << wrong;
    EXPECT_EQ(std::get<FieldError>(read).field, "plots[0].colour");
  }
}

}  // namespace
}  // namespace vibro
