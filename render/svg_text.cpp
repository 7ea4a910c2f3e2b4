#include "render/svg_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vibro::render {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else
      out += c;
  }
  return out;
}

int channel(double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

}  // namespace

std::string svg_text_elements(const std::vector<PlacedText>& texts) {
  std::string out;
  char head[512];
  for (const PlacedText& t : texts) {
    const char* anchor = t.h == HAlign::left ? "start" : t.h == HAlign::center ? "middle" : "end";
    std::snprintf(head, sizeof head,
                  "<text transform=\"translate(%.2f %.2f) rotate(%.2f)\" x=\"0\" y=\"%.2f\" "
                  "font-family=\"DejaVu Sans, sans-serif\" font-size=\"%.2f\" text-anchor=\"%s\" "
                  "fill=\"rgb(%d,%d,%d)\" fill-opacity=\"%.3f\">",
                  t.at.x, t.at.y, t.angle * 180.0 / M_PI, t.baseline, t.size_px, anchor,
                  channel(t.colour.r), channel(t.colour.g), channel(t.colour.b), t.colour.a);
    out += head;
    out += escaped(t.text);
    out += "</text>\n";
  }
  return out;
}

void append_to_svg(std::vector<std::uint8_t>& svg, const std::string& elements) {
  const std::string end = "</svg>";
  auto at = std::search(svg.rbegin(), svg.rend(), end.rbegin(), end.rend());
  if (at == svg.rend()) return;
  const auto position = at.base() - static_cast<std::ptrdiff_t>(end.size());
  svg.insert(position, elements.begin(), elements.end());
}

namespace {

// Replaces the value of the first attribute `name` in the root element (within its tag).
void set_root_attribute(std::vector<std::uint8_t>& svg, const std::string& name,
                        const std::string& value) {
  const std::string text(svg.begin(), svg.end());
  const std::size_t root = text.find("<svg");
  if (root == std::string::npos) return;
  const std::size_t tag_end = text.find('>', root);
  const std::size_t at = text.find(" " + name + "=\"", root);
  if (at == std::string::npos || at > tag_end) return;
  const std::size_t begin = at + name.size() + 3;
  const std::size_t end = text.find('"', begin);
  if (end == std::string::npos || end > tag_end) return;
  svg.erase(svg.begin() + static_cast<std::ptrdiff_t>(begin),
            svg.begin() + static_cast<std::ptrdiff_t>(end));
  svg.insert(svg.begin() + static_cast<std::ptrdiff_t>(begin), value.begin(), value.end());
}

std::string millimetres(double mm) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2fmm", mm);
  return text;
}

}  // namespace

void set_svg_size_mm(std::vector<std::uint8_t>& svg, double width_mm, double height_mm) {
  set_root_attribute(svg, "width", millimetres(width_mm));
  set_root_attribute(svg, "height", millimetres(height_mm));
}

}  // namespace vibro::render
