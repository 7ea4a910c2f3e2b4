// The plots of a sweep: the bifurcation diagram, the section, the impact map and the regime map
// draw their points (the series colours appear where the data is), as PNG, well-formed SVG and
// PDF; without a sweep they are refused.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "core/analysis/sweep.h"
#include "png_decode.h"
#include "render/figure.h"
#include "render/layout.h"
#include "svg_check.h"
#include "swept.h"

namespace vibro {
namespace {

using testing::draw;
using testing::figure_of;
using testing::impact_oscillator;
using testing::Swept;

Swept sweep(SectionKind section, bool grid) {
  Swept s;
  s.spec.axis = {"model.pellets[0].Omega", 3.0, 8.0, 12};
  if (grid) s.spec.axis2 = SweepAxis{"model.pellets[0].F0", 0.1, 0.5, 4};
  s.spec.transient = 20;
  s.spec.record = 16;
  s.spec.section = section;
  SimOptions o;
  o.rtol = 1e-8;
  o.atol = 1e-11;
  o.check = false;
  EXPECT_FALSE(validate_sweep(impact_oscillator(), s.spec));
  s.result = run_sweep(impact_oscillator(), o, s.spec, {});
  return s;
}

// The share of the image's pixels in a blue of the first series colour (translucent dots over
// white included): blue well above red. The axes, text and grid are grey.
double share_of_blue(const testing::Decoded& image) {
  long n = 0;
  for (std::uint32_t p : image.argb) {
    const int r = (p >> 16) & 0xff, b = p & 0xff;
    n += b - r > 40 ? 1 : 0;
  }
  return static_cast<double>(n) / static_cast<double>(image.argb.size());
}

TEST(SweepPlots, EachKindDrawsItsPoints) {
  const Swept strobe = sweep(SectionKind::stroboscopic, false);
  const Swept impacts = sweep(SectionKind::impact, false);
  const Swept grid = sweep(SectionKind::stroboscopic, true);
  const struct {
    SweepView kind;
    const Swept* swept;
    double at_least;  // share of pixels in the first series colour
  } cases[] = {{SweepView::bifurcation, &strobe, 2e-4},
               {SweepView::section, &strobe, 2e-4},
               {SweepView::impact_map, &impacts, 2e-4},
               {SweepView::regime_map, &grid, 0.03}};  // cells of period 1 fill part of it
  for (const auto& c : cases) {
    const RenderResult png = draw(c.kind, *c.swept, ImageFormat::png);
    ASSERT_TRUE(png.ok()) << png.error->message;
    const testing::Decoded image = testing::decode_png(png.bytes);
    ASSERT_EQ(image.width, 1200);
    EXPECT_GT(share_of_blue(image), c.at_least) << static_cast<int>(c.kind);
    const RenderResult svg = draw(c.kind, *c.swept, ImageFormat::svg);
    ASSERT_TRUE(svg.ok());
    const std::string text(svg.bytes.begin(), svg.bytes.end());
    EXPECT_EQ(testing::xml_balance_error(text), "") << static_cast<int>(c.kind);
    const RenderResult pdf = draw(c.kind, *c.swept, ImageFormat::pdf);
    ASSERT_TRUE(pdf.ok());
    EXPECT_EQ(pdf.content_type, "application/pdf");
    const std::string doc(pdf.bytes.begin(), pdf.bytes.end());
    EXPECT_TRUE(doc.starts_with("%PDF-")) << static_cast<int>(c.kind);
    EXPECT_NE(doc.rfind("%%EOF"), std::string::npos);
  }
}

// A regime map's every cell is data: the legend sits beside the plot, and neighbouring cells
// meet without seams, so a map of one period is that period's colour everywhere inside its frame.
TEST(SweepPlots, TheRegimeMapsLegendAndSeamsHideNoCell) {
  Swept s;
  s.spec.axis = {"model.pellets[0].Omega", 3.0, 8.0, 37};
  s.spec.axis2 = SweepAxis{"model.pellets[0].F0", 0.1, 0.5, 23};
  for (int j = 0; j < s.spec.axis2->count; ++j)
    for (int i = 0; i < s.spec.axis.count; ++i) {
      SweepRun run;
      run.value = s.spec.axis.value(i);
      run.value2 = s.spec.axis2->value(j);
      run.period = 1;
      s.result.runs.push_back(run);
    }
  const FigureSpec figure = figure_of(SweepView::regime_map);
  const RenderResult png = draw(SweepView::regime_map, s, ImageFormat::png);
  ASSERT_TRUE(png.ok()) << png.error->message;
  const testing::Decoded image = testing::decode_png(png.bytes);
  const render::Rect area = render::figure_layout(figure).front().plots.front();
  const std::uint32_t period_1 = 0xff0072b2;
  long other = 0;
  for (int y = static_cast<int>(area.y) + 2; y < static_cast<int>(area.bottom()) - 2; ++y)
    for (int x = static_cast<int>(area.x) + 2; x < static_cast<int>(area.right()) - 2; ++x)
      other += image.argb[static_cast<std::size_t>(y) * image.width + x] != period_1 ? 1 : 0;
  EXPECT_EQ(other, 0);
  // The legend is drawn: the period's swatch right of the plot.
  long swatch = 0;
  for (int y = static_cast<int>(area.y); y < static_cast<int>(area.bottom()); ++y)
    for (int x = static_cast<int>(area.right()) + 4; x < image.width; ++x)
      swatch += image.argb[static_cast<std::size_t>(y) * image.width + x] == period_1 ? 1 : 0;
  EXPECT_GT(swatch, 50);
}

// Periods above 8 share one colour and one legend entry, "period > 8", in a colour of its own:
// the legend listed it once per period above 8, in the grey of "not periodic".
TEST(SweepPlots, TheRegimeMapsLongPeriodsAreOneEntryApartFromNotPeriodic) {
  Swept s;
  s.spec.axis = {"model.pellets[0].Omega", 3.0, 8.0, 4};
  s.spec.axis2 = SweepAxis{"model.pellets[0].F0", 0.1, 0.5, 2};
  const int periods[] = {1, 9, 10, 12, 0, 0, 9, 1};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) {
      SweepRun run;
      run.value = s.spec.axis.value(i);
      run.value2 = s.spec.axis2->value(j);
      run.period = periods[4 * j + i];
      s.result.runs.push_back(run);
    }
  const RenderResult svg = draw(SweepView::regime_map, s, ImageFormat::svg);
  ASSERT_TRUE(svg.ok());
  const std::string text(svg.bytes.begin(), svg.bytes.end());
  EXPECT_EQ(testing::count_of(text, "period &gt; 8"), 1);
  EXPECT_EQ(testing::count_of(text, "not periodic"), 1);

  const RenderResult png = draw(SweepView::regime_map, s, ImageFormat::png);
  ASSERT_TRUE(png.ok());
  const testing::Decoded image = testing::decode_png(png.bytes);
  const render::Rect area =
      render::figure_layout(figure_of(SweepView::regime_map)).front().plots.front();
  std::set<std::uint32_t> colours;
  for (int y = static_cast<int>(area.y) + 2; y < static_cast<int>(area.bottom()) - 2; ++y)
    for (int x = static_cast<int>(area.x) + 2; x < static_cast<int>(area.right()) - 2; ++x)
      colours.insert(image.argb[static_cast<std::size_t>(y) * image.width + x]);
  EXPECT_EQ(colours.size(), 3u);  // period 1, period > 8, not periodic
}

TEST(SweepPlots, WithoutASweepTheyAreRefused) {
  const RenderResult r = render_figure(figure_of(SweepView::bifurcation), impact_oscillator(),
                                       RunResult{}, ImageFormat::png);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->field, "plots[0].kind");
}

}  // namespace
}  // namespace vibro
