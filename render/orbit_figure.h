// The figure of a periodic motion (API.md, "Periodic motions and their stability"): with a
// continued branch, the branch over its parameter (over the sweep's bifurcation diagram when one
// of the same parameter is given); without, the scene's own plots of one return of the motion,
// started on its state, so a phase portrait shows the closed orbit with its impacts. render/
// runs nothing: the caller runs that return (core/analysis orbit_return, planned with plan_run)
// and draws it with render_figure.
#pragma once

#include "core/analysis/bifurcation_curve.h"
#include "core/analysis/orbit_continuation.h"
#include "core/analysis/periodic_orbit.h"
#include "render/figure.h"

namespace vibro {

struct OrbitFigure {
  const OrbitBranch* branch = nullptr;  // with its spec, when continued
  const ContinuationSpec* continuation = nullptr;
  const SweepSpec* sweep_spec = nullptr;  // drawn beneath the branch, if given
  const SweepResult* sweep = nullptr;
  // Bifurcation curves followed from the branch: given (with their spec), the figure is them
  // (kind "bifurcation_curves"), over the regime map of a 2-D sweep of the same two parameters.
  const std::vector<BifurcationCurve>* curves = nullptr;
  const FollowSpec* follow = nullptr;
};

// Whether a 2-D sweep spans the same two parameters as the curves (in either order).
bool sweep_of_curves(const SweepSpec& sweep, const ContinuationSpec& continuation,
                     const FollowSpec& follow);

// Whether the scene's sweep may be drawn beneath an orbit's branch, known before the orbit is
// sought: one axis over the continued parameter, or two spanning the followed curves' (`follow`
// may be null).
bool sweep_may_lie_beneath(const SweepSpec& sweep, const ContinuationSpec& continuation,
                           const FollowSpec* follow);

// Whether the figure is the continued branch (a continuation with points); else it is one
// return of the motion.
bool draws_branch(const OrbitFigure& orbit);

// Whether the figure draws its sweep_spec's sweep beneath the branch or the curves: the sweep a
// caller runs (every caller the same, so that `vibro orbit`, the server and Python draw one
// figure) before render_branch_figure. Needs the branch and curves, not the sweep.
bool draws_sweep_beneath(const OrbitFigure& orbit);

// The continued branch (or its curves) in one panel; `figure` is the scene's (its size). Call when
// draws_branch.
RenderResult render_branch_figure(const FigureSpec& figure, const Model& model,
                                  const OrbitFigure& orbit, ImageFormat format);

}  // namespace vibro
