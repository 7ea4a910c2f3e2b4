// `vibro simulate SCENE | - | --preset NAME [-o OUT.json|OUT.csv] [--what events|trajectory]`:
// the run as JSON (events, summary, stats, warnings), or its events or samples as CSV.
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/commands.h"
#include "app/scene_options.h"
#include "app/usage.h"
#include "core/analysis/checked_run.h"
#include "io/result_json.h"
#include "io/run_csv.h"
#include "io/whole_file.h"

namespace vibro {
namespace {

struct SimulateOptions {
  SceneOutput job;
  std::optional<RunTable> table;
};

int simulate(const SimulateOptions& o) {
  auto scene = load_scene(o.job.scene);
  if (!scene) return 2;
  const std::string& out = o.job.out;
  std::optional<RunTable> table = o.table;
  const bool csv = out.ends_with(".csv");
  if (!out.empty() && !csv && !out.ends_with(".json")) {
    print_error("-o", "name the output OUT.json or OUT.csv");
    return 2;
  }
  if (table && !csv) {
    print_error("--what", "applies to a CSV output (-o OUT.csv)");
    return 2;
  }
  if (csv && !table) table = RunTable::events;
  SimOptions options = scene->sim;
  options.record.assign(scene->model.size(),
                        table ? *table == RunTable::trajectory : scene->trajectories);
  const RunResult run = simulate(scene->model, options);
  const std::string text =
      table ? run_csv(run, *table) : result_to_json(run, scene->model).dump(2) + "\n";
  if (out.empty()) {
    std::cout << text;  // checked once the command ends (app/main.cpp)
  } else if (const auto problem = write_whole_file(out, text)) {
    print_error("-o", problem->message);
    return 1;
  }
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
  return {command, [o] { return simulate(*o); }};
}

}  // namespace vibro
