// vibro.simulate(scene, trajectories=None, deadline_ms=None) -> vibro.Run: the run `vibro simulate`
// makes of the scene (app/simulate_command.cpp), its JSON the same text.
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/analysis/checked_run.h"
#include "io/result_json.h"
#include "io/run_csv.h"
#include "python/bindings.h"
#include "python/columns.h"
#include "python/keys.h"
#include "python/run_values.h"
#include "python/scene_error.h"
#include "python/scene_input.h"

namespace vibro::python {
namespace {

// A finished run and what Python reads of it, each part made when first asked for and kept.
class Run {
 public:
  Run(Model model, RunResult run) : model_(std::move(model)), run_(std::move(run)) {}

  // One array per column of the events' CSV (io/run_csv.h: event,t,kind,pellet,limiter,phi,
  // dphi_before,dphi_after), a row per pellet an event touches; limiter −1 where none. An event
  // that touches no pellet would have pellet −1 and NaN speeds, as pandas reads its empty cells.
  py::dict events() {
    if (events_) return events_.cast<py::dict>();
    const std::vector<Event>& e = run_.events;
    std::size_t n = 0;
    NameColumn kind;
    for (const Event& event : e) {
      n += event_row_count(event);
      kind.note(event_kind_name(event.kind));
    }
    kind.allocate(n);
    Column<std::int64_t> event(n), pellet(n), limiter(n);
    Column<double> t(n), phi(n), dphi_before(n), dphi_after(n);
    const auto cell = [](const std::vector<double>& xs, std::size_t i) {
      return i < xs.size() ? xs[i] : std::numeric_limits<double>::quiet_NaN();
    };
    std::size_t row = 0;
    for (std::size_t k = 0; k < e.size(); ++k) {
      const Event& ev = e[k];
      const std::string_view kind_name = event_kind_name(ev.kind);
      for (std::size_t i = 0; i < event_row_count(ev); ++i, ++row) {
        event[row] = static_cast<std::int64_t>(k);
        t[row] = ev.t;
        kind.set(row, kind_name);
        pellet[row] = i < ev.pellets.size() ? ev.pellets[i] : -1;
        limiter[row] = ev.limiter;
        phi[row] = ev.phi;
        dphi_before[row] = cell(ev.dphi_before, i);
        dphi_after[row] = cell(ev.dphi_after, i);
      }
    }
    py::dict d;
    put<"event">(d, event.array());
    put<"t">(d, t.array());
    put<"kind">(d, kind.array());
    put<"pellet">(d, pellet.array());
    put<"limiter">(d, limiter.array());
    put<"phi">(d, phi.array());
    put<"dphi_before">(d, dphi_before.array());
    put<"dphi_after">(d, dphi_after.array());
    events_ = d;
    return d;
  }

  // The parts of the run's JSON other than its events and trajectories, as Python values
  // (python/run_values.h).
  py::object summary() {
    if (!summary_) {
      const std::string sentence = answer();  // releases the GIL: another thread may get here
      if (!summary_) summary_ = summary_values(run_, sentence);
    }
    return summary_;
  }
  py::object stats() {
    if (!stats_) stats_ = stats_values(run_);
    return stats_;
  }
  py::object warnings() {
    if (!warnings_) warnings_ = warning_values(run_.warnings);
    return warnings_;
  }
  py::object lyapunov() {
    if (!lyapunov_) lyapunov_ = lyapunov_values(run_.lyapunov);
    return lyapunov_;
  }

  // Per recorded pellet {"pellet", "branches": [{"index", "t", "phi", "dphi"}]}, the samples as
  // arrays; None when the run recorded none.
  py::object trajectories() {
    if (trajectories_) return trajectories_;
    if (run_.tracks.empty()) return py::none();
    py::list tracks;
    for (const PelletTrack& track : run_.tracks) {
      py::list branches;
      for (const Branch& b : track.branches) {
        const std::vector<Sample>& s = b.samples;
        py::dict branch;
        branch["index"] = b.index;
        branch["t"] = column<double>(s.size(), [&](std::size_t k) { return s[k].t; });
        branch["phi"] = column<double>(s.size(), [&](std::size_t k) { return s[k].phi; });
        branch["dphi"] = column<double>(s.size(), [&](std::size_t k) { return s[k].dphi; });
        branches.append(branch);
      }
      py::dict t;
      t["pellet"] = track.pellet;
      t["branches"] = branches;
      tracks.append(t);
    }
    trajectories_ = tracks;
    return tracks;
  }

  // `vibro simulate`'s output for the same scene: the JSON of API.md, indented by 2.
  std::string to_json() const {
    std::string text;
    {
      py::gil_scoped_release release;
      text = result_to_json(run_, model_).dump(2) + "\n";
    }
    return text;
  }
  // summary["answer"]: the run in one sentence, made once, with the GIL released meanwhile (it is
  // most of what reading the summary costs), so that other Python threads go on.
  std::string answer() {
    if (answer_.empty()) {
      std::string sentence;
      {
        py::gil_scoped_release release;
        sentence = answer_sentence(run_, model_);
      }
      answer_ = std::move(sentence);
    }
    return answer_;
  }

 private:
  Model model_;
  RunResult run_;
  std::string answer_;  // empty until asked for, as the Python values below are null
  py::object events_;
  py::object summary_, stats_, warnings_, lyapunov_;
  py::object trajectories_;
};

Run simulate_scene(py::handle scene_value, std::optional<bool> trajectories,
                   std::optional<double> deadline_ms) {
  Scene scene = scene_from_python(scene_value);
  if (trajectories) scene.trajectories = *trajectories;
  if (deadline_ms) {
    if (!(*deadline_ms > 0.0))  // as `vibro simulate --deadline-ms`
      raise_scene_error({"deadline_ms", "must be a positive number of milliseconds"});
    scene.sim.deadline_ms = *deadline_ms;
  }
  SimOptions options = scene.sim;
  options.record.assign(scene.model.size(), scene.trajectories);
  // Ctrl-C stops the run: it runs on this thread, the GIL released, and takes the GIL back now
  // and then to let Python's signal handlers run (a handler that raises cancels it).
  options.cancelled = [stop = false]() mutable {
    if (!stop) {
      py::gil_scoped_acquire gil;
      stop = PyErr_CheckSignals() != 0;
    }
    return stop;
  };
  RunResult run;
  {
    py::gil_scoped_release release;
    run = simulate(scene.model, options);
  }
  if (run.stats.termination == Termination::cancelled) throw py::error_already_set();
  return Run(std::move(scene.model), std::move(run));
}

}  // namespace

void add_simulate(py::module_& m) {
  py::class_<Run>(m, "Run", "A finished run of a scene (vibro.simulate).")
      .def_property_readonly("events", &Run::events,
                             "The events, a dict of equal-length numpy arrays, one per column of "
                             "the events' CSV: event, t, kind, pellet, limiter, phi, "
                             "dphi_before, dphi_after (a row per pellet an event touches; "
                             "limiter -1 where none).")
      .def_property_readonly(
          "summary", &Run::summary,
          "The summary as in the JSON: impacts, the last impact, final states, the answer.")
      .def_property_readonly(
          "stats", &Run::stats,
          "The run's statistics and trust fields as in the JSON (wall_ms is this run's).")
      .def_property_readonly("warnings", &Run::warnings, "The warnings, a list of dicts.")
      .def_property_readonly(
          "lyapunov", &Run::lyapunov,
          "The Lyapunov exponents as in the JSON when the scene asks for them, else None.")
      .def_property_readonly("trajectories", &Run::trajectories,
                             "Per recorded pellet, its branches with the numpy arrays t, phi, "
                             "dphi; None unless trajectories were asked for.")
      .def_property_readonly("answer", &Run::answer, "summary['answer']: the run in one sentence.")
      .def("to_json", &Run::to_json,
           "The run as `vibro simulate` prints it for the same scene (API.md's JSON).")
      .def("__repr__", [](Run& r) { return "<vibro.Run: " + r.answer() + ">"; });

  m.def("simulate", &simulate_scene, py::arg("scene"), py::arg("trajectories") = py::none(),
        py::arg("deadline_ms") = py::none(),
        "Simulates a scene (a dict shaped as the JSON scene) as `vibro simulate` does.\n\n"
        "trajectories: True or False overrides the scene's \"trajectories\" (record every "
        "pellet's branches).\ndeadline_ms: wall clock allowed for the run, as --deadline-ms.\n"
        "Raises vibro.SceneError naming the field of a bad scene. The GIL is released while the "
        "run goes on.");
}

}  // namespace vibro::python
