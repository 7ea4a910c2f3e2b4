#include "render/plot_validate.h"

#include <cmath>
#include <variant>

namespace vibro {
namespace {

using Checked = std::optional<FieldError>;

Checked check_pellet(const std::string& field, int pellet, int count) {
  if (pellet >= 0 && pellet < count) return std::nullopt;
  if (count == 0) return FieldError{field, "the model has no pellets"};
  return FieldError{field, "must be a pellet index in 0.." + std::to_string(count - 1) +
                               " (indices count from 0: pellet 1 is 0), got " +
                               std::to_string(pellet)};
}

Checked check_range(const std::string& field, const std::optional<AxisLimits>& range) {
  if (!range || (std::isfinite(range->lo) && std::isfinite(range->hi) && range->lo < range->hi))
    return std::nullopt;
  return FieldError{field, "must be [lo, hi], two finite numbers with lo < hi"};
}

// Each kind's checks, in the order its fields are read: pellets, branches, window, instant,
// overlay, axis ranges, camera.
struct PlotCheck {
  const std::string& field;
  const PlotContext& context;
  const Limits& limits;

  std::string at(const char* name) const { return field + "." + name; }
  std::string at(const char* name, std::size_t j) const {
    return at(name) + "[" + std::to_string(j) + "]";
  }
  Checked pellet(int p) const { return check_pellet(at("pellet"), p, context.pellets); }
  Checked window(const TimeWindow& w) const {
    if (!std::isfinite(w.t_from) || w.t_from < 0.0)
      return FieldError{at("t_from"), "must be a finite time ≥ 0 s"};
    if (std::isnan(w.t_to) || w.t_to <= w.t_from)
      return FieldError{at("t_to"), "must be later than t_from"};
    return std::nullopt;
  }
  Checked ranges(const std::optional<AxisLimits>& phi,
                 const std::optional<AxisLimits>& dphi) const {
    if (auto e = check_range(at("phi_range"), phi)) return e;
    return check_range(at("dphi_range"), dphi);
  }

  Checked operator()(const PhasePlot& plot) const {
    if (auto e = pellet(plot.pellet)) return e;
    if (plot.branches.size() > static_cast<std::size_t>(limits.plot_branches))
      return FieldError{at("branches"),
                        "must list at most " + std::to_string(limits.plot_branches) + " branches"};
    for (std::size_t j = 0; j < plot.branches.size(); ++j)
      if (plot.branches[j] < 1)
        return FieldError{at("branches", j), "must be a branch number ≥ 1 (branches count from 1)"};
    if (auto e = window(plot)) return e;
    const auto& through = plot.first_integral_through;
    if (through && (!std::isfinite(through->phi) || !std::isfinite(through->dphi)))
      return FieldError{at("first_integral"), "must be a finite (phi, dphi)"};
    return ranges(plot.phi_range, plot.dphi_range);
  }
  Checked operator()(const TimePlot& plot) const {
    if (plot.pellets.empty() && context.pellets == 0)
      return FieldError{at("pellets"), "the model has no pellets"};
    if (plot.pellets.size() > static_cast<std::size_t>(limits.pellets))
      return FieldError{at("pellets"),
                        "must list at most " + std::to_string(limits.pellets) + " pellets"};
    for (std::size_t j = 0; j < plot.pellets.size(); ++j)
      if (auto e = check_pellet(at("pellets", j), plot.pellets[j], context.pellets)) return e;
    if (auto e = window(plot)) return e;
    return ranges(plot.phi_range, plot.dphi_range);
  }
  Checked operator()(const CylinderPlot& plot) const {
    if (auto e = pellet(plot.pellet)) return e;
    if (auto e = window(plot)) return e;
    const Camera& c = plot.camera;
    if (!std::isfinite(c.azimuth_deg))
      return FieldError{at("camera") + ".azimuth", "must be a finite angle, degrees"};
    if (!(std::abs(c.elevation_deg) <= 89.0))
      return FieldError{at("camera") + ".elevation", "must be in [-89, 89] degrees"};
    if (!(c.distance >= 1.5 && c.distance <= 50.0))
      return FieldError{at("camera") + ".distance", "must be in [1.5, 50]"};
    return std::nullopt;
  }
  Checked operator()(const MechanismPlot& plot) const {
    if (std::isfinite(plot.t) && plot.t >= 0.0 && plot.t <= context.t_end) return std::nullopt;
    if (std::isinf(context.t_end))
      return FieldError{at("t"), "must be a finite time ≥ 0 s, within [0, t_end]"};
    return FieldError{at("t"),
                      "must be a time in [0, t_end] = [0, " + shortest_text(context.t_end) + "] s"};
  }
  Checked operator()(const WorkPrecisionPlot& plot) const { return window(plot); }
  Checked operator()(const SweepPlot& plot) const { return pellet(plot.pellet); }
  Checked operator()(const BranchPlot& plot) const { return pellet(plot.pellet); }
};

}  // namespace

std::optional<FieldError> validate_plot(const PlotSpec& plot, const std::string& field,
                                        const PlotContext& context, const Limits& limits) {
  return std::visit(PlotCheck{field, context, limits}, plot);
}

}  // namespace vibro
