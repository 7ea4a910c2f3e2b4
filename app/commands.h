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

int simulate_command(const Args& args);
int presets_command(const Args& args);
int preset_command(const Args& args);
int render_command(const Args& args);
int serve_command(const Args& args);
int work_precision_command(const Args& args);
int sweep_command(const Args& args);

}  // namespace vibro
