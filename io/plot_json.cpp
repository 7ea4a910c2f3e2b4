#include "io/plot_json.h"

#include <cmath>
#include <type_traits>
#include <variant>

#include "io/json_fields.h"

namespace vibro {
namespace {

using nlohmann::json;

// What a plot's reader knows of the scene around it.
struct PlotContext {
  int pellets = 0;     // the model's
  double t_end = 0.0;  // s, the run's
};

// An axis's [lo, hi], two finite numbers with lo < hi; nothing when the field is absent.
std::optional<AxisLimits> axis_limits(Fields& f, const char* name) {
  const json* list = f.array(name, 2);
  if (!list) return std::nullopt;
  if (list->size() != 2) throw FieldException(f.path(name), "must be [lo, hi]");
  const double lo = as_number((*list)[0], item(f.path(name), 0));
  const double hi = as_number((*list)[1], item(f.path(name), 1));
  if (!(lo < hi)) throw FieldException(f.path(name), "must be [lo, hi] with lo < hi");
  return AxisLimits{lo, hi};
}

// The instant a mechanism panel shows, in [0, t_end] s.
double read_instant(Fields& f, double t_end) {
  const double t = f.number("t", 0.0);
  if (!(t >= 0.0 && t <= t_end))
    throw FieldException(f.path("t"),
                         "must be a time in [0, t_end] = [0, " + json(t_end).dump() + "] s");
  return t;
}

int read_pellet(Fields& f, int pellets) {
  const json* v = f.value("pellet");
  return v ? index_in(*v, f.path("pellet"), pellets, "pellet") : 0;
}

void read_window(Fields& f, TimeWindow& w) {
  w.t_from = f.number("t_from", 0.0);
  if (auto to = f.number("t_to")) w.t_to = *to;
  if (w.t_from < 0.0) throw FieldException(f.path("t_from"), "must be ≥ 0");
  if (!(w.t_to > w.t_from)) throw FieldException(f.path("t_to"), "must be greater than t_from");
}

std::string read_title(Fields& f) { return f.string("title", 200).value_or(""); }

std::vector<int> read_branches(Fields& f) {
  std::vector<int> branches;
  if (const json* list = f.array("branches", 10000)) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      const long b = as_integer((*list)[i], item(f.path("branches"), i));
      if (b < 1) throw FieldException(item(f.path("branches"), i), "branches are numbered from 1");
      branches.push_back(static_cast<int>(b));
    }
  }
  return branches;
}

// Each kind from the fields it reads, in the order its errors are reported.
PhasePlot create_phase(Fields& f, const PlotContext& c) {
  PhasePlot p;
  p.pellet = read_pellet(f, c.pellets);
  read_window(f, p);
  p.branches = read_branches(f);
  if (const json* fi = f.value("first_integral")) {
    Fields g(*fi, f.path("first_integral"));
    p.first_integral_through = PhasePoint{g.required_number("phi"), g.required_number("dphi")};
    g.done();
  }
  p.friction_zone = f.boolean("friction_zone", false);
  p.wrap = f.boolean("wrap", false);
  p.branch_labels = f.boolean("labels", true);
  p.phi_range = axis_limits(f, "phi_range");
  p.dphi_range = axis_limits(f, "dphi_range");
  p.title = read_title(f);
  return p;
}

TimePlot create_time(Fields& f, const PlotContext& c) {
  TimePlot p;
  if (const json* list = f.array("pellets", 64)) {
    if (list->empty()) throw FieldException(f.path("pellets"), "must name at least one pellet");
    for (std::size_t i = 0; i < list->size(); ++i)
      p.pellets.push_back(index_in((*list)[i], item(f.path("pellets"), i), c.pellets, "pellet"));
  } else {
    for (int i = 0; i < c.pellets; ++i) p.pellets.push_back(i);
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
  if (std::abs(camera.elevation_deg) > 89.0)
    throw FieldException(c.path("elevation"), "must be in [-89, 89] degrees");
  if (!(camera.distance >= 1.5 && camera.distance <= 50.0))
    throw FieldException(c.path("distance"), "must be in [1.5, 50]");
  return camera;
}

CylinderPlot create_cylinder(Fields& f, const PlotContext& c) {
  CylinderPlot p;
  p.pellet = read_pellet(f, c.pellets);
  read_window(f, p);
  p.title = read_title(f);
  if (const json* cam = f.value("camera")) p.camera = read_camera(*cam, f.path("camera"));
  return p;
}

// Every pellet, at one instant: no pellet to pick and no window.
MechanismPlot create_mechanism(Fields& f, const PlotContext& c) {
  MechanismPlot p;
  p.t = read_instant(f, c.t_end);
  p.title = read_title(f);
  return p;
}

WorkPrecisionPlot create_work_precision(Fields& f, const PlotContext&) {
  WorkPrecisionPlot p;
  read_window(f, p);
  p.title = read_title(f);
  return p;
}

// The kinds a scene may list, by name.
struct KindReader {
  const char* name;
  PlotSpec (*create)(Fields&, const PlotContext&);
};

template <class Plot, Plot (*Create)(Fields&, const PlotContext&)>
PlotSpec as_spec(Fields& f, const PlotContext& c) {
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
    write_ranges(p.phi_range, p.dphi_range, j);
  }
  void operator()(const TimePlot& p) const {
    j["kind"] = "time";
    j["pellets"] = p.pellets;
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
    static constexpr const char* kViews[] = {"bifurcation", "section",  "impact_map",
                                             "regime_map",  "lyapunov", "lyapunov_map"};
    j["kind"] = kViews[static_cast<int>(p.view)];
    j["pellet"] = p.pellet;
  }
  void operator()(const BranchPlot& p) const {
    j["kind"] = "branch";
    j["pellet"] = p.pellet;
  }
};

}  // namespace

PlotSpec plot_from_json(const json& j, const std::string& path, int pellets, double t_end) {
  Fields f(j, path);
  const auto kind = f.string("kind", 32);
  if (!kind) throw FieldException(f.path("kind"), std::string("is required: ") + kKinds);
  for (const KindReader& reader : kReaders) {
    if (*kind != reader.name) continue;
    PlotSpec plot = reader.create(f, {pellets, t_end});
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
