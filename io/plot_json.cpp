#include "io/plot_json.h"

#include <cmath>
#include <limits>
#include <type_traits>
#include <variant>

#include "io/json_fields.h"

namespace vibro {
namespace {

using nlohmann::json;

// An axis's [lo, hi]; nothing when the field is absent (lo < hi: validate_plot).
std::optional<AxisLimits> axis_limits(Fields& f, const char* name) {
  const json* list = f.array(name, 2);
  if (!list) return std::nullopt;
  if (list->size() != 2) throw FieldException(f.path(name), "must be [lo, hi]");
  return AxisLimits{as_number((*list)[0], item(f.path(name), 0)),
                    as_number((*list)[1], item(f.path(name), 1))};
}

// An index, a count or a branch number: an integer that fits an int (its range: validate_plot).
int read_int(const json& v, const std::string& field) {
  const long i = as_integer(v, field);
  if (i < std::numeric_limits<int>::min() || i > std::numeric_limits<int>::max())
    throw FieldException(field, "is out of range, got " + std::to_string(i));
  return static_cast<int>(i);
}

std::vector<int> read_ints(const json& list, const std::string& field) {
  std::vector<int> values;
  for (std::size_t i = 0; i < list.size(); ++i) values.push_back(read_int(list[i], item(field, i)));
  return values;
}

int read_pellet(Fields& f) {
  const json* v = f.value("pellet");
  return v ? read_int(*v, f.path("pellet")) : 0;
}

void read_window(Fields& f, TimeWindow& w) {
  w.t_from = f.number("t_from", 0.0);
  if (auto to = f.number("t_to")) w.t_to = *to;
}

std::string read_title(Fields& f) { return f.string("title", 200).value_or(""); }

// Each kind from the fields it reads, in the order its errors are reported.
PhasePlot create_phase(Fields& f, const Limits& limits) {
  PhasePlot p;
  p.pellet = read_pellet(f);
  read_window(f, p);
  if (const json* list = f.array("branches", limits.plot_branches))
    p.branches = read_ints(*list, f.path("branches"));
  if (const json* fi = f.value("first_integral")) {
    Fields g(*fi, f.path("first_integral"));
    p.first_integral_through = PhasePoint{g.required_number("phi"), g.required_number("dphi")};
    g.done();
  }
  p.friction_zone = f.boolean("friction_zone", false);
  p.wrap = f.boolean("wrap", false);
  p.branch_labels = f.boolean("labels", true);
  if (const auto colours = f.string("colour", 16)) {
    if (*colours == "branch")
      p.colours = PhaseColours::branch;
    else if (*colours == "one")
      p.colours = PhaseColours::one;
    else if (*colours == "time")
      p.colours = PhaseColours::time;
    else
      throw FieldException(f.path("colour"),
                           "must be \"branch\", \"one\" or \"time\", got \"" + *colours + "\"");
  }
  p.phi_range = axis_limits(f, "phi_range");
  p.dphi_range = axis_limits(f, "dphi_range");
  p.title = read_title(f);
  return p;
}

// An empty list would read as "every pellet", which leaving it out says.
TimePlot create_time(Fields& f, const Limits& limits) {
  TimePlot p;
  if (const json* list = f.array("pellets", limits.pellets)) {
    if (list->empty()) throw FieldException(f.path("pellets"), "must name at least one pellet");
    p.pellets = read_ints(*list, f.path("pellets"));
  }
  p.show_dphi = f.boolean("dphi", false);
  read_window(f, p);
  p.phi_range = axis_limits(f, "phi_range");
  p.dphi_range = axis_limits(f, "dphi_range");
  p.title = read_title(f);
  return p;
}

Camera read_camera(const json& j, const std::string& path) {
  Fields c(j, path);
  Camera camera;
  camera.azimuth_deg = c.number("azimuth", camera.azimuth_deg);
  camera.elevation_deg = c.number("elevation", camera.elevation_deg);
  camera.distance = c.number("distance", camera.distance);
  c.done();
  return camera;
}

CylinderPlot create_cylinder(Fields& f, const Limits&) {
  CylinderPlot p;
  p.pellet = read_pellet(f);
  read_window(f, p);
  p.title = read_title(f);
  if (const json* cam = f.value("camera")) p.camera = read_camera(*cam, f.path("camera"));
  return p;
}

// Every pellet, at one instant: no pellet to pick and no window.
MechanismPlot create_mechanism(Fields& f, const Limits&) {
  MechanismPlot p;
  p.t = f.number("t", 0.0);
  p.title = read_title(f);
  return p;
}

WorkPrecisionPlot create_work_precision(Fields& f, const Limits&) {
  WorkPrecisionPlot p;
  read_window(f, p);
  p.title = read_title(f);
  return p;
}

// The kinds a scene may list, by name.
struct KindReader {
  const char* name;
  PlotSpec (*create)(Fields&, const Limits&);
};

template <class Plot, Plot (*Create)(Fields&, const Limits&)>
PlotSpec as_spec(Fields& f, const Limits& c) {
  return Create(f, c);
}

constexpr KindReader kReaders[] = {
    {"phase", as_spec<PhasePlot, create_phase>},
    {"time", as_spec<TimePlot, create_time>},
    {"cylinder", as_spec<CylinderPlot, create_cylinder>},
    {"mechanism", as_spec<MechanismPlot, create_mechanism>},
    {"work_precision", as_spec<WorkPrecisionPlot, create_work_precision>},
};
constexpr const char* kKinds =
    "\"phase\", \"time\", \"cylinder\", \"mechanism\" or \"work_precision\"";

// A window's fields and a phase or time plot's axis ranges, when not their defaults.
void write_window(const TimeWindow& w, json& j) {
  if (w.t_from != 0.0) j["t_from"] = w.t_from;
  if (std::isfinite(w.t_to)) j["t_to"] = w.t_to;
}

void write_ranges(const std::optional<AxisLimits>& phi, const std::optional<AxisLimits>& dphi,
                  json& j) {
  if (phi) j["phi_range"] = {phi->lo, phi->hi};
  if (dphi) j["dphi_range"] = {dphi->lo, dphi->hi};
}

// Each kind's fields, named as its reader reads them.
struct PlotWriter {
  json& j;

  void operator()(const PhasePlot& p) const {
    j["kind"] = "phase";
    j["pellet"] = p.pellet;
    write_window(p, j);
    if (!p.branches.empty()) j["branches"] = p.branches;
    if (p.first_integral_through)
      j["first_integral"] = {{"phi", p.first_integral_through->phi},
                             {"dphi", p.first_integral_through->dphi}};
    if (p.friction_zone) j["friction_zone"] = true;
    if (p.wrap) j["wrap"] = true;
    if (!p.branch_labels) j["labels"] = false;
    if (p.colours != PhaseColours::branch)
      j["colour"] = p.colours == PhaseColours::one ? "one" : "time";
    write_ranges(p.phi_range, p.dphi_range, j);
  }
  void operator()(const TimePlot& p) const {
    j["kind"] = "time";
    if (!p.pellets.empty()) j["pellets"] = p.pellets;
    if (p.show_dphi) j["dphi"] = true;
    write_window(p, j);
    write_ranges(p.phi_range, p.dphi_range, j);
  }
  void operator()(const CylinderPlot& p) const {
    j["kind"] = "cylinder";
    j["pellet"] = p.pellet;
    write_window(p, j);
    j["camera"] = {{"azimuth", p.camera.azimuth_deg},
                   {"elevation", p.camera.elevation_deg},
                   {"distance", p.camera.distance}};
  }
  void operator()(const MechanismPlot& p) const {
    j["kind"] = "mechanism";
    j["t"] = p.t;
  }
  void operator()(const WorkPrecisionPlot& p) const {
    j["kind"] = "work_precision";
    write_window(p, j);
  }
  // Drawn from a sweep's or an orbit's result, never listed in a scene; written for completeness.
  void operator()(const SweepPlot& p) const {
    static constexpr const char* kViews[] = {
        "bifurcation", "section", "impact_map", "regime_map", "lyapunov", "lyapunov_map", "basins"};
    j["kind"] = kViews[static_cast<int>(p.view)];
    j["pellet"] = p.pellet;
  }
  void operator()(const BranchPlot& p) const {
    j["kind"] = p.curves ? "bifurcation_curves" : "branch";
    j["pellet"] = p.pellet;
  }
};

}  // namespace

PlotSpec plot_from_json(const json& j, const std::string& path, const Limits& limits) {
  Fields f(j, path);
  const auto kind = f.string("kind", 32);
  if (!kind) throw FieldException(f.path("kind"), std::string("is required: ") + kKinds);
  for (const KindReader& reader : kReaders) {
    if (*kind != reader.name) continue;
    PlotSpec plot = reader.create(f, limits);
    f.done();
    return plot;
  }
  throw FieldException(f.path("kind"),
                       std::string("must be ") + kKinds + ", got \"" + *kind + "\"");
}

json plot_to_json(const PlotSpec& plot) {
  json j;
  std::visit(PlotWriter{j}, plot);
  const std::string& title =
      std::visit([](const auto& p) -> const std::string& { return p.title; }, plot);
  if (!title.empty()) j["title"] = title;
  return j;
}

}  // namespace vibro
