// vibro.render(scene, format="png") -> vibro.Image: the scene's plots as `vibro render` draws them
// (app/render_command.cpp), the same bytes.
#include <optional>

#include "core/analysis/checked_run.h"
#include "core/analysis/work_precision.h"
#include "python/bindings.h"
#include "python/image.h"
#include "python/scene_error.h"
#include "python/scene_input.h"
#include "render/run_plan.h"

namespace vibro::python {

ImageFormat image_format(const std::string& name) {
  const std::optional<ImageFormat> format = image_format_named(name);
  if (!format)
    raise_scene_error({"format", "must be \"png\", \"svg\" or \"pdf\", got \"" + name + "\""});
  return *format;
}

py::object image_of(const RenderResult& drawn, ImageFormat format) {
  if (!drawn.ok()) raise_scene_error(*drawn.error);
  const py::bytes bytes(reinterpret_cast<const char*>(drawn.bytes.data()), drawn.bytes.size());
  const char* name = format == ImageFormat::png   ? "png"
                     : format == ImageFormat::svg ? "svg"
                                                  : "pdf";
  return py::module_::import("vibro").attr("Image")(bytes, name);
}

namespace {

py::object render_scene(py::handle scene_value, const std::string& format_name) {
  const ImageFormat format = image_format(format_name);
  const Scene scene = scene_from_python(scene_value);
  check(validate_figure(scene.figure, scene.model, format));
  RenderResult image;
  {
    py::gil_scoped_release release;
    const RunPlan plan = plan_run(scene.figure, scene.sim, scene.model.size());
    const RunResult run = simulate(scene.model, plan.options);
    std::optional<WorkPrecisionReport> sweep;
    if (plan.needs_work_precision) sweep = work_precision(scene.model, scene.sim);
    image = render_figure(scene.figure, scene.model, run, format, {sweep ? &*sweep : nullptr});
  }
  return image_of(image, format);
}

}  // namespace

void add_render(py::module_& m) {
  m.def("render", &render_scene, py::arg("scene"), py::arg("format") = "png",
        "Draws a scene's plots as `vibro render` does: a vibro.Image (bytes) in the format "
        "\"png\", \"svg\" or \"pdf\", which a notebook shows. Raises vibro.SceneError naming the "
        "field of a bad scene or figure. The GIL is released while it runs and draws.");
}

}  // namespace vibro::python
