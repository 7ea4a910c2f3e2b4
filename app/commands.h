// The `vibro` subcommands. Each takes its arguments (after the subcommand's name) and returns
// the process exit code: 0 success, 1 failure, 2 bad usage or bad scene.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/scene.h"

namespace vibro {

using Args = std::vector<std::string>;

struct Command {
  std::string name;
  std::string usage;
  std::function<int(const Args&)> run;
};

const std::vector<Command>& commands();

// Reads the scene a command names: a file, "-" for stdin, or "--preset NAME"; with common
// overrides (--t-end, --method, --rtol, --atol, --deadline-ms, --trajectories). On failure
// prints the error (naming the field) as JSON to stderr and returns nothing.
std::optional<Scene> load_scene(const Args& args, std::size_t& next);

// An error as every command reports it: {"error", "field"} as JSON on stderr.
void print_error(const std::string& field, const std::string& message);

// The scene and output file of a command whose only option is `-o OUT` (or --output): out is ""
// when it is not given. Nothing, the error printed, for a bad scene or another option.
struct SceneAndOutput {
  Scene scene;
  std::string out;
};
std::optional<SceneAndOutput> scene_and_output(const Args& args, const std::string& command);

int simulate_command(const Args& args);
int presets_command(const Args& args);
int preset_command(const Args& args);
int render_command(const Args& args);
int serve_command(const Args& args);
int work_precision_command(const Args& args);
int sweep_command(const Args& args);
int orbit_command(const Args& args);

}  // namespace vibro
