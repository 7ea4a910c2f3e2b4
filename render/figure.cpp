#include "render/figure.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <cstdio>
#include <exception>
#include <utility>
#include <variant>

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
const char* pellets_field(const PlotSpec& plot) {
  if (std::holds_alternative<TimePlot>(plot)) return "pellets";
  // A mechanism draws every pellet.
  return std::holds_alternative<MechanismPlot>(plot) ? "kind" : "pellet";
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
      return FieldError{field + pellets_field(plot), "the run recorded no trajectory for pellet " +
                                                         std::to_string(pellet + 1) +
                                                         "; ask for its branches"};
    }
    const double end = run.stats.t_reached;
    const auto* mechanism = std::get_if<MechanismPlot>(&plot);
    if (mechanism && mechanism->t > end + 1e-12 * (1.0 + end)) {
      char text[96];
      std::snprintf(text, sizeof text,
                    "is after the end of the run at t = %g s: must be within [0, t_end]", end);
      return FieldError{field + "t", text};
    }
  }
  return std::nullopt;
}

// Where and from what a panel is drawn, whatever its kind.
struct Frame {
  const Model& model;
  const RunResult& run;
  const render::PanelLayout& layout;
  const render::Style& style;
  std::vector<PlotAxes>* axes;
};

// Draws one panel: each kind's drawer with the data it needs, or an error naming the panel's
// kind when that data is not given.
struct PanelDrawer {
  cairo_t* cr;
  const Frame& frame;
  const PanelData& data;
  std::string kind_field;  // "plots[i].kind"

  using Drawn = std::optional<FieldError>;

  template <class Plot>
  render::PanelInput<Plot> input(const Plot& plot) const {
    return {plot, frame.model, frame.run, frame.layout, frame.style, frame.axes};
  }
  Drawn operator()(const PhasePlot& plot) const {
    render::draw_phase_panel(cr, input(plot));
    return std::nullopt;
  }
  Drawn operator()(const TimePlot& plot) const {
    render::draw_time_panel(cr, input(plot));
    return std::nullopt;
  }
  Drawn operator()(const CylinderPlot& plot) const {
    if (auto message = render::draw_cylinder_panel(cr, input(plot)))
      return FieldError{kind_field, *message};
    return std::nullopt;
  }
  Drawn operator()(const MechanismPlot& plot) const {
    render::draw_mechanism_panel(cr, input(plot));
    return std::nullopt;
  }
  Drawn operator()(const WorkPrecisionPlot& plot) const {
    if (!data.work_precision) return FieldError{kind_field, "needs a work-precision sweep"};
    render::draw_work_precision_panel(cr, input(plot), *data.work_precision);
    return std::nullopt;
  }
  Drawn operator()(const SweepPlot& plot) const {
    if (!data.sweep) return FieldError{kind_field, "needs a sweep"};
    if (auto e = validate_sweep_plot(plot.view, data.sweep->spec)) return e;
    const SweepData& sweep = *data.sweep;
    if (plot.view == SweepView::regime_map)
      render::draw_regime_map_panel(cr, input(plot), sweep);
    else if (plot.view == SweepView::lyapunov)
      render::draw_lyapunov_panel(cr, input(plot), sweep);
    else if (plot.view == SweepView::lyapunov_map)
      render::draw_lyapunov_map_panel(cr, input(plot), sweep);
    else if (plot.view == SweepView::basins)
      render::draw_basins_panel(cr, input(plot), sweep);
    else
      render::draw_sweep_points_panel(cr, input(plot), sweep,
                                      data.branch ? &*data.branch : nullptr);
    return std::nullopt;
  }
  Drawn operator()(const BranchPlot& plot) const {
    if (!data.branch) return FieldError{kind_field, "needs a continued periodic motion"};
    if (plot.curves) return curves(plot);
    if (!data.sweep) {
      render::draw_branch_panel(cr, input(plot), *data.branch);
      return std::nullopt;
    }
    // Over the sweep beneath it: that sweep's bifurcation diagram with the branch drawn on it.
    const SweepPlot diagram{SweepView::bifurcation, plot.pellet, plot.coordinate, plot.title};
    render::draw_sweep_points_panel(cr, input(diagram), *data.sweep, &*data.branch);
    return std::nullopt;
  }

  // Bifurcation curves, over the regime map of a 2-D sweep of the same two parameters if given.
  Drawn curves(const BranchPlot& plot) const {
    const BranchData& branch = *data.branch;
    if (!branch.curves || !branch.follow)
      return FieldError{kind_field,
                        "needs bifurcation curves (periodic_orbit.continuation.follow)"};
    const SweepSpec* spec = data.sweep ? &data.sweep->spec : nullptr;
    const std::string& p1 = branch.continuation.parameter;
    const std::string& p2 = branch.follow->parameter2;
    const bool same =
        spec && spec->axis2 && spec->axis.parameter == p1 && spec->axis2->parameter == p2;
    const bool swapped =
        spec && spec->axis2 && spec->axis.parameter == p2 && spec->axis2->parameter == p1;
    if (!same && !swapped) {
      render::draw_curves_panel(cr, input(plot), branch);
      return std::nullopt;
    }
    const SweepPlot map{SweepView::regime_map, plot.pellet, plot.coordinate,
                        plot.title.empty() ? "Bifurcation curves over the regime map" : plot.title};
    const render::Style& style = frame.style;
    render::draw_regime_map_panel(
        cr, input(map), *data.sweep,
        [&](const render::Transform& tr, std::vector<render::LegendEntry>& legend) {
          render::draw_bifurcation_curves(cr, tr, *branch.curves, swapped, style, legend);
        });
    return std::nullopt;
  }
};

// Draws panel i of the figure with the given layout.
std::optional<FieldError> draw_panel(cairo_t* cr, const FigureSpec& figure, std::size_t i,
                                     const Frame& frame, const PanelData& data) {
  return std::visit(PanelDrawer{cr, frame, data, "plots[" + std::to_string(i) + "].kind"},
                    figure.plots[i]);
}

// Whether a panel's legend may move beside or above its plot (a 3-D view and a map keep theirs).
bool legend_movable(const PlotSpec& plot) {
  if (std::holds_alternative<CylinderPlot>(plot)) return false;
  const auto* sweep = std::get_if<SweepPlot>(&plot);
  return !sweep || !map_view(sweep->view);
}

// The same panel with room for its legend beside the plot or above it, whichever leaves the data
// the larger share of its plot area.
std::pair<render::PanelLayout, render::LegendPlace> with_room_for_legend(
    const render::PanelLayout& layout, const render::Style& style, const render::LegendFit& fit) {
  const render::Rect& plot = layout.plots.front();
  const double column = fit.size.x / style.scale + 2.0 * render::kLegendInset;
  const double strip = fit.strip.y / style.scale + render::kLegendInset;
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
  const render::Style style = render::style_for(figure);
  const auto layouts = render::figure_layout(figure);
  // A legend that would hide data in every corner of its plot goes beside it or above it instead:
  // the panel is drawn again, narrower or lower. An image is drawn once and its cell painted over
  // when it must be redrawn; a vector figure (where what is painted over stays in the file) is
  // first drawn on a pixel of scratch, which only measures.
  const bool raster = cairo_surface_get_type(cairo_get_target(cr)) == CAIRO_SURFACE_TYPE_IMAGE;
  render::SurfacePtr scratch_surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1));
  render::CairoPtr scratch(cairo_create(scratch_surface.get()));
  for (std::size_t i = 0; i < layouts.size(); ++i) {
    const bool movable = legend_movable(figure.plots[i]);
    render::LegendFit fit;
    std::vector<PlotAxes> measured;
    cairo_t* first = raster || !movable ? cr : scratch.get();
    render::watch_legends(first, &fit);
    const std::size_t axes_before = axes.size();
    auto e = draw_panel(first, figure, i,
                        {model, run, layouts[i], style, first == cr ? &axes : &measured}, data);
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
      e = draw_panel(cr, figure, i, {model, run, roomy, style, &axes}, data);
      render::place_legends(cr, render::LegendPlace::inside);
      if (e) return e;
    } else if (first != cr) {
      if (auto again = draw_panel(cr, figure, i, {model, run, layouts[i], style, &axes}, data))
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
  auto bytes = render::encode_png_argb32(
      cairo_image_surface_get_data(surface.get()), figure.width, figure.height,
      cairo_image_surface_get_stride(surface.get()), true, figure.print ? figure.print->dpi : 0.0);
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
  // A PDF is measured in points: 0.75 pt per pixel, the CSS ratio, so that 1200 px print 12.5 in;
  // with a print size, 72 / dpi, so that the page is its size (to half a dot).
  const double pdf_scale = figure.print ? 72.0 / figure.print->dpi : 0.75;
  const double scale = format == ImageFormat::pdf ? pdf_scale : 1.0;
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
  if (format == ImageFormat::svg) {
    render::append_to_svg(bytes, render::svg_text_elements(texts));
    // At its print size: the page in mm, over the same view box of pixels.
    if (figure.print)
      render::set_svg_size_mm(bytes, figure.print->width_mm, figure.print->height_mm);
  }
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    return failure(
        {"", std::string(format == ImageFormat::pdf ? "PDF" : "SVG") +
                 " output failed: " + cairo_status_to_string(cairo_surface_status(surface.get()))});
  return {std::move(bytes), std::string(content_type(format)), std::nullopt, std::move(axes)};
}

RenderResult render_sized(const FigureSpec& figure, const Model& model, const RunResult& run,
                          ImageFormat format, const PanelData& data) {
  if (auto e = validate_figure(figure, model, format)) return failure(*e);
  if (auto e = check_tracks(figure, model, run)) return failure(*e);
  return format == ImageFormat::png ? render_png(figure, model, run, data)
                                    : render_vector(figure, model, run, data, format);
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
    if (figure.print) {
      // Its pixels from its print size, whatever the caller left in width and height.
      FigureSpec sized = figure;
      apply_print_size(sized);
      if (auto e = check_print_size(*figure.print, {})) return failure(*e);
      return render_sized(sized, model, run, format, data);
    }
    return render_sized(figure, model, run, format, data);
  } catch (const std::exception& e) {
    // Out of memory, mostly: an error value, never an exception across the module boundary.
    return failure({"", std::string("rendering failed: ") + e.what()});
  }
}

}  // namespace vibro
