// vibro.sweep(scene, threads=None, progress=None) -> vibro.Sweep: the scene's sweep as `vibro
// sweep` runs it (app/sweep_command.cpp), on `threads` threads with the GIL released; the same
// points.
#include <algorithm>
#include <array>
#include <atomic>
#include <limits>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "core/analysis/sweep.h"
#include "io/scene_json.h"
#include "io/sweep_json.h"
#include "python/bindings.h"
#include "python/columns.h"
#include "python/image.h"
#include "python/interruptible.h"
#include "python/json_values.h"
#include "python/scene_error.h"
#include "python/scene_input.h"

namespace vibro::python {
namespace {

// A finished sweep with the scene it ran (to draw it), and its points as Python reads them.
class Sweep {
 public:
  Sweep(Scene scene, SweepResult result) : scene_(std::move(scene)), result_(std::move(result)) {
    for (std::size_t r = 0; r < result_.runs.size(); ++r)
      for (std::size_t p = 0; p < result_.runs[r].points.size(); ++p) where_.emplace_back(r, p);
  }

  const SweepSpec& spec() const { return *scene_.sweep; }

  // One array per column of the sweep's CSV, in its order, and "run" (the index into `runs`).
  py::dict points() {
    if (points_) return points_.cast<py::dict>();
    const std::size_t n = where_.size();
    const auto run = [&](std::size_t k) -> const SweepRun& {
      return result_.runs[where_[k].first];
    };
    const auto point = [&](std::size_t k) -> const SectionPoint& {
      return run(k).points[where_[k].second];
    };
    const std::array<std::string, 2> values = sweep_value_names(spec());
    py::dict d;
    d[py::str(values[0])] = column<double>(n, [&](std::size_t k) { return run(k).value; });
    d[py::str(values[1])] = column<double>(n, [&](std::size_t k) { return run(k).value2; });
    d["start"] = column<std::int64_t>(n, [&](std::size_t k) { return run(k).start; });
    d["direction"] = column<std::int64_t>(n, [&](std::size_t k) { return run(k).direction; });
    d["pellet"] = column<std::int64_t>(n, [&](std::size_t k) { return point(k).pellet; });
    d["t"] = column<double>(n, [&](std::size_t k) { return point(k).t; });
    d["phi"] = column<double>(n, [&](std::size_t k) { return point(k).phi; });
    d["dphi"] = column<double>(n, [&](std::size_t k) { return point(k).dphi; });
    d["phase"] = column<double>(n, [&](std::size_t k) { return point(k).phase; });
    d["limiter"] = column<std::int64_t>(n, [&](std::size_t k) { return point(k).limiter; });
    d["trusted"] = column<bool>(n, [&](std::size_t k) { return point(k).trusted; });
    d["period"] = column<std::int64_t>(n, [&](std::size_t k) { return run(k).period; });
    d["impacts_per_period"] =
        column<double>(n, [&](std::size_t k) { return run(k).impacts_per_period; });
    d["lyapunov"] = column<double>(n, [&](std::size_t k) { return lyapunov(run(k)); });
    if (result_.classified)
      d["attractor"] = column<std::int64_t>(n, [&](std::size_t k) { return run(k).attractor; });
    d["run"] = column<std::int64_t>(n, [&](std::size_t k) { return where_[k].first; });
    points_ = d;
    return d;
  }

  // One array per column of the JSON's "runs", one entry per run.
  py::dict runs() {
    if (runs_) return runs_.cast<py::dict>();
    const std::vector<SweepRun>& r = result_.runs;
    const std::size_t n = r.size();
    py::dict d;
    d["value"] = column<double>(n, [&](std::size_t k) { return r[k].value; });
    d["value2"] = column<double>(n, [&](std::size_t k) { return r[k].value2; });
    d["start"] = column<std::int64_t>(n, [&](std::size_t k) { return r[k].start; });
    d["direction"] = column<std::int64_t>(n, [&](std::size_t k) { return r[k].direction; });
    d["period"] = column<std::int64_t>(n, [&](std::size_t k) { return r[k].period; });
    d["impacts_per_period"] =
        column<double>(n, [&](std::size_t k) { return r[k].impacts_per_period; });
    d["at_rest"] = column<bool>(n, [&](std::size_t k) { return r[k].at_rest; });
    d["sticks"] = column<bool>(n, [&](std::size_t k) { return r[k].sticks; });
    d["trusted"] = column<bool>(n, [&](std::size_t k) { return r[k].trusted; });
    d["trusted_until"] = column<double>(n, [&](std::size_t k) { return r[k].trusted_until; });
    d["error_estimate"] = column<double>(n, [&](std::size_t k) { return r[k].error_estimate; });
    d["lyapunov"] = column<double>(n, [&](std::size_t k) { return lyapunov(r[k]); });
    d["termination"] =
        string_column(n, [&](std::size_t k) { return termination_name(r[k].termination); });
    d["message"] = string_column(n, [&](std::size_t k) { return r[k].message; });
    if (result_.classified)
      d["attractor"] = column<std::int64_t>(n, [&](std::size_t k) { return r[k].attractor; });
    runs_ = d;
    return d;
  }

  py::dict stats() const {
    py::dict d;
    d["cancelled"] = result_.cancelled;
    d["points"] = where_.size();
    d["runs"] = result_.runs.size();
    d["threads"] = result_.threads;
    d["wall_ms"] = result_.wall_ms;
    return d;
  }

  // The JSON's "attractors", a list of dicts; None when the sweep classified none.
  py::object attractors() const {
    if (!result_.classified) return py::none();
    py::list list;
    for (const Attractor& a : result_.attractors) {
      py::list section;
      for (const auto& [phi, dphi] : a.section) {
        py::dict state;
        state["phi"] = phi;
        state["dphi"] = dphi;
        section.append(state);
      }
      py::dict d;
      d["id"] = a.id;
      d["at_rest"] = a.at_rest;
      d["period"] = a.period;
      d["impacts_per_period"] = a.impacts_per_period;
      d["section"] = section;
      d["cells"] = a.cells;
      list.append(d);
    }
    return list;
  }

  // With its scene, as `vibro sweep` writes it (so that `vibro plot` can redraw it).
  std::string to_json() const {
    return sweep_result_text(spec(), result_, scene_to_json(scene_)) + "\n";
  }
  std::string to_csv() const { return sweep_result_csv(spec(), result_); }

  // As `vibro sweep -o OUT.png --plot PLOT --pellet PELLET --coordinate COORDINATE` draws it.
  py::object render(const std::string& plot, const std::string& format_name, int pellet,
                    const std::string& coordinate) const {
    const ImageFormat format = image_format(format_name);
    SweepPlot drawn;
    const auto view = sweep_plot_kind(plot, spec());
    if (!view) raise_scene_error({"plot", std::string("must be ") + kSweepPlotNames});
    drawn.view = *view;
    if (pellet < 0 || pellet >= scene_.model.size())
      raise_scene_error(
          {"pellet", "must be a pellet index in 0.." + std::to_string(scene_.model.size() - 1)});
    drawn.pellet = pellet;
    if (coordinate != "dphi" && coordinate != "phi")
      raise_scene_error({"coordinate", "must be \"dphi\" or \"phi\""});
    drawn.coordinate = coordinate == "phi" ? SectionCoordinate::phi : SectionCoordinate::dphi;
    check(validate_sweep_plot(drawn.view, spec()));
    FigureSpec figure;
    figure.width = scene_.figure.width;
    figure.height = scene_.figure.height;
    figure.plots = {drawn};
    RenderResult image;
    {
      py::gil_scoped_release release;
      image = render_figure(figure, scene_.model, RunResult{}, format,
                            {nullptr, SweepData{spec(), result_}});
    }
    return image_of(image, format);
  }

 private:
  // NaN where the run has no exponent (the CSV leaves it empty), −infinity where every
  // perturbation dies.
  static double lyapunov(const SweepRun& run) {
    return run.lyapunov.value_or(std::numeric_limits<double>::quiet_NaN());
  }

  Scene scene_;
  SweepResult result_;
  std::vector<std::pair<std::size_t, std::size_t>> where_;  // per point: its run, its index there
  py::object points_, runs_;                                // null until asked for
};

// `threads` as `vibro sweep --threads` takes it: one per core when not given.
int thread_count(std::optional<int> threads) {
  if (!threads) return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (*threads < 1 || *threads > 1024)
    raise_scene_error({"threads", "must be a whole number from 1 to 1024"});
  return *threads;
}

Sweep sweep_scene(py::handle scene_value, std::optional<int> threads, py::object progress) {
  Scene scene = scene_from_python(scene_value);
  if (!scene.sweep)
    raise_scene_error({"sweep", "the scene has no sweep: add one (API.md, \"Sweeps\")"});
  const SweepSpec& spec = *scene.sweep;
  std::atomic<bool> cancel{false};
  std::atomic<long> done{0};
  const long total = sweep_runs(spec);
  SweepControl control;
  control.threads = thread_count(threads);
  control.cancel = &cancel;
  control.progress = [&done](long d, long) {  // from any worker: keep the largest count
    long seen = done.load();
    while (d > seen && !done.compare_exchange_weak(seen, d)) {
    }
  };
  long reported = -1;
  std::function<void()> report;
  if (!progress.is_none())
    report = [&] {
      const long d = done.load();
      if (d == reported) return;
      reported = d;
      progress(d, total);
    };
  SweepResult result;
  run_interruptible([&] { result = run_sweep(scene.model, scene.sim, spec, control); }, cancel,
                    report);
  return Sweep(std::move(scene), std::move(result));
}

}  // namespace

void add_sweep(py::module_& m) {
  py::class_<Sweep>(m, "Sweep", "A finished sweep (vibro.sweep).")
      .def_property_readonly(
          "points", &Sweep::points,
          "The section points: a dict of equal-length numpy arrays, one per "
          "column of `vibro sweep -o OUT.csv` (the swept values under the "
          "parameters' field paths, or value2 for a sweep of one; start, direction, "
          "pellet, t, phi, dphi, phase, limiter, trusted, period, "
          "impacts_per_period, lyapunov: NaN without one; attractor when the "
          "sweep classifies attractors) and run, the index of its run in `runs`.")
      .def_property_readonly("runs", &Sweep::runs,
                             "One entry per run: a dict of numpy arrays (the JSON's \"runs\").")
      .def_property_readonly("attractors", &Sweep::attractors,
                             "With \"classify\": \"attractor\": the attractors the runs settle "
                             "on, [{id, period, impacts_per_period, section: [{phi, dphi}], "
                             "cells}] as in the JSON; else None.")
      .def_property_readonly("stats", &Sweep::stats,
                             "cancelled, points, runs, threads, wall_ms, as in the JSON.")
      .def_property_readonly(
          "parameter", [](const Sweep& s) { return s.spec().axis.parameter; }, "The swept field.")
      .def_property_readonly(
          "parameter2",
          [](const Sweep& s) -> py::object {
            if (!s.spec().axis2) return py::none();
            return py::str(s.spec().axis2->parameter);
          },
          "The second swept field of a 2-D sweep, else None.")
      .def("to_json", &Sweep::to_json, "The sweep as `vibro sweep` prints it (API.md's JSON).")
      .def("to_csv", &Sweep::to_csv, "The points as `vibro sweep -o OUT.csv` writes them.")
      .def("render", &Sweep::render, py::arg("plot") = "", py::arg("format") = "png",
           py::arg("pellet") = 0, py::arg("coordinate") = "dphi",
           "Draws the sweep as `vibro sweep -o OUT.png --plot PLOT` does: plot is "
           "\"bifurcation\", \"section\", \"impact_map\", \"regime_map\", \"lyapunov\", "
           "\"lyapunov_map\" or \"basins\" (\"\": the basins of a sweep classifying attractors, "
           "else the regime map of a 2-D sweep, else the bifurcation diagram).")
      .def("_repr_png_",
           [](const Sweep& s) -> py::object {
             try {
               return s.render("", "png", 0, "dphi");
             } catch (const py::error_already_set&) {
               return py::none();
             }
           })
      .def("__repr__", [](const Sweep& s) {
        return "<vibro.Sweep over " + s.spec().axis.parameter + ": " +
               std::to_string(s.stats()["runs"].cast<long>()) + " runs>";
      });

  m.def("sweep", &sweep_scene, py::arg("scene"), py::arg("threads") = py::none(),
        py::arg("progress") = py::none(),
        "Runs the scene's sweep as `vibro sweep` does, on `threads` threads (default: one per "
        "core) with the GIL released.\n\nprogress: a callable given (runs done, runs in all), "
        "called on the calling thread every 50 ms while the count grows and once at the end. "
        "Ctrl-C (KeyboardInterrupt) or an exception raised by progress stops the runs under way "
        "and raises it. Raises vibro.SceneError naming the field of a bad scene.");
}

}  // namespace vibro::python
