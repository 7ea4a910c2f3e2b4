#include "app/sweep_plot_options.h"

#include "app/scene_options.h"
#include "app/usage.h"
#include "io/sweep_json.h"

namespace vibro {

void add_sweep_plot_options(CLI::App& command, SweepPlotOptions& o) {
  command.add_option("--plot", o.plot, std::string("what to draw: ") + kSweepPlotNames)
      ->type_name("KIND");
  command.add_option("--pellet", o.pellet, "the pellet drawn, an index from 0 (default 0)")
      ->type_name("I");
  command
      .add_option_function<std::string>(
          "--coordinate",
          [&o](const std::string& v) {
            o.coordinate = v == "phi" ? SectionCoordinate::phi : SectionCoordinate::dphi;
          },
          "the coordinate drawn at each section: dphi (the default) or phi")
      ->check(accepted_if([](const std::string& v) { return v == "dphi" || v == "phi"; },
                          "must be \"dphi\" or \"phi\""))
      ->type_name("C");
}

std::optional<SweepPlot> sweep_plot_of(const SweepPlotOptions& o, const Scene& scene, bool drawn) {
  SweepPlot plot;
  plot.coordinate = o.coordinate;
  if (o.pellet) {
    const std::string& v = *o.pellet;
    plot.pellet = v.size() == 1 && v[0] >= '0' && v[0] <= '9' ? v[0] - '0' : -1;
    if (plot.pellet < 0 || plot.pellet >= scene.model.size()) {
      print_error("--pellet",
                  "must be a pellet index in 0.." + std::to_string(scene.model.size() - 1));
      return std::nullopt;
    }
  }
  const auto kind = sweep_plot_kind(o.plot, *scene.sweep);
  if (!kind) {
    print_error("--plot", std::string("must be ") + kSweepPlotNames);
    return std::nullopt;
  }
  plot.view = *kind;
  if (const auto e = drawn ? validate_sweep_plot(plot.view, *scene.sweep) : std::nullopt) {
    print_error(e->field, e->message);
    return std::nullopt;
  }
  return plot;
}

std::optional<std::string> sweep_image(const Scene& scene, const SweepPlot& plot,
                                       const SweepResult& result, ImageFormat format) {
  FigureSpec figure = scene.figure;  // its size, and its print size if it has one
  figure.plots = {plot};
  return drawn_bytes(render_figure(figure, scene.model, RunResult{}, format,
                                   {nullptr, SweepData{*scene.sweep, result}}));
}

}  // namespace vibro
