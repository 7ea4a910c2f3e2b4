// Legends never cover data: in a small figure, where every corner of a phase portrait holds a
// curve or a mark, its legend is drawn beside or above the plot, outside the plot area the
// figure reports (RenderResult::plot_axes).
#include <gtest/gtest.h>

#include <string>

#include "core/analysis/checked_run.h"
#include "paper_scene.h"
#include "render/figure.h"

namespace vibro {
namespace {

// The anchor of every <text> element whose content is `label`: render/svg_text.h writes each as
// transform="translate(x y) ...".
std::vector<std::pair<double, double>> text_positions(const std::string& svg,
                                                      const std::string& label) {
  std::vector<std::pair<double, double>> at;
  for (std::size_t p = svg.find("<text"); p != std::string::npos; p = svg.find("<text", p + 1)) {
    const std::size_t close = svg.find('>', p), end = svg.find("</text>", p);
    if (svg.substr(close + 1, end - close - 1) != label) continue;
    const std::size_t t = svg.find("translate(", p) + std::string("translate(").size();
    const std::size_t space = svg.find(' ', t);
    at.push_back({std::stod(svg.substr(t, space - t)), std::stod(svg.substr(space + 1))});
  }
  return at;
}

TEST(LegendRoom, InASmallFigureThePortraitsLegendsStayOutOfTheirPlots) {
  const Model model = testing::paper_model();
  const RunResult run = simulate(model, testing::paper_options());
  FigureSpec figure;
  PhasePlot a, b;
  b.pellet = 1;
  figure.plots = {a, b};
  figure.width = 600;
  figure.height = 300;
  const RenderResult svg = render_figure(figure, model, run, ImageFormat::svg);
  ASSERT_TRUE(svg.ok()) << svg.error->message;
  ASSERT_EQ(svg.plot_axes.size(), 2u);
  const std::string text(svg.bytes.begin(), svg.bytes.end());
  const auto labels = text_positions(text, "limiter impact");
  ASSERT_EQ(labels.size(), 2u);
  for (const auto& [x, y] : labels) {
    for (const PlotAxes& p : svg.plot_axes) {
      const bool inside =
          x >= p.left && x <= p.left + p.width && y >= p.top && y <= p.top + p.height;
      EXPECT_FALSE(inside) << "a legend label at (" << x << ", " << y
                           << ") inside the plot of pellet " << p.pellet + 1;
    }
  }
  // At the full size the same legends fit in a free corner: inside their plots.
  figure.width = 1200;
  figure.height = 800;
  const RenderResult large = render_figure(figure, model, run, ImageFormat::svg);
  const std::string large_text(large.bytes.begin(), large.bytes.end());
  int inside = 0;
  for (const auto& [x, y] : text_positions(large_text, "limiter impact"))
    for (const PlotAxes& p : large.plot_axes)
      inside += x >= p.left && x <= p.left + p.width && y >= p.top && y <= p.top + p.height;
  EXPECT_GE(inside, 1);
}

}  // namespace
}  // namespace vibro
