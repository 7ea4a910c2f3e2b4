// A real vibro server on an ephemeral loopback port, with a web directory of its own, for the
// tests to attack over real sockets.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#include "server/config.h"
#include "server/http.h"
#include "server/service.h"

namespace vibro::testing {

class TestServer {
 public:
  // `config.port` and `config.web_dir` are set here; the access log is off.
  // The access log stays off (quiet test output) unless `access_log`.
  explicit TestServer(server::ServerConfig config = {}, bool access_log = false);
  ~TestServer();

  int port() const { return port_; }
  httplib::Client client() const;
  // The web directory: index.html, app.js, style.css, logo.svg, a symlink to a file outside it.
  const std::filesystem::path& web_dir() const { return web_dir_; }
  // A file next to the web directory that must never be served.
  const std::filesystem::path& secret() const { return secret_; }

 private:
  std::filesystem::path root_, web_dir_, secret_;
  std::unique_ptr<server::Service> service_;
  std::thread thread_;
  int port_ = -1;
};

// A fixture whose tests share one default server (suites run one at a time).
class SharedServerTest : public ::testing::Test {
 public:
  static void SetUpTestSuite() { server = new TestServer(); }
  static void TearDownTestSuite() {
    delete server;
    server = nullptr;
  }
  static inline TestServer* server = nullptr;
};

// Sends raw bytes and reads one response: its head and Content-Length bytes of body (or until
// the server closes the connection, or `timeout_ms` passes).
struct RawReply {
  std::string bytes;
  int status() const;            // from the status line, or -1
  bool announces_close() const;  // "Connection: close": the client is to hang up
};
RawReply raw_exchange(int port, const std::string& request, int timeout_ms = 3000);

// The width and height in a PNG's header, or {-1, -1} if the bytes are not a PNG.
std::pair<int, int> png_size(const std::string& bytes);

// A scene as JSON text: the paper preset with the given t_end, small and quick to draw.
std::string paper_scene(double t_end, int width = 400, int height = 300);

}  // namespace vibro::testing
