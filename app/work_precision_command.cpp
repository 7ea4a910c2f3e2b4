// `vibro work-precision SCENE [-o wp.png|wp.svg|wp.pdf|wp.json]... [--repeats N]`: for each method
// (or the one --method names) and tolerance from 1e-3 to 1e-12, the median run time and the true
// error; prints the table as JSON, or writes it and draws the diagram from one timing, saying where
// each went.
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/scene_options.h"
#include "app/usage.h"
#include "core/analysis/work_precision.h"
#include "io/work_precision_json.h"
#include "render/figure.h"

namespace vibro {
namespace {

struct WorkPrecisionCommandOptions {
  SceneOutput job;
  WorkPrecisionOptions run;
};

int work_precision_diagram(const WorkPrecisionCommandOptions& o) {
  const auto scene = load_scene(o.job.scene);
  if (!scene) return 2;
  if (!outputs_named(o.job.outs, {".png", ".svg", ".pdf", ".json"},
                     "image OUT.png, OUT.svg or OUT.pdf, or the table OUT.json"))
    return 2;
  WorkPrecisionOptions run = o.run;
  // --method draws that method's curve alone.
  if (o.job.scene.overrides.contains("solver") &&
      o.job.scene.overrides["solver"].contains("method"))
    run.methods = {scene->sim.method};
  const WorkPrecisionReport report = work_precision(scene->model, scene->sim, run);
  if (o.job.outs.empty()) {
    std::cout << work_precision_to_json(report).dump(2) << "\n";
    return 0;
  }
  FigureSpec figure = scene->figure;  // its size, and its print size if it has one
  WorkPrecisionPlot plot;
  if (!scene->name.empty()) plot.title = "Work-precision, " + scene->name + " scene";
  figure.plots = {plot};
  for (const std::string& out : o.job.outs) {  // one timing, written or drawn in every form asked
    const auto image = image_format_of_file(out);
    const auto bytes =
        image ? drawn_bytes(render_figure(figure, scene->model, RunResult{}, *image, {&report}))
              : std::optional<std::string>(work_precision_to_json(report).dump(2) + "\n");
    if (!bytes || !write_output(out, *bytes)) return 1;
    // Where each output went, not the table (some 400 lines).
    std::cout << nlohmann::json{{image ? "image" : "table", out}, {"bytes", bytes->size()}}.dump()
              << "\n";
  }
  return 0;
}

}  // namespace

Command add_work_precision_command(CLI::App& vibro) {
  auto o = std::make_shared<WorkPrecisionCommandOptions>();
  CLI::App* command = add_scene_command(
      vibro, "work-precision",
      "Error against run time per method, tolerances 1e-3 to 1e-12: the table as "
      "JSON, or the diagram",
      "draw the diagram (OUT.png, OUT.svg or OUT.pdf) or write the table (OUT.json) instead",
      o->job);
  command
      ->add_option("--repeats", o->run.repeats,
                   "timed runs per point, their median kept (default 3)")
      ->transform(integer_in(1, 50))
      ->type_name("N");
  return {command, [o] { return work_precision_diagram(*o); }};
}

}  // namespace vibro
