#include "core/run/recorder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/events/narrow_bracket.h"
#include "core/integrators/series.h"
#include "core/model/dynamics.h"
#include "core/run/negative_normal.h"

namespace vibro {
namespace {
constexpr std::size_t kMaxWarnings = 100;
const double kNone = std::numeric_limits<double>::quiet_NaN();
}  // namespace

Recorder::Recorder(const Model& model, const std::vector<bool>& record, double record_until,
                   long max_samples)
    : model_(model),
      track_of_(model.size(), -1),
      open_(model.size(), false),
      record_until_(record_until),
      max_samples_(max_samples),
      negative_since_(model.size(), kNone),
      near_top_(model.size(), false),
      stretch_length_(model.size(), 0.0),
      warning_of_(model.size(), -1),
      stretches_(model.size(), 0) {
  for (int i = 0; i < model.size(); ++i) {
    if (i < static_cast<int>(record.size()) && record[i]) {
      track_of_[i] = static_cast<int>(tracks_.size());
      tracks_.push_back({i, {}});
    }
  }
  pending_.resize(tracks_.size());
  lowest_.assign(2 * tracks_.size(), std::numeric_limits<double>::infinity());
  highest_.assign(2 * tracks_.size(), -std::numeric_limits<double>::infinity());
}

int Recorder::pieces(const Vec& start, const Vec& inside, double theta, const Vec& end,
                     int fewest) {
  constexpr double kChord = 1e-4;
  constexpr int kMost = 64;
  double worst = 0.0;
  for (std::size_t k = 0; k < tracks_.size(); ++k) {
    const int pellet = tracks_[k].pellet;
    for (int c = 0; c < 2; ++c) {
      const int j = c == 0 ? phi_index(pellet) : dphi_index(pellet);
      double& lo = lowest_[2 * k + c];
      double& hi = highest_[2 * k + c];
      for (double v : {start[j], inside[j], end[j]})
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
      const double chord = start[j] + theta * (end[j] - start[j]);
      const double off = std::abs(inside[j] - chord) / (4.0 * theta * (1.0 - theta));
      if (hi > lo && std::isfinite(off)) worst = std::max(worst, off / (hi - lo));
    }
  }
  const double needed = std::ceil(std::sqrt(worst / kChord));
  return static_cast<int>(
      std::clamp(needed, static_cast<double>(fewest), static_cast<double>(kMost)));
}

void Recorder::sample(double t, const Vec& y) {
  if (t > record_until_) return;
  // The same state twice (a run that ends where its last step did) is one sample, unless it
  // opens a branch an instant ended (an instant that changes no speed, as a reversal): each
  // branch begins at its event's state. At an instant every pellet keeps both states, so that
  // the pellets' samples stay at the same times.
  const bool opens = std::any_of(tracks_.begin(), tracks_.end(),
                                 [&](const PelletTrack& track) { return !open_[track.pellet]; });
  if (t == last_t_ && y == last_y_ && !opens) return;
  last_t_ = t;
  last_y_ = y;
  const bool on_stride = ++calls_ % stride_ == 0;
  for (std::size_t k = 0; k < tracks_.size(); ++k) {
    PelletTrack& track = tracks_[k];
    const int i = track.pellet;
    const Sample s{t, y[phi_index(i)], y[dphi_index(i)]};
    if (!open_[i]) {
      track.branches.push_back({static_cast<int>(track.branches.size()) + 1, {}});
      open_[i] = true;
      keep(track, s);
    } else if (on_stride) {
      pending_[k].reset();
      keep(track, s);
    } else {
      pending_[k] = s;  // kept if it turns out to end the branch
    }
  }
  if (max_samples_ > 0 && kept_ > max_samples_) thin();
}

void Recorder::keep(PelletTrack& track, const Sample& s) {
  track.branches.back().samples.push_back(s);
  ++kept_;
}

void Recorder::flush_pending(int k) {
  if (!pending_[k]) return;
  keep(tracks_[k], *pending_[k]);
  pending_[k].reset();
}

void Recorder::thin() {
  kept_ = 0;
  for (PelletTrack& track : tracks_)
    for (Branch& b : track.branches) {
      std::vector<Sample>& v = b.samples;
      std::size_t out = 0;
      for (std::size_t j = 0; j < v.size(); ++j)
        if (j % 2 == 0 || j + 1 == v.size()) v[out++] = v[j];
      v.resize(out);
      kept_ += static_cast<long>(out);
    }
  stride_ *= 2;
}

// A dip of N below zero strictly inside a step whose checked ends are both positive is not
// looked for: it lasts less than the step, and finding it surely needs N's minimum on the dense
// output of every step near the top (the bodies' accelerations at its ends, or samples inside),
// a cost every sliding step would pay. The event search's samples inside a step would catch some
// such dips for a cos per sample, but only on the steps the search samples inside (those near
// some other watch's root), so that which dips are reported would still depend on the method.
void Recorder::check_normal_force(double t, const Vec& y, const std::vector<Body>& bodies,
                                  const StepView* step) {
  if (model_.friction != FrictionLaw::paper || model_.alpha0 == 0.0) return;
  for (const Body& b : bodies) {
    const int leader = b.leader();
    const bool sliding = b.mode == Mode::sliding;
    const double cos_phi = std::cos(y[phi_index(leader)]);
    const double dphi = y[dphi_index(leader)];
    const bool near_top_now = cos_phi < 0.0 && model_.R * dphi * dphi < 2.0 * model_.g;
    const bool near_top = near_top_now || near_top_[leader];
    near_top_[leader] = near_top_now;
    const bool negative = sliding && model_.g * cos_phi + model_.R * dphi * dphi < 0.0;
    // Positive at both ends, it may still have dipped below zero between them.
    if (step && sliding && !negative && std::isnan(negative_since_[leader]))
      find_negative_inside(*step, b, t, cos_phi, near_top);
    // After each checked point a member's window is open just where its body's N is negative.
    // A body keeps its mode and members through an interval, whose start is checked: at a step's
    // end a member that differs saw N change sign since the step's start, the last checked point.
    double at = t;
    bool located = false;
    for (int i : b.members) {
      if (negative == !std::isnan(negative_since_[i])) continue;
      if (step && sliding && !located) {
        dense_.resize(y.size());
        at = sign_change(*step, leader, step->t_prev(), t, negative);
        located = true;
      }
      if (negative)
        negative_since_[i] = at;
      else
        close_warning(i, at);
    }
  }
}

void Recorder::find_negative_inside(const StepView& step, const Body& body, double t,
                                    double cos_at_t, bool near_top) {
  const int leader = body.leader();
  const std::optional<NegativeStretch> in =
      negative_normal_inside(model_, step, leader, t, cos_at_t, near_top);
  if (!in) return;
  dense_.resize(static_cast<std::size_t>(3 * model_.size()));
  const double begin = sign_change(step, leader, in->begin_lo, in->begin_hi, true);
  const double end = sign_change(step, leader, in->end_lo, in->end_hi, false);
  for (int i : body.members) {
    negative_since_[i] = begin;
    close_warning(i, end);
  }
}

double Recorder::sign_change(const StepView& step, int leader, double lo, double hi,
                             bool to_negative) {
  // Positive before the change, at or below zero after it. A polynomial step's dense output is
  // its polynomials: the leader's two are evaluated alone, by the same sums as dense().
  const StepPolynomials* p = step.polynomials();
  auto f = [&](double s) {
    double phi, dphi;
    if (p) {
      phi = integrators::horner(p->component(phi_index(leader)), s - p->t0);
      dphi = integrators::horner(p->component(dphi_index(leader)), s - p->t0);
    } else {
      step.dense(s, dense_);
      phi = dense_[phi_index(leader)];
      dphi = dense_[dphi_index(leader)];
    }
    const double n = normal_per_mass(model_, phi, dphi);
    return to_negative ? n : -n;
  };
  const double f_lo = f(lo), f_hi = f(hi);
  // The dense output may differ from the checked states by round-off (and from an event's
  // polished state by more): where it does not bracket the change, the change is at that end.
  if (!(f_lo > 0.0)) return lo;
  if (!(f_hi <= 0.0)) return hi;
  // To a nanosecond in a second's span: the window is a warning's, read at a few digits, and
  // the steps toward round-off would take two thirds of the evaluations.
  const auto tolerance = [](double t) { return 1e-9 * std::max(1.0, std::abs(t)); };
  return narrow_bracket(f, {lo, hi, f_lo, f_hi}, true, tolerance).hi;
}

void Recorder::close_warning(int pellet, double t) {
  const double since = negative_since_[pellet];
  if (std::isnan(since)) return;
  negative_since_[pellet] = kNone;
  const int w = warning_of_[pellet];
  const bool same_approach = w >= 0 && since - warnings_[w].t_end < stretch_length_[pellet];
  stretch_length_[pellet] = t - since;
  if (!same_approach) {
    if (warnings_.size() >= kMaxWarnings) return;
    warning_of_[pellet] = static_cast<int>(warnings_.size());
    stretches_[pellet] = 0;
    warnings_.push_back({"negative_normal_force", "", pellet, since, t});
    warning_stretches_.push_back(0);
  }
  warnings_[warning_of_[pellet]].t_end = t;
  warning_stretches_[warning_of_[pellet]] = ++stretches_[pellet];
}

namespace {

// The message of a negative-normal-force warning that holds n stretches.
std::string negative_normal_message(const Warning& warning, int n) {
  std::ostringstream msg;
  msg << "pellet " << warning.pellet + 1 << ": the normal force g cos(phi) + R dphi^2 is negative ";
  if (n > 1) msg << "in " << n << " stretches, each sooner after the last than it lasted, ";
  msg << "from t = " << warning.t_begin << " s to " << warning.t_end
      << " s; there the paper's friction law pushes the pellet along (not physical)";
  return msg.str();
}

}  // namespace

void Recorder::end_branch(int pellet) {
  if (track_of_[pellet] >= 0) flush_pending(track_of_[pellet]);
  open_[pellet] = false;
}

void Recorder::finish(double t, RunResult& result) {
  for (std::size_t k = 0; k < tracks_.size(); ++k) flush_pending(static_cast<int>(k));
  for (int i = 0; i < model_.size(); ++i) close_warning(i, t);
  for (std::size_t w = 0; w < warnings_.size(); ++w)
    warnings_[w].message = negative_normal_message(warnings_[w], warning_stretches_[w]);
  result.tracks = std::move(tracks_);
  result.warnings = std::move(warnings_);
}

}  // namespace vibro
