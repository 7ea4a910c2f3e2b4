#include "server/flags.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <optional>
#include <string_view>

namespace vibro::server {
namespace {

std::optional<double> parse_number(std::string_view text) {
  double x = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(x)) return {};
  return x;
}

std::optional<long> parse_integer(std::string_view text) {
  long x = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (ec != std::errc() || end != text.data() + text.size()) return {};
  return x;
}

// A flag that takes a value; `set` returns an error message, or nothing when the value fits.
struct Flag {
  std::string_view name;
  std::string_view help;
  std::function<std::optional<std::string>(ServerConfig&, std::string_view)> set;
};

template <class T>
Flag integer_flag(std::string_view name, std::string_view help, long lo, long hi,
                  T ServerConfig::*field) {
  return {name, help, [=](ServerConfig& c, std::string_view v) -> std::optional<std::string> {
            const auto x = parse_integer(v);
            if (!x || *x < lo || *x > hi) {
              return "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                     "]";
            }
            c.*field = static_cast<T>(*x);
            return std::nullopt;
          }};
}

template <class T>
Flag limit_flag(std::string_view name, std::string_view help, long lo, long hi, T Limits::*field) {
  return {name, help, [=](ServerConfig& c, std::string_view v) -> std::optional<std::string> {
            const auto x = parse_number(v);
            if (!x || *x < lo || *x > hi) {
              return "must be a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
            }
            c.limits.*field = static_cast<T>(*x);
            return std::nullopt;
          }};
}

const std::vector<Flag>& flags() {
  using C = ServerConfig;
  using L = Limits;
  static const std::vector<Flag> list = {
      {"--host", "address to listen on (default 127.0.0.1, loopback only)",
       [](C& c, std::string_view v) -> std::optional<std::string> {
         c.host = v;
         return std::nullopt;
       }},
      integer_flag("--port", "TCP port (default 8080; 0 picks a free one)", 0, 65535, &C::port),
      {"--web", "directory of the web page (default: the repository's web/)",
       [](C& c, std::string_view v) -> std::optional<std::string> {
         c.web_dir = v;
         return std::nullopt;
       }},
      integer_flag("--threads", "simulation and render workers (default: one per core)", 1, 256,
                   &C::workers),
      integer_flag("--queue", "jobs that may wait for a worker before 503 (default 64)", 0, 100000,
                   &C::queue),
      integer_flag("--connections", "connection threads (default 32)", 1, 1024,
                   &C::connection_threads),
      integer_flag("--read-timeout", "seconds a stalled client may hold a request (default 5)", 1,
                   300, &C::read_timeout_s),
      integer_flag("--write-timeout", "seconds a stalled client may hold a response (default 5)", 1,
                   300, &C::write_timeout_s),
      integer_flag("--keep-alive", "seconds an idle connection stays open (default 2)", 0, 300,
                   &C::keep_alive_s),
      {"--cache-mib", "result and image cache, MiB (default 64; 0 turns it off)",
       [](C& c, std::string_view v) -> std::optional<std::string> {
         const auto x = parse_integer(v);
         if (!x || *x < 0 || *x > 65536) return "must be an integer in [0, 65536]";
         c.cache_bytes = static_cast<std::size_t>(*x) * 1024 * 1024;
         return std::nullopt;
       }},
      limit_flag("--max-body", "request body, bytes (default 65536)", 1024, 64L << 20,
                 &L::body_bytes),
      limit_flag("--max-t-end", "simulated time span, s (default 1000)", 1, 1000000, &L::t_end),
      limit_flag("--max-events", "events per run (default 20000)", 1, 10000000, &L::events),
      limit_flag("--max-steps", "integrator steps per run (default 2000000)", 1, 1000000000,
                 &L::steps),
      limit_flag("--max-samples", "trajectory points per run (default 200000)", 1000, 100000000,
                 &L::samples),
      limit_flag("--deadline-ms", "wall clock per simulation, ms (default 2000)", 1, 600000,
                 &L::deadline_ms),
      limit_flag("--max-width", "image width, px (default 4000)", 64, 8192, &L::width),
      limit_flag("--max-height", "image height, px (default 4000)", 64, 8192, &L::height),
      limit_flag("--max-pixels", "image width × height (default 8000000)", 4096, 40000000,
                 &L::pixels),
      limit_flag("--max-pellets", "pellets per scene (default 8)", 1, 64, &L::pellets),
      limit_flag("--max-limiters", "limiters per scene (default 16)", 0, 256, &L::limiters),
      limit_flag("--max-plots", "plots per image (default 8)", 1, 16, &L::plots),
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
