// A sweep's "lyapunov" field read strictly and written back, and the exponents in the result's
// JSON (null where there is none or it is −infinity: JSON has no infinities) and CSV (an empty
// cell, "-inf", or the value to the bit), after the columns that were there before.
#include "io/sweep_json.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>

#include "io/presets.h"
#include "io/scene_json.h"

namespace vibro {
namespace {

using nlohmann::json;

// The impact-oscillator preset with its sweep's "lyapunov" set to `value` (absent: not set).
std::variant<Scene, FieldError> with_lyapunov(const std::optional<json>& value) {
  json scene = json::parse(*preset_json("impact-oscillator"));
  if (value) scene["sweep"]["lyapunov"] = *value;
  return scene_from_text(scene.dump());
}

TEST(SweepJson, LyapunovIsReadStrictlyAndWrittenBack) {
  EXPECT_FALSE(std::get<Scene>(with_lyapunov(std::nullopt)).sweep->lyapunov);
  EXPECT_FALSE(std::get<Scene>(with_lyapunov(false)).sweep->lyapunov);
  const Scene asked = std::get<Scene>(with_lyapunov(true));
  ASSERT_TRUE(asked.sweep->lyapunov);
  EXPECT_EQ(sweep_to_json(*asked.sweep)["lyapunov"], true);
  const Scene again = std::get<Scene>(scene_from_text(scene_to_json(asked).dump()));
  EXPECT_TRUE(again.sweep->lyapunov);
  for (const json& wrong : {json(1), json("true"), json::array()}) {
    const auto read = with_lyapunov(wrong);
    ASSERT_TRUE(std::holds_alternative<FieldError>(read)) << wrong;
    EXPECT_EQ(std::get<FieldError>(read).field, "sweep.lyapunov");
  }
}

// Three runs of one point each: an exponent that is no short decimal, none, and −infinity.
SweepResult three_runs() {
  SweepResult result;
  for (int k = 0; k < 3; ++k) {
    SweepRun run;
    run.value = k;
    run.points = {{0, 1.0, 0.5, -0.25, 0.0, -1, true}};
    result.runs.push_back(run);
  }
  result.runs[0].lyapunov = 0.1 + 1.0 / 3.0;
  result.runs[2].lyapunov = -std::numeric_limits<double>::infinity();
  return result;
}

TEST(SweepJson, TheResultsRunsCarryTheExponentOrNull) {
  SweepSpec spec;
  spec.lyapunov = true;
  const json j = sweep_result_json(spec, three_runs());
  const json& column = j["runs"]["lyapunov"];
  ASSERT_EQ(column.size(), 3u);
  EXPECT_EQ(column[0].get<double>(), 0.1 + 1.0 / 3.0);
  EXPECT_TRUE(column[1].is_null());
  EXPECT_TRUE(column[2].is_null());
  // What a client parses back is the same number, and never an infinity or NaN.
  const std::string text = j.dump();
  EXPECT_EQ(json::parse(text)["runs"]["lyapunov"][0].get<double>(), 0.1 + 1.0 / 3.0);
  EXPECT_EQ(text.find("inf"), std::string::npos);
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_EQ(j["runs"]["error_estimate"].size(), 3u);  // the columns before it are all there
}

TEST(SweepJson, TheCsvEndsWithTheExponentEmptyOrMinusInf) {
  SweepSpec spec;
  spec.axis.parameter = "model.pellets[0].F0";
  std::istringstream csv(sweep_result_csv(spec, three_runs()));
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "model.pellets[0].F0,value2,start,direction,pellet,t,phi,dphi,phase,limiter,trusted,"
            "period,impacts_per_period,lyapunov");
  std::vector<std::string> last_cells;
  while (std::getline(csv, line)) last_cells.push_back(line.substr(line.rfind(',') + 1));
  ASSERT_EQ(last_cells.size(), 3u);
  const double back = std::strtod(last_cells[0].c_str(), nullptr);
  const double sent = 0.1 + 1.0 / 3.0;
  EXPECT_EQ(std::memcmp(&back, &sent, sizeof back), 0) << last_cells[0];
  EXPECT_EQ(last_cells[1], "");
  EXPECT_EQ(last_cells[2], "-inf");
  EXPECT_EQ(std::strtod(last_cells[2].c_str(), nullptr), -std::numeric_limits<double>::infinity());
}

// The header names what was swept, by the parameters' field paths: a CSV read alone says what its
// first two columns are (they were "value" and "value2", whatever the sweep).
TEST(SweepJson, TheCsvHeaderNamesTheSweptParameters) {
  SweepSpec spec;
  spec.axis.parameter = "model.forcing.omega";
  spec.axis2 = SweepAxis{"model.pellets[0].F0", 0.0, 1.0, 2};
  const std::string csv = sweep_result_csv(spec, three_runs());
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "model.forcing.omega,model.pellets[0].F0,start,direction,pellet,t,phi,dphi,phase,"
            "limiter,trusted,period,impacts_per_period,lyapunov");
  spec.axis.parameter = "odd,\"name\"";  // quoted as CSV, so the header stays 14 cells
  EXPECT_EQ(sweep_csv_header(spec).substr(0, 15), "\"odd,\"\"name\"\"\",");
}

// Many points, with numbers JSON cannot hold among them.
SweepResult many_points(int runs, int points) {
  SweepResult result;
  for (int k = 0; k < runs; ++k) {
    SweepRun run;
    run.value = 0.1 * k;
    run.message = k == 1 ? "stopped at t = 1 s: \"quoted\"" : "";
    for (int i = 0; i < points; ++i)
      run.points.push_back(
          {i % 3, i * 0.1, 1.0 / (i + 1), i == 7 ? NAN : -0.5 * i, 1e-300 * i, i % 2, i % 5 != 0});
    result.runs.push_back(std::move(run));
  }
  return result;
}

// The result goes out in pieces of some 64 KiB, never as one document: together they are the
// document, every number reads back to the bit (NaN as null), and a reader that goes away stops
// the writing at once.
TEST(SweepJson, TheResultIsWrittenInPiecesAndStopsWhenTheReaderGoesAway) {
  const SweepResult result = many_points(4, 8000);
  SweepSpec spec;
  spec.axis.parameter = "model.pellets[0].F0";
  std::vector<std::size_t> sizes;
  std::string text;
  ASSERT_TRUE(write_sweep_result_json(spec, result, [&](std::string_view piece) {
    sizes.push_back(piece.size());
    text += piece;
    return true;
  }));
  ASSERT_GT(sizes.size(), 10u);
  for (std::size_t n : sizes) EXPECT_LE(n, 70u * 1024u);
  const json j = json::parse(text);
  EXPECT_EQ(j, sweep_result_json(spec, result));
  const std::vector<std::string> point_keys = {"direction", "dphi",    "limiter", "pellet",
                                               "phase",     "phi",     "run",     "start",
                                               "t",         "trusted", "value",   "value2"};
  for (const std::string& key : point_keys) EXPECT_EQ(j["points"][key].size(), 32000u) << key;
  EXPECT_EQ(j["points"].size(), point_keys.size());
  EXPECT_EQ(j["runs"].size(), 14u);
  EXPECT_EQ(j["stats"]["points"], 32000);
  EXPECT_EQ(j["runs"]["message"][1], "stopped at t = 1 s: \"quoted\"");
  for (int i : {0, 3, 7, 7999}) {
    const SectionPoint& p = result.runs[2].points[i];
    const std::size_t at = 16000 + i;
    EXPECT_EQ(j["points"]["phi"][at].get<double>(), p.phi);
    EXPECT_EQ(j["points"]["phase"][at].get<double>(), p.phase);
    EXPECT_EQ(j["points"]["pellet"][at], p.pellet);
    EXPECT_EQ(j["points"]["limiter"][at], p.limiter);
    EXPECT_EQ(j["points"]["trusted"][at], p.trusted);
    EXPECT_EQ(j["points"]["run"][at], 2);
    EXPECT_EQ(j["points"]["value"][at].get<double>(), 0.2);
  }
  EXPECT_TRUE(j["points"]["dphi"][16007].is_null());
  EXPECT_TRUE(j["points"]["value"][0].is_number_float());  // 0.0 stays a double

  int calls = 0;
  EXPECT_FALSE(write_sweep_result_json(spec, result,
                                       [&](std::string_view) { return ++calls > 1 && false; }));
  EXPECT_EQ(calls, 1);
  calls = 0;
  std::string csv;
  ASSERT_TRUE(write_sweep_result_csv(spec, result, [&](std::string_view piece) {
    ++calls;
    csv += piece;
    return true;
  }));
  EXPECT_GT(calls, 10);
  EXPECT_EQ(csv, sweep_result_csv(spec, result));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 32000);
  calls = 0;
  EXPECT_FALSE(
      write_sweep_result_csv(spec, result, [&](std::string_view) { return ++calls > 1 && false; }));
  EXPECT_EQ(calls, 1);
}

TEST(SweepJson, TheLyapunovPlotsHaveNames) {
  const SweepSpec spec;
  EXPECT_EQ(sweep_plot_kind("lyapunov", spec), SweepView::lyapunov);
  EXPECT_EQ(sweep_plot_kind("lyapunov_map", spec), SweepView::lyapunov_map);
  EXPECT_EQ(sweep_plot_kind("lyapunov map", spec), std::nullopt);
  EXPECT_NE(std::string(kSweepPlotNames).find("\"lyapunov_map\""), std::string::npos);
}

}  // namespace
}  // namespace vibro
