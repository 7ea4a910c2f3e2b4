#include "io/run_csv.h"

#include <algorithm>
#include <cmath>
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
      for (std::size_t i = 0; i < event_row_count(e); ++i) {
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
  if (table == RunTable::uniform) {
    out << "t,pellet,phi,dphi\n";
    for (const StateAt& at : run.stops)
      for (std::size_t p = 0; p < at.pellets.size(); ++p)
        out << at.t << ',' << p << ',' << at.pellets[p].phi << ',' << at.pellets[p].dphi << '\n';
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

std::variant<std::vector<double>, FieldError> uniform_times(double dt, double t_end, int pellets,
                                                            long most, const std::string& field) {
  if (!std::isfinite(dt) || dt <= 0.0)
    return FieldError{field, "must be a positive number of seconds"};
  const double count =
      std::floor(t_end / dt * (1.0 + 1e-12)) + 1.0;  // t_end itself, if on the grid
  if (count * std::max(pellets, 1) > static_cast<double>(most)) {
    std::ostringstream why;
    why << "samples " << t_end << " s every " << dt << " s for " << pellets
        << " pellets: more than the " << most
        << " samples a uniform trajectory holds; take a larger dt or a shorter t_end";
    return FieldError{field, why.str()};
  }
  std::vector<double> times(static_cast<std::size_t>(count));
  for (std::size_t k = 0; k < times.size(); ++k)
    times[k] = std::min(static_cast<double>(k) * dt, t_end);
  return times;
}

}  // namespace vibro
