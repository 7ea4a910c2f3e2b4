// The work-precision diagram's axes fit its data, and the labels at the lines' ends stay inside
// the plot (which clips): the slowest point's label goes before it, not beside it past the frame.
#include <gtest/gtest.h>

#include <string>

#include "core/analysis/work_precision.h"
#include "render/figure.h"
#include "svg_check.h"
#include "tests/core/impact_oscillator.h"

namespace vibro {
namespace {

// Two methods over 0.35 to 12 ms, dopri5 the slowest at its tightest tolerance.
WorkPrecisionReport report() {
  WorkPrecisionReport r;
  const double dopri5_ms[] = {0.35, 0.6, 1.5, 4.0, 12.0};
  const double dop853_ms[] = {0.4, 0.5, 0.7, 1.0, 1.6};
  for (int k = 0; k < 5; ++k) {
    const double rtol = std::pow(10.0, -3 - 2 * k);
    r.points.push_back({Method::dopri5, rtol, rtol * 1e-2, dopri5_ms[k], rtol * 10.0});
    r.points.push_back({Method::dop853, rtol, rtol * 1e-2, dop853_ms[k], rtol * 3.0});
  }
  return r;
}

TEST(WorkPrecisionPlot, AxesFitTheDataAndEndLabelsStayInside) {
  FigureSpec figure;
  figure.width = 600;  // a twentieth of the axis beyond the last point: less than its label
  figure.plots = {WorkPrecisionPlot{}};
  const WorkPrecisionReport data = report();
  const RenderResult svg =
      render_figure(figure, testing::impact_oscillator(), RunResult{}, ImageFormat::svg, {&data});
  ASSERT_TRUE(svg.ok()) << svg.error->message;
  const std::string text(svg.bytes.begin(), svg.bytes.end());
  // Ticks within 0.35 to 12 ms, not the whole decades 0.1 to 100 around them.
  for (const char* outside : {">0.1<", ">100<", ">10\u207b\u00b9<", ">10\u00b2<"})
    EXPECT_EQ(testing::count_of(text, outside), 0) << outside;
  EXPECT_EQ(testing::count_of(text, ">10\u00b9<") + testing::count_of(text, ">10<"), 1);
  // dopri5's rtol 1e-11 point is the rightmost: its label stands before it, anchored at its end.
  const std::string label = "rtol 10\u207b\u00b9\u00b9</text>";
  const std::size_t at = text.find(label);
  ASSERT_NE(at, std::string::npos);
  const std::size_t open = text.rfind("<text", at);
  EXPECT_NE(text.substr(open, at - open).find("text-anchor=\"end\""), std::string::npos)
      << text.substr(open, at - open);
}

}  // namespace
}  // namespace vibro
