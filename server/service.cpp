#include "server/service.h"

#include <malloc.h>
#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <string_view>
#include <thread>

#include "server/access_log.h"
#include "server/api.h"
#include "server/api_error.h"
#include "server/connection_pool.h"
#include "server/http.h"
#include "server/router.h"
#include "server/whole_response.h"

namespace vibro::server {
namespace {

// Header lines a request may have; browsers send about 20.
constexpr std::size_t kMaxHeaderLines = 100;

using httplib::Request;
using httplib::Response;

// cpp-httplib 0.11 listens with a backlog of 5, compiled in: a burst of new connections beyond
// it is dropped by the kernel and retried by the clients a second later. Listening again on the
// bound socket updates the backlog in place (Linux).
class HttpServer : public httplib::Server {
 public:
  void widen_backlog() { ::listen(svr_sock_, SOMAXCONN); }
};

// The bytes a response takes on the wire, headers and body, within a status line's margin.
std::size_t wire_bytes(const Response& res) {
  // A streamed body (a sweep's result) is written as it is made: never one segment.
  if (res.content_provider_) return std::numeric_limits<std::size_t>::max();
  std::size_t n = 64 + res.body.size();
  for (const auto& [name, value] : res.headers) n += name.size() + value.size() + 4;
  return n;
}

std::vector<Route> api_routes(Api& api) {
  auto bind = [&api](auto member) {
    return [&api, member](const Request& req, Response& res) { (api.*member)(req, res); };
  };
  return {
      {"GET", "/api/health", bind(&Api::health)},
      {"GET", "/api/limits", bind(&Api::limits)},
      {"GET", "/api/presets", bind(&Api::preset_list)},
      {"GET", "/api/presets/", bind(&Api::preset)},
      {"GET", "/api/simulate", bind(&Api::simulate_get)},
      {"POST", "/api/simulate", bind(&Api::simulate_post)},
      {"GET", "/api/render", bind(&Api::render_get)},
      {"POST", "/api/render", bind(&Api::render_post)},
      {"POST", "/api/work-precision", bind(&Api::work_precision_post)},
      {"POST", "/api/sweep", bind(&Api::sweep_post)},
      {"POST", "/api/periodic-orbit", bind(&Api::orbit_post)},
      {"GET", "/api/jobs/", bind(&Api::job_get)},
      {"DELETE", "/api/jobs/", bind(&Api::job_delete)},
  };
}

// Whether every header name is an HTTP token and no value holds a control character. cpp-httplib
// keeps a folded continuation line (obs-fold) as a header whose name starts with a space, and a
// NUL inside a value; both are refused, as nginx refuses them. A line without a colon it drops
// before any handler sees it.
std::optional<ApiError> check_header_lines(const Request& req) {
  auto token_char = [](unsigned char c) {
    return std::isalnum(c) || std::string_view("!#$%&'*+-.^_`|~").find(c) != std::string_view::npos;
  };
  for (const auto& [name, value] : req.headers) {
    if (name.empty() || !std::all_of(name.begin(), name.end(), token_char))
      return ApiError{400, "headers", "a header line is not \"Name: value\" (folded or malformed)"};
    if (std::any_of(value.begin(), value.end(),
                    [](unsigned char c) { return c < 0x20 && c != '\t'; }))
      return ApiError{400, "headers", "the header " + name + " holds a control character"};
  }
  if (req.version == "HTTP/1.1" && !req.has_header("Host"))
    return ApiError{400, "Host", "an HTTP/1.1 request must say its Host"};
  return std::nullopt;
}

// Whether the response being written on this connection thread was told "Connection: close"
// because connections wait for a thread (between the post-routing handler and the logger).
thread_local bool crowded_close = false;

// Errors cpp-httplib makes itself (a malformed request line, a body over the payload limit, a
// target too long) get the same JSON shape as ours.
httplib::Server::HandlerResponse json_error(const Request&, Response& res, std::size_t body_limit) {
  if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
  switch (res.status) {
    case 413:
      send_error(
          res,
          {413, "body",
           "the body is over the server's limit of " + std::to_string(body_limit) + " bytes"},
          true);
      break;
    case 414:
      send_error(res, {414, "path", "the request target is too long"}, true);
      break;
    default:
      send_error(res, {res.status, "request", "the request could not be read as HTTP/1.1"}, true);
  }
  return httplib::Server::HandlerResponse::Handled;
}

}  // namespace

struct Service::State {
  explicit State(const ServerConfig& config)
      : config(config),
        log(config.access_log),
        api(config),
        router(
            api_routes(api),
            [this](const Request& req, Response& res) { api.static_file(req, res); },
            config.limits.body_bytes) {}

  const ServerConfig config;
  const AccessLog log;
  Api api;
  const Router router;
  HttpServer http;
  std::atomic<ConnectionPool*> pool{nullptr};  // cpp-httplib's, while it serves
  std::atomic<bool> stop_requested{false};
  std::atomic<bool> serving{false};
  std::atomic<bool> served{false};
};

Service::Service(const ServerConfig& config) : state_(std::make_unique<State>(config)) {
  // A client that hangs up mid-response must not end the process with SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  State& s = *state_;
  httplib::Server& http = s.http;
  http.new_task_queue = [&s, n = config.connection_threads] {
    s.pool = new ConnectionPool(n);
    return s.pool.load();
  };
  // Only SO_REUSEADDR: cpp-httplib's default adds SO_REUSEPORT, with which a second server on
  // the same port starts and takes half of the connections (and of the job polls).
  http.set_socket_options([](socket_t sock) {
    const int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  http.set_payload_max_length(config.limits.body_bytes);
  http.set_read_timeout(config.read_timeout_s);
  http.set_write_timeout(config.write_timeout_s);
  http.set_keep_alive_timeout(config.keep_alive_s);
  // Bounds what a client that ignores "Connection: close" after a refusal can make the server
  // read: cpp-httplib keeps the socket and takes the unread body for further (bad) requests.
  http.set_keep_alive_max_count(100);
  http.set_tcp_nodelay(true);
  http.set_pre_routing_handler([&s](const Request& req, Response& res) {
    s.log.start();
    s.pool.load()->busy();
    // cpp-httplib 0.11 reads and keeps any number of header lines (10^6 of them: 200 MB), with
    // no setting to stop it; the most this server can do is refuse such a request and give the
    // memory back. A front door (scripts/deploy.sh) refuses it after 33 KiB instead.
    if (req.headers.size() > kMaxHeaderLines) {
      const_cast<Request&>(req).headers.clear();
      malloc_trim(0);
      send_error(res,
                 {431, "headers", "more than " + std::to_string(kMaxHeaderLines) + " header lines"},
                 true);
      return httplib::Server::HandlerResponse::Handled;
    }
    if (auto error = check_header_lines(req)) {
      send_error(res, *error, true);
      return httplib::Server::HandlerResponse::Handled;
    }
    // cpp-httplib 0.11 compresses JSON and SVG answers on every response, with brotli at its
    // slowest quality when the client accepts "br" (every browser): some 200 ms of CPU for one
    // cached SVG on a connection thread. On loopback compression buys nothing, so the server
    // answers uncompressed (a reverse proxy may compress). The request is cpp-httplib's own
    // non-const object, handed to this handler as const.
    const_cast<Request&>(req).headers.erase("Accept-Encoding");
    return s.router.route(req, res);
  });
  for (const Route& r : s.router.routes()) {
    if (r.method == "POST") http.Post(r.path, r.handler);
  }
  http.set_error_handler(httplib::Server::HandlerWithResponse(
      [limit = config.limits.body_bytes](const Request& req, Response& res) {
        return json_error(req, res, limit);
      }));
  // What went wrong inside stays inside: the log says what, the client only that it was not
  // its fault.
  http.set_exception_handler([](const Request& req, Response& res, std::exception_ptr error) {
    std::string what = "unknown exception";
    try {
      std::rethrow_exception(error);
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    std::fprintf(stderr, "vibro: %s %s failed: %s\n", req.method.c_str(), req.path.c_str(),
                 what.c_str());
    send_error(res, {500, "server", "internal error"});
  });
  // Around the writing of a response: its headers are written right after the first, its body
  // right before the second.
  // While a connection waits for a thread, this one is not kept alive for another request.
  http.set_post_routing_handler([&s](const Request& req, Response& res) {
    crowded_close = s.pool.load()->crowded() && !res.has_header("Connection");
    if (crowded_close) {
      res.headers.erase("Keep-Alive");
      res.set_header("Connection", "close");
    }
    hold_if_whole({req.remote_addr, req.remote_port, req.local_port}, wire_bytes(res));
  });
  http.set_logger([&s](const Request& req, const Response& res) {
    release_held();
    s.pool.load()->idle({req.remote_addr, req.remote_port, req.local_port}, crowded_close);
    s.log.write(req, res);
  });
}

Service::~Service() = default;

int Service::bind(std::string* why) {
  const ServerConfig& c = state_->config;
  errno = 0;
  const int port = c.port == 0 ? state_->http.bind_to_any_port(c.host)
                   : state_->http.bind_to_port(c.host, c.port) ? c.port
                                                               : -1;
  if (port > 0) state_->http.widen_backlog();
  if (port < 0 && why)
    *why = errno == EADDRINUSE ? "address in use"
           : errno             ? std::strerror(errno)
                               : "no such address";
  return port;
}

bool Service::serve() {
  State& s = *state_;
  s.serving = true;
  const bool ok = s.stop_requested || s.http.listen_after_bind();
  s.served = true;
  return ok;
}

void Service::stop() {
  State& s = *state_;
  s.stop_requested = true;
  // cpp-httplib ignores stop() before its accept loop runs: wait for the loop (or for serve()
  // to have returned) so a stop that races the start is not lost.
  while (s.serving && !s.served && !s.http.is_running()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  s.http.stop();
}

bool Service::warm_up(std::string& error) { return state_->api.warm_up(error); }

}  // namespace vibro::server
