#include "render/cylinder_panel.h"

#include "render/figure.h"

#ifdef VIBRO_HAVE_RENDER3D
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "render/axes.h"
#include "render/gl/cylinder_camera.h"
#include "render/gl/cylinder_layout.h"
#include "render/gl/cylinder_view.h"
#include "render/image_surface.h"
#include "render/text.h"
#include "render/ticks.h"
#include "render/track_window.h"
#endif

namespace vibro {

bool cylinder_panels_available() {
#ifdef VIBRO_HAVE_RENDER3D
  return true;
#else
  return false;
#endif
}

}  // namespace vibro

namespace vibro::render {

#ifdef VIBRO_HAVE_RENDER3D
namespace {

// The visible branches, numbered so that branch n gets the colour it has in the 2-D panels
// (render/gl counts its palette from 0), and φ̇ on a padded range that the caption states.
gl::CylinderScene cylinder_scene(const PanelInput<CylinderPlot>& in) {
  gl::CylinderScene scene;
  Range dphi;
  for (const Branch& b : find_track(in.run, in.spec.pellet)->branches) {
    gl::CylinderBranch branch{b.index - 1, {}};
    for (const Sample& s : clip_to_window(b.samples, in.spec.t_from, in.spec.t_to)) {
      branch.points.push_back({s.phi, s.dphi});
      dphi.include(s.dphi);
    }
    if (!branch.points.empty()) scene.branches.push_back(std::move(branch));
  }
  for (const Limiter& l : in.model.limiters) scene.limiter_angles.push_back(l.angle);
  scene.camera = in.spec.camera;
  const Range range = padded(dphi, 0.05);
  scene.dphi_range = gl::DphiRange{range.lo, range.hi};
  return scene;
}

std::string caption(const gl::DphiRange& r) {
  const double step = nice_step(r.hi - r.lo, 20.0);
  return "height: \u03c6\u0307 from " + format_tick(r.lo, step) + " to " + format_tick(r.hi, step) +
         " rad/s";
}

std::string default_title(const CylinderPlot& spec, double t_end) {
  return "Phase cylinder, pellet " + std::to_string(spec.pellet + 1) + window_suffix(spec, t_end);
}

// The size render/gl draws the view at: the plot area, up to its limit.
std::pair<int, int> view_size(const Rect& area) {
  return {std::clamp(static_cast<int>(area.w), 1, gl::kMaxCylinderViewSide),
          std::clamp(static_cast<int>(area.h), 1, gl::kMaxCylinderViewSide)};
}

std::vector<CylinderLabel> labels_of(const gl::CylinderScene& scene, const Model& model,
                                     const Rect& area) {
  const auto [w, h] = view_size(area);
  const gl::ViewSetup setup = gl::cylinder_camera(scene.camera, w, h);
  auto at = [&](gl::Vec3 p) {
    const gl::ViewFraction f = gl::view_fraction(setup, p);
    return Point{area.x + f.x * area.w, area.y + f.y * area.h};
  };
  std::vector<CylinderLabel> labels;
  for (int quarter = 0; quarter < 4; ++quarter) {  // beyond the floor's longer ticks
    const double phi = quarter * 0.5 * std::numbers::pi;
    labels.push_back({pi_label(2L * quarter),
                      at({1.28 * std::cos(phi), 1.28 * std::sin(phi), -gl::kHalfHeight})});
  }
  const gl::HeightScale scale = gl::height_scale(scene);
  const double step = nice_step(scale.hi - scale.lo, 20.0);
  labels.push_back({"\u03c6\u0307 = " + format_tick(scale.hi, step) + " rad/s",
                    at({0.0, 0.0, gl::kHalfHeight})});
  labels.push_back({"\u03c6\u0307 = " + format_tick(scale.lo, step) + " rad/s",
                    at({0.0, 0.0, -gl::kHalfHeight})});
  for (std::size_t k = 0; k < model.limiters.size(); ++k) {
    const double a = model.limiters[k].angle;
    labels.push_back({"limiter " + std::to_string(k + 1),
                      at({std::cos(a), std::sin(a), gl::kHalfHeight + 0.06})});
  }
  return labels;
}

}  // namespace

std::vector<CylinderLabel> cylinder_labels(const PanelInput<CylinderPlot>& in) {
  return labels_of(cylinder_scene(in), in.model, in.layout.plots.front());
}

std::optional<std::string> draw_cylinder_panel(cairo_t* cr, const PanelInput<CylinderPlot>& in) {
  const Rect& area = in.layout.plots.front();
  const gl::CylinderScene scene = cylinder_scene(in);
  // Views larger than render/gl allows are drawn at its limit and scaled up.
  const auto [w, h] = view_size(area);
  std::string error;
  const Image view = gl::render_cylinder_view(scene, w, h, &error);
  const SurfacePtr surface = surface_from_image(view);
  if (!surface) return error.empty() ? "the 3-D view could not be drawn" : error;

  cairo_save(cr);
  cairo_translate(cr, area.x, area.y);
  cairo_scale(cr, area.w / w, area.h / h);
  cairo_set_source_surface(cr, surface.get(), 0.0, 0.0);
  cairo_paint(cr);
  cairo_restore(cr);

  draw_title(cr, in.layout.title_anchor,
             in.spec.title.empty() ? default_title(in.spec, in.run.stats.t_reached) : in.spec.title,
             in.style);
  set_font(cr, in.style.note_font());
  for (const CylinderLabel& label : labels_of(scene, in.model, area))
    draw_text_on_backdrop(cr, label.text, label.at, {HAlign::center, VAlign::middle}, kInk,
                          in.style.px(1.5));
  draw_text(cr, caption(*scene.dphi_range),
            {area.x + in.style.px(8.0), area.bottom() - in.style.px(6.0)},
            {HAlign::left, VAlign::bottom}, kMutedInk);
  return std::nullopt;
}
#else
std::optional<std::string> draw_cylinder_panel(cairo_t*, const PanelInput<CylinderPlot>&) {
  return "3-D panels are not available in this build";
}

std::vector<CylinderLabel> cylinder_labels(const PanelInput<CylinderPlot>&) { return {}; }
#endif

}  // namespace vibro::render
