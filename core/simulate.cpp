#include "core/simulate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>

#include "core/chatter.h"
#include "core/contacts.h"
#include "core/dynamics.h"
#include "core/first_integral.h"
#include "core/impacts.h"
#include "core/motion.h"
#include "core/recorder.h"
#include "core/watch.h"

namespace vibro {
namespace {

using Clock = std::chrono::steady_clock;

class Simulation {
 public:
  Simulation(const Model& model, const SimOptions& options, std::unique_ptr<Stepper> stepper)
      : model_(model),
        opt_(options),
        n_(model.size()),
        y_(3 * n_),
        armed_(model.limiters.size(), true),
        recorder_(model, options.record, options.record_until),
        stepper_(stepper ? std::move(stepper)
                         : make_stepper(options.method,
                                        StepperOptions{options.rtol, options.atol,
                                                       std::numeric_limits<double>::infinity()})) {
    for (int i = 0; i < n_; ++i) {
      y_[phi_index(i)] = model.pellets[i].phi0;
      y_[dphi_index(i)] = model.pellets[i].dphi0;
      y_[work_index(i)] = 0.0;
    }
    time_scale_ = std::sqrt(model.R / std::max(model.g, 1e-300));
    if (!std::isfinite(time_scale_) || time_scale_ <= 0.0) time_scale_ = 1.0;
    // Independent of the tolerance, so runs at different tolerances list the same impacts.
    // Summing in closed form errs by about chatter_time²/time_scale (the accelerations change
    // that little over the summed flights): 1e-8·sqrt(R/g).
    chatter_time_ = 1e-4 * time_scale_;
    double v_scale = 1.0 / time_scale_;
    for (const Pellet& p : model.pellets) v_scale = std::max(v_scale, std::abs(p.dphi0));
    v_eps_ = 1e-13 * v_scale;
    v_merge_ = 1e-9 * v_scale;
    energy0_ = total_energy();
    energy_scale_ = 0.0;
    for (int i = 0; i < n_; ++i) {
      const Pellet& p = model.pellets[i];
      energy_scale_ += 0.5 * p.m * model.R * model.R * p.dphi0 * p.dphi0 +
                       2.0 * p.m * model.g * model.R;
    }
    energy_scale_ = std::max(energy_scale_, 1e-300);
    if (n_ >= 2) neighbours_ = circular_neighbours(y_, n_);
  }

  RunResult run();

 private:
  double total_energy() const;
  double total_work() const;
  void check_energy();
  void initial_instant();
  void instant(double t, const std::vector<Crossing>& crossings);
  void assign_modes(double t, const std::vector<LimiterContact>& limiter_contacts,
                    const std::vector<PairContact>& pair_contacts,
                    const std::vector<int>& struck_limiter_of, const std::vector<bool>& reversed,
                    const std::vector<bool>& released, std::vector<bool>& touched);
  void resolve_instant(double t, const std::vector<LimiterContact>& limiter_contacts,
                       const std::vector<PairContact>& pair_contacts,
                       const std::vector<bool>& reversed, const std::vector<bool>& released);
  void start_segment(double t);
  void add_event(Event e, double t);
  bool over_budget(double t);
  void fail(double t, const std::string& why);
  void first_integral_check(const Vec& y);

  const Model& model_;
  const SimOptions& opt_;
  const int n_;
  Vec y_;
  std::vector<Body> bodies_;
  std::vector<Neighbours> neighbours_;
  std::vector<bool> armed_;
  std::vector<Watch> watches_;
  CrossingFinder finder_;
  Recorder recorder_;
  std::unique_ptr<Stepper> stepper_;
  std::unique_ptr<SegmentDynamics> dynamics_;
  RunResult result_;

  double time_scale_ = 1.0;   // sqrt(R/g), s
  double chatter_time_ = 0.0; // chatter series shorter than this are summed, s
  double v_eps_ = 0.0;        // speeds below this are zero, rad/s
  double v_merge_ = 0.0;     // touching pellets closer in speed than this move together, rad/s
  double contact_distance_ = 1e-10;  // neighbours closer than this (relative) touch, rad
  double energy0_ = 0.0, energy_scale_ = 1.0, impact_losses_ = 0.0;
  double max_energy_defect_ = 0.0, max_fi_residual_ = 0.0;
  std::vector<std::unique_ptr<FirstIntegral>> first_integral_;  // per body, this segment
  int impacts_ = 0;
  int same_instant_ = 0;
  double last_instant_ = -1.0;
  Clock::time_point started_ = Clock::now();
  bool stopped_ = false;
};

double Simulation::total_energy() const {
  double E = 0.0;
  for (int i = 0; i < n_; ++i) E += energy(model_, i, y_[phi_index(i)], y_[dphi_index(i)]);
  return E;
}

double Simulation::total_work() const {
  double W = 0.0;
  for (int i = 0; i < n_; ++i) W += y_[work_index(i)];
  return W;
}

// Energy balance: E(t) − E(0) = work of the force and friction + energy lost at impacts.
void Simulation::check_energy() {
  const double defect = total_energy() - energy0_ - total_work() - impact_losses_;
  energy_scale_ = std::max(energy_scale_, std::abs(total_work()));
  if (std::isfinite(defect)) {
    max_energy_defect_ = std::max(max_energy_defect_, std::abs(defect) / energy_scale_);
  }
}

void Simulation::first_integral_check(const Vec& y) {
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    if (!first_integral_[b]) continue;
    const int L = bodies_[b].leader();
    const double r = first_integral_[b]->residual(y[phi_index(L)], y[dphi_index(L)]);
    if (std::isfinite(r)) max_fi_residual_ = std::max(max_fi_residual_, std::abs(r));
  }
}

void Simulation::add_event(Event e, double t) {
  e.t = t;
  if (!e.pellets.empty()) e.phi = y_[phi_index(e.pellets[0])];
  if (e.kind == EventKind::limiter || e.kind == EventKind::collision ||
      e.kind == EventKind::chatter) {
    ++impacts_;
    result_.summary.last_impact = {impacts_, e.t};
    if (e.kind == EventKind::collision) {
      ++result_.summary.collisions;
      if (e.limiter >= 0) ++result_.summary.limiter_impacts;
    } else if (e.kind == EventKind::limiter) {
      ++result_.summary.limiter_impacts;
      ++result_.summary.impacts_by_limiter[e.limiter][e.pellets[0]];
    } else {
      ++result_.summary.chatter_sequences;
    }
  }
  result_.events.push_back(std::move(e));
}

void Simulation::fail(double t, const std::string& why) {
  std::ostringstream msg;
  msg << "stopped at t = " << t << " s: " << why;
  result_.stats.message = msg.str();
  stopped_ = true;
}

bool Simulation::over_budget(double t) {
  const StepperStats& s = stepper_->stats();
  if (static_cast<long>(result_.events.size()) >= opt_.max_events) {
    result_.stats.termination = Termination::event_limit;
    fail(t, "the run reached its limit of " + std::to_string(opt_.max_events) + " events");
  } else if (s.steps + s.rejected >= opt_.max_steps) {
    result_.stats.termination = Termination::step_limit;
    fail(t, "the run reached its limit of " + std::to_string(opt_.max_steps) + " steps");
  } else if (std::isfinite(opt_.deadline_ms) &&
             std::chrono::duration<double, std::milli>(Clock::now() - started_).count() >
                 opt_.deadline_ms) {
    result_.stats.termination = Termination::deadline;
    std::ostringstream why;
    why << "the run took longer than its deadline of " << opt_.deadline_ms << " ms";
    fail(t, why.str());
  }
  return stopped_;
}

// Modes after the impacts of an instant: which pellets move together, who slides, sticks or
// rests, and the events that say so.
void Simulation::assign_modes(double t, const std::vector<LimiterContact>& limiter_contacts,
                              const std::vector<PairContact>& pair_contacts,
                              const std::vector<int>& struck_limiter_of,
                              const std::vector<bool>& reversed, const std::vector<bool>& released,
                              std::vector<bool>& touched) {
  std::vector<Body> old = std::move(bodies_);
  std::vector<int> old_body(n_);
  for (std::size_t b = 0; b < old.size(); ++b)
    for (int i : old[b].members) old_body[i] = static_cast<int>(b);

  bodies_ = join_touching(model_, t, y_, pair_contacts, limiter_contacts, armed_,
                          {v_merge_, chatter_time_});

  for (Body& body : bodies_) {
    double P = 0.0, M = 0.0;
    for (int i : body.members) {
      P += model_.pellets[i].m * y_[dphi_index(i)];
      M += model_.pellets[i].m;
    }
    double v = P / M;
    for (int i : body.members) {  // a plastic merge: its energy goes to the impact losses
      const double vi = y_[dphi_index(i)];
      impact_losses_ += 0.5 * model_.pellets[i].m * model_.R * model_.R * (v * v - vi * vi);
    }
    const int L = body.leader();
    const double phi = y_[phi_index(L)];
    // The limiter the body is pressed against, if any: a contact of this instant, or a limiter
    // it sits on (a flight too short to leave it).
    int lim = -1, side = 0;
    for (const LimiterContact& c : limiter_contacts) {
      for (int i : body.members) {
        if (c.pellet == i && armed_[c.limiter]) {
          lim = c.limiter;
          side = c.side;
        }
      }
    }
    const double a_free = body_free_acceleration(model_, body, t, phi);
    if (lim < 0 && std::abs(v) <= v_eps_) {
      for (int l = 0; l < static_cast<int>(model_.limiters.size()); ++l) {
        const double d = wrap_angle(phi - model_.limiters[l].angle);
        if (armed_[l] && std::abs(d) <= 1e-14 * (1.0 + std::abs(phi)) &&
            model_.limiters[l].acts_on(L)) {
          lim = l;
          side = a_free > 0.0 ? -1 : 1;
        }
      }
    }
    const double capacity = stick_capacity(model_, phi);
    const Body& before = old[old_body[L]];
    const bool was_moving = before.mode == Mode::sliding;

    // Chatter: a lone pellet leaving a fixed limiter slowly, pressed back: sum the series.
    if (std::abs(v) > v_eps_ && body.members.size() == 1 && struck_limiter_of[L] >= 0 &&
        armed_[struck_limiter_of[L]]) {
      const int l = struck_limiter_of[L];
      const int sd = v > 0.0 ? 1 : -1;
      if (auto series = chatter_series(model_, t, model_.limiters[l].angle, sd, std::abs(v),
                                       model_.limiters[l].k, a_free);
          series && series->t_next / (1.0 - series->r) <= chatter_time_) {
        Event e;
        e.kind = EventKind::chatter;
        e.pellets = {L};
        e.limiter = l;
        e.dphi_before = {v};
        e.dphi_after = {0.0};
        e.impacts_resolved = series->impacts;
        e.t_accumulation = series->t_star;
        impact_losses_ -= 0.5 * model_.pellets[L].m * model_.R * model_.R * v * v;
        y_[dphi_index(L)] = 0.0;
        v = 0.0;
        lim = l;
        side = sd;
        add_event(std::move(e), series->t_star);
        touched[L] = true;
      }
    }

    if (std::abs(v) > v_eps_) {
      body.mode = Mode::sliding;
      body.s = v > 0.0 ? 1 : -1;
    } else {
      v = 0.0;
      if (lim >= 0 && !(side * a_free > capacity)) {
        body.mode = Mode::resting;
        body.limiter = lim;
        body.side = side;
      } else if (lim >= 0) {
        body.mode = Mode::sliding;
        body.s = side;
      } else if (std::abs(a_free) <= capacity) {
        body.mode = Mode::stuck;
      } else {
        body.mode = Mode::sliding;
        body.s = a_free > 0.0 ? 1 : -1;
      }
    }
    for (int i : body.members) y_[dphi_index(i)] = v;

    // Events that say how the motion changed.
    bool any_reversed = false, any_released = false;
    for (int i : body.members) {
      any_reversed = any_reversed || reversed[i];
      any_released = any_released || released[i];
    }
    EventKind kind;
    bool emit = false;
    if (any_reversed && was_moving) {
      kind = body.mode == Mode::sliding ? EventKind::reversal : EventKind::stick;
      emit = true;
    } else if (any_released && body.mode == Mode::sliding && !was_moving) {
      kind = EventKind::release;
      emit = true;
    }
    if (emit) {
      Event e;
      e.kind = kind;
      e.pellets = body.members;
      e.limiter = body.mode == Mode::resting ? body.limiter : -1;
      e.dphi_before.assign(body.members.size(), 0.0);
      e.dphi_after.assign(body.members.size(), v);
      add_event(std::move(e), t);
      for (int i : body.members) touched[i] = true;
    }
  }
}

void Simulation::instant(double t, const std::vector<Crossing>& crossings) {
  std::vector<LimiterContact> limiter_contacts;
  std::vector<PairContact> pair_contacts;
  std::vector<bool> reversed(n_, false), released(n_, false), at_limiter(n_, false);

  // Snap each crossing exactly onto its event: the angle onto the limiter, the speed to zero,
  // the two pellets onto one place.
  for (const Crossing& c : crossings) {
    const Watch& w = watches_[c.watch];
    switch (w.kind) {
      case WatchKind::limiter: {
        const Body& b = bodies_[w.body];
        const double shift = w.target - y_[phi_index(w.pellet)];
        for (int i : b.members) {
          y_[phi_index(i)] += shift;
          at_limiter[i] = true;
        }
        y_[phi_index(w.pellet)] = w.target;
        const int front = b.s > 0 ? b.members.back() : b.members.front();
        limiter_contacts.push_back({front, w.limiter, -b.s});
        break;
      }
      case WatchKind::reversal:
        for (int i : bodies_[w.body].members) {
          y_[dphi_index(i)] = 0.0;
          reversed[i] = true;
        }
        break;
      case WatchKind::gap: {
        const double off = w.target;
        double& pb = y_[phi_index(w.pellet)];
        double& pa = y_[phi_index(w.other)];
        if (at_limiter[w.pellet]) {
          pa = pb - off;
        } else if (at_limiter[w.other]) {
          pb = pa + off;
        } else {
          const double mid = 0.5 * (pb + pa + off);
          pb = mid;
          pa = mid - off;
        }
        pair_contacts.push_back({w.pellet, w.other});
        break;
      }
      case WatchKind::release:
      case WatchKind::separation:
        for (int i : bodies_[w.body].members) released[i] = true;
        break;
    }
  }
  snap_touching(y_, neighbours_, contact_distance_, at_limiter, pair_contacts);
  // Standing contacts: bodies resting on limiters, and pellets moving together.
  for (const Body& b : bodies_) {
    if (b.mode == Mode::resting) {
      const int nearest = b.side > 0 ? b.members.front() : b.members.back();
      limiter_contacts.push_back({nearest, b.limiter, b.side});
    }
    for (std::size_t k = 0; k + 1 < b.members.size(); ++k) {
      bool split = false;
      for (const Crossing& c : crossings) {
        const Watch& w = watches_[c.watch];
        split = split || (w.kind == WatchKind::separation && &bodies_[w.body] == &b &&
                          w.split == static_cast<int>(k) + 1);
      }
      if (!split) pair_contacts.push_back({b.members[k], b.members[k + 1]});
    }
  }

  resolve_instant(t, limiter_contacts, pair_contacts, reversed, released);
}

// Impacts among the contacts of an instant, then the modes that follow; the events of both.
void Simulation::resolve_instant(double t, const std::vector<LimiterContact>& limiter_contacts,
                                 const std::vector<PairContact>& pair_contacts,
                                 const std::vector<bool>& reversed,
                                 const std::vector<bool>& released) {
  std::vector<double> v(n_), place(n_);
  for (int i = 0; i < n_; ++i) {
    v[i] = y_[dphi_index(i)];
    place[i] = y_[phi_index(i)];
  }
  const std::vector<double> v_before = v;
  std::vector<Event> impacts =
      resolve_impacts(model_, v, armed_, limiter_contacts, pair_contacts, place);
  std::vector<int> struck_limiter_of(n_, -1);
  std::vector<bool> touched(n_, false);
  for (int i = 0; i < n_; ++i) {
    impact_losses_ += 0.5 * model_.pellets[i].m * model_.R * model_.R *
                      (v[i] * v[i] - v_before[i] * v_before[i]);
    y_[dphi_index(i)] = v[i];
  }
  for (Event& e : impacts) {
    for (int i : e.pellets) touched[i] = true;
    if (e.kind == EventKind::limiter) struck_limiter_of[e.pellets[0]] = e.limiter;
    add_event(std::move(e), t);
  }
  assign_modes(t, limiter_contacts, pair_contacts, struck_limiter_of, reversed, released, touched);
  for (int i = 0; i < n_; ++i)
    if (touched[i]) recorder_.end_branch(i);
  check_energy();
}

void Simulation::initial_instant() {
  bodies_.clear();
  for (int i = 0; i < n_; ++i) {
    Body b;
    b.members = {i};
    const double v = y_[dphi_index(i)];
    b.mode = v == 0.0 ? Mode::stuck : Mode::sliding;
    b.s = v < 0.0 ? -1 : 1;
    bodies_.push_back(b);
  }
  // A pellet that starts on an armed limiter strikes it at t = 0 if it moves, or rests on it.
  std::vector<LimiterContact> contacts;
  for (int i = 0; i < n_; ++i) {
    const double phi = y_[phi_index(i)];
    for (int l = 0; l < static_cast<int>(model_.limiters.size()); ++l) {
      const double d = wrap_angle(phi - model_.limiters[l].angle);
      if (!model_.limiters[l].acts_on(i) || std::abs(d) > 1e-12 * (1.0 + std::abs(phi))) continue;
      y_[phi_index(i)] = phi - d;
      const double v = y_[dphi_index(i)];
      const double a = free_acceleration(model_, i, 0.0, phi);
      const int side = v != 0.0 ? (v > 0.0 ? -1 : 1) : (a > 0.0 ? -1 : 1);
      contacts.push_back({i, l, side});
    }
  }
  const std::vector<bool> none(n_, false);
  resolve_instant(0.0, contacts, {}, none, none);
}

void Simulation::start_segment(double t) {
  watches_.clear();
  first_integral_.clear();
  const bool unforced_paper = model_.friction == FrictionLaw::paper;
  for (int b = 0; b < static_cast<int>(bodies_.size()); ++b) {
    const Body& body = bodies_[b];
    const int L = body.leader();
    bool forced = false;
    for (int i : body.members) forced = forced || model_.pellets[i].force.active();
    std::unique_ptr<FirstIntegral> fi;
    if (body.mode == Mode::sliding) {
      watches_.push_back({WatchKind::reversal, b, L});
      int lim;
      double target;
      if (next_limiter(model_, armed_, body, y_[phi_index(L)], body.s, lim, target)) {
        watches_.push_back({WatchKind::limiter, b, L, -1, lim, target});
      }
      if (unforced_paper && !forced && body.members.size() == 1) {
        fi = std::make_unique<FirstIntegral>(model_, body.s, y_[phi_index(L)], y_[dphi_index(L)]);
      }
    } else if (forced) {
      watches_.push_back({WatchKind::release, b, L});
    }
    first_integral_.push_back(std::move(fi));
    for (int k = 1; k < static_cast<int>(body.members.size()); ++k) {
      Watch w{WatchKind::separation, b, L};
      w.split = k;
      watches_.push_back(w);
    }
  }
  // Gaps between neighbours in different bodies.
  std::vector<int> body_of(n_);
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    for (int i : bodies_[b].members) body_of[i] = static_cast<int>(b);
  for (const Neighbours& nb : neighbours_) {
    if (body_of[nb.behind] == body_of[nb.ahead]) continue;
    Watch w{WatchKind::gap, -1, nb.behind, nb.ahead};
    w.target = nb.offset;
    const double gap = y_[phi_index(nb.ahead)] - y_[phi_index(nb.behind)] + nb.offset;
    if (gap <= contact_distance_ * (1.0 + std::abs(y_[phi_index(nb.behind)]))) {
      deflate(w, model_, bodies_, t, y_, y_[dphi_index(nb.ahead)] - y_[dphi_index(nb.behind)]);
    }
    watches_.push_back(w);
  }
  dynamics_ = std::make_unique<SegmentDynamics>(model_, bodies_);
  stepper_->start(*dynamics_, t, y_);
  finder_.start(watches_, model_, bodies_, t, y_);
  recorder_.sample(t, y_);
  recorder_.check_normal_force(t, y_, bodies_);
}

RunResult Simulation::run() {
  const auto t0 = Clock::now();
  result_.summary.impacts_by_limiter.assign(model_.limiters.size(), std::vector<int>(n_, 0));
  result_.stats.method = std::string(method_name(opt_.method));
  result_.stats.rtol = opt_.rtol;
  result_.stats.atol = opt_.atol;

  double t = 0.0;
  const double t_end = opt_.t_end;
  initial_instant();
  const int m = std::max(opt_.samples_per_step, 2);
  std::vector<double> times(m + 1);
  std::vector<Vec> states(m + 1, Vec(3 * n_));
  Vec y_event(3 * n_);

  while (!stopped_ && t < t_end) {
    start_segment(t);
    bool anything_moves = false;
    bool forced_rest = false;
    for (const Body& b : bodies_) {
      anything_moves = anything_moves || b.mode == Mode::sliding;
      for (int i : b.members)
        forced_rest = forced_rest || (b.mode != Mode::sliding && model_.pellets[i].force.active());
    }
    if (!anything_moves && !forced_rest) {
      t = t_end;  // everything rests and nothing can pull it away: the rest of the run is known
      break;
    }
    double h_max = std::numeric_limits<double>::infinity();
    if (forced_rest) {  // a release is a root in time alone: sample the forcing finely enough
      for (const Pellet& p : model_.pellets)
        if (p.force.active() && p.force.Omega != 0.0)
          h_max = std::min(h_max, kTwoPi / std::abs(p.force.Omega) / 16.0);
    }
    bool event = false;
    while (!stopped_ && !event && t < t_end) {
      const double limit = std::min(t_end, stepper_->t() + h_max);
      const StepStatus status = stepper_->step(limit);
      if (status != StepStatus::ok) {
        result_.stats.termination = Termination::numerical_failure;
        fail(stepper_->t(), status == StepStatus::step_underflow ? "the step size underflowed"
                            : status == StepStatus::non_finite
                                ? "the state became non-finite"
                                : "the implicit method's Newton iteration failed");
        t = stepper_->t();
        break;
      }
      const double a = stepper_->t_prev(), b = stepper_->t();
      for (int k = 0; k < m; ++k) {
        times[k] = a + (b - a) * (k + 1) / (m + 1);
        stepper_->dense(times[k], states[k]);
      }
      times[m] = b;
      states[m] = stepper_->y();
      const double simultaneous = 1e-12 * (1.0 + std::abs(b));
      std::vector<Crossing> found = finder_.find(
          watches_, model_, bodies_, a, times, states, simultaneous,
          [&](double tt, Vec& out) { stepper_->dense(tt, out); });
      const double t_stop = found.empty() ? b : found.front().t;
      for (int k = 0; k <= m && times[k] < t_stop; ++k) recorder_.sample(times[k], states[k]);
      if (found.empty()) {
        t = b;
        y_ = stepper_->y();
        recorder_.check_normal_force(t, y_, bodies_);
      } else {
        t = found.front().t;
        stepper_->dense(t, y_event);
        y_ = y_event;
        first_integral_check(y_);
        recorder_.sample(t, y_);
        recorder_.check_normal_force(t, y_, bodies_);
        same_instant_ = std::abs(t - last_instant_) <= simultaneous ? same_instant_ + 1 : 0;
        last_instant_ = t;
        if (same_instant_ > 1000) {
          result_.stats.termination = Termination::numerical_failure;
          fail(t, "events do not advance in time (an unresolved Zeno sequence)");
          break;
        }
        instant(t, found);
        event = true;
      }
      if (!std::isfinite(y_.sum())) {
        result_.stats.termination = Termination::numerical_failure;
        fail(t, "the state became non-finite");
      }
      if (!stopped_) over_budget(t);
    }
  }
  if (!stopped_) {
    t = std::max(t, t_end);
    first_integral_check(y_);
    check_energy();
  }
  if (stopped_) {
    // Report the last finite state.
    if (!std::isfinite(y_.sum())) y_ = stepper_->y();
  }
  recorder_.sample(std::min(t, t_end), y_);
  recorder_.finish(t, result_);
  std::stable_sort(result_.events.begin(), result_.events.end(),
                   [](const Event& a, const Event& b) { return a.t < b.t; });

  for (int i = 0; i < n_; ++i) {
    FinalState f;
    f.phi = y_[phi_index(i)];
    f.dphi = y_[dphi_index(i)];
    for (const Body& b : bodies_) {
      for (int j : b.members) {
        if (j != i) continue;
        f.state = b.mode == Mode::sliding ? PelletState::sliding
                  : b.mode == Mode::stuck ? PelletState::stuck
                                          : PelletState::resting_at_limiter;
        f.limiter = b.mode == Mode::resting ? b.limiter : -1;
      }
    }
    if (!std::isfinite(f.phi) || !std::isfinite(f.dphi)) f = FinalState{};
    result_.summary.final.push_back(f);
  }
  const StepperStats& s = stepper_->stats();
  Stats& st = result_.stats;
  st.steps = s.steps;
  st.rejected = s.rejected;
  st.rhs_evals = s.rhs_evals;
  st.jac_evals = s.jac_evals;
  st.lu_decomps = s.lu_decomps;
  st.stiff_switches = s.stiff_switches;
  st.energy_defect = max_energy_defect_;
  st.first_integral_residual = max_fi_residual_;
  st.error_estimate = std::max(max_energy_defect_, max_fi_residual_);
  st.t_reached = std::min(t, t_end);
  st.wall_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  return std::move(result_);
}

}  // namespace

RunResult simulate(const Model& model, const SimOptions& options) {
  return Simulation(model, options, nullptr).run();
}

RunResult simulate(const Model& model, const SimOptions& options, std::unique_ptr<Stepper> stepper) {
  return Simulation(model, options, std::move(stepper)).run();
}

}  // namespace vibro
