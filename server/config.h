// Everything `vibro serve` can be told, in one struct: where to listen, how many threads, and the
// limits that bound the work any one request may cause. docs/SERVER.md lists the defaults and the
// flags that change them.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "core/run/limits.h"

namespace vibro::server {

// The server's limits: the core's (core/run/limits.h, where each is described), tightened. A
// scene over a limit that can be known up front (sizes, counts, t_end) is refused before any
// work; the rest (events, steps, samples, wall clock) stop the run. The sweep budgets are checked
// up front where they can be (validate_sweep, validate_orbit_request; server/sweep_limits.h);
// finished sweeps hold at most 4 × sweep_points section points in all, the oldest dropped first.
struct Limits : vibro::Limits {
  Limits() {
    body_bytes = 64 * 1024;
    t_end = 1000.0;
    events = 20000;
    steps = 2'000'000;
    samples = 200'000;
    deadline_ms = 2000.0;
    width = 4000;
    height = 4000;
    pixels = 8'000'000;
    sweep_periods = 1e6;
    sweep_points = 1'000'000;
    sweep_seconds = 300.0;
    sweep_vector_points = 100'000;
  }
};

struct ServerConfig {
  std::string host = "127.0.0.1";  // loopback unless told otherwise
  int port = 8080;                 // 0: an ephemeral port (tests)
  std::string web_dir;             // static files; empty: the repository's web/
  int workers = 0;                 // simulation and render threads; 0: one per core
  std::size_t queue = 64;          // jobs waiting for a worker; beyond it: 503
  // Threads that read requests and write responses; each holds one connection at a time,
  // so this must cover the clients' keep-alive connections.
  int connection_threads = 32;
  int read_timeout_s = 5;  // a client that stalls this long mid-request is dropped
  int write_timeout_s = 5;
  int keep_alive_s = 2;                        // idle keep-alive connections are closed after this
  std::size_t cache_bytes = 64 * 1024 * 1024;  // results and images, least recently used dropped
  bool access_log = true;                      // one line per request on stderr
  Limits limits;
  int sweep_jobs = 1;           // sweeps running at once, on threads of their own
  int sweep_threads = 1;        // threads of one sweep
  std::size_t sweep_queue = 8;  // sweeps waiting; beyond it: 503
  // Behind the front door (scripts/deploy.sh), replica k's sweep job ids begin "r<k>-", so that
  // nginx routes a job's polls to the replica that holds it; 0: alone, no prefix.
  int replica = 0;
};

// The limits as GET /api/limits shows them.
nlohmann::json limits_json(const Limits& limits);

// The worker count after resolving 0 to the number of cores.
int worker_count(const ServerConfig& config);

// The web directory after resolving empty to the repository's web/.
std::string web_dir(const ServerConfig& config);

}  // namespace vibro::server
