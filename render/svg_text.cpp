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

}  // namespace vibro::render
