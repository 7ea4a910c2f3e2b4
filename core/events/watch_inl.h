// Template definitions for watch.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace vibro {

template <class F>
double brent_root(F&& f, double a, double b, double fa, double fb) {
  // Keeps [lo, hi] with f(lo) > 0 >= f(hi) and returns hi: the event is then certainly
  // reached, never reported a hair before it.
  double lo = a, hi = b, flo = fa, fhi = fb;
  double c = lo, fc = flo, d = hi - lo, e = d;
  for (int iter = 0; iter < 200; ++iter) {
    const double tol = 4.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(hi));
    if (hi - lo <= tol || fhi == 0.0) break;
    // Brent's step from the current best point hi, with the other end lo.
    double m = 0.5 * (lo - hi);
    double p, q;
    double x;
    if (std::abs(e) >= tol && std::abs(fc) > std::abs(fhi)) {
      double s = fhi / fc;
      if (c == lo) {
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {
        const double qq = fc / flo, r = fhi / flo;
        p = s * (2.0 * m * qq * (qq - r) - (hi - c) * (r - 1.0));
        q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0)
        q = -q;
      else
        p = -p;
      if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    x = hi + (std::abs(d) > tol ? d : (m > 0 ? tol : -tol) * 0.5);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double fx = f(x);
    c = hi;
    fc = fhi;
    if (fx > 0.0) {
      lo = x;
      flo = fx;
    } else {
      hi = x;
      fhi = fx;
    }
  }
  return hi;
}

template <class Dense>
bool CrossingFinder::march(const Watch& w, const Model& model, const std::vector<Body>& bodies,
                           double t, Closing c, double t_end, Dense& dense, double& lo, double& hi,
                           double& g_lo, double& g_hi) {
  // From each point to where its quadratic (or, without a curvature, its tangent) meets zero:
  // there the watch has crossed, or it is followed on toward its minimum, until the prediction
  // points past t_end or away.
  Vec& y = scratch_left_;  // sized by find
  for (int k = 0; k < 64; ++k) {
    const double next = t + c.time_to_zero();
    if (!(next < t_end) || !(next > t)) return false;
    dense(next, y);
    const Closing at = closing(w, model, *law_, bodies, next, y, true);
    if (at.value <= 0.0) {
      lo = t;
      hi = next;
      dense(t, y);
      g_lo = evaluate(w, model, bodies, t, y);
      dense(next, y);
      g_hi = evaluate(w, model, bodies, next, y);
      return g_lo > 0.0 && g_hi <= 0.0;
    }
    t = next;
    c = at;
  }
  return false;
}

template <class Dense>
bool CrossingFinder::minimum_between(const Watch& w, int index, const Model& model,
                                     const std::vector<Body>& bodies, double t_a, const Closing& a,
                                     double t_b, const Closing& b, Dense& dense, double& lo,
                                     double& hi, double& g_lo, double& g_hi,
                                     std::vector<Graze>& grazes) {
  Vec& y = scratch_left_;  // sized by find
  const double tm = brent_root(
      [&](double t) {
        dense(t, y);
        return -closing(w, model, *law_, bodies, t, y).rate;
      },
      t_a, t_b, -a.rate, -b.rate);
  dense(tm, y);
  const Closing m = closing(w, model, *law_, bodies, tm, y);
  if (m.value <= 0.0) {
    lo = t_a;
    hi = tm;
    g_hi = evaluate(w, model, bodies, tm, y);
    dense(t_a, y);
    g_lo = evaluate(w, model, bodies, t_a, y);
    return g_lo > 0.0 && g_hi <= 0.0;
  }
  // Half the second derivative there, from the rates either side.
  const double c = 0.5 * (b.rate - a.rate) / (t_b - t_a);
  if (auto graze = near_miss(w, tm, m.value, c, largest_[index], y)) grazes.push_back(*graze);
  return false;
}

template <class Dense>
std::vector<Crossing> CrossingFinder::find(const std::vector<Watch>& watches, const Model& model,
                                           const std::vector<Body>& bodies, double t_prev,
                                           std::span<const double> times,
                                           std::span<const Vec> states, double simultaneous,
                                           Dense&& dense) {
  struct Bracket {
    int watch;
    double a, b, fa, fb;
  };
  std::vector<Bracket> brackets;
  std::vector<Graze> grazes;
  scratch_.resize(states.front().size());
  scratch_left_.resize(states.front().size());
  // The values calm() found at this step's end, and which watches it found calm over the step.
  const std::size_t end = times.size() - 1;
  const bool judged = times[end] == calm_end_;
  for (std::size_t w = 0; w < watches.size(); ++w) {
    const bool of_time = depends_on_time_alone(watches[w]);
    const bool follows = follows_motion(watches[w].kind);
    for (std::size_t k = judged && calm_[w] ? end : 0; k < times.size(); ++k) {
      const double t_before = k == 0 || (judged && calm_[w]) ? t_prev : times[k - 1];
      const bool at_end = judged && k == end;
      const double g =
          at_end ? end_value_[w] : evaluate(watches[w], model, bodies, times[k], states[k]);
      if (armed_[w] && of_time) {
        Bracket first{static_cast<int>(w), 0.0, 0.0, 0.0, 0.0};
        if (scan_between(watches[w], model, bodies, states[k], t_before, last_[w], times[k], g,
                         first.a, first.b, first.fa, first.fb)) {
          brackets.push_back(first);
          break;
        }
      } else if (armed_[w] && g <= 0.0) {
        brackets.push_back({static_cast<int>(w), t_before, times[k], last_[w], g});
        break;
      } else if (follows && armed_[w] && closing_[w].meets_within(times[k] - t_before)) {
        // Closing fast enough to meet before this sample, yet apart at it: the two may have
        // met and parted between (a pellet knocked onto another 7e-9 rad ahead at 0.8 rad/s,
        // pressed back at 1e4 rad/s², apart again at the step's samples 1e-4 s later; two
        // pellets parting at 8e-5 rad/s, pressed together again within 5e-4 s, a step 8e-3 s).
        Bracket met{static_cast<int>(w), 0.0, 0.0, 0.0, 0.0};
        if (march(watches[w], model, bodies, t_before, closing_[w], times[k], dense, met.a, met.b,
                  met.fa, met.fb)) {
          brackets.push_back(met);
          break;
        }
      }
      Closing now;
      if (follows) {
        now = at_end ? end_closing_[w]
                     : closing(watches[w], model, *law_, bodies, times[k], states[k]);
        if (watches[w].kind != WatchKind::reversal)
          now.curvature = (now.rate - closing_[w].rate) / (times[k] - t_before);
        largest_[w] = std::max(largest_[w], now.value);
        Bracket met{static_cast<int>(w), 0.0, 0.0, 0.0, 0.0};
        if (armed_[w] && g > 0.0 && closing_[w].value > 0.0 && closing_[w].rate < 0.0 &&
            now.rate > 0.0 &&
            minimum_between(watches[w], static_cast<int>(w), model, bodies, t_before, closing_[w],
                            times[k], now, dense, met.a, met.b, met.fa, met.fb, grazes)) {
          brackets.push_back(met);
          break;
        }
      }
      if (g > 0.0) armed_[w] = true;
      last_[w] = g;
      if (follows) closing_[w] = now;
    }
  }
  std::sort(brackets.begin(), brackets.end(),
            [](const Bracket& x, const Bracket& y) { return x.b < y.b; });
  std::vector<Crossing> found;
  double earliest = std::numeric_limits<double>::infinity();
  Vec& y = scratch_;
  y.resize(states.front().size());
  for (const Bracket& br : brackets) {
    if (br.a > earliest + simultaneous) break;
    const Watch& w = watches[br.watch];
    auto g = [&](double t) {
      dense(t, y);
      return evaluate(w, model, bodies, t, y);
    };
    const double t = brent_root(g, br.a, br.b, br.fa, br.fb);
    found.push_back({br.watch, t});
    earliest = std::min(earliest, t);
  }
  // A watch may have dipped below zero and come back between two samples before the earliest
  // crossing (a pellet that overshoots a limiter just before it reverses). At the earliest
  // crossing, every watch must still be positive; one that is not crossed earlier: find it.
  for (int pass = 0; pass < 8 && std::isfinite(earliest); ++pass) {
    dense(earliest, y);
    bool added = false;
    for (std::size_t w = 0; w < watches.size(); ++w) {
      if (!armed_[w] || std::any_of(found.begin(), found.end(), [&](const Crossing& c) {
            return c.watch == static_cast<int>(w);
          }))
        continue;
      const double g_end = evaluate(watches[w], model, bodies, earliest, y);
      if (g_end > 0.0) continue;
      // The last sample before `earliest` where it was positive brackets the root.
      double a = t_prev, fa = 0.0;
      Vec& ya = scratch_left_;
      ya.resize(y.size());
      dense(t_prev, ya);
      fa = evaluate(watches[w], model, bodies, t_prev, ya);
      for (std::size_t k = 0; k < times.size() && times[k] < earliest; ++k) {
        const double g = evaluate(watches[w], model, bodies, times[k], states[k]);
        if (g > 0.0) {
          a = times[k];
          fa = g;
        }
      }
      if (!(fa > 0.0)) continue;
      const Watch& watch = watches[w];
      auto g = [&](double t) {
        dense(t, ya);
        return evaluate(watch, model, bodies, t, ya);
      };
      const double t = brent_root(g, a, earliest, fa, g_end);
      found.push_back({static_cast<int>(w), t});
      earliest = std::min(earliest, t);
      added = true;
    }
    if (!added) break;
  }
  std::erase_if(found, [&](const Crossing& c) { return c.t > earliest + simultaneous; });
  auto keep = [&](const Graze& g) {
    if (!first_graze_ || g.earliest < first_graze_->earliest) first_graze_ = g;
  };
  // Near misses before the step's first event (after it, another interval starts).
  for (const Graze& g : grazes)
    if (g.t < earliest) keep(g);
  // A body that turns within its error of the limiter ahead of it may as well have struck it,
  // and one that strikes within its error of turning may as well have turned.
  if (std::isfinite(earliest)) {
    dense(earliest, y);
    for (const Crossing& c : found) {
      const Watch& turn = watches[c.watch];
      if (turn.kind == WatchKind::limiter || turn.kind == WatchKind::gap) {
        if (auto graze = grazing_crossing(
                turn, earliest, closing(turn, model, *law_, bodies, earliest, y, true), y))
          keep(*graze);
        continue;
      }
      if (turn.kind != WatchKind::reversal) continue;
      // At the turn the way left to the limiter is at its minimum, curving up at half the
      // deceleration.
      const double curvature = -0.5 * closing(turn, model, *law_, bodies, earliest, y).rate;
      for (const Watch& lim : watches)
        if (lim.kind == WatchKind::limiter && lim.body == turn.body)
          if (auto graze = near_miss(lim, earliest, raw_value(lim, model, bodies, earliest, y),
                                     curvature, 0.0, y))
            keep(*graze);
    }
  }
  std::sort(found.begin(), found.end(),
            [](const Crossing& x, const Crossing& y) { return x.t < y.t; });
  return found;
}

}  // namespace vibro
