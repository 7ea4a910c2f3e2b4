#include "core/analysis/trust.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <span>
#include <sstream>
#include <tuple>

#include "core/analysis/monodromy.h"
#include "core/analysis/trust_policy.h"
#include "core/events/event_tolerances.h"
#include "core/model/motion.h"

namespace vibro {
namespace {

constexpr double kSmallestRtol = 1e-14;  // validate_options' lower bound
constexpr double kSmallestAtol = 1e-16;

bool listed_alike(const Event& a, const Event& b) {
  return a.kind == b.kind && a.pellets == b.pellets && a.limiter == b.limiter;
}

std::string describe(const Event& e) {
  std::ostringstream s;
  s << event_kind_name(e.kind) << " of pellet";
  if (e.pellets.size() > 1) s << "s";
  for (std::size_t k = 0; k < e.pellets.size(); ++k) s << (k ? " and " : " ") << e.pellets[k] + 1;
  if (e.limiter >= 0) s << " at limiter " << e.limiter + 1;
  s.precision(7);
  s << " at t = " << e.t << " s";
  return s.str();
}

std::string describe_run_end(const RunResult& run) {
  std::ostringstream s;
  s.precision(7);
  s << "ends at t = " << run.stats.t_reached << " s";
  return s.str();
}

// The speeds an instant's collisions leave its pellets with (the last each of its impacts left,
// pellet by pellet; none for a pellet whose last impact was on a limiter, which sets the sign of
// the speed it leaves), and the largest speed the instant meets or leaves.
struct Leaving {
  std::vector<std::pair<int, double>> speeds;
  double largest = 0.0;
};

void note_leaving(const Event& e, Leaving& l) {
  const bool collision = e.kind == EventKind::collision;
  for (std::size_t j = 0; j < e.pellets.size() && j < e.dphi_after.size(); ++j) {
    auto same = std::find_if(l.speeds.begin(), l.speeds.end(),
                             [&](const auto& s) { return s.first == e.pellets[j]; });
    if (same != l.speeds.end()) l.speeds.erase(same);
    if (collision) l.speeds.emplace_back(e.pellets[j], e.dphi_after[j]);
    l.largest = std::max(l.largest, std::abs(e.dphi_after[j]));
  }
  for (double v : e.dphi_before) l.largest = std::max(l.largest, std::abs(v));
}

// Whether an event lists a speed before and after for each of its pellets (events made by hand
// may list none).
bool has_speeds(const Event& e) {
  return e.dphi_before.size() == e.pellets.size() && e.dphi_after.size() == e.pellets.size();
}

// Merges event e of one instant into `into`, the instant's event of its kind (and limiter): a
// pellet new to it joins with the speeds e gives it, a pellet it lists already leaves at the speed
// e leaves it with. Merged in the order listed, each pellet's speeds are those before the
// instant's first impact on it and after its last. Speeds are kept only where every event merged
// lists them.
void merge_into(Event& into, const Event& e) {
  const bool speeds = has_speeds(into) && has_speeds(e);
  if (!speeds) {
    into.dphi_before.clear();
    into.dphi_after.clear();
  }
  for (std::size_t j = 0; j < e.pellets.size(); ++j) {
    const auto at = std::find(into.pellets.begin(), into.pellets.end(), e.pellets[j]);
    if (at != into.pellets.end()) {
      if (speeds) into.dphi_after[at - into.pellets.begin()] = e.dphi_after[j];
      continue;
    }
    into.pellets.push_back(e.pellets[j]);
    if (!speeds) continue;
    into.dphi_before.push_back(e.dphi_before[j]);
    into.dphi_after.push_back(e.dphi_after[j]);
  }
}

// Puts an event's pellets in index order, each with its speeds.
void sort_pellets(Event& e) {
  if (std::is_sorted(e.pellets.begin(), e.pellets.end())) return;
  std::vector<std::size_t> order(e.pellets.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return e.pellets[x] < e.pellets[y]; });
  const bool speeds = has_speeds(e);
  Event sorted = e;
  for (std::size_t j = 0; j < order.size(); ++j) {
    sorted.pellets[j] = e.pellets[order[j]];
    if (!speeds) continue;
    sorted.dphi_before[j] = e.dphi_before[order[j]];
    sorted.dphi_after[j] = e.dphi_after[order[j]];
  }
  e = std::move(sorted);
}

// The speed at which an impact closes: a limiter impact's pellet on its limiter, a collision's two
// pellets on each other; 0 for other events and for a collision of more than two.
double approach_speed(const Event& e) {
  if (e.kind == EventKind::limiter && !e.dphi_before.empty()) return std::abs(e.dphi_before[0]);
  if (e.kind == EventKind::collision && e.dphi_before.size() == 2)
    return std::abs(e.dphi_before[0] - e.dphi_before[1]);
  return 0.0;
}

// One event of a run by_instant(), with what the trust check reads of the events it merges.
struct Listed {
  Event event;
  // The approach_speed of the first impact merged into it: the one whose closing the instant was
  // found at (when it comes first) and whose angles' round-off moves it.
  double approach = 0.0;
  Leaving leaving;  // what its instant leaves
};

// The events of a run, one per instant and kind (and limiter) in a fixed order, so that a run
// and its shadow list them alike. Each instant's events are gathered in place at the end of the
// list: they are few, and a run has many instants.
std::vector<Listed> group_instants(const std::vector<Event>& events) {
  auto order = [](const Listed& x, const Listed& y) {
    return std::tie(x.event.kind, x.event.limiter, x.event.pellets) <
           std::tie(y.event.kind, y.event.limiter, y.event.pellets);
  };
  std::vector<Listed> out;
  out.reserve(events.size());
  for (std::size_t i = 0; i < events.size();) {
    const double t = events[i].t;
    const auto first = static_cast<std::ptrdiff_t>(out.size());  // the instant's, from here on
    Leaving instant_left;
    for (; i < events.size() && events[i].t <= t + kTrustPolicy.same_instant * (1.0 + std::abs(t));
         ++i) {
      const Event& e = events[i];
      const bool merges = e.kind == EventKind::collision || e.kind == EventKind::limiter;
      auto same = std::find_if(out.begin() + first, out.end(), [&](const Listed& x) {
        return merges && x.event.kind == e.kind && x.event.limiter == e.limiter;
      });
      if (same == out.end())
        out.push_back({e, approach_speed(e), {}});
      else
        merge_into(same->event, e);
      note_leaving(e, instant_left);
    }
    const auto instant = std::span(out).subspan(static_cast<std::size_t>(first));
    for (Listed& l : instant)
      if (l.event.kind == EventKind::collision || l.event.kind == EventKind::limiter)
        sort_pellets(l.event);
    // A stable insertion sort: an instant holds a few events (std::stable_sort would take a
    // buffer from the heap for each).
    for (std::size_t k = 1; k < instant.size(); ++k)
      for (std::size_t j = k; j > 0 && order(instant[j], instant[j - 1]); --j)
        std::swap(instant[j], instant[j - 1]);
    for (Listed& l : instant) l.leaving = instant_left;
  }
  return out;
}

// The time from event k to the nearest event at another instant (or the run's start or end).
double spacing(const std::vector<Listed>& events, std::size_t k, double t_end) {
  const double t = events[k].event.t;
  const double same = kTrustPolicy.same_instant * (1.0 + std::abs(t));
  double before = t, after = t_end - t;
  for (std::size_t j = k; j-- > 0;)
    if (events[j].event.t < t - same) {
      before = t - events[j].event.t;
      break;
    }
  for (std::size_t j = k + 1; j < events.size(); ++j)
    if (events[j].event.t > t + same) {
      after = events[j].event.t - t;
      break;
    }
  return std::min(before, after);
}

// Whether the speeds a run's and its shadow's collisions leave a pellet with at one instant leave
// its turn unresolved: within turn_speed_errors of their difference of zero, and that difference
// past round-off. The first such pellet, or -1. A pellet that leaves an impact slowly turns soon
// after, or not at all, as the sign of its speed has it.
int uncertain_turn(const Leaving& run, const Leaving& shadow) {
  const double round_off = kTrustPolicy.speed_round_off_ulps *
                           std::numeric_limits<double>::epsilon() *
                           std::max(run.largest, shadow.largest);
  for (const auto& speed : run.speeds) {  // (pellet, speed); not a structured binding, which
                                          // clang 14 cannot capture in the lambda
    auto other = std::find_if(shadow.speeds.begin(), shadow.speeds.end(),
                              [&](const auto& s) { return s.first == speed.first; });
    if (other == shadow.speeds.end()) continue;
    const double error = std::abs(speed.second - other->second);
    if (error > round_off && kTrustPolicy.turn_speed_errors * error > std::abs(speed.second))
      return speed.first;
  }
  return -1;
}

// How early a grazing event may come that a run and its shadow put at t, s: a contact decided by
// a position error δ (ten times what the tolerance holds an angle to) under accelerations up to
// a (gravity and the largest force) moves by up to sqrt(2δ/a). A run and its shadow that part
// at a grazing collision both put it 5e-5 s after a reference did, far more than their events'
// error before it.
double grazing_window(const Model& model, const Stats& st, double phi) {
  double a = model.g / model.R;
  for (const Pellet& p : model.pellets) a += std::abs(p.force.F0) / (p.m * model.R);
  const double delta =
      kTrustPolicy.grazing_tolerances * (st.rtol * (1.0 + angle_size(phi)) + st.atol);
  return a > 0.0 ? std::sqrt(2.0 * delta / a) : 0.0;
}

// Where the trust ends when the runs part at event k: `margin` before the earlier of their
// events k, but never before the last event both list alike (or the start), less ten times the
// event times' error. The true sequence may part earlier than either run, before the last event
// both list alike (Trust.TheTrustEndsTenErrorsBeforeTheLastEventListedAlike). The margin is ten
// times the event times' error (the bound the estimate keeps), and where the runs list different
// events, at least the grazing window.
double trust_end(const std::vector<Listed>& run, const std::vector<Listed>& shadow, std::size_t k,
                 double margin, double error) {
  double first = std::numeric_limits<double>::infinity();
  if (k < run.size()) first = run[k].event.t;
  if (k < shadow.size()) first = std::min(first, shadow[k].event.t);
  const double last = k == 0 ? 0.0
                             : std::max(0.0, std::min(run[k - 1].event.t, shadow[k - 1].event.t) -
                                                 kTrustPolicy.margin_errors * error);
  return std::max(last, first - margin);
}

// The round-off of an impact's time from the round-off of the angles it is found at: a hundred
// ulps of the angle over the speed of approach (Listed::approach). Pellets near 7 rad meeting at
// 1e-3 rad/s collide at times that round-off alone moves by 1e-11 s; every run agreed with its
// shadow to 1e-14 s, a reference at rtol 1e-13 put them 7e-11 s away.
double placement_round_off(const Listed& l) {
  if (!(l.approach > 0.0)) return 0.0;
  return kTrustPolicy.placement_round_off_ulps * std::numeric_limits<double>::epsilon() *
         (1.0 + std::abs(l.event.phi)) / l.approach;
}

// How far a start a round-off apart moves an instant, to first order (from the variational
// equations along the shadow's path, instant_shifts).
struct StartShift {
  // The shadow's own start 64 ulps ahead (check_model). A chain that amplifies errors amplifies
  // it as it amplifies the run's own error, and where the two are alike the shadow lands where
  // the run did (Trust.AShadowsStartDoesNotHideTheRunsError). Less this shift, the shadow is where
  // it would be from the run's start.
  double start = 0.0;
  // Every angle a few ulps on (4ε·(1 + |φ|)), the resting pellets' too (not those exactly on a
  // limiter's angle), every other pellet's back: the round-off a run carries, as the chain
  // amplifies it. The shadow cannot move resting pellets (it would break equilibria), and a
  // chain from rest amplifies round-off it does not see (Trust.AChainFromRestCarriesItsRoundOff).
  // Pellets at one place moved alike would keep their gaps; 64 ulps over-stated that
  // scatter sixtyfold.
  double round_off = 0.0;
};

// The shadow's instants with their StartShift; none where the path holds what the saltations do
// not cover (pellets moving together).
class StartShifts {
 public:
  StartShifts(const Model& model, const RunResult& shadow, double budget_ms) {
    if (shadow.path.empty()) return;
    const Model moved = check_model(model);
    const double ulps = kTrustPolicy.carried_ulps * std::numeric_limits<double>::epsilon();
    Mat deltas = Mat::Zero(2 * model.size(), 2);
    for (int i = 0; i < model.size(); ++i) {
      const Pellet& p = model.pellets[i];
      deltas(2 * i, 0) = moved.pellets[i].phi0 - p.phi0;
      deltas(2 * i + 1, 0) = moved.pellets[i].dphi0 - p.dphi0;
      const bool on_a_limiter = std::any_of(model.limiters.begin(), model.limiters.end(),
                                            [&](const Limiter& l) { return l.angle == p.phi0; });
      const double sign = i % 2 == 0 ? 1.0 : -1.0;
      deltas(2 * i, 1) = on_a_limiter ? 0.0 : sign * ulps * (1.0 + std::abs(p.phi0));
      deltas(2 * i + 1, 1) = sign * ulps * p.dphi0;
    }
    // A tenth of the shift is all the estimate needs: `auto` at rtol 1e-4 put the shifts within
    // 1 % of the difference of shadows started with and without the 64 ulps.
    const InstantShifts s =
        instant_shifts(model, shadow.path, deltas, kTrustPolicy.shift_rtol, budget_ms);
    for (Eigen::Index k = 0; k < s.dt.rows(); ++k)
      if (!shadow.path[k].events.empty())
        at_.push_back({shadow.path[k].t, {s.dt(k, 0), s.dt(k, 1)}});
  }
  // The instant at t's (none where none is known).
  StartShift at(double t) const {
    const double same = kTrustPolicy.same_instant * (1.0 + std::abs(t));
    auto it = std::lower_bound(at_.begin(), at_.end(), t - same,
                               [](const Instant& x, double v) { return x.t < v; });
    return it != at_.end() && it->t <= t + same ? it->shift : StartShift{};
  }

 private:
  struct Instant {
    double t;
    StartShift shift;
  };
  std::vector<Instant> at_;  // in time order
};

// Whether the times of event k, dt apart, leave the events' order and spacing unresolved: they
// differ by more than a share of the time to the neighbouring events and by more than the
// tolerance explains, or the two runs put the spacing before it that share apart and more than
// round-off (kTrustPolicy.unresolved_share).
bool unresolved(const std::vector<Listed>& a, const std::vector<Listed>& b, std::size_t k,
                double dt, double explained, double round_off, double t_reached) {
  const double t = a[k].event.t;
  const double gap_a = t - (k == 0 ? 0.0 : a[k - 1].event.t),
               gap_b = b[k].event.t - (k == 0 ? 0.0 : b[k - 1].event.t);
  const double gap_difference = std::abs(gap_a - gap_b);
  return (dt > kTrustPolicy.unresolved_share * spacing(a, k, t_reached) && dt > explained) ||
         (gap_difference > kTrustPolicy.unresolved_share * std::min(gap_a, gap_b) &&
          gap_difference > round_off);
}

// Ends the trust ten errors before event k (the earlier of the two runs' times) where its
// instant's collisions leave a pellet whose turn is unresolved (uncertain_turn): the turn may come
// at once, or not at all; true if it does.
bool ends_at_uncertain_turn(const std::vector<Listed>& a, const std::vector<Listed>& b,
                            std::size_t k, TrustReport& r) {
  const int pellet = uncertain_turn(a[k].leaving, b[k].leaving);
  if (pellet < 0) return false;
  auto speed = [&](const Leaving& l) {
    return std::find_if(l.speeds.begin(), l.speeds.end(),
                        [&](const auto& s) { return s.first == pellet; })
        ->second;
  };
  r.uncertain_turn = static_cast<int>(k);
  r.turning_pellet = pellet;
  r.run_speed = speed(a[k].leaving);
  r.shadow_speed = speed(b[k].leaving);
  const double end = std::max(
      0.0, std::min(a[k].event.t, b[k].event.t) - kTrustPolicy.margin_errors * r.event_time_error);
  r.trusted_until = std::min(r.trusted_until, end);
  return true;
}

// Ends the trust before the first event one run lists and the other does not (or lists
// otherwise): event k of both, or the first past the shorter list, if it comes before t_common.
void end_at_first_difference(const Model& model, const Stats& st, const std::vector<Listed>& a,
                             const std::vector<Listed>& b, std::size_t k, double t_common,
                             TrustReport& r) {
  const std::size_t n = std::min(a.size(), b.size());
  const Event* e = nullptr;
  if (k < n && !listed_alike(a[k].event, b[k].event)) {
    e = a[k].event.t < b[k].event.t ? &a[k].event : &b[k].event;
  } else if (k == n && a.size() != b.size()) {
    const std::vector<Listed>& longer = a.size() > n ? a : b;
    if (longer[n].event.t <= t_common) e = &longer[n].event;
  }
  if (!e) return;
  r.first_difference = static_cast<int>(k);
  const double window = grazing_window(model, st, e->phi);
  r.trusted_until =
      std::min(r.trusted_until,
               trust_end(a, b, k, std::max(kTrustPolicy.margin_errors * r.event_time_error, window),
                         r.event_time_error));
}

// The final states' difference completes a report.
TrustReport finish(const Model& model, const RunResult& run, const RunResult& shadow,
                   TrustReport r) {
  const double time_scale = event_tolerances(model).time_scale;
  if (run.stats.t_reached == shadow.stats.t_reached) {
    for (std::size_t i = 0; i < run.summary.final.size() && i < shadow.summary.final.size(); ++i) {
      const FinalState& a = run.summary.final[i];
      const FinalState& b = shadow.summary.final[i];
      r.state_error = std::max(
          {r.state_error, std::abs(a.phi - b.phi), time_scale * std::abs(a.dphi - b.dphi)});
    }
  } else {
    r.state_error = std::numeric_limits<double>::infinity();  // not comparable: no estimate
  }
  return r;
}

// Ends the trust before the run's first near miss, if that comes before where it ends already,
// with a warning a person reads; true if it did. The shadow cannot see it: run by the same
// method, it may miss the same way.
bool ends_at_graze(RunResult& run) {
  Stats& st = run.stats;
  if (!run.graze || !(run.graze->earliest < st.trusted_until)) return false;
  const Graze& g = *run.graze;
  st.trusted_until = g.earliest;
  std::ostringstream why;
  why.precision(3);
  why << "events are trusted until t = " << std::setprecision(7) << g.earliest
      << " s: at t = " << g.t << " s " << std::setprecision(3);
  // A minimum below zero is a crossing that would have turned that far past (a grazing one).
  const bool struck = g.value < 0.0;
  switch (g.of) {
    case Graze::Of::speed:
      why << "the speed of pellet " << g.pellet + 1 << " fell to " << g.value
          << " rad/s and turned away";
      break;
    case Graze::Of::gap:
      why << "pellets " << g.pellet + 1 << " and " << g.other + 1
          << (struck ? " collided so slowly that they would have turned " : " came within ")
          << std::abs(g.value) << (struck ? " rad past each other" : " rad and turned away");
      break;
    case Graze::Of::limiter:
      why << "pellet " << g.pellet + 1;
      if (struck)
        why << " struck limiter " << g.other + 1 << " so slowly that it would have turned "
            << -g.value << " rad past it";
      else
        why << " came within " << g.value << " rad of limiter " << g.other + 1
            << " and turned away";
      break;
    case Graze::Of::order:
      why << "pellet " << g.pellet + 1 << " took two impacts at one instant, each closing within "
          << "the contact radius of the other: which came first, and with it what they left,";
      break;
  }
  if (g.of != Graze::Of::order)
    why << ", within the " << g.error << " the tolerance leaves uncertain: whether it "
        << (g.of == Graze::Of::speed ? "stops"
            : g.of == Graze::Of::gap ? "collides"
                                     : "strikes")
        << " there";
  why << " depends on differences below the tolerance ("
      << (g.of == Graze::Of::order ? "a near-simultaneous impact" : "a grazing event")
      << "); tighten rtol to see whether the events after it converge";
  run.warnings.push_back({"not_trusted", why.str(), -1, st.trusted_until, st.t_reached});
  return true;
}

double largest_of_estimates(const Model& model, const Stats& st) {
  const double time_scale = event_tolerances(model).time_scale;
  return std::max({st.event_time_error / time_scale, st.state_error, st.energy_defect,
                   st.first_integral_residual});
}

}  // namespace

std::vector<Event> by_instant(const std::vector<Event>& events) {
  std::vector<Event> listed;
  for (Listed& l : group_instants(events)) listed.push_back(std::move(l.event));
  return listed;
}

ShadowOptions check_options(const SimOptions& run) {
  ShadowOptions shadow{run};
  SimOptions& o = shadow.options;
  // Another method errs independently where the same one at a tighter tolerance may take the
  // same steps: `auto` (an explicit method where the scene is not stiff) checks Radau IIA, whose
  // own shadow shared its bias on an ill-conditioned cascade. `auto` weighing DOPRI5 against DOP853
  // (rtol 1e-6 and looser) is checked by `auto` on DOP853, more accurate than either (a run mostly
  // on DOP853 checked by DOPRI5 was blind to the error of its first DOPRI5 steps, which DOPRI5
  // shared at every tolerance).
  //
  // DOP853 is checked by Taylor. DOPRI5, checking it above rtol 1e-8 at a thirtieth of the
  // tolerance (a hundredth would have cost 3.3×), erred as much as DOP853 and cancelled its
  // error (3e-3 s estimated at 1.1e-4 s; ctest
  // trust_scene.dop853_checked_by_dopri5_cancelled_its_error). DOP853 checking itself shared the
  // error of its flights cut short by events: a flight shorter than the run's and the shadow's
  // steps is one step of its own length at any tolerance, and so is its error (a few ulps of the
  // angle on a 4.7 ms flight, the same from rtol 1e-9 to 1e-12), which a chain of slow impacts
  // amplified 1e5 times: a run at rtol 1e-9 erred 4.5e-10 s, its shadow at 1e-11 4.6e-10 s, and
  // the estimate was 35 times short (ctest trust_scene.dop853_shared_its_short_flights_error).
  // Taylor's flights are one step of a series whose length follows the tolerance.
  //
  // Taylor checks DOPRI5 too: DOP853's floor on such flights is its error as DOPRI5's shadow, and
  // at rtol 1e-11 and 1e-13 (shadow at 1e-13 and 1e-14) the run and the shadow erred alike there:
  // estimates 0.48 and 0.29 of the error (Trust.Dopri5CheckedByDop853SharedItsShortFlightsFloor).
  // Over trust_scan seeds 1-4 × 300 (--taylor 1) the worst estimate / true error of DOPRI5 went
  // from 0.69 to 0.98, no run's trust to its end changed, and the median check cost went from
  // 2.01-3.10× to 1.63-2.72× (rtol 1e-10 … 1e-6).
  //
  // Held alike, a
  // run at rtol 1e-6 and its shadow at 1e-8 took the same steps of 1/Ω and shared an error a
  // chaotic chain amplified: the shadow's longest step is half the run's, and a capped step errs
  // 2⁹ times less (2⁶ for DOPRI5; Trust.AShadowDoesNotShareTheRunsCappedSteps).
  //
  // Taylor checks itself as DOP853 does: at a hundredth of the tolerance its series is two or
  // three orders longer (Taylor::order_for) and its steps, set by the series' radius, fall
  // elsewhere; its longest step is halved alike. DOP853 as its shadow judged no better
  // (trust_scan --taylor 1, seeds 1-16 × 200: one estimate ten times short either way, no wrong
  // event vouched for) at a median check cost of 2.45-3.10× against 2.35-2.61×. That estimate
  // (seed 3, scene 154, rtol 1e-10) is short of the scan's reference's own error, not the run's:
  // against DOP853 at atol 1e-17 or Taylor at rtol 1e-13 it is 0.86 and 0.44 of the truth, and
  // the scan, whose references now run at atol 1e-17 with Taylor among them, judges it so.
  //
  // The shadow's error must be well below the run's, whatever the methods' error constants
  // and whatever luck a run has: it runs at a hundredth of both tolerances (at a thirtieth
  // DOP853 missed a lucky run's error: the run at rtol 1e-8 erred 3.6e-10 s, the shadow
  // 3.3e-10 s as much; ctest trust_scene.a_shadow_at_a_thirtieth_erred_as_much_as_a_lucky_run).
  // Over 640,000 runs of trust_scan (seeds 1-32) these choices took the estimates ten times short
  // from 21 to 17 at the same cost (median 2.25× the bare run for DOP853, 2.11× for DOPRI5, 1.31×
  // for Radau IIA).
  if (run.method == Method::dopri5 || run.method == Method::dop853) o.method = Method::taylor;
  if (run.method == Method::radau5) o.method = Method::automatic;
  if (run.method == Method::automatic && auto_explicit_for(run.rtol) == AutoExplicit::dopri5)
    shadow.auto_explicit =
        AutoExplicit::dop853;  // covers the runs that weigh DOPRI5 against DOP853
  o.rtol = std::max(run.rtol / kTrustPolicy.shadow_tolerance_ratio, kSmallestRtol);
  o.atol = std::max(run.atol / kTrustPolicy.shadow_tolerance_ratio, kSmallestAtol);
  shadow.longest_step_scale = kTrustPolicy.shadow_step_share;
  o.record.clear();
  o.stops.clear();
  o.check = false;
  // The start's shifts are found along its path, over its first 20,000 instants (about 20 MB; a
  // run may list 200,000): past them the shadow is taken as it is.
  o.keep_path = true;
  o.path_limit = kTrustPolicy.shift_instants;
  o.lyapunov = false;
  return shadow;
}

Model check_model(const Model& model) {
  Model m = model;
  const double ulps = kTrustPolicy.start_ulps * std::numeric_limits<double>::epsilon();
  for (Pellet& p : m.pellets) {
    if (p.dphi0 != 0.0) p.phi0 += ulps * (1.0 + std::abs(p.phi0));
    p.dphi0 *= 1.0 + ulps;
  }
  return m;
}

TrustReport compare_runs(const Model& model, const RunResult& run, const RunResult& shadow,
                         double budget_ms) {
  TrustReport r;
  const double t_common = std::min(run.stats.t_reached, shadow.stats.t_reached);
  r.trusted_until = t_common;
  const EventTolerances tol = event_tolerances(model);
  const double time_scale = tol.time_scale;
  const std::vector<Listed> a = group_instants(run.events), b = group_instants(shadow.events);
  const std::size_t n = std::min(a.size(), b.size());
  const StartShifts shifts(model, shadow, budget_ms);
  std::size_t k = 0;
  bool summed = false;  // a chatter series was summed at or before event k
  for (; k < n && listed_alike(a[k].event, b[k].event); ++k) {
    const double t = a[k].event.t;
    if (t > t_common) break;
    // The shadow as it is, and less its start's shift: the start is there to part round-off the
    // run and the shadow would share (check_model), the shift to keep it from hiding the error.
    const StartShift shift = shifts.at(b[k].event.t);
    const double dt =
        std::max(std::abs(t - b[k].event.t), std::abs(t - (b[k].event.t - shift.start)));
    const double round_off =
        std::max({kTrustPolicy.time_round_off_ulps * std::numeric_limits<double>::epsilon() *
                      (time_scale + t),
                  placement_round_off(a[k]), std::abs(shift.round_off)});
    // Times that differ by more than a tenth of the time to the neighbouring events, and by
    // more than the tolerance explains (a thousand times rtol over the time scale and the time
    // run: sensitive dynamics amplified them), leave the events' order and spacing unresolved,
    // however alike the lists look. A squeeze's impacts, 1e-11 s apart and shifted alike by
    // 5e-11 s, are resolved. So is a spacing that the two put ten times apart, whatever the
    // tolerance explains: a chaotic run at rtol 1e-7 and its shadow put a turn and an impact
    // 5.7e-7 s and 6.9e-6 s apart (each 2e-5 s off, less than the 9e-5 s the tolerance
    // explains), and a reference listed them the other way round.
    const double explained = kTrustPolicy.explained_rtols * run.stats.rtol * (time_scale + t);
    if (unresolved(a, b, k, dt, explained, round_off, run.stats.t_reached)) {
      r.unresolved = static_cast<int>(k);
      r.trusted_until =
          std::min(r.trusted_until,
                   trust_end(a, b, k, kTrustPolicy.margin_errors * std::max(dt, r.event_time_error),
                             r.event_time_error));
      return finish(model, run, shadow, r);
    }
    // Errors the run and its shadow share, the shadow cannot see: the round-off of event times
    // (a thousand ulps of the time scale and the time run, or of the angles an impact is found
    // at, or of the start as the chain amplifies it), from a summed chatter on, the summation's
    // own error (chatter_time²/T0, docs/MODEL.md:
    // both sum the same way), and a bias of one method.
    summed = summed || a[k].event.kind == EventKind::chatter;
    const double chatter = summed ? tol.chatter_time * tol.chatter_time / time_scale : 0.0;
    // A run vouches for no less than a hundredth of what its tolerance asks, rtol·(T0 + t): a
    // run and its shadow of one method that agree far better than asked may share the error
    // (both 1e-12 s apart, a reference 2e-11 s away, rtol asking 1e-9 s).
    const double asked = kTrustPolicy.asked_share * run.stats.rtol * (time_scale + t);
    r.event_time_error = std::max({r.event_time_error, dt, round_off, chatter, asked});
    if (ends_at_uncertain_turn(a, b, k, r)) return finish(model, run, shadow, r);
  }
  end_at_first_difference(model, run.stats, a, b, k, t_common, r);
  return finish(model, run, shadow, r);
}

void apply_check(const Model& model, const RunResult& shadow, RunResult& run, double budget_ms) {
  const auto started = std::chrono::steady_clock::now();
  const TrustReport r = compare_runs(model, run, shadow, budget_ms);
  const double compared_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  Stats& st = run.stats;
  st.check = true;
  std::ostringstream method;
  method << std::setprecision(3) << shadow.stats.method << " at rtol " << shadow.stats.rtol;
  st.check_method = method.str();
  st.check_wall_ms = shadow.stats.wall_ms + compared_ms;
  st.wall_ms += st.check_wall_ms;
  st.event_time_error = r.event_time_error;
  st.state_error = r.state_error;
  st.trusted_until = r.trusted_until;
  st.error_estimate = largest_of_estimates(model, st);
  if (ends_at_graze(run)) return;

  const std::vector<Event> listed = by_instant(run.events), checked = by_instant(shadow.events);
  std::ostringstream why;
  why.precision(7);
  if (r.uncertain_turn >= 0) {
    const auto k = static_cast<std::size_t>(r.uncertain_turn);
    why << "events are trusted until t = " << r.trusted_until << " s: at t = " << listed[k].t
        << " s this run's collisions leave pellet " << r.turning_pellet + 1 << " at "
        << std::setprecision(3) << r.run_speed << " rad/s, and the check run's (" << st.check_method
        << ") at " << r.shadow_speed
        << " rad/s, within ten times their difference of zero. Whether and when it turns depends "
           "on differences below the tolerance (a sensitive turn); tighten rtol to see whether "
           "the events after it converge";
    run.warnings.push_back({"not_trusted", why.str(), -1, r.trusted_until, st.t_reached});
  } else if (r.unresolved >= 0) {
    const auto k = static_cast<std::size_t>(r.unresolved);
    why << "events are trusted until t = " << r.trusted_until << " s: after that this run lists "
        << describe(listed[k]) << ", and the check run (" << st.check_method
        << ") lists it at t = " << checked[k].t
        << " s, more than a tenth of the time to the neighbouring events. "
        << "The events from there on are not resolved (sensitive dynamics); tighten rtol to see "
           "whether they converge";
    run.warnings.push_back({"not_trusted", why.str(), -1, r.trusted_until, st.t_reached});
  } else if (r.first_difference >= 0) {
    const auto k = static_cast<std::size_t>(r.first_difference);
    why << "events are trusted until t = " << r.trusted_until << " s: after that this run lists ";
    why << (k < listed.size() ? describe(listed[k]) : "no more events");
    why << ", and the check run (" << st.check_method << ") lists ";
    why << (k < checked.size() ? describe(checked[k]) : "no more events");
    why << ". The events from there on depend on differences below the tolerance (a grazing "
           "impact, a stick test at its threshold, or sensitive dynamics); tighten rtol to see "
           "whether they converge";
    run.warnings.push_back({"not_trusted", why.str(), -1, r.trusted_until, st.t_reached});
  } else if (shadow.stats.t_reached < st.t_reached) {
    why << "events are trusted until t = " << r.trusted_until << " s: the check run ("
        << st.check_method << ") " << describe_run_end(shadow) << " (" << shadow.stats.message
        << "), so later events are not checked";
    run.warnings.push_back({"not_trusted", why.str(), -1, r.trusted_until, st.t_reached});
  }
}

void apply_unchecked(const Model& model, RunResult& run) {
  Stats& st = run.stats;
  st.check = false;
  st.check_method.clear();
  const double consistency = std::max(st.energy_defect, st.first_integral_residual);
  st.event_time_error = consistency * event_tolerances(model).time_scale;
  st.state_error = consistency;
  st.trusted_until = st.t_reached;
  st.error_estimate = largest_of_estimates(model, st);
  ends_at_graze(run);
}

}  // namespace vibro
