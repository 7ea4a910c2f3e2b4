// The `vibro` subcommands. Each add_* declares its subcommand on the program's CLI::App (its
// description, options and their help) and returns it with what runs it once the command line
// is parsed. A run returns the process exit code: 0 success, 1 failure, 2 bad usage or bad scene
// (reported as app/usage.h says).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace vibro {

struct Command {
  CLI::App* app;  // the subcommand, owned by the program's CLI::App
  // Runs it with the options the parse stored (held by the closure, bound by the add_* call).
  std::function<int()> run;
};

Command add_simulate_command(CLI::App& vibro);
Command add_render_command(CLI::App& vibro);
Command add_work_precision_command(CLI::App& vibro);
Command add_sweep_command(CLI::App& vibro);
Command add_orbit_command(CLI::App& vibro);
Command add_plot_command(CLI::App& vibro);
Command add_serve_command(CLI::App& vibro);
Command add_presets_command(CLI::App& vibro);
Command add_preset_command(CLI::App& vibro);

}  // namespace vibro
