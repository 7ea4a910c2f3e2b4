// The true error of a run against a reference run of the same scene (vibro's dop853 at
// rtol 1e-13): the times of the first impacts, and the final state.
#pragma once

#include "core/model/model.h"
#include "core/run/result.h"
#include "core/run/sim_options.h"

namespace vibro::bench {

// The reference: dop853 at rtol 1e-13, atol 1e-15, with the options' t_end and no recording.
RunResult reference_run(const Model& model, const SimOptions& options);

struct RunError {
  // max(|Δt| of the first `compared` impacts (s), |Δphi| (rad), |Δdphi|·sqrt(R/g) (rad)) at the
  // end; 1 when the impacts differ in kind or pellets, or the run found fewer of them.
  double error = 0.0;
  double event_time_error = 0.0;  // s
  double final_error = 0.0;       // rad
  int impacts = 0;  // limiter impacts, collisions and chatter sequences, all of the run
  int compared = 0;
  bool same_impacts =
      true;  // the first `compared` impacts match the reference's in kind and pellets
};

// Compares the first min(max_compared, reference impacts) impacts, and the final state.
RunError run_error(const Model& model, const RunResult& run, const RunResult& reference,
                   int max_compared = 50);

}  // namespace vibro::bench
