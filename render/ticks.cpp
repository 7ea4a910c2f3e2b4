#include "render/ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>

namespace vibro::render {
namespace {

constexpr const char* kMinus = "\u2212";
constexpr const char* kPi = "\u03c0";

// The multiples of `step` inside r; `label` names the multiple k.
template <typename Label>
std::vector<Tick> multiples(Range r, double step, Label label) {
  std::vector<Tick> ticks;
  const double slack = 1e-9 * step;
  const long first = static_cast<long>(std::ceil((r.lo - slack) / step));
  const long last = static_cast<long>(std::floor((r.hi + slack) / step));
  for (long k = first; k <= last; ++k) ticks.push_back({k * step, label(k)});
  return ticks;
}

// The next smaller 1-2-5 step: 10 → 5 → 2 → 1 → 0.5.
double finer_step(double step) {
  const double magnitude = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  const double normalized = step / magnitude;
  return normalized > 4.0 ? 2.0 * magnitude : normalized > 1.5 ? magnitude : 0.5 * magnitude;
}

}  // namespace

double nice_step(double span, double intervals) {
  const double raw = span / std::max(intervals, 1.0);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double normalized = raw / magnitude;
  // Thresholds at the geometric means between 1, 2, 5 and 10.
  const double nice = normalized < 1.4142   ? 1.0
                      : normalized < 3.1623 ? 2.0
                      : normalized < 7.0711 ? 5.0
                                            : 10.0;
  return nice * magnitude;
}

std::string format_tick(double value, double step) {
  if (std::abs(value) < 1e-9 * step) return "0";
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 12);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, std::abs(value));
  return value < 0 ? std::string(kMinus) + buffer : std::string(buffer);
}

std::vector<Tick> nice_ticks(Range r, double length_px, double spacing_px, double min_gap_px) {
  if (r.empty() || !(r.span() > 0.0)) return {};
  double step = nice_step(r.span(), std::max(2.0, std::round(length_px / spacing_px)));
  auto at = [&r](double s) {
    return multiples(r, s, [s](long k) { return format_tick(k * s, s); });
  };
  std::vector<Tick> ticks = at(step);
  while (ticks.size() < 3 && finer_step(step) / r.span() * length_px >= min_gap_px) {
    step = finer_step(step);
    ticks = at(step);
  }
  return ticks;
}

std::string pi_label(long quarters) {
  if (quarters == 0) return "0";
  const long divisor = std::gcd(std::labs(quarters), 4L);
  const long numerator = std::labs(quarters) / divisor;
  const long denominator = 4 / divisor;
  std::string label;
  if (quarters < 0) label = kMinus;
  if (numerator != 1) label += std::to_string(numerator);
  label += kPi;
  if (denominator != 1) label += '/' + std::to_string(denominator);
  return label;
}

std::vector<Tick> angle_ticks(Range r, double length_px, double min_spacing_px) {
  if (r.empty() || !(r.span() > 0.0)) return {};
  const double px_per_unit = length_px / r.span();
  for (long quarters_per_step : {1L, 2L, 4L, 8L}) {
    const double step = quarters_per_step * std::numbers::pi / 4.0;
    if (step * px_per_unit < min_spacing_px) continue;
    auto ticks = multiples(r, step, [&](long k) { return pi_label(k * quarters_per_step); });
    if (ticks.size() < 3) return {};
    return ticks;
  }
  return {};
}

std::vector<Tick> axis_ticks(Range r, double length_px, bool angle_axis, bool vertical) {
  if (angle_axis) {
    auto ticks = angle_ticks(r, length_px);
    // A short vertical axis: multiples of π as close as a label's height, before plain numbers.
    if (ticks.empty() && vertical) ticks = angle_ticks(r, length_px, 20.0);
    if (!ticks.empty()) return ticks;
  }
  return nice_ticks(r, length_px, 100.0, vertical ? 18.0 : 35.0);
}

}  // namespace vibro::render
