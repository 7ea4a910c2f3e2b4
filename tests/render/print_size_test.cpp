// A figure's print size (FigureSpec::print): PNG pixels of width_mm / 25.4 · dpi that say their
// resolution, PDF and SVG pages at the size asked, and text and lines that follow font_pt, not
// the figure's size.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "png_decode.h"
#include "render/figure.h"
#include "render/style.h"
#include "synthetic_run.h"

namespace vibro {
namespace {

FigureSpec printed(double width_mm, double height_mm, double font_pt, double dpi) {
  FigureSpec figure;
  figure.plots = {PhasePlot{}, TimePlot{}};
  figure.print = PrintSize{width_mm, height_mm, font_pt, dpi};
  return figure;  // width and height left at 1200 × 800: the print size sets them
}

std::string drawn(const FigureSpec& figure, ImageFormat format) {
  const Model model = testing::synthetic_model();
  const RunResult run = testing::synthetic_run(model, 6.0);
  const RenderResult r = render_figure(figure, model, run, format);
  EXPECT_TRUE(r.ok()) << (r.error ? r.error->field + ": " + r.error->message : "");
  return {r.bytes.begin(), r.bytes.end()};
}

std::string font_size(double pt, double dpi) {
  char text[64];
  std::snprintf(text, sizeof text, "font-size=\"%.2f\"", pt / 72.0 * dpi);
  return text;
}

TEST(PrintSize, APngHasThePixelsAndSaysItsResolution) {
  const std::string png = drawn(printed(85.0, 60.0, 8.0, 300.0), ImageFormat::png);
  const std::vector<std::uint8_t> bytes(png.begin(), png.end());
  const testing::Decoded image = testing::decode_png(bytes);
  EXPECT_EQ(image.width, 1004);  // 85 / 25.4 · 300 = 1003.9
  EXPECT_EQ(image.height, 709);  // 60 / 25.4 · 300 = 708.7
  // pHYs: 300 dots per inch are 11811 per metre, along x and y, the unit the metre.
  const std::size_t at = png.find("pHYs");
  ASSERT_NE(at, std::string::npos);
  const std::string expected = {0, 0, 0x2e, 0x23, 0, 0, 0x2e, 0x23, 1};
  EXPECT_EQ(png.substr(at + 4, 9), expected);
}

TEST(PrintSize, APdfPageIsTheSizeAsked) {
  const std::string pdf = drawn(printed(85.0, 60.0, 8.0, 300.0), ImageFormat::pdf);
  const std::size_t at = pdf.find("/MediaBox [ 0 0 ");
  ASSERT_NE(at, std::string::npos);
  double w = 0.0, h = 0.0;
  ASSERT_EQ(std::sscanf(pdf.c_str() + at, "/MediaBox [ 0 0 %lf %lf", &w, &h), 2);
  // 85 mm = 240.94 pt and 60 mm = 170.08 pt, to half a dot (0.12 pt at 300 dpi).
  EXPECT_NEAR(w, 85.0 / 25.4 * 72.0, 0.5 * 72.0 / 300.0);
  EXPECT_NEAR(h, 60.0 / 25.4 * 72.0, 0.5 * 72.0 / 300.0);
}

TEST(PrintSize, AnSvgPageIsTheSizeAskedAndItsTextFollowsFontPt) {
  const std::string single = drawn(printed(85.0, 60.0, 8.0, 300.0), ImageFormat::svg);
  EXPECT_NE(single.find("width=\"85.00mm\" height=\"60.00mm\" viewBox=\"0 0 1004 709\""),
            std::string::npos);
  // Tick labels of 8 pt: 33.33 px of the 1004 px that are 85 mm.
  EXPECT_NE(single.find(font_size(8.0, 300.0)), std::string::npos);
  // Twice as wide, the same text size: the text follows font_pt, not the figure.
  const std::string twice = drawn(printed(170.0, 60.0, 8.0, 300.0), ImageFormat::svg);
  EXPECT_NE(twice.find("width=\"170.00mm\""), std::string::npos);
  EXPECT_NE(twice.find(font_size(8.0, 300.0)), std::string::npos);
  const std::string larger = drawn(printed(85.0, 60.0, 10.0, 300.0), ImageFormat::svg);
  EXPECT_NE(larger.find(font_size(10.0, 300.0)), std::string::npos);
  EXPECT_EQ(larger.find(font_size(8.0, 300.0)), std::string::npos);
}

TEST(PrintSize, LinesFollowFontPt) {
  FigureSpec figure = printed(85.0, 60.0, 8.0, 300.0);
  const double scale = render::style_for(figure).scale;
  EXPECT_NEAR(render::style_for(figure).tick_font(), 8.0 / 72.0 * 300.0, 1e-9);
  figure.print->font_pt = 10.0;
  EXPECT_NEAR(render::style_for(figure).curve_width(), 1.25 * 1.5 * scale, 1e-9);
  // Axes space their ticks by their labels' size: an axis of 1000 px with labels of 2.5 times the
  // size of a 1200 × 800 figure's has room for as many labels as one of 400 px there.
  const render::Style print = render::style_for(figure);
  EXPECT_NEAR(print.axis_room(1000.0), 1000.0 / print.scale, 1e-9);
  // The same figure without a print size keeps the style of its pixels, ticks spaced by pixels.
  figure.print.reset();
  EXPECT_EQ(render::style_for(figure).scale, render::style_for(1200, 800).scale);
  EXPECT_EQ(render::style_for(figure).axis_room(1000.0), 1000.0);
}

TEST(PrintSize, ABadPrintSizeIsRefusedNamingItsField) {
  const Model model = testing::synthetic_model();
  const RunResult run = testing::synthetic_run(model, 1.0);
  const RenderResult r =
      render_figure(printed(170.0, 100.0, 8.0, 2000.0), model, run, ImageFormat::png);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->field, "figure.dpi");
  EXPECT_TRUE(r.bytes.empty());
}

}  // namespace
}  // namespace vibro
