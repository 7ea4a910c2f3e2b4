// What lies far outside a plot's axes is drawn near them or not at all (issue 31's render
// fuzzer). A phase portrait whose φ̇ range was far narrower than its velocity jumps stroked each
// jump, dashed, to points millions of pixels off the image: cairo's vector surfaces work through
// every dash of such a line (a 780-byte scene asked for 0.9 GB and got "out of memory" for its SVG
// and PDF), and past 2²³ px its fixed-point coordinates wrap, which can bring an impact marker
// back into view at the wrong place.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "render/figure.h"
#include "synthetic_run.h"

namespace vibro {
namespace {

// The largest magnitude of any number in the path data (d="...") of an SVG.
double largest_path_coordinate(const std::string& svg) {
  double largest = 0.0;
  for (std::size_t at = svg.find(" d=\""); at != std::string::npos; at = svg.find(" d=\"", at)) {
    const std::size_t end = svg.find('"', at + 4);
    const std::string data = svg.substr(at + 4, end - at - 4);
    for (const char* p = data.c_str(); *p;) {
      char* next = nullptr;
      const double v = std::strtod(p, &next);
      if (next == p) {
        ++p;
        continue;
      }
      largest = std::max(largest, std::abs(v));
      p = next;
    }
    at = end;
  }
  return largest;
}

// The synthetic run's limiter impacts reverse pellet 1's φ̇ (8.1 → −4.9 rad/s at 0.068 s): its
// jumps cross φ̇ = 0, through a range of 0.01 rad/s, hundreds of plot heights long.
TEST(FarOutside, ANarrowRangeDrawsNothingFarOffTheImage) {
  const Model model = testing::synthetic_model();
  const RunResult run = testing::synthetic_run(model, 10.0);
  PhasePlot plot;
  plot.dphi_range = AxisLimits{0.0, 0.01};
  const int width = 800, height = 600;
  const RenderResult svg = render_figure({{plot}, width, height}, model, run, ImageFormat::svg);
  ASSERT_TRUE(svg.ok()) << svg.error->message;
  // Curves and jumps are clamped to four times the plot's size beyond its edges.
  EXPECT_LT(largest_path_coordinate(std::string(svg.bytes.begin(), svg.bytes.end())),
            6.0 * std::max(width, height));
}

}  // namespace
}  // namespace vibro
