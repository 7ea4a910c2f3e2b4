// The scene a command runs and what its command line changes in it, shared by simulate, render,
// work-precision, sweep and orbit: SCENE.json, - for stdin, or --preset NAME; --t-end, --method,
// --rtol, --atol, --deadline-ms, --no-check, --trajectories.
#pragma once

#include <CLI/CLI.hpp>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/scene.h"
#include "render/figure.h"

namespace vibro {

struct SceneSource {
  std::string file;                                     // a path, or "-" for stdin
  std::string preset;                                   // a preset's name
  nlohmann::json overrides = nlohmann::json::object();  // merged into the scene's JSON
  double deadline_ms = 0.0;                             // 0: the scene's own
};

// What every scene command takes: its scene, and the files it writes, one per -o in the order
// given (none when -o is not given): one run writes them all.
struct SceneOutput {
  SceneSource scene;
  std::vector<std::string> outs;
};

// Adds the subcommand `name` with the SCENE positional, the options above and -o,--output OUT,
// which may be repeated (`output_help` says what it writes), bound to `job` (which must outlive
// the parse).
CLI::App* add_scene_command(CLI::App& vibro, const std::string& name,
                            const std::string& description, const std::string& output_help,
                            SceneOutput& job);

// Reads and checks the scene with its overrides. On failure prints the error (naming the field:
// "scene", "preset", or the scene's own, such as "t_end") and returns nothing.
std::optional<Scene> load_scene(const SceneSource& source);

// Whether every output's name ends in one of `endings` (".json", ".png", ...); else prints
// {"field": "-o", "error": "name the output " + `names`} and returns false.
bool outputs_named(const std::vector<std::string>& outs, std::initializer_list<const char*> endings,
                   const std::string& names);

// Writes `bytes` whole to `out` (io/whole_file.h); false after printing why (field "-o").
bool write_output(const std::string& out, std::string_view bytes);

// The image's bytes; empty after printing why it could not be drawn (the field at fault).
std::optional<std::string> drawn_bytes(const RenderResult& image);

}  // namespace vibro
