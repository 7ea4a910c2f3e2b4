// `vibro render SCENE | - | --preset NAME -o OUT.png|OUT.svg|OUT.pdf`: simulate what the scene's
// plots need and draw them; prints the image's name and size, the answer and the run's stats.
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/scene_options.h"
#include "app/usage.h"
#include "core/analysis/checked_run.h"
#include "core/analysis/work_precision.h"
#include "io/result_json.h"
#include "render/figure.h"
#include "render/run_plan.h"

namespace vibro {
namespace {

int render(const SceneOutput& o) {
  const auto loaded = load_scene(o.scene);
  if (!loaded) return 2;
  const Scene& scene = *loaded;
  if (o.outs.empty()) {
    print_error("-o", "name the image with -o OUT.png, OUT.svg or OUT.pdf");
    return 2;
  }
  for (const std::string& out : o.outs) {
    const auto format = image_format_of_file(out);
    if (!format) {
      print_error("-o", "name the image with -o OUT.png, OUT.svg or OUT.pdf");
      return 2;
    }
    if (auto e = validate_figure(scene.figure, scene.model, *format)) {
      print_error(e->field, e->message);
      return 2;
    }
  }
  const RunPlan plan = plan_run(scene.figure, scene.sim, scene.model.size());
  const RunResult run = simulate(scene.model, plan.options);
  std::optional<WorkPrecisionReport> sweep;
  if (plan.needs_work_precision) sweep = work_precision(scene.model, scene.sim);
  nlohmann::json images = nlohmann::json::array();
  for (const std::string& out : o.outs) {  // one run, drawn in every format asked for
    const auto bytes = drawn_bytes(render_figure(
        scene.figure, scene.model, run, *image_format_of_file(out), {sweep ? &*sweep : nullptr}));
    if (!bytes || !write_output(out, *bytes)) return 1;
    images.push_back({{"image", out}, {"bytes", bytes->size()}});
  }
  nlohmann::json j = result_to_json(run, scene.model);
  // One image: {"image", "bytes", ...} as before; several: "images": [{"image", "bytes"}, ...].
  nlohmann::json said = images.size() == 1 ? images[0] : nlohmann::json{{"images", images}};
  said["answer"] = j["summary"]["answer"];
  said["stats"] = j["stats"];
  std::cout << said.dump(2) << "\n";
  return 0;
}

}  // namespace

Command add_render_command(CLI::App& vibro) {
  auto o = std::make_shared<SceneOutput>();
  CLI::App* command = add_scene_command(
      vibro, "render",
      "Draw a scene's plots (phase portraits, phi(t), the 3-D cylinder) to an image",
      "the image: OUT.png, OUT.svg or OUT.pdf", *o);
  return {command, [o] { return render(*o); }};
}

}  // namespace vibro
