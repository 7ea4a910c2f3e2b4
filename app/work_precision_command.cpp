// `vibro work-precision SCENE [-o wp.png|wp.svg] [--repeats N]`: for each method and tolerance
// from 1e-3 to 1e-12, the median run time and the true error; prints the table as JSON and
// draws the diagram.
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "core/work_precision.h"
#include "io/work_precision_json.h"
#include "render/figure.h"

namespace vibro {
namespace {

void usage_error(const std::string& field, const std::string& message) {
  std::cerr << nlohmann::json{{"error", message}, {"field", field}}.dump() << "\n";
}

}  // namespace

int work_precision_command(const Args& args) {
  std::size_t next = 0;
  auto scene = load_scene(args, next);
  if (!scene) return 2;
  std::string out;
  WorkPrecisionOptions options;
  for (; next < args.size(); ++next) {
    const std::string& a = args[next];
    if ((a == "-o" || a == "--output") && next + 1 < args.size()) {
      out = args[++next];
    } else if (a == "--repeats" && next + 1 < args.size()) {
      try {
        options.repeats = std::stoi(args[++next]);
      } catch (const std::exception&) {
        options.repeats = 0;
      }
      if (options.repeats < 1 || options.repeats > 50) {
        usage_error("--repeats", "must be an integer in [1, 50]");
        return 2;
      }
    } else {
      usage_error(a, "is not an option of `vibro work-precision`");
      return 2;
    }
  }
  if (!out.empty() && !image_format_of_file(out)) {
    usage_error("-o", "name the image OUT.png, OUT.svg or OUT.pdf");
    return 2;
  }
  const WorkPrecisionReport report = work_precision(scene->model, scene->sim, options);
  if (!out.empty()) {
    FigureSpec figure;
    figure.width = scene->figure.width;
    figure.height = scene->figure.height;
    PlotSpec plot;
    plot.kind = PlotKind::work_precision;
    if (!scene->name.empty()) plot.title = "Work-precision, " + scene->name + " scene";
    figure.plots = {plot};
    const ImageFormat format = *image_format_of_file(out);
    const RenderResult image = render_figure(figure, scene->model, RunResult{}, format, {&report});
    if (!image.ok()) {
      usage_error(image.error->field, image.error->message);
      return 1;
    }
    std::ofstream file(out, std::ios::binary);
    file.write(reinterpret_cast<const char*>(image.bytes.data()),
               static_cast<std::streamsize>(image.bytes.size()));
    if (!file) {
      usage_error(out, "cannot write the file");
      return 1;
    }
  }
  std::cout << work_precision_to_json(report).dump(2) << "\n";
  return 0;
}

}  // namespace vibro
