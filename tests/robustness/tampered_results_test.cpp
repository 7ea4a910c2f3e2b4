// `vibro plot` on saved results someone has edited (docs/ROBUSTNESS.md, "Saved results"): a
// basin sweep, a 1-D sweep and a continued branch as vibro writes them, each value in turn
// replaced by a hostile one (wrong type, negative, huge, past an int, an ulp-sized range) or
// removed, and each array emptied or grown. Each document is either refused naming a field, or
// read and drawn by every plot it can be drawn as, without a crash (ASan in CI), an exception or
// a hang. Deterministic; under the sanitizers a quarter of the documents are drawn.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/analysis/periodic_orbit.h"
#include "core/analysis/sweep.h"
#include "io/orbit_json.h"
#include "io/saved_results.h"
#include "io/scene_json.h"
#include "io/sweep_json.h"
#include "render/orbit_figure.h"
#include "tests/sanitizers.h"

namespace vibro {
namespace {

using nlohmann::json;

constexpr int kDrawEvery = vibro::testing::kUnderAsan ? 4 : 1;

// The values a leaf is replaced by.
std::vector<json> hostile_values() {
  return {json(nullptr), json(true),         json("x"),           json(-1),
          json(0),       json(2147483648LL), json(-2147483649LL), json(1e308),
          json(-1e308),  json(5e-324),       json::array(),       json::object()};
}

// Whether each array index on the way to the leaf (a JSON pointer, "/points/t/3") is its array's
// first or last: the other elements are read by the same code. The writers' keys hold no '/'.
bool at_an_end(const json& doc, const std::string& leaf) {
  const json* here = &doc;
  for (std::size_t at = 1, end; at <= leaf.size(); at = end + 1) {
    end = std::min(leaf.find('/', at), leaf.size());
    const std::string step = leaf.substr(at, end - at);
    if (here->is_array()) {
      const std::size_t k = std::stoul(step);
      if (k != 0 && k + 1 != here->size()) return false;
      here = &(*here)[k];
    } else {
      here = &(*here)[step];
    }
  }
  return true;
}

// Every variant of `doc`: each leaf (of the first and last element of each array) replaced by
// each hostile value or removed.
void each_variant(const json& doc, const std::function<void(const json&, const std::string&)>& f) {
  const json flat = doc.flatten();
  for (const auto& [pointer, value] : flat.items()) {
    const std::string where = pointer;
    const json::json_pointer p(pointer);
    if (!at_an_end(doc, pointer)) continue;
    for (const json& v : hostile_values()) {
      json changed = doc;
      changed[p] = v;
      f(changed, where + " = " + v.dump());
    }
    json removed = doc;
    removed[p.parent_pointer()].is_object()
        ? void(removed[p.parent_pointer()].erase(p.back()))
        : void(removed[p.parent_pointer()].erase(std::stoul(p.back())));
    f(removed, where + " removed");
  }
}

// A document's arrays, each emptied and each grown (a column longer than the others).
void each_array_change(const json& doc,
                       const std::function<void(const json&, const std::string&)>& f,
                       const json::json_pointer& at = json::json_pointer()) {
  const json& here = doc[at];
  if (here.is_array() && !here.empty()) {
    json emptied = doc;
    emptied[at] = json::array();
    f(emptied, at.to_string() + " emptied");
    json grown = doc;
    grown[at].push_back(here.back());
    f(grown, at.to_string() + " grown");
  }
  if (here.is_object())
    for (const auto& [key, value] : here.items()) each_array_change(doc, f, at / key);
}

Scene scene_of(const json& scene_json) {
  SceneOrError read = scene_from_json(scene_json);
  if (auto* e = std::get_if<FieldError>(&read)) ADD_FAILURE() << e->field << " " << e->message;
  return std::get<Scene>(std::move(read));
}

json basin_scene() {
  return {{"model",
           {{"R", 0.5},
            {"pellets", {{{"m", 0.1}, {"phi0", 0.1}, {"F0", 0.3}, {"Omega", 6.8}}}},
            {"limiters", {{{"angle", 0.0}, {"k", 0.8}}}}}},
          {"t_end", 20.0},
          {"width", 240},
          {"height", 160},
          {"sweep",
           {{"parameter", "model.pellets[0].phi0"},
            {"from", 0.01},
            {"to", 1.6},
            {"count", 3},
            {"parameter2",
             {{"parameter", "model.pellets[0].dphi0"}, {"from", -8.0}, {"to", 8.0}, {"count", 2}}},
            {"transient", 100},
            {"record", 4},
            {"continuation", "none"},
            {"classify", "attractor"}}}};
}

json line_scene() {
  json scene = basin_scene();
  scene["sweep"] = {{"parameter", "model.pellets[0].Omega"},
                    {"from", 5.0},
                    {"to", 7.0},
                    {"count", 3},
                    {"transient", 20},
                    {"record", 4},
                    {"section", "impact"},
                    {"lyapunov", true}};
  return scene;
}

// The saved sweep as `vibro sweep -o R.json` writes it (with its scene).
json saved_sweep(const Scene& scene, const json& scene_json) {
  const SweepResult result = run_sweep(scene.model, scene.sim, *scene.sweep, SweepControl{});
  return sweep_result_json(*scene.sweep, result, scene_json);
}

// Counts what happened to the variants of one document, checking each outcome on the way.
struct Tally {
  long documents = 0, refused = 0, drawn = 0, not_drawn = 0;

  // A read's outcome: true (and counted) when it was refused, which must name a field.
  template <class Read>
  bool refuses(const Read& read, const std::string& what) {
    ++documents;
    const auto* e = std::get_if<FieldError>(&read);
    if (!e) return false;
    EXPECT_FALSE(e->field.empty()) << what;
    ++refused;
    return true;
  }
  // A drawing: an image with bytes, or an error naming a field.
  void add(const RenderResult& r, const std::string& what) {
    if (r.ok()) {
      EXPECT_FALSE(r.bytes.empty()) << what;
      ++drawn;
    } else {
      EXPECT_FALSE(r.error->field.empty()) << what;
      ++not_drawn;
    }
  }
  ~Tally() {
    std::cout << "[ tampered ] " << documents << " documents: " << refused << " refused, " << drawn
              << " drawn, " << not_drawn << " not drawn\n";
  }
};

// Reads the variant as `vibro plot` does and draws it as every plot of `views`.
void plot_sweep(const Scene& scene, const json& doc, const std::string& what,
                const std::vector<SweepView>& views, Tally& tally) {
  const auto read = read_sweep_result(doc);
  if (tally.refuses(read, what) || tally.documents % kDrawEvery != 0) return;
  for (SweepView view : views) {
    if (view == SweepView::basins && !std::get<SweepResult>(read).classified) continue;
    FigureSpec figure = scene.figure;
    figure.plots = {SweepPlot{view}};
    tally.add(render_figure(figure, scene.model, RunResult{}, ImageFormat::png,
                            {nullptr, SweepData{*scene.sweep, std::get<SweepResult>(read)}}),
              what);
  }
}

void tamper_with_sweep(const json& scene_json, const std::vector<SweepView>& views) {
  const Scene scene = scene_of(scene_json);
  const json saved = saved_sweep(scene, scene_json);
  json without_scene = saved;
  without_scene.erase("scene");  // the scene is read (and fuzzed) as any scene is
  Tally tally;
  const auto plot = [&](const json& doc, const std::string& what) {
    plot_sweep(scene, doc, what, views, tally);
  };
  each_variant(without_scene, plot);
  each_array_change(without_scene, plot);
}

TEST(TamperedResults, ABasinSweepIsRefusedOrDrawn) {
  tamper_with_sweep(basin_scene(), {SweepView::basins, SweepView::regime_map});
}

TEST(TamperedResults, ALineSweepIsRefusedOrDrawn) {
  tamper_with_sweep(line_scene(), {SweepView::bifurcation, SweepView::section,
                                   SweepView::impact_map, SweepView::lyapunov});
}

// A continued branch as `vibro orbit -o R.json` writes it: stable and unstable points, complex
// multipliers, a period doubling and a grazing.
json saved_branch() {
  OrbitResult sent;
  for (int k = 0; k < 4; ++k)
    sent.branch.points.push_back({5.0 + 0.1 * k,
                                  {{0.25 + 0.01 * k, -1.0 / 3.0}},
                                  {{0.5, 0.25 * k}, {-1.25, -0.25 * k}},
                                  k != 2,
                                  2.0});
  sent.branch.bifurcations.push_back(
      {BifurcationKind::period_doubling, 5.15, {{0.25, -0.5}}, std::nullopt, {}});
  sent.branch.bifurcations.push_back(
      {BifurcationKind::grazing, 5.25, {{0.27, -0.4}}, std::nullopt, {}});
  sent.branch.message = "a fold ahead";
  return orbit_result_json(sent);
}

TEST(TamperedResults, AContinuedBranchIsRefusedOrDrawn) {
  json scene_json = basin_scene();
  scene_json.erase("sweep");
  scene_json["periodic_orbit"] = {
      {"continuation", {{"parameter", "model.pellets[0].Omega"}, {"to", 5.3}}}};
  const Scene scene = scene_of(scene_json);
  const ContinuationSpec& continuation = *scene.periodic_orbit->continuation;
  Tally tally;
  const auto plot = [&](const json& doc, const std::string& what) {
    const auto read = read_orbit_branch(doc, multiplier_band(scene.sim));
    if (tally.refuses(read, what)) return;
    const OrbitBranch& branch = std::get<OrbitBranch>(read);
    const OrbitFigure figure{&branch, &continuation};
    if (!draws_branch(figure)) return;
    tally.add(render_branch_figure(scene.figure, scene.model, figure, ImageFormat::png), what);
  };
  const json saved = saved_branch();
  each_variant(saved, plot);
  each_array_change(saved, plot);
}

}  // namespace
}  // namespace vibro
