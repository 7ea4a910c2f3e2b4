// Sweeps as jobs through the HTTP API: 202 with an id, progress to done, the result in every
// format, cancel, a full queue answering 503 with Retry-After, and bad sweeps named.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "io/presets.h"
#include "io/scene_json.h"
#include "server/jobs.h"
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

// A pellet rattling elastically between stops at ±0.05 rad, swept over its starting speed: an
// impact section of some 20 points per period, known only as it runs.
json rattle_scene(int count, int record) {
  return {{"model",
           {{"R", 0.5},
            {"pellets", {{{"m", 0.1}, {"phi0", 0.0}, {"dphi0", 1.5}}}},
            {"limiters", {{{"angle", -0.05}, {"k", 1.0}}, {{"angle", 0.05}, {"k", 1.0}}}}}},
          {"t_end", 10},
          {"sweep",
           {{"parameter", "model.pellets[0].dphi0"},
            {"from", 1.0},
            {"to", 2.0},
            {"count", count},
            {"transient", 0},
            {"record", record},
            {"section", "impact"}}}};
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
  EXPECT_NE(json::parse(unknown->body)["error"].get<std::string>().find("lyapunov_map"),
            std::string::npos);
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

// Finished jobs are kept up to JobOptions::kept however they end: those queued behind the last
// submit end after it (the queue full, then quiet), and were once all kept on top of it:
// 32 + 8 queued + 1 running = 41 by default.
TEST(SweepJobs, AtMostKeptFinishedJobsAreKept) {
  server::JobOptions options;
  options.queue = 8;
  options.kept = 2;
  server::Jobs jobs(options);
  const Scene scene = std::get<Scene>(scene_from_text(sweep_scene(3, 100)));
  std::vector<std::string> ids;
  for (int k = 0; k < 9; ++k)
    if (const auto status = jobs.submit(server::JobKind::sweep, scene)) ids.push_back(status->id);
  ASSERT_GT(ids.size(), options.kept + 1);
  // Until the last ends (each job ends after the one before it: one runs at a time).
  for (int k = 0; k < 1200; ++k) {
    const auto last = jobs.status(ids.back());
    if (last && last->state != server::JobState::queued && last->state != server::JobState::running)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::size_t kept = 0;
  for (const std::string& id : ids) kept += jobs.status(id).has_value();
  EXPECT_EQ(kept, options.kept);
  EXPECT_TRUE(jobs.finished(ids.back())) << "the newest is kept";
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
  grid["sweep"]["parameter2"] = {
      {"parameter", "model.pellets[0].F0"}, {"from", 0.5}, {"to", 0.1}, {"count", 3}};
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

// The points and runs columns are written to the connection as they are formatted (chunked), not
// built whole on a connection thread first.
TEST(SweepJobs, TheResultIsStreamedNotBuiltWhole) {
  TestServer server;
  auto c = server.client();
  auto res = c.Post("/api/sweep", sweep_scene(12), "application/json");
  ASSERT_EQ(res->status, 202) << res->body;
  const std::string location = res->get_header_value("Location");
  ASSERT_EQ(wait_until_ended(c, location)["status"], "done");
  for (const char* format : {"json", "csv"}) {
    auto got = c.Get((location + "/result?format=" + format).c_str());
    ASSERT_EQ(got->status, 200);
    EXPECT_EQ(got->get_header_value("Transfer-Encoding"), "chunked") << format;
    EXPECT_FALSE(got->has_header("Content-Length")) << format;
    EXPECT_EQ(got->get_header_value("Cache-Control"), "no-store");
    if (std::string(format) == "json")
      EXPECT_EQ(json::parse(got->body)["points"]["phi"].size(), 12u * 21u);
    else
      EXPECT_EQ(std::count(got->body.begin(), got->body.end(), '\n'), 1 + 12 * 21);
  }
}

// A streamed result's bytes are written after the response left its handler with an empty body:
// the access log counts them as they go.
TEST(SweepJobs, TheAccessLogCountsAStreamedResultsBytes) {
  TestServer server({}, true);
  auto c = server.client();
  auto res = c.Post("/api/sweep", sweep_scene(4), "application/json");
  ASSERT_EQ(res->status, 202) << res->body;
  const std::string location = res->get_header_value("Location");
  ASSERT_EQ(wait_until_ended(c, location)["status"], "done");
  ::testing::internal::CaptureStderr();
  auto got = c.Get((location + "/result?format=csv").c_str());
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the line follows the body
  const std::string log = ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(got->status, 200);
  EXPECT_NE(log.find("/result?format=csv 200 " + std::to_string(got->body.size()) + " B"),
            std::string::npos)
      << log;
}

// The section points a sweep may keep are bounded: a stroboscopic sweep over the bound is refused
// up front, an impact-section sweep that reaches it while it runs fails, naming the field, and
// keeps nothing.
TEST(SweepJobs, ThePointsASweepKeepsAreBounded) {
  server::ServerConfig config;
  config.limits.sweep_points = 1000;
  TestServer server(config);
  auto c = server.client();
  auto over = c.Post("/api/sweep", sweep_scene(50, 20), "application/json");  // 50 × 21 points
  ASSERT_EQ(over->status, 400) << over->body;
  EXPECT_EQ(json::parse(over->body)["field"], "sweep.record");
  EXPECT_NE(json::parse(over->body)["error"].get<std::string>().find("1050"), std::string::npos);
  EXPECT_EQ(c.Post("/api/sweep", sweep_scene(47, 20), "application/json")->status, 202);

  auto res = c.Post("/api/sweep", rattle_scene(10, 20).dump(), "application/json");
  ASSERT_EQ(res->status, 202) << res->body;
  const std::string location = res->get_header_value("Location");
  const json ended = wait_until_ended(c, location);
  ASSERT_EQ(ended["status"], "failed") << ended.dump();
  EXPECT_EQ(ended["field"], "sweep.record");
  EXPECT_NE(ended["error"].get<std::string>().find("1000 section points"), std::string::npos);
  EXPECT_LT(ended["progress"]["done"].get<long>(), 10);
  auto result = c.Get((location + "/result").c_str());
  EXPECT_EQ(result->status, 409);
  EXPECT_EQ(json::parse(result->body)["field"], "sweep.record");
}

// One sweep cannot hold the sweep thread for long: its runs share a wall-clock budget. A sweep
// whose runs would each be left less than 10 ms of it is refused up front; 40 runs of some 1.4 s
// each (56 s with the deadline of one simulation alone) end within it.
TEST(SweepJobs, ASweepIsBoundedByItsWallClockBudget) {
  server::ServerConfig config;
  config.limits.sweep_seconds = 2.0;
  TestServer server(config);
  auto c = server.client();
  auto over = c.Post("/api/sweep", sweep_scene(400, 1), "application/json");
  ASSERT_EQ(over->status, 400) << over->body;
  EXPECT_EQ(json::parse(over->body)["field"], "sweep.count");

  // The impact oscillator on a 1 nm circle from 10^7 rad/s: some 1.4 s a run alone.
  json slow = json::parse(sweep_scene(40, 1));
  slow["model"]["R"] = 1e-9;
  slow["model"]["pellets"][0]["dphi0"] = 1e7;
  slow["sweep"]["transient"] = 0;
  slow["sweep"]["section"] = "impact";
  auto res = c.Post("/api/sweep", slow.dump(), "application/json");
  ASSERT_EQ(res->status, 202) << res->body;
  const std::string location = res->get_header_value("Location");
  const auto t0 = std::chrono::steady_clock::now();
  const json ended = wait_until_ended(c, location);  // gives up after 30 s
  ASSERT_FALSE(ended.is_null())
      << "still running after "
      << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s";
  EXPECT_TRUE(ended["status"] == "done" || ended["status"] == "failed") << ended.dump();
}

// Finished sweeps hold at most 4 × limits.sweep_points in all: past it the oldest is forgotten.
TEST(SweepJobs, FinishedSweepsHoldBoundedPoints) {
  server::ServerConfig config;
  config.limits.sweep_points = 300;  // finished ones: 1200 in all
  TestServer server(config);
  auto c = server.client();
  std::vector<std::string> jobs;
  for (int k = 0; k < 5; ++k) {  // 252 points each
    auto res = c.Post("/api/sweep", sweep_scene(12), "application/json");
    ASSERT_EQ(res->status, 202) << res->body;
    jobs.push_back(res->get_header_value("Location"));
    ASSERT_EQ(wait_until_ended(c, jobs.back())["status"], "done");
  }
  EXPECT_EQ(c.Get(jobs[0].c_str())->status, 404);  // 5 × 252 > 1200
  for (int k = 1; k < 5; ++k) EXPECT_EQ(c.Get((jobs[k] + "/result").c_str())->status, 200) << k;
}

// A sweep's plot is drawn on a worker; as SVG or PDF only up to limits.sweep_vector_points
// points (each is a mark of its own there), as PNG whatever its points.
TEST(SweepJobs, ALargeSweepIsDrawnAsPngOnly) {
  server::ServerConfig config;
  config.limits.sweep_vector_points = 200;
  TestServer server(config);
  auto c = server.client();
  auto res = c.Post("/api/sweep", sweep_scene(12), "application/json");  // 252 points
  ASSERT_EQ(res->status, 202) << res->body;
  const std::string location = res->get_header_value("Location");
  ASSERT_EQ(wait_until_ended(c, location)["status"], "done");
  for (const char* format : {"svg", "pdf"}) {
    auto refused = c.Get((location + "/result?format=" + format).c_str());
    ASSERT_EQ(refused->status, 400) << format;
    EXPECT_EQ(json::parse(refused->body)["field"], "format");
    EXPECT_NE(json::parse(refused->body)["error"].get<std::string>().find("png"),
              std::string::npos);
  }
  auto png = c.Get((location + "/result?format=png").c_str());
  ASSERT_EQ(png->status, 200);
  EXPECT_EQ(png_size(png->body), (std::pair<int, int>{1200, 800}));
  EXPECT_FALSE(png->get_header_value("X-Vibro-Parameter-Axis").empty());
  // A regime map draws a cell per run, not a mark per point.
  EXPECT_EQ(c.Get((location + "/result?format=svg&plot=regime_map").c_str())->status, 200);
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

// A basin map's summary (part=summary) is its attractors and stats without the points and runs,
// whose size grows with the cells; another part, or a summary as CSV, is refused naming "part".
TEST(SweepJobs, ABasinMapsSummaryHasItsAttractorsWithoutThePoints) {
  TestServer server;
  auto c = server.client();
  json s = json::parse(std::string(*preset_json("impact-oscillator")));
  s["model"]["pellets"][0]["Omega"] = 6.8;  // two period-1 motions coexist (docs/SWEEPS.md)
  s["sweep"] = {{"parameter", "model.pellets[0].phi0"},
                {"from", 0.01},
                {"to", 1.6},
                {"count", 4},
                {"parameter2",
                 {{"parameter", "model.pellets[0].dphi0"}, {"from", -8}, {"to", 8}, {"count", 4}}},
                {"transient", 100},
                {"record", 8},
                {"classify", "attractor"}};
  auto res = c.Post("/api/sweep", s.dump(), "application/json");
  ASSERT_EQ(res->status, 202) << res->body;
  const std::string location = res->get_header_value("Location");
  ASSERT_EQ(wait_until_ended(c, location)["status"], "done");

  const json whole = json::parse(c.Get((location + "/result?format=json").c_str())->body);
  auto summary = c.Get((location + "/result?format=json&part=summary").c_str());
  ASSERT_EQ(summary->status, 200) << summary->body;
  EXPECT_EQ(summary->get_header_value("Content-Type"), "application/json");
  json expected = whole;
  expected.erase("points");
  expected.erase("runs");
  EXPECT_EQ(json::parse(summary->body), expected);
  EXPECT_FALSE(expected["attractors"].empty());
  EXPECT_EQ(json::parse(c.Get((location + "/result?format=json&part=all").c_str())->body), whole);

  for (const char* query : {"?format=json&part=points", "?format=csv&part=summary",
                            "?format=png&part=summary", "?part=attractors"}) {
    auto bad = c.Get((location + "/result" + query).c_str());
    ASSERT_EQ(bad->status, 400) << query;
    EXPECT_EQ(json::parse(bad->body)["field"], "part") << query;
  }
}

}  // namespace
}  // namespace vibro::testing
