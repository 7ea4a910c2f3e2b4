#include "render/limiter_lines.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "render/text.h"

namespace vibro::render {

std::vector<LimiterLine> limiter_lines(const Model& model, Range angles) {
  std::vector<LimiterLine> lines;
  if (angles.empty()) return lines;
  for (int i = 0; i < static_cast<int>(model.limiters.size()); ++i) {
    const Limiter& l = model.limiters[i];
    const long first = static_cast<long>(std::ceil((angles.lo - l.angle) / kTwoPi));
    const long last = static_cast<long>(std::floor((angles.hi - l.angle) / kTwoPi));
    for (long n = first; n <= last && n - first < 64; ++n)
      lines.push_back({l.angle + n * kTwoPi, i, l.mobile});
  }
  std::sort(lines.begin(), lines.end(),
            [](const LimiterLine& a, const LimiterLine& b) { return a.angle < b.angle; });
  return lines;
}

std::vector<std::string> limiter_label_choices(const LimiterLine& line) {
  const std::string number = std::to_string(line.limiter + 1);
  std::vector<std::string> choices;
  if (line.mobile) choices.push_back("limiter " + number + " (mobile)");
  choices.push_back("limiter " + number);
  choices.push_back(number);
  return choices;
}

void draw_limiter_lines(cairo_t* cr, const Transform& tr, const std::vector<LimiterLine>& lines,
                        Orientation orientation, const Style& style) {
  const Rect& a = tr.area();
  const double dash[] = {style.px(6.0), style.px(4.0)};
  set_colour(cr, kMutedInk);
  cairo_set_line_width(cr, style.thin_width());
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  for (bool mobile : {false, true}) {
    cairo_set_dash(cr, dash, mobile ? 2 : 0, 0.0);
    for (const LimiterLine& line : lines) {
      if (line.mobile != mobile) continue;
      if (orientation == Orientation::vertical) {
        const double x = std::floor(tr.px(line.angle)) + 0.5;
        cairo_move_to(cr, x, a.y);
        cairo_line_to(cr, x, a.bottom());
      } else {
        const double y = std::floor(tr.py(line.angle)) + 0.5;
        cairo_move_to(cr, a.x, y);
        cairo_line_to(cr, a.right(), y);
      }
    }
    cairo_stroke(cr);
  }
  cairo_set_dash(cr, nullptr, 0, 0.0);
}

std::vector<Rect> draw_limiter_labels(cairo_t* cr, const Transform& tr,
                                      const std::vector<LimiterLine>& lines,
                                      Orientation orientation, const Style& style,
                                      const Obstacles& data) {
  const Rect& a = tr.area();
  const double gap = style.px(4.0);
  const bool vertical = orientation == Orientation::vertical;
  set_font(cr, style.note_font());
  // A box may not cross another limiter's line, leave the plot, or cover a placed label.
  std::vector<Rect> placed;
  const auto free = [&](const Rect& box, const LimiterLine& own) {
    if (box.x < a.x || box.right() > a.right() || box.y < a.y || box.bottom() > a.bottom())
      return false;
    for (const LimiterLine& other : lines) {
      if (&other == &own) continue;
      const double at = vertical ? tr.px(other.angle) : tr.py(other.angle);
      if (vertical ? (at > box.x && at < box.right()) : (at > box.y && at < box.bottom()))
        return false;
    }
    const auto covers = [&](const Rect& r) { return r.overlaps(box); };
    const auto crosses = [&](const std::vector<Point>& curve) {
      return length_inside(box, curve) > 0.0;
    };
    return std::none_of(placed.begin(), placed.end(), covers) &&
           std::none_of(data.boxes.begin(), data.boxes.end(), covers) &&
           std::none_of(data.lines.begin(), data.lines.end(), crosses);
  };
  for (const LimiterLine& line : lines) {
    // Beside a vertical line, right then left, from its top down in steps of a line of text
    // until a place is free of the data; above a horizontal one at the right end, then below.
    const double x = tr.px(line.angle), y = tr.py(line.angle);
    using Spot = std::pair<Point, TextAlign>;
    std::vector<Spot> spots;
    if (vertical) {
      const double step = 1.4 * style.note_font();
      for (double top = a.y + gap; top + step <= a.bottom(); top += step)
        for (double side : {1.0, -1.0})
          spots.push_back(
              {{x + side * gap, top}, {side > 0 ? HAlign::left : HAlign::right, VAlign::top}});
    } else {
      spots = {{{a.right() - gap, y - 0.5 * gap}, {HAlign::right, VAlign::bottom}},
               {{a.right() - gap, y + 0.5 * gap}, {HAlign::right, VAlign::top}}};
    }
    bool done = false;
    for (const std::string& label : limiter_label_choices(line)) {
      for (const auto& [at, align] : spots) {
        const Rect box = text_box(cr, label, at, align);
        if (!free(box, line)) continue;
        draw_text_on_backdrop(cr, label, at, align, kMutedInk, style.px(2.0));
        placed.push_back(box);
        done = true;
        break;
      }
      if (done) break;
    }
  }
  return placed;
}

}  // namespace vibro::render
