// What a scene asks to be drawn: the `plots` list of API.md, as plain values.
// The scene reader (io/) fills these; render/ draws them. Indices count from 0.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/run/result.h"

namespace vibro {

enum class PlotKind {
  phase,           // (φ, φ̇) of one pellet, branches told apart
  time,            // φ(t) (optionally φ̇(t)) of the listed pellets
  cylinder,        // 3-D (OSMesa): the trajectory on the phase cylinder (cos φ, sin φ, φ̇)
  work_precision,  // log error against log run time, one line per method (a sweep, not the run)
  bifurcation,     // a sweep's section points of one pellet against the swept parameter
  section,         // a sweep's section points of one pellet in the (φ, φ̇) plane
  impact_map,      // a sweep's impacts of one pellet: φ̇ before impact against the forcing phase
  regime_map,      // a 2-D sweep's cells coloured by the period of the motion
  lyapunov,        // a 1-D sweep's largest Lyapunov exponents against the swept parameter
  lyapunov_map,    // a 2-D sweep's cells coloured by the largest Lyapunov exponent
  branch,          // a continued periodic motion against its parameter, stability and bifurcations
  mechanism,  // the circle, limiters, pellets and forces at one instant, to scale (paper Fig. 1)
};
// The plot kinds that draw a sweep rather than a run.
inline bool draws_sweep(PlotKind kind) {
  return kind == PlotKind::bifurcation || kind == PlotKind::section ||
         kind == PlotKind::impact_map || kind == PlotKind::regime_map ||
         kind == PlotKind::lyapunov || kind == PlotKind::lyapunov_map;
}

// The plot kinds that draw the scene's own run (the others draw a report, a sweep or a branch).
inline bool draws_run(PlotKind kind) {
  return kind == PlotKind::phase || kind == PlotKind::time || kind == PlotKind::cylinder ||
         kind == PlotKind::mechanism;
}

// The section coordinate a bifurcation diagram draws against the parameter.
enum class SectionCoordinate { dphi, phi };

struct Camera {
  double azimuth_deg = 35.0;
  double elevation_deg = 25.0;
  double distance = 5.0;  // in cylinder radii; sets the strength of the perspective
};

// Axis limits a scene sets, lo < hi.
struct AxisLimits {
  double lo = 0.0;
  double hi = 1.0;
};

struct PlotSpec {
  PlotKind kind = PlotKind::phase;
  int pellet = 0;            // phase, cylinder
  std::vector<int> pellets;  // time
  bool show_dphi = false;    // time: also draw φ̇(t) on a second axis
  double t_from = 0.0;       // window drawn, s
  double t_to = std::numeric_limits<double>::infinity();  // clipped to t_end
  double t = 0.0;             // mechanism: the instant drawn, s, in [0, t_end]
  std::vector<int> branches;  // phase: only these motion intervals (numbered from 1); empty: all
  std::optional<PhasePoint> first_integral_through;  // phase: exact unforced curve through it
  bool friction_zone = false;  // phase: shade |φ| ≤ α0 (mod 2π) where a pellet can rest
  bool wrap = false;           // phase: φ on one turn, [−π, π)
  bool branch_labels = true;   // phase: number the branches
  std::optional<AxisLimits> phi_range;   // phase, time: the φ axis; default: the data's
  std::optional<AxisLimits> dphi_range;  // phase, time: the φ̇ axis; default: the data's
  std::string title;                     // empty: a default title
  Camera camera;                         // cylinder
  SectionCoordinate coordinate = SectionCoordinate::dphi;  // bifurcation, branch
};

struct FigureSpec {
  std::vector<PlotSpec> plots;
  int width = 1200;
  int height = 800;
};

}  // namespace vibro
