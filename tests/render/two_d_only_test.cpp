// A 2-D-only scene must not load or touch OSMesa: this program draws only 2-D panels, in PNG and
// SVG, and then looks for libOSMesa among the process's mappings.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/analysis/checked_run.h"
#include "paper_scene.h"
#include "render/figure.h"
#include "render/gl/offscreen_context.h"

namespace vibro {
namespace {

bool osmesa_mapped() {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line))
    if (line.find("OSMesa") != std::string::npos) return true;
  return false;
}

TEST(TwoDimensionalScene, NeverLoadsOsmesa) {
  const Model model = testing::paper_model();
  const RunResult run = simulate(model, testing::paper_options());
  FigureSpec figure;
  PhasePlot phase;
  TimePlot time;
  figure.plots = {phase, time};
  for (ImageFormat format : {ImageFormat::png, ImageFormat::svg}) {
    const RenderResult image = render_figure(figure, model, run, format);
    ASSERT_TRUE(image.ok()) << image.error->message;
    EXPECT_GT(image.bytes.size(), 1000u);
  }
  EXPECT_FALSE(gl::osmesa_loaded());
  EXPECT_FALSE(osmesa_mapped());
}

}  // namespace
}  // namespace vibro
