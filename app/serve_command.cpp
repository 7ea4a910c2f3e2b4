// `vibro serve [flags]`: the HTTP service of API.md and the web page, until SIGINT or SIGTERM.
// Each flag sets one field of server::ServerConfig (docs/SERVER.md lists them with the defaults).
#include <iostream>
#include <memory>
#include <string>

#include "app/commands.h"
#include "app/usage.h"
#include "render/figure_size.h"
#include "server/config.h"
#include "server/service.h"
#include "server/stop_signals.h"

namespace vibro {
namespace {

int serve(const server::ServerConfig& config) {
  server::Service service(config);
  std::string error;
  if (!service.warm_up(error)) {
    std::cerr << "vibro serve: the paper scene does not render: " << error << "\n";
    return 1;
  }
  std::string why;
  const int port = service.bind(&why);
  if (port < 0) {
    std::cerr << "vibro serve: cannot listen on " << config.host << ":" << config.port << ": "
              << why << "\n";
    return 1;
  }
  server::StopOnSignals stop_on_signals([&service] { service.stop(); });
  std::cout << "vibro serve: http://" << config.host << ":" << port << "/ (paper scene ready)"
            << std::endl;
  return service.serve() ? 0 : 1;
}

// A whole number in [lo, hi] stored in `field`.
template <class T>
void add_integer_flag(CLI::App& serve, const std::string& name, const std::string& help, T& field,
                      double lo, double hi) {
  serve.add_option(name, field, help)->transform(integer_in(lo, hi))->type_name("N");
}

void add_flags(CLI::App& serve, server::ServerConfig& c) {
  server::Limits& l = c.limits;
  // The server only tightens the core's limits: each flag's largest value is the core's.
  const vibro::Limits core;
  serve.add_option("--host", c.host, "address to listen on (default 127.0.0.1, loopback only)")
      ->type_name("ADDRESS");
  add_integer_flag(serve, "--port", "TCP port (default 8080; 0 picks a free one)", c.port, 0,
                   65535);
  serve
      .add_option("--web", c.web_dir, "directory of the web page (default: the repository's web/)")
      ->type_name("DIR");
  add_integer_flag(serve, "--threads", "simulation and render workers (default: one per core)",
                   c.workers, 1, 256);
  add_integer_flag(serve, "--queue", "jobs that may wait for a worker before 503 (default 64)",
                   c.queue, 0, 1e5);
  add_integer_flag(serve, "--connections", "connection threads (default 32)", c.connection_threads,
                   1, 1024);
  add_integer_flag(serve, "--read-timeout",
                   "seconds a stalled client may hold a request (default 5)", c.read_timeout_s, 1,
                   300);
  add_integer_flag(serve, "--write-timeout",
                   "seconds a stalled client may hold a response (default 5)", c.write_timeout_s, 1,
                   300);
  add_integer_flag(serve, "--keep-alive", "seconds an idle connection stays open (default 2)",
                   c.keep_alive_s, 0, 300);
  serve
      .add_option_function<std::size_t>(
          "--cache-mib", [&c](std::size_t mib) { c.cache_bytes = mib << 20; },
          "result and image cache, MiB (default 64; 0 turns it off)")
      ->transform(integer_in(0, 65536))
      ->type_name("N");
  serve.add_flag_callback(
      "--quiet", [&c] { c.access_log = false; }, "no access log");
  add_integer_flag(serve, "--max-body", "request body, bytes (default 65536)", l.body_bytes, 1024,
                   64 << 20);
  serve.add_option("--max-t-end", l.t_end, "simulated time span, s (default 1000)")
      ->check(number_in(1, core.t_end))
      ->type_name("S");
  add_integer_flag(serve, "--max-events", "events per run (default 20000)", l.events, 1, 1e7);
  add_integer_flag(serve, "--max-steps", "integrator steps per run (default 2000000)", l.steps, 1,
                   1e9);
  add_integer_flag(serve, "--max-samples",
                   "trajectory points kept per run, thinned past it (default 200000)", l.samples,
                   1000, 1e8);
  serve.add_option("--deadline-ms", l.deadline_ms, "wall clock per simulation, ms (default 2000)")
      ->check(number_in(1, 6e5))
      ->type_name("MS");
  add_integer_flag(serve, "--max-width", "image width, px (default 4000)", l.width, kMinFigureSide,
                   core.width);
  add_integer_flag(serve, "--max-height", "image height, px (default 4000)", l.height,
                   kMinFigureSide, core.height);
  add_integer_flag(serve, "--max-pixels", "image width × height (default 8000000)", l.pixels, 4096,
                   core.pixels);
  add_integer_flag(serve, "--max-pellets", "pellets per scene (default 8)", l.pellets, 1,
                   core.pellets);
  add_integer_flag(serve, "--max-limiters", "limiters per scene (default 16)", l.limiters, 0,
                   core.limiters);
  add_integer_flag(serve, "--max-plots", "plots per image (default 8)", l.plots, 1, core.plots);
  add_integer_flag(serve, "--sweep-jobs", "sweeps running at once (default 1)", c.sweep_jobs, 1,
                   64);
  add_integer_flag(serve, "--sweep-threads", "threads of one sweep (default 1)", c.sweep_threads, 1,
                   256);
  add_integer_flag(serve, "--sweep-queue", "sweeps that may wait before 503 (default 8)",
                   c.sweep_queue, 0, 1000);
  serve
      .add_option("--max-sweep-s", l.sweep_seconds,
                  "wall clock of one sweep job, s, shared by its runs (default 300)")
      ->check(number_in(1, 86400))
      ->type_name("S");
  add_integer_flag(serve, "--replica",
                   "behind scripts/deploy.sh: this replica's number, the prefix r<N>- of its "
                   "sweep job ids (default 0: none)",
                   c.replica, 0, 999);
}

}  // namespace

Command add_serve_command(CLI::App& vibro) {
  auto config = std::make_shared<server::ServerConfig>();
  CLI::App* command = vibro.add_subcommand(
      "serve", "The HTTP service and the web page (docs/SERVER.md), until SIGINT or SIGTERM");
  add_flags(*command, *config);
  return {command, [config] { return serve(*config); }};
}

}  // namespace vibro
