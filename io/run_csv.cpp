#include "io/run_csv.h"

#include <iomanip>
#include <sstream>
#include <vector>

namespace vibro {
namespace {

template <class T>
void put_list(std::ostream& out, const std::vector<T>& items) {
  for (std::size_t k = 0; k < items.size(); ++k) out << (k ? ";" : "") << items[k];
}

}  // namespace

std::optional<RunTable> run_table_named(std::string_view name) {
  if (name == "events") return RunTable::events;
  if (name == "trajectory") return RunTable::trajectory;
  return std::nullopt;
}

std::string run_csv(const RunResult& run, RunTable table) {
  std::ostringstream out;
  out << std::setprecision(17);
  if (table == RunTable::events) {
    out << "t,kind,pellets,limiter,phi,dphi_before,dphi_after\n";
    for (const Event& e : run.events) {
      out << e.t << ',' << event_kind_name(e.kind) << ',';
      put_list(out, e.pellets);
      out << ',' << e.limiter << ',' << e.phi << ',';
      put_list(out, e.dphi_before);
      out << ',';
      put_list(out, e.dphi_after);
      out << '\n';
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
