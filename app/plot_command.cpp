// `vibro plot RESULT.json [--plot KIND] [--pellet I] [--coordinate C] [--scene SCENE.json |
// --preset NAME] [--over SWEEP.json] -o OUT.png|.svg|.pdf...`: redraws a saved result without
// running anything: a sweep's points (`vibro sweep -o RESULT.json`) as any of its plots, or a
// periodic motion's continued branch (`vibro orbit -o RESULT.json`), over the saved sweep of the
// same parameter when --over names one (as `vibro orbit` draws it). The result names the scene that
// made it (its "scene"); one saved without it (the server's) is drawn with the scene given by
// --scene or
// --preset. Prints where each image went.
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <variant>

#include "app/commands.h"
#include "app/scene_options.h"
#include "app/sweep_plot_options.h"
#include "app/usage.h"
#include "core/analysis/periodic_orbit.h"
#include "io/saved_results.h"
#include "io/scene_json.h"
#include "io/whole_file.h"
#include "render/orbit_figure.h"

namespace vibro {
namespace {

using nlohmann::json;

struct PlotOptions {
  std::string result;  // the saved result's file
  SceneSource scene;   // when the result does not carry its scene
  SweepPlotOptions plot;
  std::string beneath;  // a saved sweep drawn beneath a branch
  std::vector<std::string> outs;
};

// The saved result as JSON; empty after printing why it cannot be read.
std::optional<json> read_result(const std::string& path) {
  auto read = read_whole_file(path);
  if (auto* problem = std::get_if<FileProblem>(&read)) {
    print_error("RESULT", problem->message);
    return std::nullopt;
  }
  json j = json::parse(std::get<std::string>(read), nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    print_error("RESULT", path + " is not JSON as `vibro sweep` or `vibro orbit` writes it");
    return std::nullopt;
  }
  return j;
}

// The scene the result was made with: the one given, else the one it carries.
std::optional<Scene> scene_of(const PlotOptions& o, const json& result) {
  if (!o.scene.file.empty() || !o.scene.preset.empty()) return load_scene(o.scene);
  if (!result.contains("scene")) {
    print_error("scene", o.result +
                             " does not say which scene made it: name that scene with --scene "
                             "SCENE.json or --preset NAME");
    return std::nullopt;
  }
  SceneOrError scene = scene_from_json(result["scene"]);
  if (auto* e = std::get_if<FieldError>(&scene)) {
    print_error("scene." + e->field, e->message);
    return std::nullopt;
  }
  return std::get<Scene>(std::move(scene));
}

// Every output drawn by `draw`, which prints why when it cannot draw.
template <class Draw>
int write_images(const std::vector<std::string>& outs, const Draw& draw) {
  for (const std::string& out : outs) {
    const auto bytes = draw(*image_format_of_file(out));
    if (!bytes) return 1;
    if (!write_output(out, *bytes)) return 1;
    std::cout << json{{"image", out}, {"bytes", bytes->size()}}.dump() << "\n";
  }
  return 0;
}

int plot_sweep(const PlotOptions& o, const Scene& scene, const json& saved) {
  if (!scene.sweep || saved.value("parameter", json()) != scene.sweep->axis.parameter) {
    print_error("scene", "is not the scene of this sweep: its sweep is not over \"" +
                             saved.value("parameter", std::string("?")) + "\"");
    return 2;
  }
  const auto plot = sweep_plot_of(o.plot, scene, true);
  if (!plot) return 2;
  auto read = read_sweep_result(saved);
  if (auto* e = std::get_if<FieldError>(&read)) {
    print_error(e->field, e->message);
    return 2;
  }
  const SweepResult& result = std::get<SweepResult>(read);
  return write_images(
      o.outs, [&](ImageFormat format) { return sweep_image(scene, *plot, result, format); });
}

// The saved sweep of --over, which must be the scene's sweep over the branch's parameter; empty
// after printing why not.
std::optional<SweepResult> sweep_beneath(const std::string& path, const Scene& scene,
                                         const ContinuationSpec* continuation) {
  const auto saved = read_result(path);
  if (!saved) return std::nullopt;
  if (!continuation || !scene.sweep || scene.sweep->axis2 ||
      scene.sweep->axis.parameter != continuation->parameter ||
      saved->value("parameter", json()) != continuation->parameter) {
    print_error("--over", "draws the scene's sweep over the branch's own parameter beneath it: " +
                              path + " is not that sweep");
    return std::nullopt;
  }
  auto read = read_sweep_result(*saved);
  if (auto* e = std::get_if<FieldError>(&read)) {
    print_error("--over", path + ": " + e->field + " " + e->message);
    return std::nullopt;
  }
  return std::get<SweepResult>(std::move(read));
}

int plot_branch(const PlotOptions& o, const Scene& scene, const json& saved) {
  const auto* continuation = scene.periodic_orbit && scene.periodic_orbit->continuation
                                 ? &*scene.periodic_orbit->continuation
                                 : nullptr;
  if (!o.plot.plot.empty() && o.plot.plot != "bifurcation") {
    print_error("--plot", "a periodic motion's branch is drawn as \"bifurcation\" (the default)");
    return 2;
  }
  auto read = read_orbit_branch(saved, multiplier_band(scene.sim));
  if (auto* e = std::get_if<FieldError>(&read)) {
    print_error(e->field, e->message);
    return 2;
  }
  const OrbitBranch& branch = std::get<OrbitBranch>(read);
  std::optional<SweepResult> sweep;
  if (!o.beneath.empty()) {
    sweep = sweep_beneath(o.beneath, scene, continuation);
    if (!sweep) return 2;
  }
  const OrbitFigure figure{&branch, continuation, sweep ? &*scene.sweep : nullptr,
                           sweep ? &*sweep : nullptr};
  if (!draws_branch(figure)) {
    print_error("branch",
                "holds no continued branch: one return of the motion is a run, drawn by "
                "`vibro orbit SCENE -o OUT.png`");
    return 2;
  }
  return write_images(o.outs, [&](ImageFormat format) {
    return drawn_bytes(render_branch_figure(scene.figure, scene.model, figure, format));
  });
}

int plot(const PlotOptions& o) {
  if (o.outs.empty()) {
    print_error("-o", "name the image with -o OUT.png, OUT.svg or OUT.pdf");
    return 2;
  }
  if (!outputs_named(o.outs, {".png", ".svg", ".pdf"}, "image OUT.png, OUT.svg or OUT.pdf"))
    return 2;
  const auto saved = read_result(o.result);
  if (!saved) return 2;
  const auto scene = scene_of(o, *saved);
  if (!scene) return 2;
  if (saved->contains("points")) return plot_sweep(o, *scene, *saved);
  if (saved->contains("branch")) return plot_branch(o, *scene, *saved);
  print_error("RESULT", o.result + " is neither a sweep's points nor a periodic motion's branch");
  return 2;
}

}  // namespace

Command add_plot_command(CLI::App& vibro) {
  auto o = std::make_shared<PlotOptions>();
  CLI::App* command = vibro.add_subcommand(
      "plot",
      "Redraw a saved sweep (vibro sweep -o R.json) or continued branch (vibro orbit -o R.json) "
      "without running anything");
  command->add_option("RESULT", o->result, "the saved result, as JSON")
      ->required()
      ->type_name("FILE");
  command
      ->add_option("--scene", o->scene.file,
                   "the scene that made the result, when the result does not carry it")
      ->type_name("FILE");
  command->add_option("--preset", o->scene.preset, "the preset that made it, instead of --scene")
      ->type_name("NAME");
  add_sweep_plot_options(*command, o->plot);
  command
      ->add_option("--over", o->beneath,
                   "a saved sweep (vibro sweep -o S.json) drawn beneath a continued branch")
      ->type_name("FILE");
  command
      ->add_option("-o,--output", o->outs,
                   "the image: OUT.png, OUT.svg or OUT.pdf (repeat -o for several)")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->expected(1)
      ->type_name("OUT");
  return {command, [o] { return plot(*o); }};
}

}  // namespace vibro
