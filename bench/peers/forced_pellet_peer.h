// Peers with their own event location, on one forced pellet between two fixed limiters (paper
// friction law): the way each library's users would write it. Odeint: steps of the dense-output
// dopri5, the sign of each event function checked at step ends, a crossing bisected on the
// dense output. CVODE: CVodeRootInit (its own root finding on its interpolant), CV_NORMAL.
// The state is (phi, dphi): no work component, so their right-hand side is cheaper than vibro's.
#pragma once

#include <string>
#include <vector>

#include "core/model/model.h"

namespace vibro::bench {

struct PeerRun {
  std::vector<double> impact_times;  // limiter impacts, s
  long steps = 0;
  long rhs_evals = 0;
  std::string failure;  // empty if the run reached t_end
};

// The model must be forced_pellet_scene()'s shape: one pellet, two fixed limiters, no sticking
// on the way (a reversal that would stick ends the run with a failure).
PeerRun odeint_forced_pellet(const Model& model, double t_end, double rtol, double atol);
PeerRun cvode_forced_pellet(const Model& model, double t_end, double rtol, double atol, bool bdf);

}  // namespace vibro::bench
