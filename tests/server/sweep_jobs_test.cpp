// Sweeps as jobs through the HTTP API: 202 with an id, progress to done, the result in every
// format, cancel, a full queue answering 503 with Retry-After, and bad sweeps named.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "io/presets.h"
#include "tests/server/test_server.h"

namespace vibro::testing {
namespace {

using nlohmann::json;

// The impact oscillator over Ω with `count` values, without continuation.
std::string sweep_scene(int count, int record = 20) {
  json s = json::parse(std::string(*preset_json("impact-oscillator")));
  s["sweep"]["count"] = count;
  s["sweep"]["continuation"] = "none";
  s["sweep"]["transient"] = 20;
  s["sweep"]["record"] = record;
  return s.dump();
}

json status_of(httplib::Client& c, const std::string& location) {
  auto res = c.Get(location.c_str());
  if (!res || res->status != 200) return {};
  return json::parse(res->body);
}

json wait_until_ended(httplib::Client& c, const std::string& location) {
  for (int k = 0; k < 600; ++k) {
    const json s = status_of(c, location);
    if (s.is_null() || (s["status"] != "queued" && s["status"] != "running")) return s;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return {};
}

TEST(SweepJobs, ASweepRunsAsAJobAndAnswersInEveryFormat) {
  TestServer server;
  auto c = server.client();
  auto res = c.Post("/api/sweep", sweep_scene(12), "application/json");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 202) << res->body;
  const std::string location = res->get_header_value("Location");
  const json queued = json::parse(res->body);
  EXPECT_EQ(location, "/api/jobs/" + queued["id"].get<std::string>());
  EXPECT_EQ(queued["progress"]["total"], 12);

  const json done = wait_until_ended(c, location);
  ASSERT_EQ(done["status"], "done") << done.dump();
  EXPECT_EQ(done["progress"]["done"], 12);

  auto points = c.Get((location + "/result?format=json").c_str());
  ASSERT_EQ(points->status, 200);
  const json r = json::parse(points->body);
  EXPECT_EQ(r["parameter"], "model.pellets[0].Omega");
  EXPECT_EQ(r["runs"]["period"].size(), 12u);
  EXPECT_EQ(r["points"]["phi"].size(), 12u * 21u);  // record + 1 section times per run
  auto csv = c.Get((location + "/result?format=csv").c_str());
  ASSERT_EQ(csv->status, 200);
  EXPECT_EQ(csv->get_header_value("Content-Type"), "text/csv");
  EXPECT_EQ(std::count(csv->body.begin(), csv->body.end(), '\n'), 1 + 12 * 21);
  auto png = c.Get((location + "/result?format=png").c_str());
  ASSERT_EQ(png->status, 200);
  EXPECT_EQ(png_size(png->body), (std::pair<int, int>{1200, 800}));
  auto svg = c.Get((location + "/result?format=svg&coordinate=phi").c_str());
  ASSERT_EQ(svg->status, 200);
  EXPECT_NE(svg->body.find("<svg"), std::string::npos);
  auto bad = c.Get((location + "/result?format=gif").c_str());
  EXPECT_EQ(bad->status, 400);
  EXPECT_EQ(json::parse(bad->body)["field"], "format");
  // A Lyapunov plot of a sweep that computed no exponents: the sweep's field is named.
  auto lyapunov = c.Get((location + "/result?format=png&plot=lyapunov").c_str());
  EXPECT_EQ(lyapunov->status, 400);
  EXPECT_EQ(json::parse(lyapunov->body)["field"], "sweep.lyapunov");
  auto unknown = c.Get((location + "/result?format=png&plot=orbit").c_str());
  EXPECT_EQ(unknown->status, 400);
  EXPECT_NE(json::parse(unknown->body)["error"].get<std::string>().find("lyapunov_map"), std::string::npos);
}

TEST(SweepJobs, AJobIsCancelledAndAFullQueueAnswers503) {
  server::ServerConfig config;
  config.sweep_queue = 1;
  TestServer server(config);
  auto c = server.client();
  // A long sweep runs, a second waits, a third finds the queue full.
  auto first = c.Post("/api/sweep", sweep_scene(400, 100), "application/json");
  ASSERT_EQ(first->status, 202);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  auto second = c.Post("/api/sweep", sweep_scene(400, 100), "application/json");
  ASSERT_EQ(second->status, 202);
  auto third = c.Post("/api/sweep", sweep_scene(400, 100), "application/json");
  ASSERT_EQ(third->status, 503);
  EXPECT_FALSE(third->get_header_value("Retry-After").empty());

  // The result is not ready while it runs.
  const std::string running = first->get_header_value("Location");
  EXPECT_EQ(c.Get((running + "/result").c_str())->status, 409);
  for (const auto* reply : {&first, &second}) {
    const std::string location = (*reply)->get_header_value("Location");
    auto del = c.Delete(location.c_str());
    ASSERT_EQ(del->status, 200);
    const json ended = wait_until_ended(c, location);
    EXPECT_EQ(ended["status"], "cancelled");
    EXPECT_LT(ended["progress"]["done"].get<long>(), 400);
  }
  EXPECT_EQ(c.Get("/api/jobs/s0000000000000000")->status, 404);
  EXPECT_EQ(c.Delete("/api/jobs/s0000000000000000")->status, 404);
}

TEST(SweepJobs, BadSweepsAreRefusedNamingTheField) {
  TestServer server;
  auto c = server.client();
  auto field = [&](const json& scene) {
    auto res = c.Post("/api/sweep", scene.dump(), "application/json");
    EXPECT_EQ(res->status, 400) << res->body;
    return json::parse(res->body)["field"].get<std::string>();
  };
  json s = json::parse(sweep_scene(10));
  json none = s;
  none.erase("sweep");
  EXPECT_EQ(field(none), "sweep");
  json unknown = s;
  unknown["sweep"]["parameter"] = "model.pellets[0].mass";
  EXPECT_EQ(field(unknown), "sweep.parameter");
  json zero = s;
  zero["sweep"]["count"] = 0;
  EXPECT_EQ(field(zero), "sweep.count");
  json grid = s;
  grid["sweep"]["parameter2"] = {{"parameter", "model.pellets[0].F0"}, {"from", 0.5}, {"to", 0.1}, {"count", 3}};
  EXPECT_EQ(field(grid), "sweep.parameter2.to");
  json unforced = s;
  unforced["model"]["pellets"][0]["F0"] = 0.0;
  unforced["model"]["pellets"][0]["Omega"] = 0.0;
  unforced["sweep"]["parameter"] = "model.limiters[0].k";
  unforced["sweep"]["from"] = 0.5;
  unforced["sweep"]["to"] = 0.9;
  EXPECT_EQ(field(unforced), "sweep.section");
  json huge = s;
  huge["sweep"]["count"] = 100000;
  EXPECT_EQ(field(huge), "sweep.count");
  json long_run = s;
  long_run["sweep"]["record"] = 5000;  // 5020 periods of 1.2 s: over the 1000 s limit
  long_run["sweep"]["count"] = 2;
  EXPECT_EQ(field(long_run), "sweep.record");
}

// Every value of a sweep is checked as a scene of its own: the middle run of two pellets swept
// through each other would start with them coinciding.
TEST(SweepJobs, EveryValueOfASweepIsChecked) {
  TestServer server;
  auto c = server.client();
  json s = json::parse(sweep_scene(3));
  s["model"]["pellets"][0]["phi0"] = 0.1;
  s["model"]["pellets"].push_back({{"m", 0.1}, {"phi0", 0.5}});
  s["sweep"]["parameter"] = "model.pellets[1].phi0";
  s["sweep"]["from"] = 0.0;
  s["sweep"]["to"] = 0.2;
  auto res = c.Post("/api/sweep", s.dump(), "application/json");
  ASSERT_EQ(res->status, 400) << res->body;
  const json e = json::parse(res->body);
  EXPECT_EQ(e["field"], "model.pellets[1].phi0");
  EXPECT_NE(e["error"].get<std::string>().find("= 0.1"), std::string::npos) << e.dump();
}

}  // namespace
}  // namespace vibro::testing
