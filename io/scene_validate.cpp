#include "io/scene.h"
#include "render/figure_size.h"
#include "render/plot_validate.h"

namespace vibro {

std::optional<FieldError> validate_scene(const Scene& s, const Limits& limits) {
  if (auto e = check_figure_sides(s.figure, limits)) return e;
  if (auto e = validate_model(s.model, limits)) return e;
  if (auto e = validate_options(s.sim, s.model.size(), limits)) return e;
  for (std::size_t i = 0; i < s.figure.plots.size(); ++i) {
    const std::string field = "plots[" + std::to_string(i) + "]";
    if (auto e = validate_plot(s.figure.plots[i], field, {s.model.size(), s.sim.t_end}, limits))
      return e;
  }
  if (s.sweep)
    if (auto e = validate_sweep(s.model, *s.sweep, limits)) return e;
  if (s.periodic_orbit)
    if (auto e = validate_orbit_request(s.model, *s.periodic_orbit, limits)) return e;
  return std::nullopt;
}

}  // namespace vibro
