#include "server/flags.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string_view>
#include <type_traits>

namespace vibro::server {
namespace {

std::optional<double> parse_number(std::string_view text) {
  double x = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(x)) return {};
  return x;
}

std::string text_of(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", x);
  return text;
}

// A flag that takes a value; `set` returns an error message, or nothing when the value fits.
struct Flag {
  std::string_view name;
  std::string_view help;
  std::function<std::optional<std::string>(ServerConfig&, std::string_view)> set;
};

Flag text_flag(std::string_view name, std::string_view help, std::string ServerConfig::*field) {
  return {name, help, [=](ServerConfig& c, std::string_view v) -> std::optional<std::string> {
            c.*field = v;
            return std::nullopt;
          }};
}

// A number in [lo, hi] (a whole one for an integer field), stored times `scale` in the field
// that `target` picks out of the config.
template <class Target>
Flag number_flag(std::string_view name, std::string_view help, double lo, double hi, Target target,
                 double scale = 1.0) {
  return {name, help, [=](ServerConfig& c, std::string_view v) -> std::optional<std::string> {
            using T = std::remove_reference_t<decltype(target(c))>;
            constexpr bool whole = std::is_integral_v<T>;
            const auto x = parse_number(v);
            if (!x || *x < lo || *x > hi || (whole && *x != std::floor(*x))) {
              return std::string(whole ? "must be an integer" : "must be a number") + " in [" +
                     text_of(lo) + ", " + text_of(hi) + "]";
            }
            target(c) = static_cast<T>(*x * scale);
            return std::nullopt;
          }};
}

template <class T>
auto in_config(T ServerConfig::*field) {
  return [field](ServerConfig& c) -> T& { return c.*field; };
}

template <class T>
auto in_limits(T Limits::*field) {
  return [field](ServerConfig& c) -> T& { return c.limits.*field; };
}

const std::vector<Flag>& flags() {
  using C = ServerConfig;
  using L = Limits;
  static const std::vector<Flag> list = {
      text_flag("--host", "address to listen on (default 127.0.0.1, loopback only)", &C::host),
      number_flag("--port", "TCP port (default 8080; 0 picks a free one)", 0, 65535,
                  in_config(&C::port)),
      text_flag("--web", "directory of the web page (default: the repository's web/)", &C::web_dir),
      number_flag("--threads", "simulation and render workers (default: one per core)", 1, 256,
                  in_config(&C::workers)),
      number_flag("--queue", "jobs that may wait for a worker before 503 (default 64)", 0, 1e5,
                  in_config(&C::queue)),
      number_flag("--connections", "connection threads (default 32)", 1, 1024,
                  in_config(&C::connection_threads)),
      number_flag("--read-timeout", "seconds a stalled client may hold a request (default 5)", 1,
                  300, in_config(&C::read_timeout_s)),
      number_flag("--write-timeout", "seconds a stalled client may hold a response (default 5)", 1,
                  300, in_config(&C::write_timeout_s)),
      number_flag("--keep-alive", "seconds an idle connection stays open (default 2)", 0, 300,
                  in_config(&C::keep_alive_s)),
      number_flag("--cache-mib", "result and image cache, MiB (default 64; 0 turns it off)", 0,
                  65536, in_config(&C::cache_bytes), 1024.0 * 1024.0),
      number_flag("--max-body", "request body, bytes (default 65536)", 1024, 64 << 20,
                  in_limits(&L::body_bytes)),
      number_flag("--max-t-end", "simulated time span, s (default 1000)", 1, 1e6,
                  in_limits(&L::t_end)),
      number_flag("--max-events", "events per run (default 20000)", 1, 1e7, in_limits(&L::events)),
      number_flag("--max-steps", "integrator steps per run (default 2000000)", 1, 1e9,
                  in_limits(&L::steps)),
      number_flag("--max-samples", "trajectory points kept per run, thinned past it (default 200000)", 1000, 1e8,
                  in_limits(&L::samples)),
      number_flag("--deadline-ms", "wall clock per simulation, ms (default 2000)", 1, 6e5,
                  in_limits(&L::deadline_ms)),
      number_flag("--max-width", "image width, px (default 4000)", 64, 8192, in_limits(&L::width)),
      number_flag("--max-height", "image height, px (default 4000)", 64, 8192,
                  in_limits(&L::height)),
      number_flag("--max-pixels", "image width × height (default 8000000)", 4096, 4e7,
                  in_limits(&L::pixels)),
      number_flag("--max-pellets", "pellets per scene (default 8)", 1, 64, in_limits(&L::pellets)),
      number_flag("--max-limiters", "limiters per scene (default 16)", 0, 256,
                  in_limits(&L::limiters)),
      number_flag("--max-plots", "plots per image (default 8)", 1, 16, in_limits(&L::plots)),
      number_flag("--sweep-jobs", "sweeps running at once (default 1)", 1, 64,
                  in_config(&C::sweep_jobs)),
      number_flag("--sweep-threads", "threads of one sweep (default 1)", 1, 256,
                  in_config(&C::sweep_threads)),
      number_flag("--sweep-queue", "sweeps that may wait before 503 (default 8)", 0, 1000,
                  in_config(&C::sweep_queue)),
      number_flag("--replica", "behind scripts/deploy.sh: this replica's number, the prefix "
                  "r<N>- of its sweep job ids (default 0: none)", 0, 999, in_config(&C::replica)),
  };
  return list;
}

}  // namespace

ConfigOrError config_from_flags(const std::vector<std::string>& args) {
  ServerConfig config;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--quiet") {
      config.access_log = false;
      continue;
    }
    const Flag* flag = nullptr;
    for (const Flag& f : flags()) {
      if (f.name == args[i]) flag = &f;
    }
    if (!flag) return FieldError{args[i], "is not a flag of `vibro serve` (try --help)"};
    if (i + 1 >= args.size()) return FieldError{args[i], "needs a value"};
    if (auto error = flag->set(config, args[++i])) return FieldError{args[i - 1], *error};
  }
  return config;
}

std::string flags_help() {
  std::string text = "  --quiet  no access log\n";
  for (const Flag& f : flags()) {
    text += "  " + std::string(f.name) + " V  " + std::string(f.help) + "\n";
  }
  return text;
}

}  // namespace vibro::server
