#include "server/config.h"

#include <algorithm>
#include <thread>

namespace vibro::server {

nlohmann::json limits_json(const Limits& limits) {
  return {{"body_bytes", limits.body_bytes},
          {"t_end", limits.t_end},
          {"events", limits.events},
          {"steps", limits.steps},
          {"samples", limits.samples},
          {"deadline_ms", limits.deadline_ms},
          {"width", limits.width},
          {"height", limits.height},
          {"pixels", limits.pixels},
          {"pellets", limits.pellets},
          {"limiters", limits.limiters},
          {"plots", limits.plots},
          {"sweep_periods", limits.sweep_periods},
          {"sweep_points", limits.sweep_points},
          {"sweep_seconds", limits.sweep_seconds},
          {"sweep_vector_points", limits.sweep_vector_points}};
}

int worker_count(const ServerConfig& config) {
  if (config.workers > 0) return config.workers;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

std::string web_dir(const ServerConfig& config) {
  return config.web_dir.empty() ? std::string(VIBRO_WEB_DIR) : config.web_dir;
}

}  // namespace vibro::server
