// The figure of a periodic motion (API.md, "Periodic motions and their stability"): with a
// continued branch, the branch over its parameter (over the sweep's bifurcation diagram when one
// of the same parameter is given); without, the scene's own plots of one return of the motion,
// started on its state, so a phase portrait shows the closed orbit with its impacts.
#pragma once

#include "core/analysis/orbit_continuation.h"
#include "core/analysis/periodic_orbit.h"
#include "render/figure.h"

namespace vibro {

struct OrbitFigure {
  const PeriodicOrbit& orbit;
  const OrbitBranch* branch = nullptr;  // with its spec, when continued
  const ContinuationSpec* continuation = nullptr;
  const SweepSpec* sweep_spec = nullptr;  // drawn beneath the branch, if given
  const SweepResult* sweep = nullptr;
};

// `figure` is the scene's (its size, and its plots for the motion itself); `options` its run's.
// An orbit that was not found is an error naming "periodic_orbit" with the reason.
RenderResult render_orbit_figure(const FigureSpec& figure, const Model& model,
                                 const SimOptions& options, const OrbitFigure& orbit,
                                 ImageFormat format);

}  // namespace vibro
