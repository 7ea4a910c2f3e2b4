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
#include "io/whole_file.h"
#include "render/figure.h"
#include "render/run_plan.h"

namespace vibro {
namespace {

int render(const SceneOutput& o) {
  const auto loaded = load_scene(o.scene);
  if (!loaded) return 2;
  const Scene& scene = *loaded;
  const std::string& out = o.out;
  const auto named = image_format_of_file(out);
  if (out.empty() || !named) {
    print_error("-o", "name the image with -o OUT.png, OUT.svg or OUT.pdf");
    return 2;
  }
  const ImageFormat format = *named;
  if (auto e = validate_figure(scene.figure, scene.model, format)) {
    print_error(e->field, e->message);
    return 2;
  }
  const RunPlan plan = plan_run(scene.figure, scene.sim, scene.model.size());
  const RunResult run = simulate(scene.model, plan.options);
  std::optional<WorkPrecisionReport> sweep;
  if (plan.needs_work_precision) sweep = work_precision(scene.model, scene.sim);
  const RenderResult image =
      render_figure(scene.figure, scene.model, run, format, {sweep ? &*sweep : nullptr});
  if (!image.ok()) {
    print_error(image.error->field, image.error->message);
    return 1;
  }
  const std::string_view bytes(reinterpret_cast<const char*>(image.bytes.data()),
                               image.bytes.size());
  if (const auto problem = write_whole_file(out, bytes)) {
    print_error("-o", problem->message);
    return 1;
  }
  nlohmann::json j = result_to_json(run, scene.model);
  std::cout << nlohmann::json{{"image", out},
                              {"bytes", image.bytes.size()},
                              {"answer", j["summary"]["answer"]},
                              {"stats", j["stats"]}}
                   .dump(2)
            << "\n";
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
