// Sweeps as JSON (API.md, "Sweeps"): the scene's "sweep" object, read strictly and written back,
// and a sweep's result as JSON or CSV, the points as columns.
#pragma once

#include <array>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "core/analysis/sweep.h"
#include "render/plot_spec.h"

namespace vibro {

// Reads a scene's "sweep" object; throws FieldException (io/json_fields.h) naming the field.
SweepSpec read_sweep(const nlohmann::json& json);
nlohmann::json sweep_to_json(const SweepSpec& spec);

// Takes the text of a document piece by piece (each some 64 KiB); false: stop writing (the
// reader went away).
using TextSink = std::function<bool(std::string_view piece)>;

// {"parameter", "parameter2", "section", "points": {columns}, "runs": {columns}, "stats"}:
// one entry per section point, and one per run with its period, impacts per period, trust and
// largest Lyapunov exponent (null without one, and for −infinity, which JSON cannot hold). Keys
// in sorted order, numbers as their shortest text that reads back to the bit.
// Written to `sink` as it is formatted: memory for one piece, whatever the points. Whether the
// sink took all of it. With `scene` (the scene's JSON, io/scene_json.h), the result says what made
// it under "scene", so that `vibro plot` can redraw it alone.
bool write_sweep_result_json(const SweepSpec& spec, const SweepResult& result, const TextSink& sink,
                             const nlohmann::json& scene = nullptr);
nlohmann::json sweep_result_json(const SweepSpec& spec, const SweepResult& result,
                                 const nlohmann::json& scene = nullptr);
// The same document as one string, as write_sweep_result_json writes it: the text of
// sweep_result_json(...).dump(), without building the tree.
std::string sweep_result_text(const SweepSpec& spec, const SweepResult& result,
                              const nlohmann::json& scene = nullptr);
// The result without its "points" and "runs" columns, whose size grows with the runs: the
// attractors (a sweep that classifies them), the parameters, the section and the stats, as
// write_sweep_result_json writes them.
bool write_sweep_summary_json(const SweepSpec& spec, const SweepResult& result,
                              const TextSink& sink);
// The points as CSV with a header row, one line per point, each run's classification on it; the
// Lyapunov exponent last, empty without one and "-inf" where every perturbation dies. Numbers
// to 17 significant digits. The header names the swept parameters by their field paths
// (sweep_csv_header): the file says what its first two columns are.
bool write_sweep_result_csv(const SweepSpec& spec, const SweepResult& result, const TextSink& sink);
std::string sweep_result_csv(const SweepSpec& spec, const SweepResult& result);
// The header row: the parameter's path, the second parameter's (or "value2", then always 0, for
// a sweep of one parameter), start, direction, pellet, t, phi, dphi, phase, limiter, trusted,
// period, impacts_per_period, lyapunov, and attractor for a sweep that classifies attractors.
std::string sweep_csv_header(const SweepSpec& spec);
// The names of the header's first two columns: the parameters' field paths ("value2" for a
// sweep of one parameter).
std::array<std::string, 2> sweep_value_names(const SweepSpec& spec);
// One run's lines, the attractor column holding `attractor` when given (a stream of chains
// writes them as they finish, io/sweep_csv_stream.h).
std::string sweep_run_csv(const SweepRun& run, std::optional<int> attractor);

// The plot a sweep is drawn as: one of kSweepPlotNames; an empty name picks the regime map for a
// 2-D sweep and the bifurcation diagram otherwise. Nothing for another name. Whether the sweep
// can be drawn so (the Lyapunov plots need "lyapunov": true) is validate_sweep_plot's question
// (render/figure.h).
std::optional<SweepView> sweep_plot_kind(const std::string& name, const SweepSpec& spec);
inline constexpr const char* kSweepPlotNames =
    "\"bifurcation\", \"section\", \"impact_map\", \"regime_map\", \"lyapunov\", "
    "\"lyapunov_map\" or \"basins\"";

}  // namespace vibro
