#include "server/api.h"

#include <exception>
#include <future>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "io/presets.h"
#include "io/scene_json.h"
#include "render/figure.h"
#include "server/api_error.h"
#include "server/etag.h"
#include "server/scene_request.h"

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
    for (const char* key : {"plots", "width", "height"}) j.erase(key);
  }
  return j.dump();
}

std::string simulate_key(const Scene& scene) { return "simulate " + canonical(scene, false); }

std::string render_key(const Scene& scene, ImageFormat format) {
  return "render " + std::string(content_type(format)) + " " + canonical(scene, true);
}

std::variant<ImageFormat, ApiError> format_of(const httplib::Request& req) {
  if (!req.has_param("format")) return ImageFormat::png;
  const std::string f = req.get_param_value("format");
  if (f == "png") return ImageFormat::png;
  if (f == "svg") return ImageFormat::svg;
  return ApiError{400, "format", "must be \"png\" or \"svg\", got \"" + f + "\""};
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

void send(httplib::Response& res, const CachedResponse& answer, bool hit) {
  res.set_header("ETag", answer.etag);
  res.set_header("Cache-Control", kCacheForever);
  res.set_header("X-Vibro-Cache", hit ? "hit" : "miss");
  res.set_content(answer.body, answer.content_type);
}

}  // namespace

Api::Api(const ServerConfig& config)
    : config_(config),
      scene_limits_(scene_limits(config.limits)),
      preset_list_(make_preset_list()),
      web_(web_dir(config)),
      cache_(config.cache_bytes),
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
  if (auto e = only_params(req, {})) return send_error(res, *e);
  SceneOrApiError scene = scene_from_body(req, scene_limits_);
  if (auto* e = std::get_if<ApiError>(&scene)) return send_error(res, *e);
  simulate(std::get<Scene>(scene), req, res);
}

void Api::simulate_get(const httplib::Request& req, httplib::Response& res) {
  SceneOrApiError scene =
      scene_from_query(req, scene_limits_, {"t_end", "method", "rtol", "atol", "trajectories", "check"});
  if (auto* e = std::get_if<ApiError>(&scene)) return send_error(res, *e);
  simulate(std::get<Scene>(scene), req, res);
}

void Api::render_post(const httplib::Request& req, httplib::Response& res) {
  if (auto e = only_params(req, {"format"})) return send_error(res, *e);
  SceneOrApiError scene = scene_from_body(req, scene_limits_);
  if (auto* e = std::get_if<ApiError>(&scene)) return send_error(res, *e);
  render(std::get<Scene>(scene), req, res);
}

void Api::render_get(const httplib::Request& req, httplib::Response& res) {
  SceneOrApiError scene =
      scene_from_query(req, scene_limits_,
                       {"format", "t_end", "width", "height", "pellet", "method", "rtol", "atol"});
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
  SceneOrApiError scene = scene_from_body(req, scene_limits_);
  if (auto* e = std::get_if<ApiError>(&scene)) return send_error(res, *e);
  auto produced = run_on_worker(
      [scene = std::get<Scene>(std::move(scene)), image, this] {
        return work_precision_scene(scene, image, config_.limits);
      },
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

void Api::simulate(const Scene& scene, const httplib::Request& req, httplib::Response& res) {
  answer(
      simulate_key(scene), [scene, this] { return simulate_scene(scene, config_.limits); }, req,
      res);
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
      CachedResponse{std::move(p.body), std::move(p.content_type), etag});
  cache_.insert(key, entry);
  send(res, *entry, false);
}

std::optional<JobResult> Api::run_on_worker(std::function<JobResult()> job, httplib::Response& res) {
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
  SceneOrError scene = scene_from_text(*preset_json("paper"), scene_limits_);
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
  cache_.insert(key, std::make_shared<const CachedResponse>(CachedResponse{
                         std::move(p.body), std::move(p.content_type), etag_of(key)}));
  return true;
}

}  // namespace vibro::server
