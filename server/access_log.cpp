#include "server/access_log.h"

#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

namespace vibro::server {
namespace {

using Clock = std::chrono::steady_clock;

thread_local std::optional<Clock::time_point> request_started;
thread_local std::size_t streamed_bytes = 0;

// The target as the client sent it, cut short and with control bytes replaced, so a request
// cannot forge or break log lines.
std::string printable(const std::string& text) {
  constexpr std::size_t kMax = 300;
  std::string out = text.substr(0, kMax);
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  }
  if (text.size() > kMax) out += "...";
  return out;
}

}  // namespace

void AccessLog::start() const {
  request_started = Clock::now();
  streamed_bytes = 0;
}

void AccessLog::streamed(std::size_t bytes) { streamed_bytes += bytes; }

void AccessLog::write(const httplib::Request& req, const httplib::Response& res) const {
  std::string ms = "-";
  if (request_started) {
    const double elapsed =
        std::chrono::duration<double, std::milli>(Clock::now() - *request_started).count();
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", elapsed);
    ms = text;
    request_started.reset();
  }
  const std::size_t bytes = res.body.size() + streamed_bytes;
  streamed_bytes = 0;
  if (!enabled_) return;
  const std::string line = "vibro: " + printable(req.method) + " " +
                           printable(req.target.empty() ? req.path : req.target) + " " +
                           std::to_string(res.status) + " " + std::to_string(bytes) + " B " + ms +
                           " ms\n";
  // One write per line keeps lines from different threads whole.
  std::fwrite(line.data(), 1, line.size(), stderr);
}

}  // namespace vibro::server
