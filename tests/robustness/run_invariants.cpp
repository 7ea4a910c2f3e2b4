#include "tests/robustness/run_invariants.h"

#include <cctype>
#include <cmath>
#include <string_view>

#include "io/result_json.h"

namespace vibro::robustness {
namespace {

// Whether `word` occurs in `text` not as part of a longer word ("inf" but not "infinitely").
bool has_word(const std::string& text, std::string_view word) {
  const auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const std::size_t end = at + word.size();
    if ((at == 0 || !letter(text[at - 1])) && (end == text.size() || !letter(text[end])))
      return true;
  }
  return false;
}

std::string event_violation(const RunResult& run, const Model& model, double t_end) {
  double t_prev = 0.0;
  for (const Event& e : run.events) {
    if (!std::isfinite(e.t) || !std::isfinite(e.phi))
      return "an event's time or angle is not finite";
    if (e.t < t_prev) return "events are out of time order";
    if (e.t > t_end * (1.0 + 1e-9) + 1e-12) return "an event lies after t_end";
    if (e.dphi_before.size() != e.pellets.size() || e.dphi_after.size() != e.pellets.size())
      return "an event lacks a velocity for a pellet it touches";
    for (double v : e.dphi_before)
      if (!std::isfinite(v)) return "an event's dphi_before is not finite";
    for (double v : e.dphi_after)
      if (!std::isfinite(v)) return "an event's dphi_after is not finite";
    for (int p : e.pellets)
      if (p < 0 || p >= model.size()) return "an event names a pellet that does not exist";
    t_prev = e.t;
  }
  return {};
}

}  // namespace

std::string run_violation(const RunResult& run, const Model& model, double t_end) {
  if (std::string e = event_violation(run, model, t_end); !e.empty()) return e;
  if (run.summary.final.size() != model.pellets.size()) return "not one final state per pellet";
  for (const FinalState& f : run.summary.final)
    if (!std::isfinite(f.phi) || !std::isfinite(f.dphi)) return "a final state is not finite";
  for (const PelletTrack& track : run.tracks)
    for (const Branch& b : track.branches)
      for (const Sample& s : b.samples)
        if (!std::isfinite(s.t) || !std::isfinite(s.phi) || !std::isfinite(s.dphi))
          return "a trajectory sample is not finite";
  if (!std::isfinite(run.stats.t_reached)) return "t_reached is not finite";
  if (run.stats.termination != Termination::completed &&
      run.stats.message.find("t = ") == std::string::npos)
    return "an early stop does not name its time: \"" + run.stats.message + "\"";
  // Non-finite numbers become null in the JSON; none may leak through text (the answer
  // sentence, the message) as "nan" or "inf".
  const std::string text = result_to_json(run, model).dump();
  if (has_word(text, "nan") || has_word(text, "inf")) return "NaN or infinity in the result JSON";
  return {};
}

}  // namespace vibro::robustness
