// The scene a command runs and what its command line changes in it, shared by simulate, render,
// work-precision, sweep and orbit: SCENE.json, - for stdin, or --preset NAME; --t-end, --method,
// --rtol, --atol, --deadline-ms, --no-check, --trajectories.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "io/scene.h"

namespace vibro {

struct SceneSource {
  std::string file;                                     // a path, or "-" for stdin
  std::string preset;                                   // a preset's name
  nlohmann::json overrides = nlohmann::json::object();  // merged into the scene's JSON
  double deadline_ms = 0.0;                             // 0: the scene's own
};

// What every scene command takes: its scene, and the file it writes ("" when -o is not given).
struct SceneOutput {
  SceneSource scene;
  std::string out;
};

// Adds the subcommand `name` with the SCENE positional, the options above and -o,--output OUT
// (`output_help` says what it writes), bound to `job` (which must outlive the parse).
CLI::App* add_scene_command(CLI::App& vibro, const std::string& name,
                            const std::string& description, const std::string& output_help,
                            SceneOutput& job);

// Reads and checks the scene with its overrides. On failure prints the error (naming the field:
// "scene", "preset", or the scene's own, such as "t_end") and returns nothing.
std::optional<Scene> load_scene(const SceneSource& source);

}  // namespace vibro
