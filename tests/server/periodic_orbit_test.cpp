// POST /api/periodic-orbit: the impact oscillator's stable period-1 motion answered at once; bad
// requests refused naming the field; a continuation run as a job whose result is a branch.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <complex>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "tests/io/orbit_scene.h"
#include "tests/server/test_server.h"

namespace vibro::testing {
namespace {

using nlohmann::json;

httplib::Result post(httplib::Client& c, const json& scene) {
  return c.Post("/api/periodic-orbit", scene.dump(), "application/json");
}

// The job's status once it is neither queued nor running, polled every 50 ms at most `polls`
// times (the last status then); null if a poll fails.
json status_when_ended(httplib::Client& c, const std::string& location, int polls) {
  json status;
  for (int k = 0; k < polls; ++k) {
    auto poll = c.Get(location.c_str());
    if (!poll || poll->status != 200) return nullptr;
    status = json::parse(poll->body);
    if (status["status"] != "queued" && status["status"] != "running") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return status;
}

// The impact oscillator's orbit continued in Ω to 6.3, posted as a job: its Location, or empty.
std::string continuation_job(httplib::Client& c) {
  json s = impact_oscillator_orbit();
  s["periodic_orbit"]["continuation"] = {
      {"parameter", "model.pellets[0].Omega"}, {"to", 6.3}, {"max_points", 30}};
  auto res = c.Post("/api/periodic-orbit", s.dump(), "application/json");
  if (!res || res->status != 202) {
    ADD_FAILURE() << (res ? res->body : "no answer");
    return "";
  }
  return res->get_header_value("Location");
}

// The impact oscillator's period doubling followed in k from Ω = 6 (as
// docs/scenes/impact-oscillator-pd-curve.json), with a regime map of (Ω, k) of count × count2
// runs to draw beneath the curve.
json curves_over_a_map(int count, int count2) {
  json s = impact_oscillator_orbit();
  s["model"]["pellets"][0]["Omega"] = 6.0;
  s["periodic_orbit"]["guess"] = {{{"phi", 0.15}, {"dphi", 0.1}}};
  s["periodic_orbit"]["continuation"] = {
      {"parameter", "model.pellets[0].Omega"},
      {"to", 5.0},
      {"max_points", 30},
      {"follow", "period_doubling"},
      {"parameter2", {{"parameter", "model.limiters[0].k"}, {"from", 0.6}, {"to", 0.95}}}};
  s["sweep"] = {
      {"parameter", "model.pellets[0].Omega"},
      {"from", 5.0},
      {"to", 6.0},
      {"count", count},
      {"parameter2",
       {{"parameter", "model.limiters[0].k"}, {"from", 0.6}, {"to", 0.95}, {"count", count2}}},
      {"transient", 20},
      {"record", 4},
      {"continuation", "none"}};
  return s;
}

class PeriodicOrbitApi : public SharedServerTest {};

TEST_F(PeriodicOrbitApi, TheImpactOscillatorsPeriodOneMotionIsStable) {
  auto c = server->client();
  auto res = post(c, impact_oscillator_orbit());
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_EQ(res->get_header_value("Content-Type"), "application/json");
  const json r = json::parse(res->body);
  const json& orbit = r["orbit"];
  EXPECT_EQ(orbit["converged"], true) << orbit["message"];
  EXPECT_EQ(orbit["stable"], true);
  EXPECT_EQ(orbit["periods"], 1);
  EXPECT_EQ(orbit["impacts_per_period"], 1.0);
  ASSERT_EQ(orbit["multipliers"].size(), 2u);
  for (const json& m : orbit["multipliers"]) {
    const std::complex<double> mu(m["re"].get<double>(), m["im"].get<double>());
    EXPECT_NEAR(std::abs(mu), 0.8, 1e-3);
    EXPECT_GT(std::abs(mu.imag()), 1e-3);  // a complex pair
  }
  EXPECT_EQ(orbit["state"].size(), 1u);
  EXPECT_FALSE(orbit["events"].empty());
  EXPECT_TRUE(r["branch"].empty());
  EXPECT_TRUE(r["bifurcations"].empty());
}

TEST_F(PeriodicOrbitApi, BadRequestsAreRefusedNamingTheField) {
  auto c = server->client();
  auto field = [&](const json& scene) {
    auto res = post(c, scene);
    EXPECT_EQ(res->status, 400) << res->body;
    return json::parse(res->body)["field"].get<std::string>();
  };
  json zero = impact_oscillator_orbit();
  zero["periodic_orbit"]["periods"] = 0;
  EXPECT_EQ(field(zero), "periodic_orbit.periods");
  json unforced = impact_oscillator_orbit();
  unforced["model"]["pellets"][0]["F0"] = 0.0;
  EXPECT_EQ(field(unforced), "model.pellets");
  // The defaults of a scene without "periodic_orbit" are checked too.
  unforced.erase("periodic_orbit");
  EXPECT_EQ(field(unforced), "model.pellets");
  json typo = impact_oscillator_orbit();
  typo["periodic_orbit"]["periodz"] = 1;
  EXPECT_EQ(field(typo), "periodic_orbit.periodz");
  json guesses = impact_oscillator_orbit();
  guesses["periodic_orbit"]["guess"].push_back({{"phi", 0.0}, {"dphi", 0.0}});
  EXPECT_EQ(field(guesses), "periodic_orbit.guess");
  json long_search = impact_oscillator_orbit();
  long_search["periodic_orbit"]["periods"] = 64;  // 41 × 64 periods of 1.05 s: over 1000 s
  EXPECT_EQ(field(long_search), "periodic_orbit.max_iterations");
  json costly = impact_oscillator_orbit();
  costly["periodic_orbit"]["continuation"] = {
      {"parameter", "model.pellets[0].Omega"}, {"to", 6.5}, {"max_points", 10000}};
  costly["periodic_orbit"]["periods"] = 16;
  EXPECT_EQ(field(costly), "periodic_orbit.continuation.max_points");
  auto query =
      c.Post("/api/periodic-orbit?periods=2", impact_oscillator_orbit().dump(), "application/json");
  EXPECT_EQ(query->status, 400);
  EXPECT_EQ(json::parse(query->body)["field"], "periods");
}

TEST_F(PeriodicOrbitApi, AskedForAnImageItDrawsOneReturnOfTheMotion) {
  auto c = server->client();
  auto png = c.Post("/api/periodic-orbit?format=png", impact_oscillator_orbit().dump(),
                    "application/json");
  ASSERT_EQ(png->status, 200) << png->body;
  EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
  EXPECT_TRUE(png->body.starts_with("\x89PNG"));
  auto bad = c.Post("/api/periodic-orbit?format=gif", impact_oscillator_orbit().dump(),
                    "application/json");
  EXPECT_EQ(bad->status, 400);
  EXPECT_EQ(json::parse(bad->body)["field"], "format");
}

TEST_F(PeriodicOrbitApi, AContinuationRunsAsAJobAndGivesABranch) {
  auto c = server->client();
  json s = impact_oscillator_orbit();
  s["periodic_orbit"]["continuation"] = {
      {"parameter", "model.pellets[0].Omega"}, {"to", 6.3}, {"max_points", 30}};
  auto res = post(c, s);
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 202) << res->body;
  const std::string location = res->get_header_value("Location");
  EXPECT_EQ(location, "/api/jobs/" + json::parse(res->body)["id"].get<std::string>());

  const json status = status_when_ended(c, location, 1200);
  ASSERT_FALSE(status.is_null());
  ASSERT_EQ(status["status"], "done") << status.dump();
  auto result = c.Get((location + "/result").c_str());
  ASSERT_EQ(result->status, 200) << result->body;
  const json r = json::parse(result->body);
  EXPECT_EQ(r["orbit"]["converged"], true);
  ASSERT_FALSE(r["branch"].empty()) << r["message"];
  EXPECT_EQ(r["branch"][0]["value"], 6.0);
  EXPECT_TRUE(r["bifurcations"].is_array());
  EXPECT_TRUE(r["reached"].is_boolean());
  // Drawn, its branch; no other format, and no plot parameters.
  auto png = c.Get((location + "/result?format=png").c_str());
  ASSERT_EQ(png->status, 200) << png->body;
  EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
  EXPECT_TRUE(png->body.starts_with("\x89PNG"));
  auto svg = c.Get((location + "/result?format=svg").c_str());
  ASSERT_EQ(svg->status, 200);
  EXPECT_NE(svg->body.find("stable periodic motion"), std::string::npos);
  auto csv = c.Get((location + "/result?format=csv").c_str());
  EXPECT_EQ(csv->status, 400);
  EXPECT_EQ(json::parse(csv->body)["field"], "format");
  auto plot = c.Get((location + "/result?plot=bifurcation").c_str());
  EXPECT_EQ(plot->status, 400);
  EXPECT_EQ(json::parse(plot->body)["field"], "plot");
}

// A followed bifurcation runs in the same job: its curve is in the result, and the image draws
// it in the plane of the two parameters.
TEST_F(PeriodicOrbitApi, AFollowedPeriodDoublingGivesItsCurve) {
  auto c = server->client();
  json s = impact_oscillator_orbit();
  s["periodic_orbit"]["continuation"] = {
      {"parameter", "model.pellets[0].Omega"},
      {"to", 5.0},
      {"max_points", 30},
      {"follow", "period_doubling"},
      {"parameter2", {{"parameter", "model.limiters[0].k"}, {"from", 0.7}, {"to", 0.9}}}};
  auto res = post(c, s);
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 202) << res->body;
  const std::string location = res->get_header_value("Location");
  const json status = status_when_ended(c, location, 1200);
  ASSERT_FALSE(status.is_null());
  ASSERT_EQ(status["status"], "done") << status.dump();
  auto result = c.Get((location + "/result").c_str());
  ASSERT_EQ(result->status, 200) << result->body;
  const json r = json::parse(result->body);
  ASSERT_EQ(r["curves"].size(), 1u) << r.dump();
  const json& curve = r["curves"][0];
  EXPECT_EQ(curve["kind"], "period_doubling");
  ASSERT_GE(curve["points"].size(), 3u) << curve["message"];
  EXPECT_EQ(curve["points"].front()["value2"], 0.7);
  EXPECT_EQ(curve["points"].back()["value2"], 0.9);
  auto svg = c.Get((location + "/result?format=svg").c_str());
  ASSERT_EQ(svg->status, 200);
  EXPECT_NE(svg->body.find("Bifurcation curves"), std::string::npos);
  EXPECT_NE(svg->body.find("period doubling"), std::string::npos);
  // Without parameter2 the follow is refused, naming the field.
  s["periodic_orbit"]["continuation"].erase("parameter2");
  res = post(c, s);
  ASSERT_EQ(res->status, 400) << res->body;
  EXPECT_EQ(json::parse(res->body)["field"], "periodic_orbit.continuation.parameter2");
}

// The curves are drawn over the scene's regime map of the same two parameters, as `vibro orbit`
// draws them (tests/app/cli_test.sh compares the bytes): the job runs the map after the branch,
// its runs counted in the progress; a sweep of other parameters is not run.
TEST_F(PeriodicOrbitApi, TheCurvesAreDrawnOverTheRegimeMapRunInTheJob) {
  auto c = server->client();
  auto res = post(c, curves_over_a_map(4, 3));
  ASSERT_EQ(res->status, 202) << res->body;
  EXPECT_EQ(json::parse(res->body)["progress"]["total"], 1000 + 12);
  const std::string location = res->get_header_value("Location");
  const json status = status_when_ended(c, location, 1200);
  ASSERT_EQ(status["status"], "done") << status.dump();
  EXPECT_EQ(status["progress"]["done"], 1012);
  auto svg = c.Get((location + "/result?format=svg").c_str());
  ASSERT_EQ(svg->status, 200) << svg->body;

  json other = curves_over_a_map(4, 3);
  other["sweep"]["parameter2"]["parameter"] = "model.pellets[0].F0";
  other["sweep"]["parameter2"]["from"] = 0.2;
  other["sweep"]["parameter2"]["to"] = 0.4;
  res = post(c, other);
  ASSERT_EQ(res->status, 202) << res->body;
  EXPECT_EQ(json::parse(res->body)["progress"]["total"], 1000);
  const std::string alone = res->get_header_value("Location");
  ASSERT_EQ(status_when_ended(c, alone, 1200)["status"], "done");
  auto bare = c.Get((alone + "/result?format=svg").c_str());
  ASSERT_EQ(bare->status, 200) << bare->body;
  // The map adds a cell per run (and its legend) to the same curves.
  EXPECT_GT(svg->body.size(), bare->body.size() + 1000);
}

}  // namespace
}  // namespace vibro::testing

namespace vibro::testing {
namespace {

// A map beneath the curves past the server's limits is refused up front, naming the field, as a
// sweep job is (server/sweep_limits.h).
TEST(PeriodicOrbitJobs, AMapBeneathTheCurvesIsBoundedAsASweepIs) {
  server::ServerConfig config;
  config.limits.sweep_points = 100;  // 12 runs × (record + 1) = 60 points pass; 40 × 25 × 5 not
  TestServer server(config);
  auto c = server.client();
  auto res = post(c, curves_over_a_map(40, 25));
  ASSERT_EQ(res->status, 400) << res->body;
  EXPECT_EQ(json::parse(res->body)["field"], "sweep.record");
  EXPECT_EQ(post(c, curves_over_a_map(4, 3))->status, 202);
}

// The map beneath the curves is cancelled with its job, between its runs.
TEST(PeriodicOrbitJobs, AMapBeneathTheCurvesIsCancelledWithItsJob) {
  TestServer server;
  auto c = server.client();
  json s = curves_over_a_map(60, 60);  // 3600 × 204 periods, within the limit of 10^6
  s["sweep"]["transient"] = 200;
  auto res = post(c, s);
  ASSERT_EQ(res->status, 202) << res->body;
  const std::string location = res->get_header_value("Location");
  json status;
  for (int k = 0; k < 1200; ++k) {  // until the map runs
    status = json::parse(c.Get(location.c_str())->body);
    const bool waits = status["status"] == "queued";
    if (!waits && (status["progress"]["done"] > 1000 || status["status"] != "running")) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_EQ(status["status"], "running") << status.dump();
  ASSERT_EQ(c.Delete(location.c_str())->status, 200);
  status = status_when_ended(c, location, 1200);
  EXPECT_EQ(status["status"], "cancelled") << status.dump();
  EXPECT_LT(status["progress"]["done"], 1000 + 60 * 60);
}

}  // namespace
}  // namespace vibro::testing

namespace vibro::testing {
namespace {

// A continuation answers to the job's wall-clock budget as a sweep does (a continuation of m
// toward 1e-300 was still running after 100 s): past it the job fails, naming the field.
TEST(PeriodicOrbitJobs, AContinuationIsBoundedByTheJobsWallClockBudget) {
  server::ServerConfig config;
  config.limits.sweep_seconds = 0.001;
  TestServer server(config);
  auto c = server.client();
  const std::string location = continuation_job(c);
  ASSERT_FALSE(location.empty());
  const json status = status_when_ended(c, location, 600);
  ASSERT_FALSE(status.is_null());
  ASSERT_EQ(status["status"], "failed") << status.dump();
  EXPECT_EQ(status["field"], "periodic_orbit.continuation.max_points") << status.dump();
}

// An orbit job's image is drawn on a worker, as every image is, and not on the connection's
// thread: while slow runs hold the one worker and its queue, asking for it is answered 503.
TEST(PeriodicOrbitJobs, AJobsImageIsDrawnOnAWorker) {
  server::ServerConfig config;
  config.workers = 1;
  config.queue = 1;
  config.limits.deadline_ms = 1500;  // each slow run holds the one worker this long
  TestServer server(config);
  auto c = server.client();
  const std::string location = continuation_job(c);
  ASSERT_FALSE(location.empty());
  const json status = status_when_ended(c, location, 1200);
  ASSERT_FALSE(status.is_null());
  ASSERT_EQ(status["status"], "done") << status.dump();

  // Two feeders keep the worker and its queue taken with slow runs for as long as the test
  // asks: a PNG request that slips in before them waits its turn (200) and is simply asked again.
  std::atomic<bool> stop{false};
  std::atomic<int> next_t_end{100};
  std::vector<std::thread> feeders;
  for (int k = 0; k < 2; ++k)
    feeders.emplace_back([&] {
      auto feeder = server.client();
      while (!stop)
        feeder.Get(
            ("/api/simulate?preset=high-frequency&t_end=" + std::to_string(next_t_end++)).c_str());
    });
  bool busy = false;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!busy && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
    auto png = c.Get((location + "/result?format=png").c_str());
    if (!png) break;  // failed below: no 503 seen
    busy = png->status == 503;
    if (!busy) EXPECT_EQ(png->status, 200) << png->body;
  }
  stop = true;
  for (std::thread& t : feeders) t.join();
  EXPECT_TRUE(busy) << "the image was drawn while the worker and its queue were taken";
}

}  // namespace
}  // namespace vibro::testing
