// The derivative of a run's final state with respect to its initial state, exactly: the
// variational equations integrated along each motion interval of the run's hybrid path, and at
// every event instant the saltation (discontinuity) matrix of its events. Of a run over whole
// forcing periods this is the Jacobian of the stroboscopic map, the monodromy matrix whose
// eigenvalues are the Floquet multipliers (docs/ORBITS.md).
#pragma once

#include <chrono>
#include <limits>
#include <string>
#include <vector>

#include "core/integrators/ode.h"
#include "core/model/model.h"
#include "core/run/deadline.h"
#include "core/run/result.h"

namespace vibro {

// States here are reduced to (phi, dphi) per pellet: component 2i is pellet i's angle, 2i + 1
// its speed.
struct PathJacobian {
  Mat matrix;  // 2N × 2N
  // Of an instant: its time's derivative with respect to the state reaching it (its first
  // crossing's surface); zero where no surface sets it (the start, a release from a limiter).
  Vec time_row;
  // Non-empty when the path holds what this does not differentiate (pellets moving together),
  // naming it; the matrix is then not set.
  std::string unsupported;
  bool out_of_time = false;  // the deadline passed before the matrix was done
};

// The saltation matrix of one instant: perturbations of the state reaching it, to those of the
// state leaving it. `sides_before` are the normal sides of the interval that reached it (empty:
// from the state).
PathJacobian instant_saltation(const Model& model, const PathSegment& segment,
                               const std::vector<int>& sides_before);

// The state transition matrix of the motion interval a segment opens, from its start to its end,
// integrated with DOP853 at rtol.
PathJacobian interval_transition(const Model& model, const PathSegment& segment, double rtol);

// Segment k's: its instant's saltation, then its interval's transition (the sides before the
// instant are segment k − 1's).
PathJacobian segment_jacobian(const Model& model, const std::vector<PathSegment>& path,
                              std::size_t k, double rtol);

// The whole path's: the segments' in turn, given up (out_of_time) once `deadline` has passed.
PathJacobian path_jacobian(const Model& model, const std::vector<PathSegment>& path, double rtol,
                           const Deadline& deadline = {});

// How far each instant of a path moves, to first order, when its initial (phi, dphi) move by
// each column of deltas (2N × m), integrated together: s, one row per segment, one column per
// perturbation; rows for the first segments only where budget_ms (wall clock) ran out.
struct InstantShifts {
  Mat dt;
  std::string unsupported;  // non-empty: the path holds what the saltations do not cover; no dt
};
InstantShifts instant_shifts(const Model& model, const std::vector<PathSegment>& path,
                             const Mat& deltas, double rtol,
                             double budget_ms = std::numeric_limits<double>::infinity());

}  // namespace vibro
