#include "render/figure.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <cstdio>
#include <exception>
#include <utility>

#include "render/axes.h"
#include "render/cairo_ptr.h"
#include "render/cylinder_panel.h"
#include "render/layout.h"
#include "render/mechanism_panel.h"
#include "render/panel.h"
#include "render/png.h"
#include "render/svg_text.h"
#include "render/text.h"
#include "render/track_window.h"

namespace vibro {
namespace {

using render::CairoPtr;
using render::SurfacePtr;

// The field that names the pellets a panel draws.
const char* pellets_field(PlotKind kind) {
  if (kind == PlotKind::time) return "pellets";
  return kind == PlotKind::mechanism ? "kind" : "pellet";  // a mechanism draws every pellet
}

// The run must hold the track of every pellet a panel draws, and reach the instant a mechanism
// panel shows (the scene reader holds it to t_end; a run may end earlier).
std::optional<FieldError> check_tracks(const FigureSpec& figure, const Model& model,
                                       const RunResult& run) {
  for (std::size_t i = 0; i < figure.plots.size(); ++i) {
    const PlotSpec& plot = figure.plots[i];
    const std::string field = "plots[" + std::to_string(i) + "].";
    for (int pellet : render::panel_pellets(plot, model.size())) {
      if (render::find_track(run, pellet)) continue;
      return FieldError{field + pellets_field(plot.kind),
                        "the run recorded no trajectory for pellet " + std::to_string(pellet + 1) +
                            "; ask for its branches"};
    }
    const double end = run.stats.t_reached;
    if (plot.kind == PlotKind::mechanism && plot.t > end + 1e-12 * (1.0 + end)) {
      char text[96];
      std::snprintf(text, sizeof text,
                    "is after the end of the run at t = %g s: must be within [0, t_end]", end);
      return FieldError{field + "t", text};
    }
  }
  return std::nullopt;
}

// The panel of a sweep's plot kind (bifurcation, section, impact map: a cloud of points).
void draw_sweep_panel(cairo_t* cr, const render::PanelInput& in) {
  if (in.spec.kind == PlotKind::regime_map)
    render::draw_regime_map_panel(cr, in);
  else if (in.spec.kind == PlotKind::lyapunov)
    render::draw_lyapunov_panel(cr, in);
  else if (in.spec.kind == PlotKind::lyapunov_map)
    render::draw_lyapunov_map_panel(cr, in);
  else
    render::draw_sweep_points_panel(cr, in);
}

// Draws panel i of the figure with the given layout.
std::optional<FieldError> draw_panel(cairo_t* cr, const FigureSpec& figure, std::size_t i,
                                     const render::PanelInput& in) {
  const PanelData& data = in.data;
  const std::string kind_field = "plots[" + std::to_string(i) + "].kind";
  switch (figure.plots[i].kind) {
    case PlotKind::phase:
      render::draw_phase_panel(cr, in);
      break;
    case PlotKind::time:
      render::draw_time_panel(cr, in);
      break;
    case PlotKind::cylinder:
      if (auto message = render::draw_cylinder_panel(cr, in))
        return FieldError{kind_field, *message};
      break;
    case PlotKind::work_precision:
      if (!data.work_precision) return FieldError{kind_field, "needs a work-precision sweep"};
      render::draw_work_precision_panel(cr, in);
      break;
    case PlotKind::bifurcation:
    case PlotKind::section:
    case PlotKind::impact_map:
    case PlotKind::regime_map:
    case PlotKind::lyapunov:
    case PlotKind::lyapunov_map:
      if (!data.sweep || !data.sweep_spec) return FieldError{kind_field, "needs a sweep"};
      if (auto e = validate_sweep_plot(figure.plots[i].kind, *data.sweep_spec)) return e;
      draw_sweep_panel(cr, in);
      break;
    case PlotKind::branch:
      if (!data.branch || !data.continuation)
        return FieldError{kind_field, "needs a continued periodic motion"};
      render::draw_branch_panel(cr, in);
      break;
    case PlotKind::mechanism:
      render::draw_mechanism_panel(cr, in);
      break;
  }
  return std::nullopt;
}

// The same panel with room for its legend beside the plot or above it, whichever leaves the data
// the larger share of its plot area.
std::pair<render::PanelLayout, render::LegendPlace> with_room_for_legend(
    const render::PanelLayout& layout, const render::Style& style, const render::LegendFit& fit) {
  const render::Rect& plot = layout.plots.front();
  const double column = fit.size.x / style.scale + 2.0 * render::kLegendInset;
  const double strip = fit.size.y / style.scale + render::kLegendInset;
  const int stacked = static_cast<int>(layout.plots.size());
  const double beside = 1.0 - style.px(column) / plot.w;
  const double above = 1.0 - style.px(strip) / (stacked * plot.h);
  if (beside >= above)
    return {render::panel_layout(layout.cell, style, stacked, column), render::LegendPlace::beside};
  return {render::panel_layout(layout.cell, style, stacked, 0.0, strip),
          render::LegendPlace::above};
}

std::optional<FieldError> draw_figure(cairo_t* cr, const FigureSpec& figure, const Model& model,
                                      const RunResult& run, const PanelData& data,
                                      std::vector<PlotAxes>& axes) {
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);
  const render::Style style = render::style_for(figure.width, figure.height);
  const auto layouts = render::figure_layout(figure);
  // A legend that would hide data in every corner of its plot goes beside it or above it instead:
  // the panel is drawn again, narrower or lower. An image is drawn once and its cell painted over
  // when it must be redrawn; a vector figure (where what is painted over stays in the file) is
  // first drawn on a pixel of scratch, which only measures.
  const bool raster = cairo_surface_get_type(cairo_get_target(cr)) == CAIRO_SURFACE_TYPE_IMAGE;
  render::SurfacePtr scratch_surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1));
  render::CairoPtr scratch(cairo_create(scratch_surface.get()));
  for (std::size_t i = 0; i < layouts.size(); ++i) {
    const PlotKind kind = figure.plots[i].kind;
    const bool movable = kind != PlotKind::cylinder && kind != PlotKind::regime_map &&
                         kind != PlotKind::lyapunov_map;
    render::LegendFit fit;
    std::vector<PlotAxes> measured;
    cairo_t* first = raster || !movable ? cr : scratch.get();
    render::watch_legends(first, &fit);
    const std::size_t axes_before = axes.size();
    auto e = draw_panel(
        first, figure, i,
        {figure.plots[i], model, run, layouts[i], style, data, first == cr ? &axes : &measured});
    render::watch_legends(first, nullptr);
    if (e) return e;
    if (movable && fit.hid_data) {
      axes.resize(axes_before);
      if (first == cr) {
        const render::Rect& c = layouts[i].cell;
        cairo_rectangle(cr, c.x, c.y, c.w, c.h);
        cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
        cairo_fill(cr);
      }
      const auto [roomy, place] = with_room_for_legend(layouts[i], style, fit);
      render::place_legends(cr, place);
      e = draw_panel(cr, figure, i, {figure.plots[i], model, run, roomy, style, data, &axes});
      render::place_legends(cr, render::LegendPlace::inside);
      if (e) return e;
    } else if (first != cr) {
      if (auto again = draw_panel(cr, figure, i,
                                  {figure.plots[i], model, run, layouts[i], style, data, &axes}))
        return again;
    }
    if (layouts.size() > 1) render::draw_panel_letter(cr, layouts[i].cell, i, style);
  }
  if (cairo_status(cr) != CAIRO_STATUS_SUCCESS)
    return FieldError{"",
                      std::string("drawing failed: ") + cairo_status_to_string(cairo_status(cr))};
  return std::nullopt;
}

RenderResult failure(FieldError error) { return {{}, {}, std::move(error), {}}; }

RenderResult render_png(const FigureSpec& figure, const Model& model, const RunResult& run,
                        const PanelData& data) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, figure.width, figure.height));
  CairoPtr cr(cairo_create(surface.get()));
  std::vector<PlotAxes> axes;
  if (auto e = draw_figure(cr.get(), figure, model, run, data, axes)) return failure(*e);
  cairo_surface_flush(surface.get());
  auto bytes =
      render::encode_png_argb32(cairo_image_surface_get_data(surface.get()), figure.width,
                                figure.height, cairo_image_surface_get_stride(surface.get()), true);
  if (bytes.empty()) return failure({"", "PNG encoding failed"});
  return {std::move(bytes), std::string(content_type(ImageFormat::png)), std::nullopt,
          std::move(axes)};
}

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(closure);
  out->insert(out->end(), data, data + length);
  return CAIRO_STATUS_SUCCESS;
}

// SVG or PDF: vector output from the same drawing calls.
RenderResult render_vector(const FigureSpec& figure, const Model& model, const RunResult& run,
                           const PanelData& data, ImageFormat format) {
  std::vector<std::uint8_t> bytes;
  // A PDF is measured in points: 0.75 pt per pixel, the CSS ratio, so that 1200 px print 12.5 in.
  const double scale = format == ImageFormat::pdf ? 0.75 : 1.0;
  SurfacePtr surface(
      format == ImageFormat::pdf
          ? cairo_pdf_surface_create_for_stream(append_bytes, &bytes, scale * figure.width,
                                                scale * figure.height)
          : cairo_svg_surface_create_for_stream(append_bytes, &bytes, figure.width, figure.height));
  // Pixels, not cairo's default points, so that the SVG shows at the size asked for.
  if (format == ImageFormat::svg)
    cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
  std::vector<render::PlacedText> texts;
  std::vector<PlotAxes> axes;
  {
    CairoPtr cr(cairo_create(surface.get()));
    cairo_scale(cr.get(), scale, scale);
    if (format == ImageFormat::svg) render::collect_text(cr.get(), &texts);
    if (auto e = draw_figure(cr.get(), figure, model, run, data, axes)) return failure(*e);
  }
  cairo_surface_finish(surface.get());
  if (format == ImageFormat::svg) render::append_to_svg(bytes, render::svg_text_elements(texts));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    return failure(
        {"", std::string(format == ImageFormat::pdf ? "PDF" : "SVG") +
                 " output failed: " + cairo_status_to_string(cairo_surface_status(surface.get()))});
  return {std::move(bytes), std::string(content_type(format)), std::nullopt, std::move(axes)};
}

}  // namespace

std::string_view content_type(ImageFormat format) {
  switch (format) {
    case ImageFormat::png:
      return "image/png";
    case ImageFormat::svg:
      return "image/svg+xml";
    case ImageFormat::pdf:
      return "application/pdf";
  }
  return "application/octet-stream";
}

std::optional<ImageFormat> image_format_named(std::string_view name) {
  if (name == "png") return ImageFormat::png;
  if (name == "svg") return ImageFormat::svg;
  if (name == "pdf") return ImageFormat::pdf;
  return std::nullopt;
}

std::optional<ImageFormat> image_format_of_file(std::string_view path) {
  const std::size_t dot = path.rfind('.');
  if (dot == std::string_view::npos || dot == 0 || path.substr(0, dot).ends_with('/'))
    return std::nullopt;
  return image_format_named(path.substr(dot + 1));
}

RenderResult render_figure(const FigureSpec& figure, const Model& model, const RunResult& run,
                           ImageFormat format, const PanelData& data) {
  try {
    if (auto e = validate_figure(figure, model, format)) return failure(*e);
    if (auto e = check_tracks(figure, model, run)) return failure(*e);
    return format == ImageFormat::png ? render_png(figure, model, run, data)
                                      : render_vector(figure, model, run, data, format);
  } catch (const std::exception& e) {
    // Out of memory, mostly: an error value, never an exception across the module boundary.
    return failure({"", std::string("rendering failed: ") + e.what()});
  }
}

}  // namespace vibro
