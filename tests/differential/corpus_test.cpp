// Every scene of corpus/ (shrunk counterexamples found by the differential tests, one JSON
// scene each, its "description" saying what failed) runs under every method at rtol 1e-11 and
// 1e-12: all must list the same events at close times (checks.h, methods_disagree), and every
// run must keep the physics (physics_fails), as must the run of the scene's own solver settings. A
// scene whose file name starts with "ill-conditioned-" has events that legitimately depend on
// differences below the tolerance: there the methods must agree only before the engine's trust
// horizon (stats.trusted_until). One whose name starts with "physics-only-" has its sequence
// change within the trust check's blind spot (a grazing impact decided alike by a run and its
// same-method shadow, docs/ACCURACY.md): only its physics is checked. The presets (presets/) run
// the same way, before their trust horizon (the grazing preset is ill-conditioned by design; the
// others are trusted to the end).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/scene_json.h"
#include "tests/differential/checks.h"

namespace vibro::differential {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> corpus_files() {
  std::vector<fs::path> files;
  for (const char* dir : {VIBRO_DIFFERENTIAL_CORPUS, VIBRO_PRESETS})
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

class Corpus : public ::testing::TestWithParam<fs::path> {};

TEST_P(Corpus, MethodsAgreeAndKeepThePhysics) {
  std::ifstream in(GetParam());
  std::stringstream text;
  text << in.rdbuf();
  const SceneOrError read = scene_from_text(text.str());
  ASSERT_TRUE(std::holds_alternative<Scene>(read))
      << std::get<FieldError>(read).field << ": " << std::get<FieldError>(read).message;
  const Scene& scene = std::get<Scene>(read);
  const std::string name = GetParam().filename().string();
  const bool ill =
      name.starts_with("ill-conditioned-") || GetParam().parent_path() == fs::path(VIBRO_PRESETS);
  const bool physics_only = name.starts_with("physics-only-");
  SceneRuns runs({scene.model, scene.sim.t_end}, ill, /*bounded=*/false);
  for (double rtol : {1e-11, 1e-12}) {
    ASSERT_FALSE(incomplete(runs, rtol)) << "a run stopped at its bounds on work";
    if (auto f = physics_only ? std::nullopt : methods_disagree(runs, rtol))
      ADD_FAILURE() << describe(*f) << "\n(" << scene.description << ")";
    for (Method m : kMethods)
      if (auto f = physics_fails(runs, m, rtol)) ADD_FAILURE() << describe(*f);
  }
  // And at the scene's own solver settings, where a physics counterexample was found.
  if (!stopped_by_budget(runs.run(scene.sim.method, scene.sim.rtol)))
    if (auto f = physics_fails(runs, scene.sim.method, scene.sim.rtol))
      ADD_FAILURE() << describe(*f);
}

// Test names from the file names: "grazing-limiter.json" -> "grazing_limiter".
std::string test_name(const ::testing::TestParamInfo<fs::path>& info) {
  std::string name = info.param.stem().string();
  if (info.param.parent_path() == fs::path(VIBRO_PRESETS)) name = "preset_" + name;
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, Corpus, ::testing::ValuesIn(corpus_files()), test_name);

}  // namespace
}  // namespace vibro::differential
