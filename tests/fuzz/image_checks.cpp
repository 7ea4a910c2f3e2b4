#include "tests/fuzz/image_checks.h"

#include <cctype>
#include <cmath>
#include <string_view>

#include "tests/render/png_decode.h"
#include "tests/render/svg_check.h"

namespace vibro::fuzz {
namespace {

std::string_view text_of(const std::vector<std::uint8_t>& bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

// The text without the whitespace that may follow its last line.
std::string_view trimmed(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    text.remove_suffix(1);
  return text;
}

std::string size_text(int width, int height) {
  return std::to_string(width) + "×" + std::to_string(height);
}

// Decoded by cairo's reader (libpng: every chunk's CRC and the zlib stream checked).
std::string png_defect(const RenderResult& image, int width, int height) {
  constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
  if (!text_of(image.bytes).starts_with(kSignature)) return "no PNG signature";
  const testing::Decoded decoded = testing::decode_png(image.bytes);
  if (decoded.argb.empty()) return "the PNG does not decode";
  if (decoded.width != width || decoded.height != height)
    return "the PNG is " + size_text(decoded.width, decoded.height) + ", not " +
           size_text(width, height);
  return {};
}

std::string svg_defect(const RenderResult& image, int width) {
  const std::string text(text_of(image.bytes));
  if (!trimmed(text).ends_with("</svg>")) return "the SVG does not end with </svg>";
  if (const std::string e = testing::xml_balance_error(text); !e.empty()) return "SVG: " + e;
  if (text.find("width=\"" + std::to_string(width)) == std::string::npos)
    return "the SVG does not say its width";
  return {};
}

std::string pdf_defect(const RenderResult& image) {
  const std::string_view text = text_of(image.bytes);
  if (!text.starts_with("%PDF-")) return "no %PDF- header";
  if (!trimmed(text).ends_with("%%EOF")) return "the PDF does not end with %%EOF";
  if (text.find("startxref") == std::string_view::npos) return "the PDF has no startxref";
  return {};
}

std::string axes_defect(const RenderResult& image, int width, int height) {
  for (const PlotAxes& a : image.plot_axes) {
    for (double v : {a.left, a.top, a.width, a.height, a.x_lo, a.x_hi, a.y_lo, a.y_hi})
      if (!std::isfinite(v)) return "a plot's axes hold a number that is not finite";
    if (a.left < 0 || a.top < 0 || a.left + a.width > width || a.top + a.height > height)
      return "a plot area (left " + std::to_string(a.left) + ", top " + std::to_string(a.top) +
             ", " + std::to_string(a.width) + " × " + std::to_string(a.height) +
             ") reaches past the " + size_text(width, height) + " image";
    if (!(a.x_lo < a.x_hi) || !(a.y_lo < a.y_hi))
      return "a plot's axes span nothing: x " + std::to_string(a.x_lo) + " to " +
             std::to_string(a.x_hi) + ", y " + std::to_string(a.y_lo) + " to " +
             std::to_string(a.y_hi);
  }
  return {};
}

}  // namespace

std::string image_defect(const RenderResult& image, ImageFormat format, int width, int height) {
  if (image.bytes.empty()) return "no bytes";
  if (image.content_type != content_type(format)) return "content type " + image.content_type;
  std::string defect;
  switch (format) {
    case ImageFormat::png:
      defect = png_defect(image, width, height);
      break;
    case ImageFormat::svg:
      defect = svg_defect(image, width);
      break;
    case ImageFormat::pdf:
      defect = pdf_defect(image);
      break;
  }
  return defect.empty() ? axes_defect(image, width, height) : defect;
}

}  // namespace vibro::fuzz
