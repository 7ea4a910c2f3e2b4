#include "tests/server/test_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/presets.h"

namespace vibro::testing {
namespace {

namespace fs = std::filesystem;

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

fs::path unique_dir() {
  static std::atomic<int> count{0};
  const fs::path dir =
      fs::temp_directory_path() /
      ("vibro-server-test-" + std::to_string(getpid()) + "-" + std::to_string(count++));
  fs::create_directories(dir / "web" / "img");
  return dir;
}

}  // namespace

TestServer::TestServer(server::ServerConfig config, bool access_log) : root_(unique_dir()) {
  web_dir_ = root_ / "web";
  secret_ = root_ / "secret.txt";
  write_file(secret_, "the secret outside web/");
  write_file(web_dir_ / "index.html", "<!doctype html><title>vibro</title>");
  write_file(web_dir_ / "app.js", "console.log('vibro');");
  write_file(web_dir_ / "style.css", "body { margin: 0; }");
  write_file(web_dir_ / "img" / "logo.svg", "<svg xmlns='http://www.w3.org/2000/svg'/>");
  write_file(web_dir_ / ".hidden.txt", "hidden");
  fs::create_symlink(secret_, web_dir_ / "link.txt");
  fs::create_directory_symlink(root_, web_dir_ / "up");

  config.port = 0;
  config.web_dir = web_dir_.string();
  config.access_log = access_log;
  service_ = std::make_unique<server::Service>(config);
  port_ = service_->bind();
  if (port_ <= 0) throw std::runtime_error("the test server cannot bind");
  thread_ = std::thread([this] { service_->serve(); });
}

TestServer::~TestServer() {
  service_->stop();
  thread_.join();
  std::error_code ec;
  fs::remove_all(root_, ec);
}

httplib::Client TestServer::client() const {
  httplib::Client c("127.0.0.1", port_);
  c.set_read_timeout(10);
  return c;
}

int RawReply::status() const {
  if (!bytes.starts_with("HTTP/1.1 ") || bytes.size() < 12) return -1;
  return std::stoi(bytes.substr(9, 3));
}

bool RawReply::announces_close() const {
  const std::size_t head_end = bytes.find("\r\n\r\n");
  const std::size_t at = bytes.find("\r\nConnection: close\r\n");
  return at != std::string::npos && at < head_end;
}

RawReply raw_exchange(int port, const std::string& request, int timeout_ms) {
  RawReply reply;
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr = {};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    ::close(fd);
    return reply;
  }
  timeval tv = {timeout_ms / 1000, (timeout_ms % 1000) * 1000};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  ::send(fd, request.data(), request.size(), MSG_NOSIGNAL);
  char buffer[4096];
  for (;;) {
    const std::size_t head_end = reply.bytes.find("\r\n\r\n");
    if (head_end != std::string::npos) {
      const std::size_t at = reply.bytes.find("Content-Length: ");
      const std::size_t length = at < head_end ? std::stoul(reply.bytes.substr(at + 16)) : 0;
      if (reply.bytes.size() >= head_end + 4 + length) break;
    }
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    reply.bytes.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return reply;
}

std::pair<int, int> png_size(const std::string& bytes) {
  static const std::string signature = "\x89PNG\r\n\x1a\n";
  if (bytes.size() < 24 || bytes.compare(0, 8, signature) != 0) return {-1, -1};
  auto be32 = [&](std::size_t at) {
    int v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
  };
  return {be32(16), be32(20)};
}

std::string paper_scene(double t_end, int width, int height) {
  nlohmann::json scene = nlohmann::json::parse(*preset_json("paper"));
  scene["t_end"] = t_end;
  scene["width"] = width;
  scene["height"] = height;
  return scene.dump();
}

}  // namespace vibro::testing
