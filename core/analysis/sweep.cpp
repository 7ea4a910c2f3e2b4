#include "core/analysis/sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <random>
#include <span>
#include <thread>
#include <tuple>

#include "core/analysis/attractors.h"
#include "core/analysis/checked_run.h"
#include "core/model/parameter.h"
#include "core/run/deadline.h"
#include "core/run/section_period.h"

namespace vibro {
namespace {

// The initial state a run starts from: the scene's, or the last state of the run before it.
struct Start {
  std::vector<double> phi, dphi;
};

Model with_values(const Model& model, const SweepSpec& spec, double v, double v2) {
  Model m = model;
  set_parameter(m, spec.axis.parameter, v);
  if (spec.axis2) set_parameter(m, spec.axis2->parameter, v2);
  return m;
}

std::optional<FieldError> check_axis(const Model& model, const SweepAxis& axis,
                                     const std::string& at, const Limits& limits) {
  Model copy = model;
  if (auto why = set_parameter(copy, axis.parameter, 0.0))
    return FieldError{at + "parameter", "\"" + axis.parameter + "\" " + *why};
  if (axis.count < 1 || axis.count > limits.sweep_runs)
    return FieldError{at + "count", "must be from 1 to " + std::to_string(limits.sweep_runs)};
  if (!std::isfinite(axis.from)) return FieldError{at + "from", "must be a finite number"};
  if (!std::isfinite(axis.to)) return FieldError{at + "to", "must be a finite number"};
  if (axis.to < axis.from) return FieldError{at + "to", "must not be below " + at + "from"};
  return std::nullopt;
}

// Why the model at one value (pair) of the sweep is not one a scene of its own could hold: the
// model's error, named by the swept parameter's path (the first axis's, unless the failing field
// is the second's) and with the values in its message; or a stroboscopic section without forcing.
std::optional<FieldError> check_value(const Model& m, const SweepSpec& spec, double v, double v2,
                                      const Limits& limits) {
  std::optional<FieldError> e = validate_model(m, limits);
  if (!e) {
    if (spec.section == SectionKind::stroboscopic &&
        std::none_of(m.pellets.begin(), m.pellets.end(),
                     [](const Pellet& p) { return p.force.Omega > 0.0; }))
      e = FieldError{"sweep.section",
                     "a stroboscopic section needs a forced pellet (Omega > 0); without forcing "
                     "use \"impact\""};
    else
      return std::nullopt;
  }
  std::string at = spec.axis.parameter + " = " + shortest_text(v);
  if (spec.axis2) at += ", " + spec.axis2->parameter + " = " + shortest_text(v2);
  const bool named = e->field == spec.axis.parameter || e->field == "sweep.section" ||
                     (spec.axis2 && e->field == spec.axis2->parameter);
  if (!named) {
    e->message = e->field + " " + e->message;
    e->field = spec.axis.parameter;
  }
  e->message += " (at " + at + ", a value of the sweep)";
  return e;
}

// A run's simulated time, transient + record periods of the model's, held to limits.t_end as a
// scene's run is.
std::optional<FieldError> check_run_time(const Model& m, const SweepSpec& spec,
                                         const Limits& limits) {
  const double span = (spec.transient + spec.record) * sweep_period(m);
  if (span <= limits.t_end) return std::nullopt;
  return FieldError{"sweep.record", "a run would last " + shortest_text(span) +
                                        " s (transient + record periods), over the limit of " +
                                        shortest_text(limits.t_end) + " s"};
}

// Every value (pair) of the sweep, each model checked as a scene of its own would be: the checks
// are not all ranges (pellets and limiters must not coincide mod 2π, a stroboscopic section
// needs forcing), so the ends alone do not vouch for the values between them.
std::optional<FieldError> check_every_value(const Model& model, const SweepSpec& spec,
                                            const Limits& limits) {
  const SweepAxis one{"", 0.0, 0.0, 1};
  const SweepAxis& a2 = spec.axis2 ? *spec.axis2 : one;
  // An axis from a value to itself has one value however many runs it makes.
  const int n = spec.axis.from == spec.axis.to ? 1 : spec.axis.count;
  const int n2 = a2.from == a2.to ? 1 : a2.count;
  Model m = model;
  double* x = parameter_field(m, spec.axis.parameter);  // check_axis found both
  double* x2 = spec.axis2 ? parameter_field(m, a2.parameter) : nullptr;
  for (int j = 0; j < n2; ++j) {
    const double v2 = a2.value(j);
    if (x2) *x2 = v2;
    for (int i = 0; i < n; ++i) {
      const double v = spec.axis.value(i);
      *x = v;
      if (auto e = check_value(m, spec, v, v2, limits)) return e;
      if (auto e = check_run_time(m, spec, limits)) return e;
    }
  }
  return std::nullopt;
}

// The speeds of start s > 0, as fractions of 2·sqrt(g/R) in [−1, 1], one per pellet.
std::vector<double> seeded_speeds(std::uint64_t seed, int start, int pellets) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(start));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> f(pellets);
  for (double& x : f) x = u(rng);
  return f;
}

bool held(const FinalState& s) { return s.state != PelletState::sliding; }

// The fewest periods a run that classifies attractors lasts before it may end where its section
// has settled: a start close to an unstable motion's stable set lingers near it for some periods
// before it leaves, and 20 periods of its record's test leave few such starts taken for settled.
int settle_min_periods(const SweepSpec& spec) { return std::max(spec.record, 20); }

// The first stroboscopic stop of a run, in periods: the record's start, or for a run that may end
// once settled (classify attractor, no Lyapunov exponent, which needs the whole record) the
// first stop of the earliest record it may end with.
int first_stop(const SweepSpec& spec) {
  if (!spec.classify_attractor || spec.lyapunov || spec.section != SectionKind::stroboscopic)
    return spec.transient;
  return std::min(spec.transient, settle_min_periods(spec) - spec.record);
}

// The floor of the period test's tolerances (section_period): a run that may end once settled is
// read as the settle test reads it, whether it ended early or not.
double period_floor(const SweepSpec& spec) {
  return first_stop(spec) < spec.transient ? kSettleFloor : 1.0;
}

// The options of one run: the transient and the record, events kept from the record's start, the
// stroboscopic stops where the section asks for them.
SimOptions sweep_run_options(const SimOptions& options, const SweepSpec& spec, double T) {
  SimOptions o = options;
  o.t_end = (spec.transient + spec.record) * T;
  o.record.clear();
  o.stops.clear();
  const int first = first_stop(spec);
  o.keep_events_from = first * T;
  o.lyapunov = spec.lyapunov;
  // The sweep reads impacts, sticks and section points, never a reversal; the exponents replay
  // the path, which is kept as the run listed it.
  o.frictionless_reversals = spec.lyapunov;
  if (spec.section == SectionKind::stroboscopic)
    for (int k = first; k <= spec.transient + spec.record; ++k) o.stops.push_back(k * T);
  if (first < spec.transient) o.settle_window = spec.record + 1;
  return o;
}

// The forcing's phase of time t, rad in [0, 2π).
double phase_of(double t, double T) { return kTwoPi * (t / T - std::floor(t / T)); }

// The stops of the run's record: the last record + 1 of a run that ended where it settled, else
// those from the transient's end on.
std::span<const StateAt> record_stops(const RunResult& r, const SweepSpec& spec) {
  const std::span<const StateAt> all(r.stops);
  if (r.settled) return all.last(std::min<std::size_t>(all.size(), spec.record + 1));
  return all.subspan(std::min<std::size_t>(all.size(), spec.transient - first_stop(spec)));
}

// The stroboscopic section's points, whether a pellet was held at one (and every pellet at every
// one: the run rests, unless an event between them says otherwise), and the period they repeat
// (the period test's tolerances with this floor).
void add_stroboscopic_points(const RunResult& r, std::span<const StateAt> stops, int pellets,
                             double T, double speed, double floor, SweepRun& run) {
  run.points.reserve(stops.size() * pellets);
  run.rests = !stops.empty();
  for (const StateAt& s : stops)
    for (int i = 0; i < pellets; ++i) {
      run.points.push_back({i, s.t, s.pellets[i].phi, s.pellets[i].dphi, phase_of(s.t, T), -1,
                            s.t <= r.stats.trusted_until});
      run.sticks = run.sticks || held(s.pellets[i]);
      run.rests = run.rests && held(s.pellets[i]);
    }
  run.period = section_period(stops, speed, floor);
}

// The recorded events: impacts counted per period, sticks noted, a run with any of them not at
// rest, limiter impacts as the impact section's points.
void add_recorded_events(const RunResult& r, const SweepSpec& spec, double T, double from,
                         SweepRun& run) {
  int impacts = 0;
  for (const Event& e : r.events) {
    if (e.t < from) continue;
    // Anything that happens over the record (a release, a stick, an impact) is motion.
    run.rests = false;
    if (e.kind == EventKind::limiter || e.kind == EventKind::collision ||
        e.kind == EventKind::chatter)
      ++impacts;
    if (e.kind == EventKind::stick) run.sticks = true;
    if (spec.section == SectionKind::impact && e.kind == EventKind::limiter)
      run.points.push_back({e.pellets[0], e.t, e.phi, e.dphi_before[0], phase_of(e.t, T), e.limiter,
                            e.t <= r.stats.trusted_until});
  }
  run.impacts_per_period = static_cast<double>(impacts) / spec.record;
}

// How the run ended, and how far it is trusted.
void add_outcome(const RunResult& r, SweepRun& run) {
  run.at_rest = std::all_of(r.summary.final.begin(), r.summary.final.end(), held);
  run.termination = r.stats.termination;
  run.message = r.stats.message;
  run.trusted =
      run.termination == Termination::completed && r.stats.trusted_until >= r.stats.t_reached;
  run.error_estimate = r.stats.error_estimate;
  run.trusted_until = r.stats.trusted_until;
  if (r.lyapunov && r.lyapunov->unsupported.empty() && !r.lyapunov->exponents.empty())
    run.lyapunov = r.lyapunov->exponents.front();
}

// One run of the sweep, from `start`; `last` receives its last state.
SweepRun run_one(const Model& model, const SimOptions& options, const SweepSpec& spec,
                 const Start& start, Start& last) {
  const double T = sweep_period(model);
  Model m = model;
  for (int i = 0; i < m.size(); ++i) {
    m.pellets[i].phi0 = start.phi[i];
    m.pellets[i].dphi0 = start.dphi[i];
  }
  const RunResult r = simulate(m, sweep_run_options(options, spec, T));
  SweepRun run;
  const std::span<const StateAt> record = record_stops(r, spec);
  if (spec.section == SectionKind::stroboscopic)
    add_stroboscopic_points(r, record, m.size(), T, speed_scale(m), period_floor(spec), run);
  // A settled run's record starts at its window's first stop.
  add_recorded_events(r, spec, T, r.settled ? record.front().t : spec.transient * T, run);
  // A vector's growth leaves up to half of it spare: a sweep keeps exactly its points.
  run.points.shrink_to_fit();
  add_outcome(r, run);
  last.phi.clear();
  last.dphi.clear();
  for (const FinalState& f : r.summary.final) {
    last.phi.push_back(f.phi);
    last.dphi.push_back(f.dphi);
  }
  return run;
}

// One chain of runs made in order, each from the state the one before it left (or each from
// its own start, without continuation).
struct Link {
  int i = 0;  // value index on the axis
  int direction = 0;
};
struct Chain {
  int start = 0;
  int j = 0;  // value index on axis2
  std::vector<Link> links;
};

// Chain c, in the order start, value2, and (without continuation) value.
Chain chain_at(const SweepSpec& spec, int c) {
  const int n = spec.axis.count;
  const int n2 = spec.axis2 ? spec.axis2->count : 1;
  if (spec.continuation == Continuation::none) return {c / (n2 * n), (c / n) % n2, {{c % n, 0}}};
  Chain chain{c / n2, c % n2, {}};
  if (spec.continuation != Continuation::backward)
    for (int i = 0; i < n; ++i) chain.links.push_back({i, +1});
  if (spec.continuation != Continuation::forward)
    for (int i = n - 1; i >= 0; --i) chain.links.push_back({i, -1});
  return chain;
}

}  // namespace

double SweepAxis::value(int i) const {
  if (count <= 1) return from;
  if (i == count - 1) return to;  // from + (to − from) may round past it
  const double v = from + (to - from) * static_cast<double>(i) / (count - 1);
  return std::clamp(v, std::min(from, to), std::max(from, to));
}

double sweep_period(const Model& model) {
  for (const Pellet& p : model.pellets)
    if (p.force.Omega > 0.0) return kTwoPi / p.force.Omega;
  return kTwoPi * time_scale(model);
}

long stroboscopic_points_per_run(const Model& model, const SweepSpec& spec) {
  return (static_cast<long>(spec.record) + 1) * model.size();
}

long sweep_runs(const SweepSpec& spec) {
  const long per_start = static_cast<long>(spec.axis.count) * (spec.axis2 ? spec.axis2->count : 1);
  const long directions = spec.continuation == Continuation::both ? 2 : 1;
  return per_start * directions * spec.initial_states;
}

std::optional<FieldError> validate_sweep(const Model& model, const SweepSpec& spec,
                                         const Limits& limits) {
  if (auto e = check_axis(model, spec.axis, "sweep.", limits)) return e;
  if (spec.axis2) {
    if (auto e = check_axis(model, *spec.axis2, "sweep.parameter2.", limits)) return e;
    if (spec.axis2->parameter == spec.axis.parameter)
      return FieldError{"sweep.parameter2.parameter", "must differ from sweep.parameter"};
  }
  const std::string periods = std::to_string(limits.sweep_run_periods) + " periods";
  if (spec.transient < 0 || spec.transient > limits.sweep_run_periods)
    return FieldError{"sweep.transient", "must be from 0 to " + periods};
  if (spec.record < 1 || spec.record > limits.sweep_run_periods)
    return FieldError{"sweep.record", "must be from 1 to " + periods};
  if (spec.initial_states < 1 || spec.initial_states > limits.sweep_starts)
    return FieldError{"sweep.initial_states",
                      "must be from 1 to " + std::to_string(limits.sweep_starts)};
  if (sweep_runs(spec) > limits.sweep_runs)
    return FieldError{"sweep.count", "the sweep would make more than " +
                                         std::to_string(limits.sweep_runs) + " runs"};
  const double total = static_cast<double>(sweep_runs(spec)) * (spec.transient + spec.record);
  if (total > limits.sweep_periods)
    return FieldError{"sweep.count",
                      "the sweep asks for " + shortest_text(total) +
                          " periods (runs × (transient + record)), over the limit of " +
                          shortest_text(limits.sweep_periods)};
  if (auto e = validate_attractor_sweep(spec)) return e;
  return check_every_value(model, spec, limits);
}

int sweep_chain_count(const SweepSpec& spec) {
  const long rows = static_cast<long>(spec.initial_states) * (spec.axis2 ? spec.axis2->count : 1);
  return static_cast<int>(spec.continuation == Continuation::none ? rows * spec.axis.count : rows);
}

std::vector<SweepRun> run_sweep_chain(const Model& model, const SimOptions& options,
                                      const SweepSpec& spec, int c, const std::atomic<bool>* cancel,
                                      const std::function<void()>& run_done,
                                      const std::function<void(double v, double v2)>& before_run,
                                      const std::function<bool(const SweepRun&)>& admit) {
  const Chain chain = chain_at(spec, c);
  const int n = model.size();
  const double v2 = spec.axis2 ? spec.axis2->value(chain.j) : 0.0;
  std::vector<SweepRun> runs;
  Start state;
  bool fresh = true;
  for (const Link& link : chain.links) {
    if (cancel && cancel->load()) break;
    const double v = spec.axis.value(link.i);
    const Model m = with_values(model, spec, v, v2);
    if (fresh || spec.continuation == Continuation::none) {
      state = Start{};
      const std::vector<double> speeds =
          chain.start > 0 ? seeded_speeds(spec.seed, chain.start, n) : std::vector<double>{};
      for (int p = 0; p < n; ++p) {
        state.phi.push_back(m.pellets[p].phi0);
        state.dphi.push_back(chain.start > 0 ? 2.0 * speed_scale(m) * speeds[p]
                                             : m.pellets[p].dphi0);
      }
      fresh = false;
    }
    if (before_run) before_run(v, v2);
    Start last;
    SweepRun run = run_one(m, options, spec, state, last);
    run.value = v;
    run.value2 = v2;
    run.start = chain.start;
    run.direction = link.direction;
    if (admit && !admit(run)) break;
    runs.push_back(std::move(run));
    state = std::move(last);
    if (run_done) run_done();
  }
  return runs;
}

void order_sweep_runs(std::vector<SweepRun>& runs) {
  auto key = [](const SweepRun& r) {
    return std::make_tuple(r.start, r.value2, r.direction < 0 ? 1 : 0, r.value);
  };
  std::stable_sort(runs.begin(), runs.end(),
                   [&](const SweepRun& a, const SweepRun& b) { return key(a) < key(b); });
}

namespace {

// What the threads of one sweep share: the next chain to take, the counts, and why the sweep
// stopped. Each worker takes whole chains; between runs it looks at the cancel flag and the
// bounds (the wall-clock budget, the section points kept).
class SweepWork {
 public:
  SweepWork(const Model& model, const SimOptions& options, const SweepSpec& spec,
            const SweepControl& control)
      : model_(model),
        options_(options),
        spec_(spec),
        control_(control),
        deadline_(Deadline::in_ms(control.budget_ms)),
        chains_(sweep_chain_count(spec)),
        total_(sweep_runs(spec)),
        done_chains_(control.keep_runs ? chains_ : 0) {}

  // Takes chains until none is left or the sweep halts.
  void work() {
    for (int c = next_++; c < chains_ && look(); c = next_++) {
      if (control_.skip && control_.skip(c)) continue;
      std::vector<SweepRun> runs = run_sweep_chain(
          model_, options_, spec_, c, &halt_, [this] { run_done(); }, {},
          [this](const SweepRun& run) { return admit(run); });
      // A chain cut short is not whole: no checkpoint keeps it.
      if (!halt_ && control_.chain_done) control_.chain_done(c, runs);
      if (control_.keep_runs) done_chains_[c] = std::move(runs);
      if (halt_) return;
    }
  }

  // The runs in a fixed order, whatever thread made which.
  SweepResult result() {
    SweepResult result;
    for (auto& runs : done_chains_)
      for (SweepRun& r : runs) result.runs.push_back(std::move(r));
    order_sweep_runs(result.runs);
    result.cancelled = cancelled_;
    result.stopped = std::move(stopped_);
    return result;
  }

 private:
  void stop(FieldError why) {
    const std::lock_guard lock(stop_mutex_);
    if (!stopped_) stopped_ = std::move(why);
    halt_ = true;
  }

  std::string runs_done() const {
    return " after " + std::to_string(done_.load()) + " of " + std::to_string(total_) + " runs";
  }

  // The bounds and the cancel flag; false once the sweep halts.
  bool look() {
    if (control_.cancel && control_.cancel->load()) {
      cancelled_ = true;
      halt_ = true;
    }
    if (deadline_.left_ms() < 0.0)
      stop({"sweep.count", "the sweep ran past its wall-clock budget of " +
                               shortest_text(control_.budget_ms / 1000.0) + " s" + runs_done() +
                               ": sweep fewer values, or record fewer periods"});
    return !halt_;
  }

  // Whether the run's points fit under the bound on the points kept.
  bool admit(const SweepRun& run) {
    if (control_.max_points <= 0) return true;
    const long n = static_cast<long>(run.points.size());
    if (kept_.fetch_add(n) + n <= control_.max_points) return true;
    kept_ -= n;
    stop({"sweep.record", "the sweep's runs would keep more than its limit of " +
                              std::to_string(control_.max_points) + " section points" +
                              runs_done() + ": record fewer periods, or sweep fewer values"});
    return false;
  }

  void run_done() {
    const long d = ++done_;
    if (control_.progress) control_.progress(d, total_);
    look();
  }

  const Model& model_;
  const SimOptions& options_;
  const SweepSpec& spec_;
  const SweepControl& control_;
  const Deadline deadline_;
  const int chains_;
  const long total_;
  std::vector<std::vector<SweepRun>> done_chains_;
  std::atomic<int> next_{0};
  std::atomic<long> done_{0};
  std::atomic<long> kept_{0};  // section points of the runs kept
  std::atomic<bool> cancelled_{false};
  std::atomic<bool> halt_{false};  // cancelled or a bound reached: no new run starts
  std::mutex stop_mutex_;
  std::optional<FieldError> stopped_;
};

}  // namespace

SweepResult run_sweep(const Model& model, const SimOptions& options, const SweepSpec& spec,
                      const SweepControl& control) {
  const auto t0 = std::chrono::steady_clock::now();
  SweepWork sweep(model, options, spec, control);
  const int threads = std::max(1, control.threads);
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back([&sweep] { sweep.work(); });
  sweep.work();
  for (std::thread& t : pool) t.join();
  SweepResult result = sweep.result();
  result.threads = threads;
  if (spec.classify_attractor) classify_attractors(model, result);
  result.wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace vibro
