// Every bad request gets a 4xx with {"error", "field"} naming what is wrong; nothing a client
// sends makes a 5xx, a hang or a body read without bound.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/sanitizers.h"
#include "tests/server/test_server.h"

namespace vibro::testing {
namespace {

using nlohmann::json;

class Errors : public SharedServerTest {};

// The error's field, after checking the status and the JSON shape.
std::string field_of(const httplib::Result& res, int status) {
  if (!res) return "<no response>";
  EXPECT_EQ(res->status, status) << res->body;
  EXPECT_EQ(res->get_header_value("Content-Type"), "application/json");
  const json body = json::parse(res->body, nullptr, false);
  if (!body.is_object() || !body["error"].is_string() || !body["field"].is_string()) {
    ADD_FAILURE() << "not an error body: " << res->body;
    return "<bad body>";
  }
  EXPECT_FALSE(body["error"].get<std::string>().empty());
  return body["field"];
}

httplib::Result post_scene(const std::string& path, const std::string& body) {
  return Errors::server->client().Post(path.c_str(), body, "application/json");
}

json paper() { return json::parse(paper_scene(5.0)); }

TEST_F(Errors, BadJsonNamesTheScene) {
  EXPECT_EQ(field_of(post_scene("/api/simulate", "{\"model\": "), 400), "scene");
  EXPECT_EQ(field_of(post_scene("/api/render", "[1, 2"), 400), "scene");
}

TEST_F(Errors, AWrongTypeNamesTheField) {
  json scene = paper();
  scene["model"]["R"] = "half a metre";
  EXPECT_EQ(field_of(post_scene("/api/simulate", scene.dump()), 400), "model.R");
  scene = paper();
  scene["model"]["pellets"][1]["m"] = -1.0;
  EXPECT_EQ(field_of(post_scene("/api/simulate", scene.dump()), 400), "model.pellets[1].m");
}

TEST_F(Errors, AnUnknownKeyIsNamed) {
  json scene = paper();
  scene["model"]["alpah0"] = 0.05;
  EXPECT_EQ(field_of(post_scene("/api/simulate", scene.dump()), 400), "model.alpah0");
}

TEST_F(Errors, TEndOverTheLimitIsRefusedUpFront) {
  json scene = paper();
  scene["t_end"] = 1e5;
  EXPECT_EQ(field_of(post_scene("/api/simulate", scene.dump()), 400), "t_end");
  EXPECT_EQ(field_of(server->client().Get("/api/render?preset=paper&t_end=5000"), 400), "t_end");
  // Just past the bound, the message shows how far: every digit the client sent.
  auto res = server->client().Get("/api/simulate?preset=paper&t_end=1000.0000001");
  ASSERT_TRUE(res);
  EXPECT_NE(res->body.find("got 1000.0000001"), std::string::npos) << res->body;
}

TEST_F(Errors, AnImageTooLargeNamesItsSize) {
  json scene = paper();
  scene["width"] = 10000;
  EXPECT_EQ(field_of(post_scene("/api/render", scene.dump()), 400), "width");
  EXPECT_EQ(field_of(server->client().Get("/api/render?preset=paper&height=9000"), 400), "height");
  // Each side within its limit, the pixels over theirs (8 000 000).
  EXPECT_EQ(field_of(server->client().Get("/api/render?preset=paper&width=4000&height=4000"), 400),
            "width");
}

TEST_F(Errors, AWorkPrecisionSweepIsLeftToTheCommandLine) {
  json scene = paper();
  scene["plots"].push_back({{"kind", "work_precision"}});
  EXPECT_EQ(field_of(post_scene("/api/render", scene.dump()), 400), "plots[3].kind");
}

TEST_F(Errors, QueryValuesAreChecked) {
  auto get = [](const char* path) { return server->client().Get(path); };
  EXPECT_EQ(field_of(get("/api/render?preset=paper&t_end=nan"), 400), "t_end");
  EXPECT_EQ(field_of(get("/api/render?preset=paper&width=wide"), 400), "width");
  EXPECT_EQ(field_of(get("/api/render?preset=paper&pellet=7"), 400), "plots[0].pellet");
  EXPECT_EQ(field_of(get("/api/render?preset=paper&format=gif"), 400), "format");
  EXPECT_EQ(field_of(get("/api/render?preset=paper&colour=red"), 400), "colour");
  EXPECT_EQ(field_of(get("/api/simulate?preset=paper&method=euler"), 400), "solver.method");
  EXPECT_EQ(field_of(get("/api/render?format=png"), 400), "preset");
}

// A parameter given twice is refused, naming it; a value is everything after the first '='.
TEST_F(Errors, AQueryParameterGivenTwiceIsRefusedAndValuesAreReadWhole) {
  auto get = [](const char* path) { return server->client().Get(path); };
  EXPECT_EQ(field_of(get("/api/simulate?preset=paper&t_end=1&t_end=2"), 400), "t_end");
  EXPECT_EQ(field_of(get("/api/render?preset=paper&preset=paper"), 400), "preset");
  auto res = get("/api/simulate?preset=paper&method=dop853=x");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400);
  EXPECT_NE(res->body.find("dop853=x"), std::string::npos) << res->body;  // not "x"
  res = get("/api/simulate?preset=paper&t_end=0%2E5&method=dop853");      // still decoded
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200) << res->body;
}

TEST_F(Errors, AnUnknownPresetIs404) {
  EXPECT_EQ(field_of(server->client().Get("/api/presets/nope"), 404), "preset");
  EXPECT_EQ(field_of(server->client().Get("/api/render?preset=nope"), 404), "preset");
  EXPECT_EQ(field_of(server->client().Get("/api/simulate?preset=nope"), 404), "preset");
}

TEST_F(Errors, AnUnknownEndpointIs404) {
  EXPECT_EQ(field_of(server->client().Get("/api/nothing"), 404), "path");
  EXPECT_EQ(field_of(post_scene("/api/nothing", "{}"), 404), "path");
}

TEST_F(Errors, AWrongMethodIs405WithAllow) {
  auto res = server->client().Post("/api/health", "{}", "application/json");
  EXPECT_EQ(field_of(res, 405), "method");
  EXPECT_EQ(res->get_header_value("Allow"), "GET");
  auto del = server->client().Delete("/api/simulate");
  EXPECT_EQ(field_of(del, 405), "method");
  EXPECT_EQ(del->get_header_value("Allow"), "GET, POST");
  EXPECT_EQ(field_of(server->client().Put("/index.html", "x", "text/plain"), 405), "method");
}

TEST_F(Errors, AnOversizedBodyIs413) {
  const std::string big = "{\"pad\": \"" + std::string(70 * 1024, 'x') + "\"}";
  EXPECT_EQ(field_of(post_scene("/api/simulate", big), 413), "body");
}

TEST_F(Errors, AWrongContentTypeIs415) {
  auto res = server->client().Post("/api/simulate", paper_scene(5.0), "text/plain");
  EXPECT_EQ(field_of(res, 415), "Content-Type");
}

TEST_F(Errors, ChunkedBodiesAreRefusedAndTheConnectionToldToEnd) {
  const RawReply reply =
      raw_exchange(server->port(),
                   "POST /api/simulate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                   "Transfer-Encoding: chunked\r\n\r\n4\r\n{\"a\"\r\n");
  EXPECT_EQ(reply.status(), 411) << reply.bytes;
  EXPECT_NE(reply.bytes.find("\"field\":\"body\""), std::string::npos);
  EXPECT_TRUE(reply.announces_close());
}

TEST_F(Errors, PostsWithoutALengthAreRefused) {
  const RawReply reply = raw_exchange(
      server->port(),
      "POST /api/render HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n\r\n{}");
  EXPECT_EQ(reply.status(), 411) << reply.bytes;
  EXPECT_TRUE(reply.announces_close());
}

TEST_F(Errors, AnnouncedOversizedBodiesAreRefusedBeforeReading) {
  const RawReply reply = raw_exchange(server->port(),
                                      "POST /api/simulate HTTP/1.1\r\nHost: x\r\n"
                                      "Content-Type: application/json\r\n"
                                      "Content-Length: 99999999999\r\n\r\n{");
  EXPECT_EQ(reply.status(), 413) << reply.bytes;
  EXPECT_TRUE(reply.announces_close());
}

TEST_F(Errors, GarbageIsA400InJson) {
  const RawReply reply = raw_exchange(server->port(), "NONSENSE\r\n\r\n");
  EXPECT_EQ(reply.status(), 400) << reply.bytes;
  EXPECT_NE(reply.bytes.find("\"field\":\"request\""), std::string::npos);
}

TEST_F(Errors, AnOverlongTargetIsRefused) {
  auto res = server->client().Get(("/api/render?preset=" + std::string(9000, 'p')).c_str());
  ASSERT_TRUE(res);
  EXPECT_GE(res->status, 400);
  EXPECT_LT(res->status, 500);
}

// Which of two Content-Length headers frames the body is a guess a proxy in front may make the
// other way (request smuggling): refused, and the connection ends.
TEST_F(Errors, TwoContentLengthsAreRefused) {
  const std::string body = paper_scene(0.5);
  const RawReply reply =
      raw_exchange(server->port(),
                   "POST /api/simulate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                   "Content-Length: " +
                       std::to_string(body.size()) + "\r\nContent-Length: 5\r\n\r\n" + body);
  EXPECT_EQ(reply.status(), 400) << reply.bytes;
  EXPECT_NE(reply.bytes.find("\"field\":\"Content-Length\""), std::string::npos);
  EXPECT_TRUE(reply.announces_close());
}

// AddressSanitizer's allocator keeps freed memory in quarantine: resident memory says nothing
// about what the server gave back there.
constexpr bool kGlibcAllocator = !vibro::testing::kUnderAsan;

// cpp-httplib keeps every header line it reads; a flood is refused, and its memory given back.
TEST_F(Errors, AHeaderFloodIsRefusedAndItsMemoryGivenBack) {
  auto rss_kib = [] {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
      if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
    return 0L;
  };
  std::string request = "GET /api/health HTTP/1.1\r\nHost: x\r\n";
  for (int i = 0; i < 400000; ++i)
    request += "X-Flood-" + std::to_string(i) + ": aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\r\n";
  request += "\r\n";
  const long before = rss_kib();
  const RawReply reply = raw_exchange(server->port(), request, 20000);
  request.clear();
  request.shrink_to_fit();
  EXPECT_EQ(reply.status(), 431) << reply.bytes.substr(0, 200);
  EXPECT_NE(reply.bytes.find("\"field\":\"headers\""), std::string::npos);
  if (kGlibcAllocator) {
    EXPECT_LT(rss_kib() - before, 16 * 1024);  // 400,000 lines held: 55 MB
  }
  auto res = server->client().Get("/api/health");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
}

// The refusal of a run that a limit stopped: 422 naming t_end, with the partial stats.
json stopped_run(const server::ServerConfig& config, const char* path) {
  TestServer server(config);
  auto res = server.client().Get(path);
  if (!res) return {};
  EXPECT_EQ(res->status, 422) << res->body;
  EXPECT_EQ(res->get_header_value("Cache-Control"), "no-store");
  json body = json::parse(res->body);
  EXPECT_EQ(body["field"], "t_end");
  return body;
}

TEST(RunLimits, ARunOverItsDeadlineIsAClearError) {
  server::ServerConfig config;
  config.limits.deadline_ms = 100;
  const json body = stopped_run(config, "/api/simulate?preset=high-frequency&t_end=100");
  EXPECT_NE(body["error"].get<std::string>().find("longer than its deadline of 100 ms"),
            std::string::npos)
      << body["error"];
  EXPECT_EQ(body["stats"]["termination"], "deadline");
  EXPECT_LT(body["stats"]["t_reached"].get<double>(), 100.0);
}

// The sample limit bounds the trajectories' memory, not the run: past it they are thinned, and
// the whole run is drawn (the paper scene, 12 s, in 1000 samples).
TEST(RunLimits, TheSampleLimitThinsTheTrajectoriesDrawn) {
  server::ServerConfig config;
  config.limits.samples = 1000;
  TestServer server(config);
  auto png = server.client().Get("/api/render?preset=paper&width=400&height=300");
  ASSERT_TRUE(png);
  EXPECT_EQ(png->status, 200) << png->body.substr(0, 300);
  auto res = server.client().Get("/api/simulate?preset=paper&trajectories=true");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body.substr(0, 300);
  const json run = json::parse(res->body);
  long samples = 0;
  double last = 0.0;
  for (const json& track : run["trajectories"])
    for (const json& branch : track["branches"]) {
      samples += static_cast<long>(branch["t"].size());
      last = std::max(last, branch["t"].back().get<double>());
    }
  EXPECT_LE(samples, 1000);
  EXPECT_GT(samples, 400);
  EXPECT_DOUBLE_EQ(last, 12.0);
}

TEST(RunLimits, AnEventLimitStopsTheRunWithItsStats) {
  server::ServerConfig config;
  config.limits.events = 10;
  const json body = stopped_run(config, "/api/render?preset=paper&width=400&height=300");
  EXPECT_EQ(body["stats"]["termination"], "event_limit");
  // Advice that works: the events are the motion's, so only a shorter span has fewer.
  const std::string why = body["error"];
  EXPECT_NE(why.find("shorten t_end to at most"), std::string::npos) << why;
  EXPECT_EQ(why.find("loosen"), std::string::npos) << why;
}

}  // namespace
}  // namespace vibro::testing
