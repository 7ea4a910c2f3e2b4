// `vibro render SCENE -o OUT.png|OUT.svg`: simulate what the scene's plots need and draw them.
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "core/simulate.h"
#include "core/work_precision.h"
#include "io/result_json.h"
#include "render/figure.h"
#include "render/run_plan.h"

namespace vibro {

int render_command(const Args& args) {
  auto job = scene_and_output(args, "render");
  if (!job) return 2;
  const Scene& scene = job->scene;
  const std::string& out = job->out;
  const auto named = image_format_of_file(out);
  if (out.empty() || !named) {
    std::cerr << nlohmann::json{{"error", "name the image with -o OUT.png, OUT.svg or OUT.pdf"}, {"field", "-o"}}.dump() << "\n";
    return 2;
  }
  const ImageFormat format = *named;
  if (auto e = validate_figure(scene.figure, scene.model, format)) {
    std::cerr << nlohmann::json{{"error", e->message}, {"field", e->field}}.dump() << "\n";
    return 2;
  }
  const RunPlan plan = plan_run(scene.figure, scene.sim, scene.model.size());
  const RunResult run = simulate(scene.model, plan.options);
  std::optional<WorkPrecisionReport> sweep;
  if (plan.needs_work_precision) sweep = work_precision(scene.model, scene.sim);
  const RenderResult image =
      render_figure(scene.figure, scene.model, run, format, {sweep ? &*sweep : nullptr});
  if (!image.ok()) {
    std::cerr << nlohmann::json{{"error", image.error->message}, {"field", image.error->field}}.dump() << "\n";
    return 1;
  }
  std::ofstream file(out, std::ios::binary);
  file.write(reinterpret_cast<const char*>(image.bytes.data()), static_cast<std::streamsize>(image.bytes.size()));
  if (!file) {
    std::cerr << nlohmann::json{{"error", "cannot write the file"}, {"field", out}}.dump() << "\n";
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

}  // namespace vibro
