// Basins of attraction (API.md, "Added in the third round"): a sweep over initial-state fields
// whose runs are labelled with the periodic motion each settles on. Two runs settle on the same
// attractor when their periods agree and their section points agree within a tolerance scaled
// to the model; every run at rest over its record (SweepRun::rests) is of one attractor, "at
// rest", wherever friction or a limiter holds its pellets (a continuum of rest states, not
// motions to tell apart). The rest attractor is numbered first, the others in the order of
// (period, section point), so that the ids do not depend on threads, processes or the order the
// runs finished in.
#pragma once

#include <optional>
#include <vector>

#include "core/analysis/sweep.h"
#include "core/model/model.h"
#include "core/run/validate.h"

namespace vibro {

// Why `spec` cannot classify attractors: an axis that is not an initial-state field
// (model.pellets[i].phi0 or .dphi0), naming it; a section other than stroboscopic; continuation
// or seeded starts, which would replace the swept initial state.
std::optional<FieldError> validate_attractor_sweep(const SweepSpec& spec);

// The run's cycle on the stroboscopic section: its last `period` states, one (phi, dphi) per
// pellet each, phi wrapped, rotated to start from the least state. Empty when the run is not
// periodic (period 0) or holds too few points.
std::vector<std::pair<double, double>> attractor_cycle(const SweepRun& run, int pellets);

// The attractors of a sweep's runs, met one run at a time in the result's order (a stream of
// chains keeps only this table, not the runs): a run at rest is of the rest attractor; another
// is of a known attractor when its period and section points match the first run of it, else of a
// new one.
class AttractorTable {
 public:
  explicit AttractorTable(const Model& model);
  // The run's provisional class, numbered in order of first appearance; −1: not periodic.
  int add(const SweepRun& run);
  // The attractors, the rest attractor first, the others' ids in the order of (period, section
  // point); id_of[k] is class k's id.
  std::vector<Attractor> finish(std::vector<int>& id_of) const;

 private:
  struct Class {
    bool rest = false;
    int period = 0;
    std::vector<std::pair<double, double>> cycle;  // of its first run
    double impacts_per_period = 0.0;
    long cells = 0;
  };
  int pellets_;
  double tol_phi_, tol_dphi_;
  std::vector<Class> classes_;
  int rest_ = -1;  // the rest attractor's class, once a run rests
};

// Labels every run of `result` (SweepRun::attractor) and lists the attractors
// (SweepResult::attractors, SweepResult::classified). The same for the same runs in the same
// order (order_sweep_runs): call it once all of a sweep's runs are in.
void classify_attractors(const Model& model, SweepResult& result);

}  // namespace vibro
