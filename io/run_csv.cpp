#include "io/run_csv.h"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <vector>

namespace vibro {
std::optional<RunTable> run_table_named(std::string_view name) {
  if (name == "events") return RunTable::events;
  if (name == "trajectory") return RunTable::trajectory;
  return std::nullopt;
}

std::string run_csv(const RunResult& run, RunTable table) {
  std::ostringstream out;
  out << std::setprecision(17);
  if (table == RunTable::events) {
    out << "event,t,kind,pellet,limiter,phi,dphi_before,dphi_after\n";
    for (std::size_t k = 0; k < run.events.size(); ++k) {
      const Event& e = run.events[k];
      // One row per pellet the event touches, so that every cell holds one value.
      for (std::size_t i = 0; i < std::max<std::size_t>(e.pellets.size(), 1); ++i) {
        out << k << ',' << e.t << ',' << event_kind_name(e.kind) << ',';
        if (i < e.pellets.size()) out << e.pellets[i];
        out << ',' << e.limiter << ',' << e.phi << ',';
        if (i < e.dphi_before.size()) out << e.dphi_before[i];
        out << ',';
        if (i < e.dphi_after.size()) out << e.dphi_after[i];
        out << '\n';
      }
    }
    return out.str();
  }
  out << "t,pellet,branch,phi,dphi\n";
  for (const PelletTrack& track : run.tracks)
    for (const Branch& b : track.branches)
      for (const Sample& s : b.samples)
        out << s.t << ',' << track.pellet << ',' << b.index << ',' << s.phi << ',' << s.dphi
            << '\n';
  return out.str();
}

}  // namespace vibro
