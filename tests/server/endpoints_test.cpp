// Every endpoint of API.md answers with the right status, content type and shape.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "io/presets.h"
#include "tests/server/test_server.h"

namespace vibro::testing {
namespace {

using nlohmann::json;

class Endpoints : public SharedServerTest {
 protected:
  // The JSON a GET answers, after checking it is a 200 of type application/json.
  static json get_json(const char* path) {
    auto res = server->client().Get(path);
    if (!res) return {};
    EXPECT_EQ(res->status, 200) << path << ": " << res->body;
    EXPECT_EQ(res->get_header_value("Content-Type"), "application/json") << path;
    return json::parse(res->body, nullptr, false);
  }
};

TEST_F(Endpoints, HealthSaysOkAndTheVersion) {
  const json body = get_json("/api/health");
  EXPECT_EQ(body["status"], "ok");
  EXPECT_TRUE(body["version"].is_string());
}

TEST_F(Endpoints, PresetsListThePaperSceneFirst) {
  const json list = get_json("/api/presets");
  ASSERT_TRUE(list.is_array());
  ASSERT_FALSE(list.empty());
  EXPECT_EQ(list[0]["name"], "paper");
  EXPECT_TRUE(list[0]["description"].is_string());
  EXPECT_TRUE(list[0]["scene"]["model"].is_object());
}

TEST_F(Endpoints, OnePresetIsItsScene) {
  const json scene = get_json("/api/presets/paper");
  EXPECT_EQ(scene["model"]["pellets"].size(), 2u);
}

TEST_F(Endpoints, LimitsAreShown) {
  const json limits = get_json("/api/limits");
  EXPECT_EQ(limits["t_end"], 1000.0);
  EXPECT_EQ(limits["body_bytes"], 65536);
}

TEST_F(Endpoints, PostSimulateGivesTheRun) {
  auto res = server->client().Post("/api/simulate", paper_scene(12.0), "application/json");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_EQ(res->get_header_value("Content-Type"), "application/json");
  const json run = json::parse(res->body);
  ASSERT_FALSE(run["events"].empty());
  EXPECT_EQ(run["events"][0]["kind"], "limiter");
  EXPECT_EQ(run["summary"]["final"].size(), 2u);
  EXPECT_EQ(run["stats"]["termination"], "completed");
  EXPECT_FALSE(run.contains("trajectories"));
  // API.md's trust fields, from the check against a run at a tighter tolerance.
  EXPECT_TRUE(run["stats"]["check"].get<bool>());
  EXPECT_DOUBLE_EQ(run["stats"]["trusted_until"].get<double>(), 12.0);
  EXPECT_GT(run["stats"]["event_time_error"].get<double>(), 0.0);
  EXPECT_GE(run["stats"]["state_error"].get<double>(), 0.0);
  EXPECT_TRUE(run["summary"]["ends_vibro_impact"].get<bool>());
}

TEST_F(Endpoints, TrajectoriesOnlyWhenAsked) {
  json scene = json::parse(paper_scene(2.0));
  scene["trajectories"] = true;
  auto res = server->client().Post("/api/simulate", scene.dump(), "application/json");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  const json run = json::parse(res->body);
  ASSERT_TRUE(run.contains("trajectories"));
  EXPECT_EQ(run["trajectories"].size(), 2u);
  EXPECT_FALSE(run["trajectories"][0]["branches"].empty());
}

// A trajectory at a uniform step (dt=): every pellet's state at t = 0, dt, 2 dt, ... to t_end,
// the first the scene's initial state; a dt that is no positive number, that would make more
// samples than the server keeps, or that is asked without what=trajectory is refused naming dt.
TEST_F(Endpoints, SimulateSamplesTheTrajectoryAtAUniformStepOnRequest) {
  auto res = server->client().Get(
      "/api/simulate?preset=paper&t_end=1&format=csv&what=trajectory&dt=0.125");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  std::istringstream rows(res->body);
  std::string line;
  std::getline(rows, line);
  EXPECT_EQ(line, "t,pellet,phi,dphi");
  std::vector<std::string> lines;
  while (std::getline(rows, line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), 2u * 9u);  // t = 0, 0.125, ..., 1 for both pellets
  for (std::size_t k = 0; k < lines.size(); ++k)
    EXPECT_EQ(std::stod(lines[k].substr(0, lines[k].find(','))), 0.125 * (k / 2)) << lines[k];
  const json scene = json::parse(*preset_json("paper"));
  EXPECT_EQ(
      lines[0], "0,0," + [&] {
        std::ostringstream s;
        s.precision(17);
        s << scene["model"]["pellets"][0]["phi0"].get<double>() << ','
          << scene["model"]["pellets"][0]["dphi0"].get<double>();
        return s.str();
      }());
  for (const char* bad : {"/api/simulate?preset=paper&format=csv&what=trajectory&dt=0",
                          "/api/simulate?preset=paper&format=csv&what=trajectory&dt=soon",
                          "/api/simulate?preset=paper&format=csv&what=trajectory&dt=1e-9",
                          "/api/simulate?preset=paper&format=csv&dt=0.1"}) {
    res = server->client().Get(bad);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << bad;
    EXPECT_EQ(json::parse(res->body)["field"], "dt") << bad << " " << res->body;
  }
}

// API.md "Exports": the events, or the sampled trajectory, as CSV: a row per event (the same
// times as the JSON's, to the bit) or per sample; bad choices named.
TEST_F(Endpoints, SimulateGivesEventsOrTheTrajectoryAsCsv) {
  auto run = server->client().Post("/api/simulate", paper_scene(3.0), "application/json");
  ASSERT_TRUE(run);
  const json events = json::parse(run->body)["events"];
  auto res =
      server->client().Post("/api/simulate?format=csv", paper_scene(3.0), "application/json");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_EQ(res->get_header_value("Content-Type"), "text/csv");
  std::istringstream rows(res->body);
  std::string line;
  std::getline(rows, line);
  EXPECT_EQ(line, "event,t,kind,pellet,limiter,phi,dphi_before,dphi_after");
  // One value per cell: a row per pellet of an event, the event's index first.
  std::size_t rows_read = 0, k = 0;
  for (; std::getline(rows, line); ++rows_read) {
    EXPECT_EQ(line.find(';'), std::string::npos) << line;
    std::vector<std::string> cells;
    for (std::istringstream split(line); std::getline(split, cells.emplace_back(), ',');) {
    }
    cells.pop_back();
    ASSERT_EQ(cells.size(), 8u) << line;
    k = std::stoul(cells[0]);
    ASSERT_LT(k, events.size());
    EXPECT_EQ(std::stod(cells[1]), events[k]["t"].get<double>());
    EXPECT_EQ(cells[2], events[k]["kind"].get<std::string>());
  }
  EXPECT_EQ(k + 1, events.size());
  EXPECT_GT(rows_read, events.size());  // the collisions take two rows
  // A collision's pellets on rows of their own, each with its speeds, no limiter (−1).
  EXPECT_NE(res->body.find(",collision,1,-1,"), std::string::npos);
  EXPECT_NE(res->body.find(",collision,0,-1,"), std::string::npos);

  res = server->client().Get("/api/simulate?preset=paper&t_end=1&format=csv&what=trajectory");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_TRUE(res->body.starts_with("t,pellet,branch,phi,dphi\n"));
  EXPECT_GT(std::count(res->body.begin(), res->body.end(), '\n'), 100);
  EXPECT_NE(res->body.find("\n0,1,1,"), std::string::npos);  // pellet 1 (index) from t = 0

  for (const char* bad :
       {"/api/simulate?preset=paper&format=xml", "/api/simulate?preset=paper&what=events",
        "/api/simulate?preset=paper&format=csv&what=branches"}) {
    res = server->client().Get(bad);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << bad;
    const std::string field = json::parse(res->body)["field"];
    EXPECT_EQ(field, std::string(bad).find("what") != std::string::npos ? "what" : "format") << bad;
  }
}

TEST_F(Endpoints, GetSimulateReadsAPresetWithOverrides) {
  auto res = server->client().Get("/api/simulate?preset=paper&t_end=3&method=dopri5");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  const json run = json::parse(res->body);
  EXPECT_DOUBLE_EQ(run["stats"]["t_reached"].get<double>(), 3.0);
  EXPECT_EQ(run["stats"]["method"], "dopri5");
  auto unchecked = server->client().Get("/api/simulate?preset=paper&t_end=3&check=false");
  ASSERT_TRUE(unchecked);
  ASSERT_EQ(unchecked->status, 200) << unchecked->body;
  EXPECT_FALSE(json::parse(unchecked->body)["stats"]["check"].get<bool>());
}

TEST_F(Endpoints, PostRenderDrawsPngAndSvg) {
  auto png = server->client().Post("/api/render?format=png", paper_scene(5.0), "application/json");
  ASSERT_TRUE(png);
  ASSERT_EQ(png->status, 200) << png->body;
  EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(png_size(png->body), std::make_pair(400, 300));

  auto svg = server->client().Post("/api/render?format=svg", paper_scene(5.0), "application/json");
  ASSERT_TRUE(svg);
  ASSERT_EQ(svg->status, 200) << svg->body;
  EXPECT_EQ(svg->get_header_value("Content-Type"), "image/svg+xml");
  EXPECT_NE(svg->body.find("<svg"), std::string::npos);

  auto pdf = server->client().Post("/api/render?format=pdf", paper_scene(5.0), "application/json");
  ASSERT_TRUE(pdf);
  ASSERT_EQ(pdf->status, 200) << pdf->body;
  EXPECT_EQ(pdf->get_header_value("Content-Type"), "application/pdf");
  EXPECT_TRUE(pdf->body.starts_with("%PDF-"));
}

TEST_F(Endpoints, GetRenderOfThePaperPresetIsAPng) {
  auto res = server->client().Get("/api/render?preset=paper&format=png");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_EQ(res->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(png_size(res->body), std::make_pair(1200, 800));
}

TEST_F(Endpoints, GetRenderOverridesSizeAndPellet) {
  auto res = server->client().Get("/api/render?preset=paper&format=png&width=400&height=320");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_EQ(png_size(res->body), std::make_pair(400, 320));

  auto one = server->client().Get("/api/render?preset=paper-fig5&width=400&pellet=0&t_end=4");
  auto two = server->client().Get("/api/render?preset=paper-fig5&width=400&pellet=1&t_end=4");
  ASSERT_TRUE(one && two);
  ASSERT_EQ(one->status, 200) << one->body;
  ASSERT_EQ(two->status, 200) << two->body;
  EXPECT_NE(one->body, two->body);
}

TEST_F(Endpoints, GetRenderTakesAPrintSize) {
  // 85 mm × 60 mm at 150 dpi: 502 × 354 px; a PDF page of 240.9 × 170.1 pt.
  auto png = server->client().Get("/api/render?preset=paper&width_mm=85&height_mm=60&dpi=150");
  ASSERT_TRUE(png);
  ASSERT_EQ(png->status, 200) << png->body;
  EXPECT_EQ(png_size(png->body), std::make_pair(502, 354));
  auto pdf = server->client().Get("/api/render?preset=paper&format=pdf&width_mm=85&font_pt=7");
  ASSERT_TRUE(pdf);
  ASSERT_EQ(pdf->status, 200) << pdf->body;
  EXPECT_NE(pdf->body.find("/MediaBox [ 0 0 240.96 160.56 ]"), std::string::npos);
  // A bad value names its field of the scene's "figure"; a number that is not one, the parameter.
  auto big = server->client().Get("/api/render?preset=paper&width_mm=170&dpi=2000");
  ASSERT_TRUE(big);
  EXPECT_EQ(big->status, 400);
  EXPECT_EQ(json::parse(big->body, nullptr, false).value("field", ""), "figure.dpi");
  auto nan = server->client().Get("/api/render?preset=paper&width_mm=wide");
  ASSERT_TRUE(nan);
  EXPECT_EQ(nan->status, 400);
  EXPECT_EQ(json::parse(nan->body, nullptr, false).value("field", ""), "width_mm");
}

TEST_F(Endpoints, HeadAnswersWithoutABody) {
  auto res = server->client().Head("/api/render?preset=paper&width=400&height=300");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_EQ(res->get_header_value("Content-Type"), "image/png");
  EXPECT_TRUE(res->body.empty());
}

}  // namespace
}  // namespace vibro::testing

namespace vibro::testing {
namespace {

TEST_F(Endpoints, WorkPrecisionGivesTheTableOrTheDiagramUncached) {
  auto table = server->client().Post("/api/work-precision", paper_scene(2.0), "application/json");
  ASSERT_TRUE(table);
  ASSERT_EQ(table->status, 200) << table->body;
  EXPECT_EQ(table->get_header_value("Content-Type"), "application/json");
  EXPECT_EQ(table->get_header_value("Cache-Control"), "no-store");
  const json body = json::parse(table->body);
  EXPECT_EQ(body["error_reference"], "reference_run");
  ASSERT_EQ(body["points"].size(), 50u);  // 5 methods × 10 tolerances
  for (const json& p : body["points"]) EXPECT_TRUE(p["error"].is_number());

  auto svg =
      server->client().Post("/api/work-precision?format=svg", paper_scene(2.0), "application/json");
  ASSERT_TRUE(svg);
  ASSERT_EQ(svg->status, 200);
  EXPECT_EQ(svg->get_header_value("Content-Type"), "image/svg+xml");
  EXPECT_NE(svg->body.find("<svg"), std::string::npos);

  auto bad =
      server->client().Post("/api/work-precision?format=gif", paper_scene(2.0), "application/json");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  EXPECT_EQ(json::parse(bad->body)["field"], "format");
}

}  // namespace
}  // namespace vibro::testing
