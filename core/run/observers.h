// The outputs of a run, each an observer the caller attaches to the driver (core/run/observer.h).
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/model/model.h"
#include "core/run/energy_balance.h"
#include "core/run/observer.h"
#include "core/run/recorder.h"
#include "core/run/sim_options.h"

namespace vibro {

// The recorded pellets' branches (RunResult::tracks) and the negative-normal-force warnings.
class Recording : public RunObserver {
 public:
  PerStep per_step() const override { return per_step_of<Recording>(); }
  // record, record_until, max_samples: SimOptions'.
  Recording(const Model& model, const std::vector<bool>& record, double record_until,
            long max_samples)
      : recorder_(model, record, record_until, max_samples) {}

  void on_instant(const InstantView& instant) override;
  void on_interval(double t, const Vec& y, const MotionInterval& interval) override;
  void on_step(const StepSamples& step) override;
  void on_step_end(double t, const Vec& y, const MotionInterval& interval, bool at_event) override;
  void on_end(const EndView& end, RunResult& result) override;

 private:
  Recorder recorder_;
  const StepView* step_ = nullptr;  // the step on_step was last told of, whose end comes next
  std::vector<Vec> states_;         // the step's samples the event search skipped
  Vec scratch_;
};

// The state at given times (RunResult::stops): a stroboscopic section whose times steps land on,
// or a polynomial step passes with the state there from its dense output (RunObserver::landing).
// With a settle window (SimOptions::settle_window) it ends the run at the first stop where the
// last `window` stops have settled (section_settled, core/run/section_period.h).
class SectionStops : public RunObserver {
 public:
  PerStep per_step() const override { return per_step_of<SectionStops>(); }
  SectionStops(const Model& model, std::vector<double> times, int settle_window = 0)
      : model_(model), times_(std::move(times)), window_(std::max(settle_window, 0)) {}

  double landing() const override;
  void on_settled(double t, const Vec& y, const std::vector<Body>& bodies) override;
  bool ends_run() const override { return settled_; }
  void on_end(const EndView& end, RunResult& result) override;

 private:
  const Model& model_;
  std::vector<double> times_;  // increasing
  std::size_t next_ = 0;       // into times_
  std::size_t window_;         // 0: no settling
  bool settled_ = false;
  std::vector<StateAt> kept_;
};

// The hybrid path (RunResult::path): the segments that end after `from` (a sweep's record), up to
// `limit` of them.
class PathKeeper : public RunObserver {
 public:
  PerStep per_step() const override { return per_step_of<PathKeeper>(); }
  PathKeeper(double t_end, double from, std::size_t limit)
      : t_end_(t_end), from_(from), limit_(limit) {}

  void on_instant(const InstantView& instant) override;
  void on_interval(double t, const Vec& y, const MotionInterval& interval) override;
  void on_end(const EndView& end, RunResult& result) override;

 private:
  double t_end_, from_;
  std::size_t limit_;
  std::vector<PathSegment> path_;
  bool full_ = false;
};

// The events from `from` on (RunResult::events, a chatter past t_end listed at t_end) and the
// summary built from them.
class EventLog : public RunObserver {
 public:
  PerStep per_step() const override { return per_step_of<EventLog>(); }
  EventLog(const Model& model, double t_end, double from)
      : model_(model), t_end_(t_end), from_(from) {}

  void on_instant(const InstantView& instant) override;
  void on_end(const EndView& end, RunResult& result) override;

 private:
  const Model& model_;
  double t_end_, from_;
  std::vector<Event> events_;
};

// The energy balance and the first integral's residual (Stats::energy_defect,
// first_integral_residual, error_estimate): the run's consistency, which does not see event times.
class EnergyCheck : public RunObserver {
 public:
  PerStep per_step() const override { return per_step_of<EnergyCheck>(); }
  explicit EnergyCheck(const Model& model) : model_(model) {}

  void on_start(const Vec& y0) override { balance_.emplace(model_, y0); }
  void on_instant(const InstantView& instant) override;
  void on_step_end(double t, const Vec& y, const MotionInterval& interval, bool at_event) override;
  void on_end(const EndView& end, RunResult& result) override;

 private:
  const Model& model_;
  std::optional<EnergyBalance> balance_;
  double max_fi_residual_ = 0.0;
};

// The observers a SimOptions asks for (all but the check and the exponents, which are analyses
// of the result: core/analysis/checked_run.h), in the order they are handed to the driver.
class StandardOutputs {
 public:
  StandardOutputs(const Model& model, const SimOptions& options);
  std::span<RunObserver* const> list() const { return list_; }

 private:
  EventLog events_;
  EnergyCheck energy_;
  Recording recording_;
  std::optional<SectionStops> stops_;
  std::optional<PathKeeper> path_;
  std::vector<RunObserver*> list_;
};

}  // namespace vibro
