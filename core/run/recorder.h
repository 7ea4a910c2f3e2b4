// Keeps what a run reports along the way: the branches of the recorded pellets' phase
// trajectories, and the intervals where the paper law's normal force is negative.
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include "core/integrators/ode.h"
#include "core/integrators/step_view.h"
#include "core/model/model.h"
#include "core/model/motion.h"
#include "core/run/result.h"

namespace vibro {

class Recorder {
 public:
  // max_samples: SimOptions::max_samples.
  Recorder(const Model& model, const std::vector<bool>& record, double record_until,
           long max_samples);

  // A state of the whole system at time t, kept for the recorded pellets.
  void sample(double t, const Vec& y);
  // Whether samples after t are kept: some pellet is recorded, and t is before record_until.
  bool wants_samples(double t) const { return !tracks_.empty() && t < record_until_; }
  // Into how many pieces (at least `fewest`, at most 64) a step's curves are cut, sampled at
  // their ends, for each chord to stay within 1e-4 of the extent the recorded pellets' φ and φ̇
  // have so far (a tenth of a pixel on a 1000-pixel axis). A chord strays from an arc by the
  // square of its length: by 4θ(1 − θ) times its largest distance at the fraction θ of the step,
  // where `inside` is the state.
  int pieces(const Vec& start, const Vec& inside, double theta, const Vec& end, int fewest);
  // Watches the paper law's normal force N of the sliding bodies at the checked points: a motion
  // interval's start (no step: a window opens or closes there, at its instant) and each step's
  // end, or its event (`step`: the step just taken, whose start is the last checked point). Where
  // N changed sign since the last checked point, the window opens or closes at N's root on the
  // step's dense output, to 1e-9 s (relative past 1 s); a cos per body at each checked point is all
  // the check costs until then (not one at every sample). Locating a change builds the step's dense
  // output where the event search did not: DOP853's three extra stages, counted in rhs_evals.
  void check_normal_force(double t, const Vec& y, const std::vector<Body>& bodies,
                          const StepView* step = nullptr);
  // Pellet i's motion interval ends at t (an event touched it); the next sample opens a new one.
  void end_branch(int pellet);
  // Closes open warning intervals at the end of the run and hands everything over.
  void finish(double t, RunResult& result);

 private:
  void close_warning(int pellet, double t);
  // Where the normal force of the body led by `leader` changes sign in [lo, hi] on the step's
  // dense output: becomes negative (`to_negative`) or stops being so.
  double sign_change(const StepView& step, int leader, double lo, double hi, bool to_negative);
  // A negative stretch of the body's N inside the step just taken to t, where N is positive at
  // both its ends (core/run/negative_normal.h), opened and closed as one; cos_at_t: cos φ of its
  // leader at t; near_top: the leader was near the circle's top at either end.
  void find_negative_inside(const StepView& step, const Body& body, double t, double cos_at_t,
                            bool near_top);
  void keep(PelletTrack& track, const Sample& s);
  void flush_pending(int track);
  // Drops every other sample of every branch, keeping its ends; doubles the stride.
  void thin();

  const Model& model_;
  std::vector<int> track_of_;  // pellet -> index in tracks_, or -1
  std::vector<PelletTrack> tracks_;
  std::vector<bool> open_;  // pellet's current branch is open
  double record_until_;
  long max_samples_;
  long kept_ = 0;    // samples in tracks_
  long calls_ = 0;   // sample() calls
  long stride_ = 1;  // one sample kept in stride_ (a branch's first and last always)
  std::vector<std::optional<Sample>> pending_;                // per track: the last sample skipped
  double last_t_ = -std::numeric_limits<double>::infinity();  // the last sample() call's
  Vec last_y_;
  std::vector<double> lowest_, highest_;  // per track: φ and φ̇ (2k, 2k + 1), the extents so far
  Vec dense_;                             // a state on a step's dense output

  // Per pellet, the negative-normal stretches: the open one's start (NaN: none), the last closed
  // one's length, and its warning (an index into warnings_, −1: none) with the stretches it holds.
  // A stretch that starts sooner after the last one than that one lasted is the same approach
  // (chatter toward a stop repeats them ever faster): it extends the warning, not a new one.
  std::vector<double> negative_since_;
  // Per pellet: near the circle's top at the last checked point, in its upper half (cos φ < 0)
  // slower than sqrt(2g/R).
  std::vector<bool> near_top_;
  std::vector<double> stretch_length_;
  std::vector<int> warning_of_;
  std::vector<int> stretches_;
  std::vector<Warning> warnings_;       // their messages written at finish()
  std::vector<int> warning_stretches_;  // per warning: the stretches it holds
};

}  // namespace vibro
