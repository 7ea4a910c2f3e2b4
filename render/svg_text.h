// An SVG figure's labels as <text> elements (API.md, "Exports": labels stay text in SVG), so a
// reader can search, select and edit them; cairo's SVG surface would write glyph outlines.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "render/text.h"

namespace vibro::render {

// The labels as SVG <text> elements, in DejaVu Sans (with sans-serif after it).
std::string svg_text_elements(const std::vector<PlacedText>& texts);

// The SVG document with the elements added at its end (before </svg>), drawn over the rest.
void append_to_svg(std::vector<std::uint8_t>& svg, const std::string& elements);

// The root element's width and height set to these, in mm (its view box unchanged): the page a
// reader prints or places at its true size.
void set_svg_size_mm(std::vector<std::uint8_t>& svg, double width_mm, double height_mm);

}  // namespace vibro::render
