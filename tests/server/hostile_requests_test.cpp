// Requests that once took the service down or made it answer late, each over real sockets:
// a periodic-orbit guess far past any angle, a second server on the same port, and connections
// that waited behind idle keep-alive ones.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "server/service.h"
#include "tests/server/test_server.h"

namespace vibro::testing {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// The request that hung a worker for ever (a turn counter in a double stops counting past 2^53).
json far_guess() {
  return json::parse(R"({"model":{"R":0.5,"alpha0":0,"pellets":[{"m":0.1,"phi0":0.1,"F0":0.3,
    "Omega":5}],"limiters":[{"angle":0,"k":0.8}]},"t_end":20,
    "periodic_orbit":{"periods":1,"guess":[{"phi":1e17,"dphi":1}]}})");
}

class HostileRequests : public SharedServerTest {};

TEST_F(HostileRequests, AnOrbitGuessPastAnyAngleIsRefusedNamingIt) {
  auto c = server->client();
  for (double dphi : {1.0, 0.0}) {
    json request = far_guess();
    request["periodic_orbit"]["guess"][0]["dphi"] = dphi;
    auto res = c.Post("/api/periodic-orbit", request.dump(), "application/json");
    ASSERT_TRUE(res) << "no answer within the client's 10 s";
    EXPECT_EQ(res->status, 400) << res->body;
    EXPECT_EQ(json::parse(res->body)["field"], "periodic_orbit.guess[0].phi");
  }
  json continued = far_guess();
  continued["periodic_orbit"]["continuation"] = {{"parameter", "model.pellets[0].Omega"},
                                                 {"to", 6.0}};
  auto res = c.Post("/api/periodic-orbit", continued.dump(), "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400) << res->body;
  json speed = far_guess();
  speed["periodic_orbit"]["guess"][0] = {{"phi", 0.1}, {"dphi", 1e8}};
  res = c.Post("/api/periodic-orbit", speed.dump(), "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(json::parse(res->body)["field"], "periodic_orbit.guess[0].dphi");
  EXPECT_EQ(c.Get("/api/health")->status, 200);
}

// What nginx refuses in a request head vibro refuses too, with the JSON of every error.
TEST_F(HostileRequests, MalformedHeaderLinesAreRefused) {
  const char* heads[] = {
      "GET /api/health HTTP/1.1\r\n\r\n",                                      // no Host
      "GET /api/health HTTP/1.1\r\nHost: x\r\nX-A: 1\r\n folded: on\r\n\r\n",  // obs-fold
      "GET /api/health HTTP/1.1\r\nHost: x\r\nBad Name: 1\r\n\r\n",
  };
  for (const char* head : heads) {
    const RawReply reply = raw_exchange(server->port(), head);
    EXPECT_EQ(reply.status(), 400) << head << reply.bytes;
    EXPECT_NE(reply.bytes.find("\"field\":"), std::string::npos) << reply.bytes;
  }
  const std::string nul =
      std::string("GET /api/health HTTP/1.1\r\nHost: x\r\nX-A: a") + '\0' + "b\r\n\r\n";
  const RawReply reply = raw_exchange(server->port(), nul);
  EXPECT_EQ(reply.status(), 400) << reply.bytes;
  EXPECT_NE(reply.bytes.find("\"field\":\"headers\""), std::string::npos);
  const RawReply ok = raw_exchange(server->port(), "GET /api/health HTTP/1.1\r\nHost: x\r\n\r\n");
  EXPECT_EQ(ok.status(), 200) << ok.bytes;
}

TEST(ServerPort, ASecondServerOnTheSamePortFailsAsAddressInUse) {
  TestServer first;
  server::ServerConfig config;
  config.port = first.port();
  config.access_log = false;
  server::Service second(config);
  std::string why;
  EXPECT_EQ(second.bind(&why), -1);
  EXPECT_EQ(why, "address in use");
}

// Two connection threads, both held by keep-alive connections that went idle after a request
// (kept alive for 30 s): a third connection is answered at once, not after 30 s.
TEST(ConnectionThreads, ANewConnectionDoesNotWaitBehindIdleKeepAliveOnes) {
  server::ServerConfig config;
  config.connection_threads = 2;
  config.keep_alive_s = 30;
  TestServer server(config);
  std::vector<httplib::Client> idle;
  for (int k = 0; k < 2; ++k) {
    idle.push_back(server.client());
    idle.back().set_keep_alive(true);
    auto res = idle.back().Get("/api/health");
    ASSERT_TRUE(res);
    ASSERT_EQ(res->status, 200);
  }
  const auto start = Clock::now();
  httplib::Client fresh("127.0.0.1", server.port());
  fresh.set_read_timeout(5);
  for (int k = 0; k < 5; ++k) {
    auto res = fresh.Get("/api/health");
    ASSERT_TRUE(res) << "request " << k << " waited past 5 s";
    EXPECT_EQ(res->status, 200);
  }
  EXPECT_LT(seconds_since(start), 5.0);
  // The idle clients reconnect as any keep-alive client does when its connection was closed.
  for (auto& c : idle) {
    auto res = c.Get("/api/health");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200);
  }
}

}  // namespace
}  // namespace vibro::testing
