#include "render/track_window.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/event_marks.h"

namespace vibro::render {
namespace {

Sample interpolate(const Sample& a, const Sample& b, double t) {
  const double w = b.t > a.t ? (t - a.t) / (b.t - a.t) : 0.0;
  return {t, a.phi + w * (b.phi - a.phi), a.dphi + w * (b.dphi - a.dphi)};
}

}  // namespace

std::vector<Sample> clip_to_window(std::span<const Sample> samples, double t_from, double t_to) {
  std::vector<Sample> inside;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Sample& s = samples[i];
    if (i > 0) {
      const Sample& prev = samples[i - 1];
      if (prev.t < t_from && s.t > t_from) inside.push_back(interpolate(prev, s, t_from));
      if (prev.t < t_to && s.t > t_to) {
        inside.push_back(interpolate(prev, s, t_to));
        break;
      }
    }
    if (s.t > t_to) break;
    if (s.t >= t_from) inside.push_back(s);
  }
  return inside;
}

const PelletTrack* find_track(const RunResult& run, int pellet) {
  for (const PelletTrack& track : run.tracks)
    if (track.pellet == pellet) return &track;
  return nullptr;
}

std::optional<Sample> state_at(const PelletTrack& track, double t) {
  const Sample* held = nullptr;
  for (const Branch& b : track.branches) {
    if (b.samples.empty()) continue;
    const auto after = std::upper_bound(b.samples.begin(), b.samples.end(), t,
                                        [](double v, const Sample& s) { return v < s.t; });
    if (after == b.samples.begin()) {  // this branch, and every later one, starts after t
      if (!held) held = &b.samples.front();
      break;
    }
    if (after != b.samples.end()) return interpolate(*(after - 1), *after, t);
    held = &b.samples.back();
  }
  if (!held) return std::nullopt;
  return Sample{t, held->phi, held->dphi};
}

bool branch_selected(const PhasePlot& spec, int index) {
  return spec.branches.empty() ||
         std::find(spec.branches.begin(), spec.branches.end(), index) != spec.branches.end();
}

bool touches(const Event& event, int pellet) {
  return std::find(event.pellets.begin(), event.pellets.end(), pellet) != event.pellets.end();
}

const Event* find_impact(std::span<const Event> events, int pellet, double t) {
  const double tolerance = 1e-9 * (1.0 + std::abs(t));
  auto it = std::lower_bound(events.begin(), events.end(), t - tolerance,
                             [](const Event& e, double v) { return e.t < v; });
  for (; it != events.end() && it->t <= t + tolerance; ++it)
    if (event_mark(it->kind) && touches(*it, pellet)) return &*it;
  return nullptr;
}

std::string window_suffix(const TimeWindow& spec, double t_end) {
  const bool from = spec.t_from > 0.0;
  const bool to = std::isfinite(spec.t_to) && !(t_end > 0.0 && spec.t_to >= t_end);
  char text[96];
  if (to || (from && t_end > 0.0))
    std::snprintf(text, sizeof text, ", t \u2208 [%g, %g] s", spec.t_from, to ? spec.t_to : t_end);
  else if (from)
    std::snprintf(text, sizeof text, ", t \u2265 %g s", spec.t_from);
  else
    return "";
  return text;
}

std::vector<int> panel_pellets(const PlotSpec& spec, int pellet_count) {
  if (const auto* phase = std::get_if<PhasePlot>(&spec)) return {phase->pellet};
  if (const auto* cylinder = std::get_if<CylinderPlot>(&spec)) return {cylinder->pellet};
  const auto* time = std::get_if<TimePlot>(&spec);
  if (!time && !std::holds_alternative<MechanismPlot>(spec)) return {};
  if (time && !time->pellets.empty()) return time->pellets;
  std::vector<int> all;
  for (int i = 0; i < pellet_count; ++i) all.push_back(i);
  return all;
}

}  // namespace vibro::render
