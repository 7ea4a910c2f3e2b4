// A gallery of figures, one per kind of panel and layout, from the paper scene and a synthetic
// run. Every figure must render; with VIBRO_RENDER_OUT=dir set they are also written there
// (dir/vibro_<name>.png and .svg) to be looked at.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "core/analysis/checked_run.h"
#include "paper_scene.h"
#include "render/figure.h"
#include "synthetic_run.h"

namespace vibro {
namespace {

struct GalleryFigure {
  std::string name;
  FigureSpec figure;
  bool synthetic = false;
};

PhasePlot phase(int pellet) {
  PhasePlot p;
  p.pellet = pellet;
  return p;
}

TimePlot time(std::vector<int> pellets, bool show_dphi) {
  TimePlot p;
  p.pellets = std::move(pellets);
  p.show_dphi = show_dphi;
  return p;
}

MechanismPlot mechanism(double t) {
  MechanismPlot p;
  p.t = t;
  return p;
}

std::vector<GalleryFigure> gallery() {
  std::vector<GalleryFigure> figures;
  PhasePlot zone = phase(0);
  zone.friction_zone = true;
  figures.push_back({"paper_phase", {{zone}, 1200, 800}});
  figures.push_back({"paper_phase_time", {{phase(0), time({0, 1}, false)}, 1200, 800}});
  figures.push_back({"paper_time_dphi", {{time({0, 1}, true)}, 1200, 800}});
  CylinderPlot cylinder;
  figures.push_back(
      {"paper_four", {{phase(0), phase(1), time({0, 1}, false), cylinder}, 1400, 1000}});
  PhasePlot window = phase(1);
  window.t_from = 2.0;
  window.t_to = 6.0;
  figures.push_back({"paper_window_thumb", {{window}, 480, 340}});
  PhasePlot overlay = phase(0);
  overlay.first_integral_through = PhasePoint{0.2, 9.0};
  overlay.friction_zone = true;
  figures.push_back({"synthetic_overlay", {{overlay, time({0, 1}, true)}, 1200, 800}, true});
  figures.push_back({"paper_mechanism", {{mechanism(0.0), mechanism(12.0)}, 1200, 640}});
  figures.push_back({"synthetic_mechanism_thumb", {{mechanism(3.0)}, 480, 340}, true});
  return figures;
}

void write(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

bool has_cylinder(const FigureSpec& f) {
  for (const PlotSpec& p : f.plots)
    if (std::holds_alternative<CylinderPlot>(p)) return true;
  return false;
}

TEST(Gallery, EveryFigureRenders) {
  const Model paper = testing::paper_model();
  const RunResult paper_run = simulate(paper, testing::paper_options());
  const Model synthetic = testing::synthetic_model();
  const RunResult synthetic_run = testing::synthetic_run(synthetic, 8.0);
  const char* out = std::getenv("VIBRO_RENDER_OUT");
  for (const GalleryFigure& g : gallery()) {
    const Model& model = g.synthetic ? synthetic : paper;
    const RunResult& run = g.synthetic ? synthetic_run : paper_run;
    for (ImageFormat format : {ImageFormat::png, ImageFormat::svg}) {
      if (format == ImageFormat::svg && has_cylinder(g.figure)) continue;
      if (has_cylinder(g.figure) && !cylinder_panels_available()) continue;
      const RenderResult result = render_figure(g.figure, model, run, format);
      ASSERT_TRUE(result.ok()) << g.name << ": " << result.error->field << ": "
                               << result.error->message;
      if (out)
        write(
            std::string(out) + "/vibro_" + g.name + (format == ImageFormat::png ? ".png" : ".svg"),
            result.bytes);
    }
  }
}

}  // namespace
}  // namespace vibro
