// `vibro simulate SCENE | - | --preset NAME [-o OUT.json|OUT.csv] [--what events|trajectory]`:
// the run as JSON (events, summary, stats, warnings), or its events or samples as CSV; with
// --dt the trajectory at a uniform time step.
#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "app/commands.h"
#include "app/scene_options.h"
#include "app/usage.h"
#include "core/analysis/checked_run.h"
#include "io/result_json.h"
#include "io/run_csv.h"

namespace vibro {
namespace {

struct SimulateOptions {
  SceneOutput job;
  std::optional<RunTable> table;
  std::optional<double> dt;  // the trajectory sampled at this uniform step, s
};

int simulate(const SimulateOptions& o) {
  auto scene = load_scene(o.job.scene);
  if (!scene) return 2;
  const std::vector<std::string>& outs = o.job.outs;
  if (!outputs_named(outs, {".json", ".csv"}, "OUT.json or OUT.csv")) return 2;
  const auto is_csv = [](const std::string& out) { return out.ends_with(".csv"); };
  const bool csv = std::any_of(outs.begin(), outs.end(), is_csv);
  const bool json = outs.empty() || !std::all_of(outs.begin(), outs.end(), is_csv);
  if (o.table && !csv) {
    print_error("--what", "applies to a CSV output (-o OUT.csv)");
    return 2;
  }
  RunTable table = o.table.value_or(RunTable::events);
  SimOptions options = scene->sim;
  if (o.dt) {
    if (table != RunTable::trajectory) {
      print_error("--dt", "samples the trajectory: give it with --what trajectory -o OUT.csv");
      return 2;
    }
    auto times =
        uniform_times(*o.dt, options.t_end, scene->model.size(), kMaxUniformSamples, "--dt");
    if (auto* e = std::get_if<FieldError>(&times)) {
      print_error(e->field, e->message);
      return 2;
    }
    options.stops = std::get<std::vector<double>>(std::move(times));
    table = RunTable::uniform;
  }
  // Samples for a trajectory CSV, and for the JSON when the scene asks for them.
  options.record.assign(scene->model.size(),
                        (csv && table == RunTable::trajectory) || (json && scene->trajectories));
  const RunResult run = simulate(scene->model, options);
  const auto text = [&](const std::string& out) {
    return is_csv(out) ? run_csv(run, table) : result_to_json(run, scene->model).dump(2) + "\n";
  };
  if (outs.empty()) std::cout << text("");  // checked once the command ends (app/main.cpp)
  for (const std::string& out : outs)
    if (!write_output(out, text(out))) return 1;
  return run.stats.termination == Termination::completed ? 0 : 1;
}

}  // namespace

Command add_simulate_command(CLI::App& vibro) {
  auto o = std::make_shared<SimulateOptions>();
  CLI::App* command = add_scene_command(
      vibro, "simulate",
      "Simulate a scene: the run as JSON (events, summary, stats, warnings), or as CSV",
      "write OUT.json or OUT.csv instead of JSON on stdout", o->job);
  command
      ->add_option_function<std::string>(
          "--what", [o](const std::string& name) { o->table = run_table_named(name); },
          "the CSV's rows: events (the default) or trajectory (the samples)")
      ->check(accepted_if([](const std::string& name) { return run_table_named(name).has_value(); },
                          "must be \"events\" or \"trajectory\""))
      ->type_name("TABLE");
  command
      ->add_option("--dt", o->dt,
                   "with --what trajectory: the state at t = 0, dt, 2 dt, ... (t,pellet,phi,dphi) "
                   "instead of the branches' samples, s")
      ->check(
          number_where([](double x) { return x > 0.0; }, "must be a positive number of seconds"))
      ->type_name("S");
  return {command, [o] { return simulate(*o); }};
}

}  // namespace vibro
