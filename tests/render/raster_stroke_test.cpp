// Curves stroked on an image surface where cairo 1.16's fast antialiasing writes past its span
// buffer (issue 31): a pixel row whose coverage changes at every column of the area drawn and is
// not zero at its right edge needs one span more than the tor22 scan converter
// (CAIRO_ANTIALIAS_FAST) allocates. With glibc's allocator an odd width puts that write on the
// next heap chunk's header, and the process aborts ("double free or corruption",
// "corrupted size vs. prev_size"); valgrind reports it at any width. AddressSanitizer does not see
// it: cairo is not instrumented. So the tests also check that the stroke never switches a context
// to the fast mode.
#include <gtest/gtest.h>

#include <vector>

#include "core/analysis/checked_run.h"
#include "png_decode.h"
#include "render/cairo_ptr.h"
#include "render/figure.h"
#include "render/polyline.h"

namespace vibro {
namespace {

using render::Point;

// A vertical zigzag one pixel apart from x = -5 to width + 5: in the rows it crosses, every pixel
// column holds a stroke edge, so each has its own coverage, and the row ends covered.
std::vector<Point> zigzag(int width) {
  std::vector<Point> points;
  for (int i = 0; - 5.0 + i <= width + 5.0; ++i) points.push_back({-5.0 + i, i % 2 ? 80.0 : 20.0});
  return points;
}

TEST(RasterStroke, ARowCoveredAtEveryColumnStrokesOnImagesOfOddWidth) {
  // Widths past the converter's 64 embedded spans, so its span buffer is on the heap.
  for (int width : {65, 301, 325, 1201}) {
    render::SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, 100));
    render::CairoPtr cr(cairo_create(surface.get()));
    cairo_set_line_width(cr.get(), 1.0);
    cairo_set_source_rgb(cr.get(), 0.0, 0.0, 0.0);
    const auto points = zigzag(width);
    render::stroke_polyline(cr.get(), points);
    EXPECT_NE(cairo_get_antialias(cr.get()), CAIRO_ANTIALIAS_FAST) << "width " << width;
    EXPECT_EQ(cairo_status(cr.get()), CAIRO_STATUS_SUCCESS) << "width " << width;
    // Something was drawn: the middle row is not transparent throughout.
    cairo_surface_flush(surface.get());
    const unsigned char* data = cairo_image_surface_get_data(surface.get());
    const int stride = cairo_image_surface_get_stride(surface.get());
    int opaque = 0;
    for (int x = 0; x < width; ++x) opaque += data[50 * stride + 4 * x + 3] > 0;
    EXPECT_GT(opaque, width / 2) << "width " << width;
  }
}

// The scene of issue 31: three pellets, bilateral friction, 500 s; its φ(t) panel is 325 px wide
// and aborted the process (`vibro render` and `vibro serve`) when drawn to PNG.
TEST(RasterStroke, IssueSceneDrawsItsTimePanelToPng) {
  Model model;
  model.R = 0.5;
  model.alpha0 = 0.08;
  model.friction = FrictionLaw::bilateral;
  model.pellets = {Pellet{0.2, 0.3, 5.0, Forcing{1.0, 4.5, 0.0}}, Pellet{0.1, -0.2, 0.0, {}},
                   Pellet{0.3, -0.6, -2.0, {}}};
  model.limiters = {Limiter{1.0, 0.7, false, -1, {}}, Limiter{-1.0, 0.5, false, -1, {}}};
  model.k_c = 0.9;
  SimOptions options;
  options.t_end = 500.0;
  options.check = false;
  options.record = {true, true, true};
  const RunResult run = simulate(model, options);
  ASSERT_EQ(run.stats.termination, Termination::completed);

  PhasePlot phase0, phase2;
  TimePlot time;
  phase2.pellet = 2;
  time.pellets = {0, 1, 2};
  const FigureSpec figure{{phase0, phase2, time}, 1200, 800};
  const RenderResult image = render_figure(figure, model, run, ImageFormat::png);
  ASSERT_TRUE(image.ok()) << image.error->field << ": " << image.error->message;
  const testing::Decoded decoded = testing::decode_png(image.bytes);
  EXPECT_EQ(decoded.width, 1200);
  EXPECT_EQ(decoded.height, 800);
}

}  // namespace
}  // namespace vibro
