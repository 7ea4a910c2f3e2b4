// Many clients at once: every request answered, the same scene with the same bytes; and a full
// worker queue answers 503 with Retry-After instead of piling up.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "tests/server/test_server.h"

namespace vibro::testing {
namespace {

TEST(Load, ConcurrentClientsGetIdenticalBytes) {
  TestServer server;
  constexpr int kThreads = 16, kRequests = 20, kScenes = 4;
  std::mutex mutex;
  std::map<int, std::string> first_bytes;  // scene → the first answer seen
  std::atomic<int> ok{0}, mismatched{0};
  std::vector<std::thread> clients;
  for (int c = 0; c < kThreads; ++c) {
    clients.emplace_back([&, c] {
      httplib::Client client = server.client();
      for (int r = 0; r < kRequests; ++r) {
        const int scene = (c + r) % kScenes;
        auto res = (r % 2 == 0)
                       ? client.Post("/api/render", paper_scene(4.0 + scene), "application/json")
                       : client.Get(("/api/render?preset=paper&width=400&height=300&t_end=" +
                                     std::to_string(4 + scene))
                                        .c_str());
        if (!res || res->status != 200) {
          ADD_FAILURE() << (res ? std::to_string(res->status) + " " + res->body
                                : httplib::to_string(res.error()));
          continue;
        }
        ++ok;
        std::lock_guard lock(mutex);
        auto [it, inserted] = first_bytes.emplace(scene, res->body);
        if (!inserted && it->second != res->body) ++mismatched;
      }
    });
  }
  for (std::thread& t : clients) t.join();
  EXPECT_EQ(ok, kThreads * kRequests);
  EXPECT_EQ(mismatched, 0);
  EXPECT_EQ(first_bytes.size(), static_cast<std::size_t>(kScenes));
}

TEST(Load, AFullQueueAnswers503WithRetryAfter) {
  server::ServerConfig config;
  config.workers = 1;
  config.queue = 1;
  config.limits.deadline_ms = 400;  // each slow run holds the one worker this long
  TestServer server(config);
  constexpr int kClients = 6;
  std::atomic<int> busy{0}, stopped{0}, other{0};
  std::atomic<bool> retry_after{true};
  std::vector<std::thread> clients;
  for (int c = 0; c < kClients; ++c) {
    clients.emplace_back([&, c] {
      auto res = server.client().Get(
          ("/api/simulate?preset=high-frequency&t_end=" + std::to_string(100 + c)).c_str());
      if (res && res->status == 503) {
        ++busy;
        if (res->get_header_value("Retry-After") != "1") retry_after = false;
        const auto body = nlohmann::json::parse(res->body);
        if (body["field"] != "server") retry_after = false;
      } else if (res && res->status == 422) {
        ++stopped;
      } else {
        ++other;
      }
    });
  }
  for (std::thread& t : clients) t.join();
  EXPECT_GE(busy, 1);
  EXPECT_GE(stopped, 1);  // one runs, one waits; both stop at the deadline
  EXPECT_LE(stopped, 3);
  EXPECT_EQ(other, 0);
  EXPECT_TRUE(retry_after);
}

TEST(Load, AStalledClientIsDroppedAtTheReadTimeout) {
  server::ServerConfig config;
  config.connection_threads = 1;  // the stalled client holds the only one
  config.read_timeout_s = 1;
  config.keep_alive_s = 1;
  TestServer server(config);
  const auto start = std::chrono::steady_clock::now();
  std::thread stalled([&] {
    // Half a request line, then nothing: the server must give up on it.
    const RawReply reply = raw_exchange(server.port(), "GET /api/hea", 5000);
    EXPECT_EQ(reply.status(), -1);
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  auto res = server.client().Get("/api/health");
  const double waited =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stalled.join();
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_LT(waited, 3.5);
}

}  // namespace
}  // namespace vibro::testing
