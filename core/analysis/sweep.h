// Parameter sweeps (API.md, "Sweeps"): one run per parameter value, or per pair of values on a
// 2-D grid, each keeping only its section's points: the stroboscopic section (the state at every
// forcing period) or the impact section (the state before every limiter impact). From them, per
// run, the period of the motion a person reads off a bifurcation diagram.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/model/model.h"
#include "core/run/limits.h"
#include "core/run/result.h"
#include "core/run/sim_options.h"
#include "core/run/validate.h"

namespace vibro {

enum class SectionKind { stroboscopic, impact };
enum class Continuation { none, forward, backward, both };

// `count` values from `from` to `to`, evenly spaced (one value: `from`).
struct SweepAxis {
  std::string parameter;  // a path of core/model/parameter.h
  double from = 0.0;
  double to = 0.0;
  int count = 1;
  double value(int i) const;
};

struct SweepSpec {
  SweepAxis axis;
  std::optional<SweepAxis> axis2;  // a 2-D grid: every value of axis2 for every value of axis
  // Counted in periods of the first forced pellet's force, 2π/Ω, or without forcing in
  // periods of a small swing, 2π·sqrt(R/g): the run lasts transient + record of them, and its
  // section points are kept over the last `record`.
  int transient = 100;
  int record = 50;
  SectionKind section = SectionKind::stroboscopic;
  // forward: each value starts from the last state of the value before it (in increasing
  // order), backward likewise in decreasing order, both: forward, then backward from where the
  // forward chain ended. Branches are followed, and hysteresis shows.
  Continuation continuation = Continuation::none;
  // Runs per value: the scene's own initial state, and then states with the pellets' speeds
  // drawn from `seed` (uniform in ±2·sqrt(g/R)), so that coexisting motions show.
  int initial_states = 1;
  std::uint64_t seed = 1;
  // The largest Lyapunov exponent of each run over its record (core/analysis/lyapunov.h).
  bool lyapunov = false;
  // "classify": "attractor": the axes are initial-state fields, and each run is labelled with
  // the attractor it settles on (core/analysis/attractors.h).
  bool classify_attractor = false;
};

// Why a sweep cannot run, naming the field ("sweep.parameter", "sweep.count", ...), or a model
// field that a swept value makes invalid: every value (every pair of a 2-D sweep) must make a
// model that passes validate_model, as a scene of its own would, and the message names the
// value. The swept parameter's path is the field, unless the model's failing field is the
// other axis's. Counts and periods are held to `limits` (sweep_runs, sweep_run_periods,
// sweep_starts).
std::optional<FieldError> validate_sweep(const Model& model, const SweepSpec& spec,
                                         const Limits& limits = {});

// The period of the motion the sweep's counts are in, s, for this model.
double sweep_period(const Model& model);

// One point of a section, stored compactly (40 bytes: a sweep may keep a million of them): the
// doubles first, then the small fields. Made as {pellet, t, phi, dphi, phase, limiter, trusted}.
struct SectionPoint {
  SectionPoint() = default;
  SectionPoint(int pellet, double t, double phi, double dphi, double phase, int limiter,
               bool trusted)
      : t(t),
        phi(phi),
        dphi(dphi),
        phase(phase),
        pellet(static_cast<std::int16_t>(pellet)),
        limiter(static_cast<std::int16_t>(limiter)),
        trusted(trusted) {}
  double t = 0.0;
  double phi = 0.0;           // unwrapped
  double dphi = 0.0;          // before the impact, for the impact section
  double phase = 0.0;         // of the period at t, rad in [0, 2π)
  std::int16_t pellet = 0;    // fewer than 2^15 pellets (Limits::pellets)
  std::int16_t limiter = -1;  // impact section: the limiter struck
  bool trusted = true;        // before the run's stats.trusted_until
};
static_assert(sizeof(SectionPoint) <= 40);

// One run: a value (pair), a start, a direction of continuation.
struct SweepRun {
  double value = 0.0;
  double value2 = 0.0;
  int start = 0;      // 0: the scene's initial state; then the seeded ones
  int direction = 0;  // +1 forward, −1 backward, 0 no continuation
  std::vector<SectionPoint> points;
  // The smallest p such that the section repeats every p periods over the record, within
  // 1e-5 of the points' spread (stroboscopic section); 0: not periodic within the record.
  int period = 0;
  double impacts_per_period = 0.0;  // limiter impacts and collisions over the record, per period
  bool at_rest = false;             // every pellet ends stuck or resting on a limiter
  bool sticks = false;              // some pellet is stuck or resting at some section point
  // Stroboscopic section: every pellet held (stuck or resting on a limiter) at every point of the
  // record and no event between them: the run is at rest over its record.
  bool rests = false;
  bool trusted = true;         // stats.trusted_until reached the end (or the check is off)
  double trusted_until = 0.0;  // s: its points before it are vouched for
  Termination termination = Termination::completed;
  std::string message;  // why the run stopped early
  double error_estimate = 0.0;
  // 1/s, SweepSpec::lyapunov: the largest Lyapunov exponent over the record; empty when not asked
  // for, or where the linearisation does not reach (pellets moving together). −infinity: every
  // perturbation dies (all pellets held).
  std::optional<double> lyapunov;
  // SweepSpec::classify_attractor: the id of the attractor in SweepResult::attractors, −1 when
  // the run is not periodic within its record (chaotic, or not yet settled).
  int attractor = -1;
};

// One attractor of a basin sweep: a periodic motion, told apart from others by its section
// points, not only by its period; or every run at rest (SweepRun::rests), one attractor wherever
// friction or a limiter holds the pellets.
struct Attractor {
  int id = 0;
  bool at_rest = false;  // the runs at rest: period 1, no impacts, no section
  int period = 0;
  double impacts_per_period = 0.0;
  // Its `period` stroboscopic states, each with one (phi, dphi) per pellet (phi wrapped to
  // (−π, π]), starting from the least of them: the order of ids.
  std::vector<std::pair<double, double>> section;
  long cells = 0;  // the runs that settle on it
};

struct SweepResult {
  std::vector<SweepRun> runs;  // in a fixed order: start, then value2, then direction, then value
  int threads = 1;
  double wall_ms = 0.0;
  bool cancelled = false;
  // Why a bound of SweepControl ended the sweep before its last run (its runs are then not all
  // here), naming the field to change: "sweep.record" for the points, "sweep.count" for the
  // wall clock.
  std::optional<FieldError> stopped;
  // SweepSpec::classify_attractor: every periodic motion the runs settle on, by id (ordered by
  // period, then section point: the same whatever ran which run).
  bool classified = false;
  std::vector<Attractor> attractors;
};

struct SweepControl {
  int threads = 1;
  // Called after every finished run, from any thread, with the runs done and in all.
  std::function<void(long done, long total)> progress;
  const std::atomic<bool>* cancel = nullptr;  // set: no new run starts
  // Chains not to run (done before: a resumed sweep); their runs are not in the result.
  std::function<bool(int chain)> skip;
  // Called after every whole chain, from any thread (a checkpoint keeps them).
  std::function<void(int chain, const std::vector<SweepRun>& runs)> chain_done;
  // false: each chain's runs go to chain_done only, and the result holds none of them (the
  // caller writes them out as chains finish: memory that does not grow with the sweep).
  bool keep_runs = true;
  // The section points the sweep may keep in all, 0: no bound. A run whose points would take
  // the sweep past it is dropped and no new run starts (SweepResult::stopped): memory stays
  // within the bound plus the runs under way.
  long max_points = 0;
  // The sweep's wall clock, ms: no run starts after it (SweepResult::stopped). Each run is
  // bounded by its own options.deadline_ms.
  double budget_ms = std::numeric_limits<double>::infinity();
};

// The number of runs the sweep makes.
long sweep_runs(const SweepSpec& spec);

// The section points of one run of a stroboscopic sweep, (record + 1) × pellets; an impact
// section's are not known before the run.
long stroboscopic_points_per_run(const Model& model, const SweepSpec& spec);

// A sweep's runs come in chains: one run per value without continuation; with it, the values of
// a row in order, each from the last state of the one before. Chains are the units a sweep is
// spread over threads and processes by, and a chain's runs are the same wherever it runs.
// Chains are numbered 0 … sweep_chain_count − 1.
int sweep_chain_count(const SweepSpec& spec);

// Runs chain c; stops before the next run once `cancel` is set. `before_run` is called with
// each run's value (pair) before it starts, `run_done` after it. `admit`, when given, is asked
// for each finished run before it is kept: false drops it and ends the chain.
std::vector<SweepRun> run_sweep_chain(
    const Model& model, const SimOptions& options, const SweepSpec& spec, int c,
    const std::atomic<bool>* cancel = nullptr, const std::function<void()>& run_done = {},
    const std::function<void(double v, double v2)>& before_run = {},
    const std::function<bool(const SweepRun&)>& admit = {});

// Puts runs in a sweep result's fixed order: start, value2, direction, value.
void order_sweep_runs(std::vector<SweepRun>& runs);

// Runs the sweep with `options` for every run (t_end is set from the spec). The result is the
// same for any number of threads. Call validate_sweep first.
SweepResult run_sweep(const Model& model, const SimOptions& options, const SweepSpec& spec,
                      const SweepControl& control);

}  // namespace vibro
