// Everything `vibro serve` can be told, in one struct: where to listen, how many threads, and the
// limits that bound the work any one request may cause. docs/SERVER.md lists the defaults and the
// flags that change them.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "io/scene.h"

namespace vibro::server {

// What one request may cost. A scene over a limit that can be known up front (sizes, counts,
// t_end) is refused before any work; the rest (events, steps, samples, wall clock) stop the run.
struct Limits {
  std::size_t body_bytes = 64 * 1024;  // request body
  double t_end = 1000.0;               // s, simulated time span
  long events = 20000;                 // events a run may list
  long steps = 2'000'000;              // accepted plus rejected integrator steps
  long samples = 200'000;              // trajectory points kept (all recorded pellets together)
  double deadline_ms = 2000.0;         // wall clock of one simulation
  int width = 4000;                    // image width, px
  int height = 4000;                   // image height, px
  long pixels = 8'000'000;             // width × height
  int pellets = 8;
  int limiters = 16;
  int plots = 8;
  double sweep_periods = 1e6;  // a sweep's runs × (transient + record) periods
  // Section points one sweep may keep (40 bytes each): a stroboscopic sweep over it is refused
  // up front, an impact-section sweep stops when it reaches it (docs/ROBUSTNESS.md, "Sweeps and
  // memory"). Finished sweeps hold at most 4 × this many in all; the oldest go first.
  long sweep_points = 1'000'000;
  // Wall clock of one sweep job, s: its runs share it (each run's deadline is at most its share),
  // a sweep that would leave a run less than 10 ms is refused up front, and one that runs past
  // it fails.
  double sweep_seconds = 300.0;
  // Section points a sweep's point plot (bifurcation, section, impact map) is drawn with as SVG
  // or PDF: each point is a mark of its own there, some 1.4 KB of memory while drawn (10^6
  // points: 1.5 GB, and 265 MB of SVG). PNG draws any number.
  long sweep_vector_points = 100'000;
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

// The scene reader's bounds, from the server's limits.
SceneLimits scene_limits(const Limits& limits);

// The limits as GET /api/limits shows them.
nlohmann::json limits_json(const Limits& limits);

// The worker count after resolving 0 to the number of cores.
int worker_count(const ServerConfig& config);

// The web directory after resolving empty to the repository's web/.
std::string web_dir(const ServerConfig& config);

}  // namespace vibro::server
