#include "tests/differential/checks.h"

#include <algorithm>
#include <cctype>
#include <limits>
#include <sstream>
#include <tuple>
#include <vector>

#include "core/analysis/checked_run.h"
#include "tests/differential/conditioning.h"

namespace vibro::differential {
namespace {

std::string run_name(Method method, double rtol) {
  std::ostringstream s;
  s << method_name(method) << "@" << rtol;
  return s.str();
}

// The text with its numbers dropped: "event 3 (chatter [0] L1 at t=-5.5): ..." -> "event
// (chatter [] L at t=): ...".
std::string without_numbers(const std::string& text) {
  std::string out;
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    const bool number_char = std::isdigit(static_cast<unsigned char>(c)) || c == '.' ||
                             ((c == '-' || c == '+' || c == 'e') && k + 1 < text.size() &&
                              std::isdigit(static_cast<unsigned char>(text[k + 1])));
    if (!number_char) out += c;
  }
  return out;
}

// A sequence or time mismatch between two runs, with the conditioning of the events involved
// and the likely cause it suggests. The signature is completed by the caller.
Finding mismatch(const Model& model, const RunResult& a, const RunResult& b, const Comparison& c,
                 const std::string& name_a, const std::string& name_b, bool across_methods) {
  Finding f;
  const bool sequence = c.verdict == Verdict::sequence;
  f.cls = across_methods
              ? (sequence ? FailureClass::methods_sequence : FailureClass::methods_time)
              : (sequence ? FailureClass::convergence_sequence : FailureClass::convergence_time);
  constexpr double inf = std::numeric_limits<double>::infinity();
  f.margin = f.isolation = f.earlier_margin = inf;
  std::ostringstream s;
  s << describe(c, name_a, name_b) << "; margins:";
  auto note = [&](const std::string& name, const RunResult& run, const std::optional<Event>& e) {
    if (!e) return Margin{inf, "none"};
    const Margin m = event_margin(model, *e);
    std::size_t k = 0;
    while (k + 1 < run.events.size() && run.events[k].t < e->t) ++k;
    const double iso = isolation(model, run, k);
    s << " " << name << " " << m.what << " " << m.value << ", isolation " << iso << ";";
    f.margin = std::min(f.margin, m.value);
    f.isolation = std::min(f.isolation, iso);
    return m;
  };
  MismatchContext context{note(name_a, a, c.a), note(name_b, b, c.b), f.isolation};
  context.slowest = inf;
  for (const Margin* m : {&context.a, &context.b})
    if (m->is_speed) context.slowest = std::min(context.slowest, m->value);
  for (const RunResult* run : {&a, &b}) {
    for (std::size_t k = 0; k < c.index && k < run->events.size(); ++k) {
      const Margin m = event_margin(model, run->events[k]);
      f.earlier_margin = std::min(f.earlier_margin, m.value);
      context.earlier_ill = context.earlier_ill || (m.ill && !m.round_off);
      if (m.is_speed) context.slowest = std::min(context.slowest, m.value);
    }
  }
  if (!sequence) context.excess = c.dt / c.tolerance;
  context.regrouped = c.a && c.b && c.a->kind == EventKind::collision &&
                      c.b->kind == EventKind::collision && c.dt <= c.tolerance;
  f.cause = likely_cause(context);
  s << " earlier events' smallest margin " << f.earlier_margin << "; likely cause "
    << cause_name(f.cause);
  f.detail = s.str();
  return f;
}

// The event-time errors two checked runs state, with the factor of ten the trust contract
// allows an estimate to fall short by.
double stated(const RunResult& a, const RunResult& b) {
  return 10.0 * (a.stats.event_time_error + b.stats.event_time_error);
}

// Two runs of the scene at rtol compared over the events both vouch for, where the runs take the
// trust horizon: the events from the earlier trusted_until on are dropped from both.
Comparison compare_trusted(const SceneRuns& runs, RunResult& a, RunResult& b, double rtol) {
  double t_end = runs.scene().t_end;
  if (runs.trust_horizon()) {
    t_end = std::min({t_end, a.stats.trusted_until, b.stats.trusted_until});
    for (RunResult* r : {&a, &b})
      std::erase_if(r->events, [&](const Event& e) { return e.t >= t_end; });
  }
  TimeTolerance tol{rtol, time_scale(runs.scene().model)};
  if (runs.trust_horizon()) tol.stated = stated(a, b);
  return compare_runs(a, b, tol, t_end);
}

}  // namespace

const RunResult& SceneRuns::run(Method method, double rtol) {
  const auto key = std::make_pair(method, rtol);
  auto it = runs_.find(key);
  if (it == runs_.end()) {
    SimOptions options = run_options(scene_, method, rtol);
    options.check = trust_horizon_;
    if (!bounded_) options.deadline_ms = std::numeric_limits<double>::infinity();
    it = runs_.emplace(key, simulate(scene_.model, options)).first;
  }
  return it->second;
}

std::string_view class_name(FailureClass c) {
  switch (c) {
    case FailureClass::methods_sequence:
      return "methods: sequence";
    case FailureClass::methods_time:
      return "methods: time";
    case FailureClass::convergence_sequence:
      return "rtol/10: sequence";
    case FailureClass::convergence_time:
      return "rtol/10: time";
    case FailureClass::physics:
      return "physics";
  }
  return "?";
}

bool incomplete(SceneRuns& runs, double rtol) {
  for (Method m : kMethods)
    if (stopped_by_budget(runs.run(m, rtol))) return true;
  return false;
}

std::optional<Finding> methods_disagree(SceneRuns& runs, double rtol) {
  const Model& model = runs.scene().model;
  const TimeTolerance tol{rtol, time_scale(model)};
  constexpr int n = static_cast<int>(kMethods.size());
  double t_end = runs.scene().t_end;
  if (runs.trust_horizon())
    for (Method m : kMethods) t_end = std::min(t_end, runs.run(m, rtol).stats.trusted_until);
  std::vector<RunResult> run(n);  // each method's events before t_end
  for (int i = 0; i < n; ++i) {
    const RunResult& full = runs.run(kMethods[i], rtol);
    run[i].events = full.events;
    run[i].stats = full.stats;
    std::erase_if(run[i].events, [&](const Event& e) { return e.t >= t_end; });
  }
  // cmp[i][j], i < j: methods i and j compared.
  std::vector<std::vector<Comparison>> cmp(n, std::vector<Comparison>(n));
  bool all_agree = true;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      TimeTolerance pair = tol;
      if (runs.trust_horizon()) pair.stated = stated(run[i], run[j]);
      cmp[i][j] = compare_runs(run[i], run[j], pair, t_end);
      all_agree = all_agree && cmp[i][j].verdict == Verdict::agree;
    }
  if (all_agree) return std::nullopt;
  // Groups of agreeing methods (each joins the first group whose first member it agrees
  // with), largest first: "dopri5+radau5 | dop853+auto" says which side each method is on.
  auto agree = [&](int i, int j) {
    return cmp[std::min(i, j)][std::max(i, j)].verdict == Verdict::agree;
  };
  std::vector<std::vector<int>> groups;
  for (int i = 0; i < n; ++i) {
    auto g =
        std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return agree(g[0], i); });
    if (g == groups.end())
      groups.push_back({i});
    else
      g->push_back(i);
  }
  std::stable_sort(groups.begin(), groups.end(),
                   [](const auto& a, const auto& b) { return a.size() > b.size(); });
  std::string split;
  for (const auto& g : groups) {
    split += split.empty() ? "" : " | ";
    for (std::size_t k = 0; k < g.size(); ++k) {
      if (k > 0) split += "+";
      split += method_name(kMethods[g[k]]);
    }
  }
  // Report the first member of the largest group against that of the next; when agreement is
  // not transitive (all in one group: a agrees with b and c, which disagree), the first
  // disagreeing pair.
  int pi = 0, pj = 1;
  if (groups.size() > 1) {
    pi = std::min(groups[0][0], groups[1][0]);
    pj = std::max(groups[0][0], groups[1][0]);
  } else {
    while (agree(pi, pj))
      std::tie(pi, pj) = pj + 1 < n ? std::pair{pi, pj + 1} : std::pair{pi + 1, pi + 2};
    split = std::string(method_name(kMethods[pi])) + " ~ " + std::string(method_name(kMethods[pj]));
  }
  const Comparison& c = cmp[pi][pj];
  const Method a = kMethods[pi], b = kMethods[pj];
  Finding f = mismatch(model, run[pi], run[pj], c, run_name(a, rtol), run_name(b, rtol), true);
  f.rtol = rtol;
  f.signature =
      std::string(class_name(f.cls)) + ", " + split + ": " + std::string(cause_name(f.cause));
  f.detail = split + ": " + f.detail;
  return f;
}

std::optional<Finding> rtol_disagrees(SceneRuns& runs, Method method, double rtol) {
  const Model& model = runs.scene().model;
  RunResult a = runs.run(method, rtol);
  RunResult b = runs.run(method, rtol / 10.0);
  const Comparison c = compare_trusted(runs, a, b, rtol);
  if (c.verdict == Verdict::agree) return std::nullopt;
  Finding f =
      mismatch(model, a, b, c, run_name(method, rtol), run_name(method, rtol / 10.0), false);
  f.method = method;
  f.rtol = rtol;
  f.signature = std::string(class_name(f.cls)) + ", " + std::string(method_name(method)) + ": " +
                std::string(cause_name(f.cause));
  return f;
}

std::optional<Finding> passed_reversals_disagree(SceneRuns& runs, Method method, double rtol) {
  const Model& model = runs.scene().model;
  RunResult listed = runs.run(method, rtol);
  SimOptions options = run_options(runs.scene(), method, rtol);
  options.check = runs.trust_horizon();
  options.frictionless_reversals = false;
  RunResult passed = simulate(model, options);
  // A body of one pellet passes its reversals; a body of several still lists them, but an event
  // does not say which it was (two bodies that turn at one instant are one reversal): the
  // reversals are left out of both.
  for (RunResult* r : {&listed, &passed})
    std::erase_if(r->events, [](const Event& e) { return e.kind == EventKind::reversal; });
  const Comparison c = compare_trusted(runs, listed, passed, rtol);
  if (c.verdict == Verdict::agree) return std::nullopt;
  const std::string name = run_name(method, rtol);
  Finding f = mismatch(model, listed, passed, c, name, name + " passing reversals", false);
  f.method = method;
  f.rtol = rtol;
  f.signature = "passed reversals, " + std::string(method_name(method)) + ": " +
                std::string(cause_name(f.cause));
  return f;
}

std::optional<Finding> physics_fails(SceneRuns& runs, Method method, double rtol) {
  const RunResult& run = runs.run(method, rtol);
  auto v = physics_violation(runs.scene().model, run, runs.scene().t_end);
  if (!v) return std::nullopt;
  Finding f;
  f.cls = FailureClass::physics;
  f.method = method;
  f.rtol = rtol;
  f.signature = "physics: " + without_numbers(*v);
  f.detail = run_name(method, rtol) + ": " + *v;
  return f;
}

std::string describe(const Finding& f) { return std::string(class_name(f.cls)) + ": " + f.detail; }

std::optional<Finding> check_again(const RandomScene& scene, const Finding& finding) {
  SceneRuns runs(scene);
  std::optional<Finding> again;
  switch (finding.cls) {
    case FailureClass::methods_sequence:
    case FailureClass::methods_time:
      if (!incomplete(runs, finding.rtol)) again = methods_disagree(runs, finding.rtol);
      break;
    case FailureClass::convergence_sequence:
    case FailureClass::convergence_time:
      if (!incomplete(runs, finding.rtol) && !incomplete(runs, finding.rtol / 10.0))
        again = rtol_disagrees(runs, finding.method, finding.rtol);
      break;
    case FailureClass::physics:
      if (!stopped_by_budget(runs.run(finding.method, finding.rtol)))
        again = physics_fails(runs, finding.method, finding.rtol);
      break;
  }
  return again;
}

bool reproduces(const RandomScene& scene, const Finding& finding) {
  const std::optional<Finding> again = check_again(scene, finding);
  return again && again->signature == finding.signature;
}

}  // namespace vibro::differential
