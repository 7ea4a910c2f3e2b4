#include "tests/differential/minimize.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

#include "core/run/validate.h"

namespace vibro::differential {
namespace {

using Edit = std::function<void(RandomScene&)>;

void remove_limiter(Model& m, int l) {
  m.limiters.erase(m.limiters.begin() + l);
  for (Limiter& o : m.limiters) {
    if (o.rearm_by == l) {
      o.mobile = false;
      o.rearm_by = -1;
    } else if (o.rearm_by > l) {
      --o.rearm_by;
    }
  }
}

void remove_pellet(Model& m, int i) {
  m.pellets.erase(m.pellets.begin() + i);
  for (int l = static_cast<int>(m.limiters.size()) - 1; l >= 0; --l) {
    std::vector<int>& list = m.limiters[l].pellets;
    if (list.empty()) continue;
    std::vector<int> kept;
    for (int p : list)
      if (p != i) kept.push_back(p > i ? p - 1 : p);
    if (kept.empty())
      remove_limiter(m, l);  // it acted on that pellet alone
    else
      list = kept;
  }
}

double round_to(double x, int digits) {
  if (x == 0.0 || !std::isfinite(x)) return x;
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, x);
  return std::strtod(text, nullptr);
}

// Every number of the scene, for rounding, and how many there are.
int number_count(const RandomScene& s) {
  return 4 + (s.model.mu_s ? 1 : 0) + 6 * s.model.size() +
         2 * static_cast<int>(s.model.limiters.size());
}
std::vector<double*> numbers(RandomScene& s) {
  Model& m = s.model;
  std::vector<double*> v = {&s.t_end, &m.R, &m.alpha0, &m.k_c};
  if (m.mu_s) v.push_back(&*m.mu_s);
  for (Pellet& p : m.pellets)
    for (double* x : {&p.m, &p.phi0, &p.dphi0, &p.force.F0, &p.force.Omega, &p.force.psi})
      v.push_back(x);
  for (Limiter& l : m.limiters) v.insert(v.end(), {&l.angle, &l.k});
  return v;
}

// The simplifications of `s`, the boldest first.
std::vector<Edit> edits(const RandomScene& s) {
  const Model& m = s.model;
  std::vector<Edit> e;
  if (s.t_end > 0.01 * time_scale(m))  // shorter runs say nothing a reader can see
    e.push_back([](RandomScene& x) { x.t_end /= 2.0; });
  for (int i = 0; i < m.size() && m.size() > 1; ++i)
    e.push_back([i](RandomScene& x) { remove_pellet(x.model, i); });
  for (int l = 0; l < static_cast<int>(m.limiters.size()); ++l)
    e.push_back([l](RandomScene& x) { remove_limiter(x.model, l); });
  for (int l = 0; l < static_cast<int>(m.limiters.size()); ++l) {
    e.push_back([l](RandomScene& x) {
      x.model.limiters[l].mobile = false;
      x.model.limiters[l].rearm_by = -1;
    });
    e.push_back([l](RandomScene& x) { x.model.limiters[l].pellets.clear(); });
  }
  for (int i = 0; i < m.size(); ++i) {
    e.push_back([i](RandomScene& x) { x.model.pellets[i].force = {}; });
    e.push_back([i](RandomScene& x) { x.model.pellets[i].dphi0 = 0.0; });
    e.push_back([i](RandomScene& x) { x.model.pellets[i].force.psi = 0.0; });
  }
  e.push_back([](RandomScene& x) { x.model.friction = FrictionLaw::paper; });
  e.push_back([](RandomScene& x) { x.model.mu_s.reset(); });
  e.push_back([](RandomScene& x) { x.model.alpha0 = 0.0; });
  e.push_back([](RandomScene& x) { x.model.k_c = 1.0; });
  for (int digits : {1, 2, 3, 4, 6, 8})
    for (int k = 0; k < number_count(s); ++k)
      e.push_back([k, digits](RandomScene& x) {
        double* v = numbers(x)[k];
        *v = round_to(*v, digits);
      });
  return e;
}

std::string text(const RandomScene& s) { return scene_json_text(s, Method::automatic, 1e-9); }

}  // namespace

RandomScene minimize(const RandomScene& scene, const Finding& finding, int attempts) {
  RandomScene best = scene;
  std::string best_text = text(best);
  bool progress = true;
  while (progress && attempts > 0) {
    progress = false;
    // Edits name pellets, limiters and numbers by index: after one that removes some, list
    // them anew.
    for (const Edit& edit : edits(best)) {
      if (attempts <= 0) break;
      RandomScene candidate = best;
      edit(candidate);
      const std::string candidate_text = text(candidate);
      if (candidate_text == best_text || validate_model(candidate.model)) continue;
      --attempts;
      if (!reproduces(candidate, finding)) continue;
      const bool removed = number_count(candidate) != number_count(best);
      best = candidate;
      best_text = candidate_text;
      progress = true;
      if (removed) break;
    }
  }
  return best;
}

}  // namespace vibro::differential
