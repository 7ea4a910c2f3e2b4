#include "io/result_json.h"

#include <cmath>
#include <utility>

#include "io/text_builder.h"

namespace vibro {
namespace {

using nlohmann::json;

json numbers(const std::vector<double>& xs) {
  json a = json::array();
  for (double x : xs) a.push_back(finite_number(x));
  return a;
}

json track_json(const PelletTrack& track) {
  json branches = json::array();
  for (const Branch& b : track.branches) {
    json t = json::array(), phi = json::array(), dphi = json::array();
    for (const Sample& s : b.samples) {
      t.push_back(finite_number(s.t));
      phi.push_back(finite_number(s.phi));
      dphi.push_back(finite_number(s.dphi));
    }
    branches.push_back({{"index", b.index}, {"t", t}, {"phi", phi}, {"dphi", dphi}});
  }
  return {{"pellet", track.pellet}, {"branches", branches}};
}

// An angle as a multiple of π/4 when it is one ("3π/2"), else in decimals at the builder's
// precision.
struct AngleText {
  double phi;
};

TextBuilder& operator<<(TextBuilder& s, AngleText angle) {
  const double q = angle.phi / (M_PI / 4.0);
  // Past 1e6 multiples of π/4 every double is within 1e-9 of an integer, and lround overflows.
  if (!(std::abs(q) < 1e6 && std::abs(q - std::round(q)) < 1e-9 && std::round(q) != 0.0))
    return s << angle.phi;
  const long n = std::lround(q);
  long num = n, den = 4;
  while (num % 2 == 0 && den > 1) {
    num /= 2;
    den /= 2;
  }
  if (num == 1)
    s << "π";
  else if (num == -1)
    s << "-π";
  else
    s << num << "π";
  if (den > 1) s << "/" << den;
  return s;
}

// "1 collision", "2 collisions".
struct CountOf {
  int n;
  std::string_view thing;
};

TextBuilder& operator<<(TextBuilder& s, CountOf c) {
  return s << c.n << " " << c.thing << (c.n == 1 ? "" : "s");
}

// "17 limiter impacts, 9 collisions, 1 chatter sequence summed to rest".
struct ImpactCounts {
  const Summary& summary;
};

TextBuilder& operator<<(TextBuilder& s, ImpactCounts c) {
  const Summary& sm = c.summary;
  s << CountOf{sm.limiter_impacts, "limiter impact"} << ", " << CountOf{sm.collisions, "collision"};
  if (sm.chatter_sequences > 0)
    s << ", " << CountOf{sm.chatter_sequences, "chatter sequence"} << " summed to rest";
  return s;
}

// What the check against a shadow run at a tighter tolerance says, in words, with its own
// precisions (the builder's is kept).
struct TrustSentence {
  const Stats& stats;
};

TextBuilder& operator<<(TextBuilder& s, TrustSentence trust) {
  const Stats& st = trust.stats;
  const int precision = s.precision();
  s.precision(3);
  if (!st.check) {
    s << "Events not checked (solver.check is off): the error estimate does not see event times.";
  } else if (st.trusted_until < st.t_reached) {
    s.precision(7);
    s << "Events trusted until t = " << st.trusted_until
      << " s only: after that they change with the tolerance.";
  } else {
    s << "Events trusted to the end, times within " << st.event_time_error << " s.";
  }
  s.precision(precision);
  return s;
}

}  // namespace

json finite_number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json event_to_json(const Event& e) {
  json j = {{"t", finite_number(e.t)},
            {"kind", event_kind_name(e.kind)},
            {"pellets", e.pellets},
            {"phi", finite_number(e.phi)},
            {"dphi_before", numbers(e.dphi_before)},
            {"dphi_after", numbers(e.dphi_after)}};
  if (e.limiter >= 0) j["limiter"] = e.limiter;
  if (e.kind == EventKind::chatter) {
    j["impacts_resolved"] = e.impacts_resolved;
    j["t_accumulation"] = finite_number(e.t_accumulation);
  } else if (e.impacts_resolved > 0) {
    j["cascade_impacts"] = e.impacts_resolved;  // a cascade taken to its plastic limit
  }
  return j;
}

std::string answer_sentence(const RunResult& run, const Model& model) {
  const Summary& sm = run.summary;
  const LastImpact& last = sm.last_impact;
  TextBuilder s(4);
  s.reserve(256 + 96 * sm.final.size());  // the sentence's usual length: one allocation
  if (last.index == 0) {
    s << "No impact happens before t = " << run.stats.t_reached << " s.";
  } else if (sm.ends_vibro_impact) {
    s << "The system stops being vibro-impact after impact " << last.index << " at t = " << last.t
      << " s (" << ImpactCounts{sm} << ").";
  } else {
    s << "The run ends at t = " << run.stats.t_reached
      << " s while the system is still vibro-impact: " << CountOf{last.index, "impact"} << " ("
      << ImpactCounts{sm} << "), the last at t = " << last.t << " s.";
  }
  for (std::size_t i = 0; i < sm.final.size(); ++i) {
    const FinalState& f = sm.final[i];
    s << " Pellet " << i + 1;
    switch (f.state) {
      case PelletState::resting_at_limiter:
        s << " rests against limiter " << f.limiter + 1 << " at φ = " << AngleText{f.phi} << ".";
        break;
      case PelletState::stuck: {
        const bool in_zone = std::abs(wrap_angle(f.phi)) <= std::atan(model.mu_static()) + 1e-12;
        s << " is at rest at φ = " << AngleText{f.phi}
          << (in_zone ? ", inside its friction zone." : ".");
        break;
      }
      case PelletState::sliding:
        s << " still moves (φ = " << AngleText{f.phi} << ", φ̇ = " << f.dphi << " rad/s).";
        break;
    }
  }
  if (run.stats.termination != Termination::completed)
    s << " The run stopped early: " << run.stats.message << ".";
  s << " " << TrustSentence{run.stats};
  return std::move(s).str();
}

json stats_to_json(const Stats& st) {
  json stats = {{"method", st.method},
                {"rtol", st.rtol},
                {"atol", st.atol},
                {"steps", st.steps},
                {"rejected", st.rejected},
                {"rhs_evals", st.rhs_evals},
                {"jac_evals", st.jac_evals},
                {"lu_decomps", st.lu_decomps},
                {"stiff_switches", st.stiff_switches},
                {"wall_ms", finite_number(st.wall_ms)},
                {"error_estimate", finite_number(st.error_estimate)},
                {"energy_defect", finite_number(st.energy_defect)},
                {"first_integral_residual", finite_number(st.first_integral_residual)},
                {"event_time_error", finite_number(st.event_time_error)},
                {"state_error", finite_number(st.state_error)},
                {"trusted_until", finite_number(st.trusted_until)},
                {"check", st.check},
                {"check_wall_ms", finite_number(st.check_wall_ms)},
                {"termination", termination_name(st.termination)},
                {"t_reached", finite_number(st.t_reached)}};
  if (!st.message.empty()) stats["message"] = st.message;
  if (!st.check_method.empty()) stats["check_method"] = st.check_method;
  return stats;
}

json result_to_json(const RunResult& run, const Model& model) {
  json events = json::array();
  for (const Event& e : run.events) events.push_back(event_to_json(e));

  json finals = json::array();
  for (const FinalState& f : run.summary.final) {
    json fj = {{"phi", finite_number(f.phi)},
               {"phi_wrapped", finite_number(wrap_angle(f.phi))},
               {"dphi", finite_number(f.dphi)},
               {"state", pellet_state_name(f.state)}};
    if (f.limiter >= 0) fj["limiter"] = f.limiter;
    finals.push_back(std::move(fj));
  }
  const Summary& sm = run.summary;
  json summary = {
      {"limiter_impacts", sm.limiter_impacts},     {"collisions", sm.collisions},
      {"chatter_sequences", sm.chatter_sequences}, {"impacts_by_limiter", sm.impacts_by_limiter},
      {"ends_vibro_impact", sm.ends_vibro_impact}, {"answer", answer_sentence(run, model)}};
  summary["final"] = std::move(finals);
  summary["last_impact"] = sm.last_impact.index > 0 ? json{{"index", sm.last_impact.index},
                                                           {"t", finite_number(sm.last_impact.t)}}
                                                    : json(nullptr);
  json stats = stats_to_json(run.stats);
  stats["events"] = run.events.size();
  json warnings = json::array();
  for (const Warning& w : run.warnings) {
    warnings.push_back({{"code", w.code},
                        {"message", w.message},
                        {"pellet", w.pellet},
                        {"t_begin", finite_number(w.t_begin)},
                        {"t_end", finite_number(w.t_end)}});
  }
  // Moved in, not listed in an initializer (which would copy every event); keys sort as before.
  json j = json::object();
  j["events"] = std::move(events);
  j["summary"] = std::move(summary);
  j["stats"] = std::move(stats);
  j["warnings"] = std::move(warnings);
  if (run.lyapunov) {
    // −infinity (a direction perturbations die in) is written as null.
    json exponents = json::array();
    for (double l : run.lyapunov->exponents) exponents.push_back(finite_number(l));
    j["lyapunov"] = {{"exponents", exponents}, {"span", finite_number(run.lyapunov->span)}};
    if (!run.lyapunov->unsupported.empty())
      j["lyapunov"]["unsupported"] = run.lyapunov->unsupported;
  }
  if (!run.tracks.empty()) {
    json tracks = json::array();
    for (const PelletTrack& t : run.tracks) tracks.push_back(track_json(t));
    j["trajectories"] = tracks;
  }
  return j;
}

}  // namespace vibro
