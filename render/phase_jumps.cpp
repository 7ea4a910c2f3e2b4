#include "render/phase_jumps.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "render/polyline.h"
#include "render/track_window.h"

namespace vibro::render {
namespace {

// The branch whose span holds t (the latest, where two meet), or null.
const Branch* branch_at(const PelletTrack& track, double t) {
  const Branch* found = nullptr;
  for (const Branch& b : track.branches)
    if (!b.samples.empty() && b.samples.front().t <= t && t <= b.samples.back().t) found = &b;
  return found;
}

}  // namespace

std::vector<Jump> velocity_jumps(const PelletTrack& track, std::span<const Event> events,
                                 const PhasePlot& spec) {
  std::vector<Jump> jumps;
  // Branches that meet without a jump (reversals, sticks) are not impacts.
  for (std::size_t i = 1; i < track.branches.size(); ++i) {
    if (!branch_selected(spec, track.branches[i - 1].index) ||
        !branch_selected(spec, track.branches[i].index))
      continue;
    const auto& prev = track.branches[i - 1].samples;
    const auto& next = track.branches[i].samples;
    if (prev.empty() || next.empty()) continue;
    const Sample& e = prev.back();
    const Sample& s = next.front();
    if (!in_window(e.t, spec) || !in_window(s.t, spec)) continue;
    const bool same_phi = std::abs(e.phi - s.phi) <= 1e-9 * (1.0 + std::abs(e.phi));
    const bool jumped = std::abs(e.dphi - s.dphi) > 1e-9 * (1.0 + std::abs(e.dphi));
    if (!same_phi || !jumped) continue;
    const Event* event = find_impact(events, track.pellet, e.t);
    if (event && event->kind == EventKind::chatter) continue;  // below, from the event itself
    // A jump no listed impact explains (one before the events kept) is drawn, but not called an
    // impact of a kind it may not be.
    jumps.push_back({{e.phi, e.dphi}, {s.phi, s.dphi}, event ? event_mark(event->kind) : nullptr});
  }
  // A chatter sequence: from the speed its summation started from to rest against the limiter.
  for (const Event& e : events) {
    if (e.kind != EventKind::chatter || !in_window(e.t, spec)) continue;
    const auto at = std::find(e.pellets.begin(), e.pellets.end(), track.pellet);
    if (at == e.pellets.end()) continue;
    const Branch* during = branch_at(track, e.t);
    if (!during || !branch_selected(spec, during->index)) continue;
    // Listed at its accumulation time, where the pellet rests against the limiter: e.phi.
    const double dphi = e.dphi_before[static_cast<std::size_t>(at - e.pellets.begin())];
    jumps.push_back({{e.phi, dphi}, {e.phi, 0.0}, event_mark(EventKind::chatter)});
  }
  return jumps;
}

std::vector<VerticalLine> jump_lines(std::span<const Jump> jumps, const Transform& tr) {
  std::map<double, std::vector<VerticalLine>> columns;  // by quarter-pixel column
  for (const Jump& j : jumps) {
    const Point a = clamped_pixel(tr, j.before), b = clamped_pixel(tr, j.after);
    columns[std::floor(4.0 * a.x)].push_back({a.x, std::min(a.y, b.y), std::max(a.y, b.y)});
  }
  std::vector<VerticalLine> lines;
  for (auto& [column, in] : columns) {
    std::sort(in.begin(), in.end(), [](const auto& p, const auto& q) { return p.top < q.top; });
    lines.push_back(in.front());
    for (const VerticalLine& l : in) {
      if (l.top <= lines.back().bottom)
        lines.back().bottom = std::max(lines.back().bottom, l.bottom);
      else
        lines.push_back(l);
    }
  }
  return lines;
}

}  // namespace vibro::render
