#include "render/text.h"

namespace vibro::render {
namespace {

// Offset from the anchor to the start of the baseline, for text of these extents.
Point origin_offset(const cairo_text_extents_t& te, const cairo_font_extents_t& fe,
                    TextAlign align) {
  const double dx = align.h == HAlign::left     ? 0.0
                    : align.h == HAlign::center ? -0.5 * te.x_advance
                                                : -te.x_advance;
  // Vertical placement from the font's ascent and descent, not the ink, so that labels of one
  // row share a baseline whatever their letters.
  double dy = 0.0;
  switch (align.v) {
    case VAlign::top:
      dy = fe.ascent;
      break;
    case VAlign::middle:
      dy = 0.5 * (fe.ascent - fe.descent);
      break;
    case VAlign::baseline:
      dy = 0.0;
      break;
    case VAlign::bottom:
      dy = -fe.descent;
      break;
  }
  return {dx, dy};
}

const cairo_user_data_key_t kSinkKey{};

std::vector<PlacedText>* sink_of(cairo_t* cr) {
  return static_cast<std::vector<PlacedText>*>(cairo_get_user_data(cr, &kSinkKey));
}

}  // namespace

void collect_text(cairo_t* cr, std::vector<PlacedText>* sink) {
  cairo_set_user_data(cr, &kSinkKey, sink, nullptr);
}

void set_font(cairo_t* cr, double size_px) {
  cairo_select_font_face(cr, kFontFamily, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size_px);
}

void set_colour(cairo_t* cr, Colour c) { cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a); }

Rect text_box(cairo_t* cr, const std::string& text, Point at, TextAlign align) {
  cairo_text_extents_t te;
  cairo_text_extents(cr, text.c_str(), &te);
  cairo_font_extents_t fe;
  cairo_font_extents(cr, &fe);
  const Point o = origin_offset(te, fe, align);
  const double baseline = at.y + o.y;
  return {at.x + o.x, baseline - fe.ascent, te.x_advance, fe.ascent + fe.descent};
}

void draw_text(cairo_t* cr, const std::string& text, Point at, TextAlign align, Colour colour,
               double angle) {
  cairo_text_extents_t te;
  cairo_text_extents(cr, text.c_str(), &te);
  cairo_font_extents_t fe;
  cairo_font_extents(cr, &fe);
  const Point o = origin_offset(te, fe, align);
  if (auto* sink = sink_of(cr)) {
    double x = at.x, y = at.y, unit = 1.0, zero = 0.0;
    cairo_user_to_device(cr, &x, &y);
    cairo_user_to_device_distance(cr, &unit, &zero);
    cairo_matrix_t font;
    cairo_get_font_matrix(cr, &font);
    sink->push_back({text, {x, y}, o.y * unit, align.h, font.xx * unit, colour, angle});
    return;
  }
  set_colour(cr, colour);
  if (angle == 0.0) {
    cairo_move_to(cr, at.x + o.x, at.y + o.y);
    cairo_show_text(cr, text.c_str());
    return;
  }
  cairo_save(cr);
  cairo_translate(cr, at.x, at.y);
  cairo_rotate(cr, angle);
  cairo_move_to(cr, o.x, o.y);
  cairo_show_text(cr, text.c_str());
  cairo_restore(cr);
}

void draw_text_on_backdrop(cairo_t* cr, const std::string& text, Point at, TextAlign align,
                           Colour colour, double pad_px) {
  const Rect box = text_box(cr, text, at, align);
  cairo_rectangle(cr, box.x - pad_px, box.y, box.w + 2.0 * pad_px, box.h);
  set_colour(cr, rgb(0xFFFFFF, 0.8));
  cairo_fill(cr);
  draw_text(cr, text, at, align, colour);
}

}  // namespace vibro::render
