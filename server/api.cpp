#include "server/api.h"

#include <algorithm>
#include <exception>
#include <future>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "io/orbit_json.h"
#include "io/presets.h"
#include "io/scene_json.h"
#include "io/sweep_json.h"
#include "render/figure.h"
#include "render/orbit_figure.h"
#include "server/access_log.h"
#include "server/api_error.h"
#include "server/etag.h"
#include "server/scene_request.h"
#include "server/sweep_limits.h"

namespace vibro::server {
namespace {

using nlohmann::json;

// The simulator is deterministic: an answer for a key never changes within a version.
constexpr const char* kCacheForever = "public, max-age=3600";

std::string make_preset_list() {
  json list = json::array();
  for (const PresetText& p : presets()) {
    json scene = json::parse(p.json);
    list.push_back({{"name", p.name},
                    {"description", scene.value("description", "")},
                    {"scene", std::move(scene)}});
  }
  return list.dump();
}

// The part of a scene its answer depends on, as canonical JSON text: names and descriptions
// are dropped, so a preset and the same scene posted by hand share one cache entry.
std::string canonical(const Scene& scene, bool with_figure) {
  json j = scene_to_json(scene);
  for (const char* key : {"name", "description", "assumptions"}) j.erase(key);
  if (!with_figure) {
    for (const char* key : {"plots", "width", "height", "figure"}) j.erase(key);
  }
  return j.dump();
}

// What a simulate request asks for: nothing for JSON, or a table as CSV (format=csv, what=events
// by default or trajectory).
std::variant<std::optional<RunTable>, ApiError> table_of(const httplib::Request& req) {
  const std::string format = req.has_param("format") ? req.get_param_value("format") : "json";
  if (format != "json" && format != "csv")
    return ApiError{400, "format", "must be \"json\" or \"csv\", got \"" + format + "\""};
  if (!req.has_param("what"))
    return format == "csv" ? std::optional<RunTable>(RunTable::events) : std::nullopt;
  if (format != "csv") return ApiError{400, "what", "applies to format=csv only"};
  const auto table = run_table_named(req.get_param_value("what"));
  if (!table) return ApiError{400, "what", "must be \"events\" or \"trajectory\""};
  return std::optional<RunTable>(*table);
}

// A trajectory sampled at a uniform step (dt=, with what=trajectory): sets the scene's stops and
// the table to read them; else why not, naming dt.
std::optional<ApiError> sample_uniformly(const httplib::Request& req, const Limits& limits,
                                         Scene& scene, std::optional<RunTable>& table) {
  if (!req.has_param("dt")) return std::nullopt;
  if (table != RunTable::trajectory)
    return ApiError{400, "dt", "samples the trajectory: ask format=csv&what=trajectory"};
  const auto dt = parse_number(req.get_param_value("dt"));
  const long most =
      limits.samples > 0 ? std::min(limits.samples, kMaxUniformSamples) : kMaxUniformSamples;
  auto times = uniform_times(dt.value_or(0.0), scene.sim.t_end, scene.model.size(), most, "dt");
  if (auto* e = std::get_if<FieldError>(&times)) return ApiError::from(*e);
  scene.sim.stops = std::get<std::vector<double>>(std::move(times));
  table = RunTable::uniform;
  return std::nullopt;
}

std::string table_key(std::optional<RunTable> table, const Scene& scene) {
  if (!table) return "";
  if (*table == RunTable::events) return " csv events";
  if (*table == RunTable::trajectory) return " csv trajectory";
  std::ostringstream key;  // the grid of times is the scene's t_end and the step
  key.precision(17);
  key << " csv uniform " << (scene.sim.stops.size() > 1 ? scene.sim.stops[1] : 0.0) << " "
      << scene.sim.stops.size();
  return key.str();
}

std::string simulate_key(const Scene& scene) { return "simulate " + canonical(scene, false); }

std::string render_key(const Scene& scene, ImageFormat format) {
  return "render " + std::string(content_type(format)) + " " + canonical(scene, true);
}

std::variant<ImageFormat, ApiError> format_of(const httplib::Request& req) {
  if (!req.has_param("format")) return ImageFormat::png;
  const std::string f = req.get_param_value("format");
  if (const auto format = image_format_named(f)) return *format;
  return ApiError{400, "format", "must be \"png\", \"svg\" or \"pdf\", got \"" + f + "\""};
}

// Parameters a POST may carry in its query: the scene itself is in the body.
std::optional<ApiError> only_params(const httplib::Request& req,
                                    std::initializer_list<std::string_view> allowed) {
  for (const auto& [name, value] : req.params) {
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
      return ApiError{400, name, "is not a parameter here: the scene goes in the body"};
    }
  }
  return std::nullopt;
}

// Behind the front door, replica k's job ids begin "r<k>-"; alone (0), they have no prefix.
// Appended rather than concatenated: GCC 12 takes "r" + string for an overlapping memcpy.
std::string job_id_prefix(int replica) {
  if (replica <= 0) return "";
  std::string prefix = "r";
  prefix += std::to_string(replica);
  prefix += '-';
  return prefix;
}

void send(httplib::Response& res, const CachedResponse& answer, bool hit) {
  res.set_header("ETag", answer.etag);
  res.set_header("Cache-Control", kCacheForever);
  res.set_header("X-Vibro-Cache", hit ? "hit" : "miss");
  for (const auto& [name, value] : answer.headers) res.set_header(name, value);
  res.set_content(answer.body, answer.content_type);
}

}  // namespace

Api::Api(const ServerConfig& config)
    : config_(config),
      preset_list_(make_preset_list()),
      web_(web_dir(config)),
      cache_(config.cache_bytes),
      jobs_({config.sweep_jobs, config.sweep_threads, config.sweep_queue, 600.0, 32,
             job_id_prefix(config.replica), config.limits.sweep_points,
             1000.0 * config.limits.sweep_seconds, 4 * config.limits.sweep_points}),
      workers_(worker_count(config), config.queue) {}

void Api::health(const httplib::Request&, httplib::Response& res) const {
  const json body = {{"status", "ok"},
                     {"version", VIBRO_VERSION},
                     {"render3d", cylinder_panels_available()},
                     {"workers", worker_count(config_)}};
  res.set_header("Cache-Control", "no-store");
  res.set_content(body.dump(), "application/json");
}

void Api::limits(const httplib::Request&, httplib::Response& res) const {
  res.set_header("Cache-Control", "no-cache");
  res.set_content(limits_json(config_.limits).dump(), "application/json");
}

void Api::preset_list(const httplib::Request&, httplib::Response& res) const {
  res.set_header("Cache-Control", "no-cache");
  res.set_content(preset_list_, "application/json");
}

void Api::preset(const httplib::Request& req, httplib::Response& res) const {
  const std::string name = req.path.substr(std::string_view("/api/presets/").size());
  const auto text = preset_json(name);
  if (!text) {
    return send_error(res, {404, "preset", "no preset named \"" + name + "\" (see /api/presets)"});
  }
  res.set_header("Cache-Control", "no-cache");
  res.set_content(std::string(*text), "application/json");
}

void Api::simulate_post(const httplib::Request& req, httplib::Response& res) {
  if (auto e = only_params(req, {"format", "what", "dt"})) return send_error(res, *e);
  SceneOrApiError scene = scene_from_body(req, config_.limits);
  if (auto* e = std::get_if<ApiError>(&scene)) return send_error(res, *e);
  simulate(std::get<Scene>(scene), req, res);
}

void Api::simulate_get(const httplib::Request& req, httplib::Response& res) {
  SceneOrApiError scene = scene_from_query(
      req, config_.limits,
      {"t_end", "method", "rtol", "atol", "trajectories", "check", "format", "what", "dt"});
  if (auto* e = std::get_if<ApiError>(&scene)) return send_error(res, *e);
  simulate(std::get<Scene>(scene), req, res);
}

void Api::render_post(const httplib::Request& req, httplib::Response& res) {
  if (auto e = only_params(req, {"format"})) return send_error(res, *e);
  SceneOrApiError scene = scene_from_body(req, config_.limits);
  if (auto* e = std::get_if<ApiError>(&scene)) return send_error(res, *e);
  render(std::get<Scene>(scene), req, res);
}

void Api::render_get(const httplib::Request& req, httplib::Response& res) {
  SceneOrApiError scene =
      scene_from_query(req, config_.limits,
                       {"format", "t_end", "width", "height", "width_mm", "height_mm", "font_pt",
                        "dpi", "pellet", "method", "rtol", "atol"});
  if (auto* e = std::get_if<ApiError>(&scene)) return send_error(res, *e);
  render(std::get<Scene>(scene), req, res);
}

void Api::work_precision_post(const httplib::Request& req, httplib::Response& res) {
  if (auto e = only_params(req, {"format"})) return send_error(res, *e);
  std::optional<ImageFormat> image;
  if (req.has_param("format") && req.get_param_value("format") != "json") {
    const auto format = format_of(req);
    if (auto* e = std::get_if<ApiError>(&format)) return send_error(res, *e);
    image = std::get<ImageFormat>(format);
  }
  SceneOrApiError scene = scene_from_body(req, config_.limits);
  if (auto* e = std::get_if<ApiError>(&scene)) return send_error(res, *e);
  auto produced =
      run_on_worker([scene = std::get<Scene>(std::move(scene)), image,
                     this] { return work_precision_scene(scene, image, config_.limits); },
                    res);
  if (!produced) return;
  if (auto* e = std::get_if<ApiError>(&*produced)) return send_error(res, *e);
  Produced& p = std::get<Produced>(*produced);
  res.set_header("Cache-Control", "no-store");
  res.set_content(std::move(p.body), p.content_type);
}

void Api::static_file(const httplib::Request& req, httplib::Response& res) const {
  const auto file = web_.find(req.path);
  if (!file) return send_error(res, {404, "path", "no such page"});
  // The page is being worked on and is small: browsers revalidate rather than keep stale copies.
  res.set_header("Cache-Control", "no-cache");
  res.set_header("X-Content-Type-Options", "nosniff");
  res.set_content(file->body, file->content_type);
}

namespace {

// How much of a sweep's result is written: all of it, as JSON or CSV, or its JSON summary
// (part=summary: the attractors and stats without the columns that grow with the runs).
enum class SweepPart { json, csv, summary };

// Which part a result query asks for (format=json|csv, part=all|summary); else why not, naming
// the parameter. Nothing for an image format.
std::optional<std::variant<SweepPart, ApiError>> sweep_part_of(const httplib::Request& req) {
  const std::string format = req.has_param("format") ? req.get_param_value("format") : "json";
  const std::string part = req.has_param("part") ? req.get_param_value("part") : "all";
  if (part != "all" && part != "summary")
    return ApiError{400, "part", "must be \"all\" or \"summary\", got \"" + part + "\""};
  if (part == "summary" && format != "json")
    return ApiError{400, "part", "part=summary applies to format=json only"};
  if (format == "csv") return SweepPart::csv;
  if (format == "json") return part == "summary" ? SweepPart::summary : SweepPart::json;
  return std::nullopt;
}

// A sweep's points, written to the connection as they are formatted (chunked): memory for one
// piece at a time, not the document. The result lives as long as the writing.
void stream_sweep_result(const Job& job, SweepPart part, httplib::Response& res) {
  auto write = [result = job.sweep, spec = *job.scene.sweep, part](std::size_t,
                                                                   httplib::DataSink& sink) {
    const TextSink to_sink = [&sink](std::string_view piece) {
      AccessLog::streamed(piece.size());
      return sink.write(piece.data(), piece.size());
    };
    const bool whole = part == SweepPart::csv    ? write_sweep_result_csv(spec, *result, to_sink)
                       : part == SweepPart::json ? write_sweep_result_json(spec, *result, to_sink)
                                                 : write_sweep_summary_json(spec, *result, to_sink);
    if (whole) sink.done();
    return whole;  // false: the client went away, the connection ends
  };
  res.set_chunked_content_provider(part == SweepPart::csv ? "text/csv" : "application/json",
                                   std::move(write));
}

json job_json(const JobStatus& s) {
  json j = {{"id", s.id},
            {"status", job_state_name(s.state)},
            {"progress", {{"done", s.done}, {"total", s.total}}}};
  // Why it failed, in the shape of an error answer.
  if (s.error) {
    j["error"] = s.error->message;
    j["field"] = s.error->field;
  }
  return j;
}

void send_status(httplib::Response& res, const JobStatus& s) {
  res.set_header("Cache-Control", "no-store");
  res.set_content(job_json(s).dump(), "application/json");
}

}  // namespace

void Api::sweep_post(const httplib::Request& req, httplib::Response& res) {
  if (auto e = only_params(req, {})) return send_error(res, *e);
  SceneOrApiError parsed = scene_from_body(req, config_.limits);
  if (auto* e = std::get_if<ApiError>(&parsed)) return send_error(res, *e);
  Scene scene = std::move(std::get<Scene>(parsed));
  if (!scene.sweep)
    return send_error(res, {400, "sweep", "is required: the sweep to run (API.md, \"Sweeps\")"});
  if (auto e = check_sweep_cost(scene, config_.limits, config_.sweep_threads))
    return send_error(res, *e);
  scene.sim = bounded_options(scene.sim, config_.limits);
  scene.sim.deadline_ms =
      std::min(scene.sim.deadline_ms,
               sweep_run_deadline_ms(*scene.sweep, config_.limits, config_.sweep_threads));
  submit(JobKind::sweep, std::move(scene), res);
}

void Api::orbit_post(const httplib::Request& req, httplib::Response& res) {
  if (auto e = only_params(req, {"format"})) return send_error(res, *e);
  const std::string format = req.has_param("format") ? req.get_param_value("format") : "json";
  const std::optional<ImageFormat> image = image_format_named(format);
  if (format != "json" && !image)
    return send_error(
        res,
        {400, "format", "must be \"json\", \"png\", \"svg\" or \"pdf\", got \"" + format + "\""});
  SceneOrApiError parsed = scene_from_body(req, config_.limits);
  if (auto* e = std::get_if<ApiError>(&parsed)) return send_error(res, *e);
  Scene scene = std::move(std::get<Scene>(parsed));
  // A scene's own request was checked as it was read; the defaults are checked here.
  if (!scene.periodic_orbit) {
    scene.periodic_orbit.emplace();
    if (auto e = validate_orbit_request(scene.model, *scene.periodic_orbit, config_.limits))
      return send_error(res, ApiError::from(*e));
  }
  scene.sim = bounded_options(scene.sim, config_.limits);
  if (scene.periodic_orbit->continuation) {
    auto beneath = sweep_beneath_options(scene);
    if (auto* e = std::get_if<ApiError>(&beneath)) return send_error(res, *e);
    return submit(JobKind::orbit, std::move(scene), res,
                  std::get<std::optional<SimOptions>>(std::move(beneath)));
  }
  auto produced =
      run_on_worker([scene = std::move(scene), image] { return orbit_scene(scene, image); }, res);
  if (!produced) return;
  if (auto* e = std::get_if<ApiError>(&*produced)) return send_error(res, *e);
  Produced& p = std::get<Produced>(*produced);
  // Not cached: a map's run that meets the deadline makes the answer depend on the load.
  res.set_header("Cache-Control", "no-store");
  res.set_content(std::move(p.body), p.content_type);
}

std::variant<std::optional<SimOptions>, ApiError> Api::sweep_beneath_options(
    const Scene& scene) const {
  const OrbitRequest& request = *scene.periodic_orbit;
  if (!scene.sweep || !sweep_may_lie_beneath(*scene.sweep, *request.continuation,
                                             request.follow ? &*request.follow : nullptr))
    return std::nullopt;
  if (auto e = check_sweep_cost(scene, config_.limits, config_.sweep_threads)) return *e;
  SimOptions options = scene.sim;  // bounded already
  options.check = false;           // as `vibro orbit` runs it
  options.deadline_ms =
      std::min(options.deadline_ms,
               sweep_run_deadline_ms(*scene.sweep, config_.limits, config_.sweep_threads));
  return options;
}

void Api::submit(JobKind kind, Scene scene, httplib::Response& res,
                 std::optional<SimOptions> beneath) {
  const auto status = jobs_.submit(kind, std::move(scene), std::move(beneath));
  if (!status) {
    res.set_header("Retry-After", "10");
    return send_error(res, {503, "server", "the job queue is full; try again later"});
  }
  res.status = 202;
  res.set_header("Location", "/api/jobs/" + status->id);
  send_status(res, *status);
}

void Api::job_get(const httplib::Request& req, httplib::Response& res) {
  std::string id = req.path.substr(std::string_view("/api/jobs/").size());
  const bool wants_result = id.ends_with("/result");
  if (wants_result) id.resize(id.size() - std::string_view("/result").size());
  if (!wants_result) {
    if (auto e = only_params(req, {})) return send_error(res, *e);
    const auto status = jobs_.status(id);
    if (!status)
      return send_error(res,
                        {404, "id", "no job \"" + id + "\" (finished ones are kept for a while)"});
    return send_status(res, *status);
  }
  const auto job = jobs_.finished(id);
  if (!job) {
    const auto status = jobs_.status(id);
    if (!status) return send_error(res, {404, "id", "no job \"" + id + "\""});
    if (status->error)
      return send_error(res,
                        {409, status->error->field, "the job failed: " + status->error->message});
    return send_error(res, {409, "id",
                            "the job is " + std::string(job_state_name(status->state)) +
                                ", not done: its result is not ready"});
  }
  if (job->kind == JobKind::sweep) return sweep_result(*job, req, res);
  // An orbit's result: its JSON, or its continued branch drawn.
  if (auto e = only_params(req, {"format"})) return send_error(res, *e);
  const std::string format = req.has_param("format") ? req.get_param_value("format") : "json";
  res.set_header("Cache-Control", "no-store");
  if (format == "json")
    return res.set_content(orbit_result_json(*job->orbit).dump(), "application/json");
  const auto image_format = image_format_named(format);
  if (!image_format)
    return send_error(
        res,
        {400, "format", "must be \"json\", \"png\", \"svg\" or \"pdf\", got \"" + format + "\""});
  // Drawn on a worker, not the connection's thread: a branch without points is drawn as one
  // return of the motion, which is a simulation.
  auto produced = run_on_worker(
      [job, format = *image_format] {
        return orbit_image(job->scene, *job->orbit, format, job->sweep.get());
      },
      res);
  if (!produced) return;
  if (auto* e = std::get_if<ApiError>(&*produced)) return send_error(res, *e);
  Produced& p = std::get<Produced>(*produced);
  res.set_content(std::move(p.body), p.content_type);
}

void Api::sweep_result(const Job& job, const httplib::Request& req, httplib::Response& res) {
  if (auto e = only_params(req, {"format", "part", "plot", "pellet", "coordinate"}))
    return send_error(res, *e);
  const SweepSpec& spec = *job.scene.sweep;
  const std::string format = req.has_param("format") ? req.get_param_value("format") : "json";
  const auto part = sweep_part_of(req);
  if (part && std::holds_alternative<ApiError>(*part))
    return send_error(res, std::get<ApiError>(*part));
  res.set_header("Cache-Control", "no-store");
  if (part) return stream_sweep_result(job, std::get<SweepPart>(*part), res);
  const auto image_format = image_format_named(format);
  if (!image_format)
    return send_error(
        res, {400, "format",
              "must be \"json\", \"csv\", \"png\", \"svg\" or \"pdf\", got \"" + format + "\""});
  SweepPlot plot;
  const auto kind = sweep_plot_kind(req.get_param_value("plot"), spec);
  if (!kind) return send_error(res, {400, "plot", std::string("must be ") + kSweepPlotNames});
  if (auto e = validate_sweep_plot(*kind, spec)) return send_error(res, ApiError::from(*e));
  plot.view = *kind;
  if (req.has_param("pellet")) {
    const std::string p = req.get_param_value("pellet");
    plot.pellet = p.size() == 1 && p[0] >= '0' && p[0] <= '9' ? p[0] - '0' : -1;
    if (plot.pellet < 0 || plot.pellet >= job.scene.model.size())
      return send_error(
          res, {400, "pellet",
                "must be a pellet index in 0.." + std::to_string(job.scene.model.size() - 1)});
  }
  if (req.has_param("coordinate")) {
    const std::string c = req.get_param_value("coordinate");
    if (c != "dphi" && c != "phi")
      return send_error(res, {400, "coordinate", "must be \"dphi\" or \"phi\""});
    plot.coordinate = c == "phi" ? SectionCoordinate::phi : SectionCoordinate::dphi;
  }
  // A point plot in SVG or PDF keeps every point as a mark of its own (Limits::
  // sweep_vector_points): a large sweep is drawn as PNG.
  const long most = config_.limits.sweep_vector_points;
  const bool marks_points = plot.view == SweepView::bifurcation ||
                            plot.view == SweepView::section || plot.view == SweepView::impact_map;
  if (*image_format != ImageFormat::png && marks_points && job.points > most)
    return send_error(res, {400, "format",
                            "the sweep's " + std::to_string(job.points) +
                                " section points are more than the server draws as a vector "
                                "image (" +
                                std::to_string(most) + "): ask format=png"});
  FigureSpec figure = job.scene.figure;  // its size, and its print size if it has one
  figure.plots = {plot};
  // Drawn on a worker, not the connection's thread: as many drawings at once as workers.
  auto draw = [figure, model = job.scene.model, spec, sweep = job.sweep,
               format = *image_format]() -> JobResult {
    const RenderResult image =
        render_figure(figure, model, RunResult{}, format, {nullptr, SweepData{spec, *sweep}});
    if (!image.ok()) return ApiError::from(*image.error, 500);
    Produced p{std::string(image.bytes.begin(), image.bytes.end()), image.content_type, {}};
    // Where the parameter lies on the image, so that a click on it can name a value (the page).
    if (const auto axis = parameter_axis(figure, spec)) {
      std::ostringstream h;
      h.precision(17);
      h << axis->left << ',' << axis->top << ',' << axis->width << ',' << axis->height << ','
        << axis->from << ',' << axis->to;
      p.headers.emplace_back("X-Vibro-Parameter-Axis", h.str());
    }
    return p;
  };
  auto produced = run_on_worker(std::move(draw), res);
  if (!produced) return;
  if (auto* e = std::get_if<ApiError>(&*produced)) return send_error(res, *e);
  Produced& p = std::get<Produced>(*produced);
  for (const auto& [name, value] : p.headers) res.set_header(name, value);
  res.set_content(std::move(p.body), p.content_type);
}

void Api::job_delete(const httplib::Request& req, httplib::Response& res) {
  if (auto e = only_params(req, {})) return send_error(res, *e);
  const std::string id = req.path.substr(std::string_view("/api/jobs/").size());
  const auto status = jobs_.cancel(id);
  if (!status) return send_error(res, {404, "id", "no job \"" + id + "\""});
  send_status(res, *status);
}

void Api::simulate(const Scene& asked, const httplib::Request& req, httplib::Response& res) {
  const auto table = table_of(req);
  if (auto* e = std::get_if<ApiError>(&table)) return send_error(res, *e);
  std::optional<RunTable> t = std::get<std::optional<RunTable>>(table);
  Scene scene = asked;
  if (auto e = sample_uniformly(req, config_.limits, scene, t)) return send_error(res, *e);
  const std::string key = simulate_key(scene) + table_key(t, scene);
  answer(
      key, [scene, t, this] { return simulate_scene(scene, config_.limits, t); }, req, res);
}

void Api::render(const Scene& scene, const httplib::Request& req, httplib::Response& res) {
  const auto format = format_of(req);
  if (auto* e = std::get_if<ApiError>(&format)) return send_error(res, *e);
  const ImageFormat f = std::get<ImageFormat>(format);
  if (auto e = check_figure(scene, f, config_.limits)) return send_error(res, *e);
  answer(
      render_key(scene, f), [scene, f, this] { return render_scene(scene, f, config_.limits); },
      req, res);
}

void Api::answer(const std::string& key, std::function<JobResult()> job,
                 const httplib::Request& req, httplib::Response& res) {
  const std::string etag = etag_of(key);
  // The tag follows from the key alone, so a client holding it needs no work at all.
  if (etag_matches(req.get_header_value("If-None-Match"), etag)) {
    res.status = 304;
    res.set_header("ETag", etag);
    res.set_header("Cache-Control", kCacheForever);
    return;
  }
  if (auto hit = cache_.find(key)) return send(res, *hit, true);
  auto produced = run_on_worker(std::move(job), res);
  if (!produced) return;
  if (auto* e = std::get_if<ApiError>(&*produced)) return send_error(res, *e);
  Produced& p = std::get<Produced>(*produced);
  auto entry = std::make_shared<const CachedResponse>(
      CachedResponse{std::move(p.body), std::move(p.content_type), etag, std::move(p.headers)});
  cache_.insert(key, entry);
  send(res, *entry, false);
}

std::optional<JobResult> Api::run_on_worker(std::function<JobResult()> job,
                                            httplib::Response& res) {
  auto promise = std::make_shared<std::promise<JobResult>>();
  std::future<JobResult> result = promise->get_future();
  const bool queued = workers_.try_post([promise, job = std::move(job)] {
    try {
      promise->set_value(job());
    } catch (...) {
      promise->set_exception(std::current_exception());  // to the exception handler: a 500
    }
  });
  if (!queued) {
    res.set_header("Retry-After", "1");
    send_error(res, {503, "server",
                     "the server is busy: every worker is taken and the queue is full; "
                     "retry in a second"});
    return std::nullopt;
  }
  return result.get();
}

bool Api::warm_up(std::string& error) {
  SceneOrError scene = scene_from_text(*preset_json("paper"), config_.limits);
  if (auto* e = std::get_if<FieldError>(&scene)) {
    error = e->field + ": " + e->message;
    return false;
  }
  const Scene& paper = std::get<Scene>(scene);
  JobResult produced = render_scene(paper, ImageFormat::png, config_.limits);
  if (auto* e = std::get_if<ApiError>(&produced)) {
    error = e->field + ": " + e->message;
    return false;
  }
  const std::string key = render_key(paper, ImageFormat::png);
  Produced& p = std::get<Produced>(produced);
  cache_.insert(
      key, std::make_shared<const CachedResponse>(CachedResponse{
               std::move(p.body), std::move(p.content_type), etag_of(key), std::move(p.headers)}));
  return true;
}

}  // namespace vibro::server
