// vibro: phase portraits of vibro-impact dynamics. `vibro help` lists the subcommands.
#include <iostream>

#include "app/commands.h"

namespace vibro {

const std::vector<Command>& commands() {
  static const std::vector<Command> list = {
      {"simulate", "vibro simulate SCENE.json | - | --preset NAME [--t-end S] [--method M] "
                   "[--rtol X] [--atol X] [--deadline-ms MS] [--no-check] [--trajectories] [-o OUT.json|OUT.csv] [--what events|trajectory]",
       simulate_command},
      {"render", "vibro render SCENE.json | - | --preset NAME -o OUT.png|OUT.svg [overrides]",
       render_command},
      {"work-precision",
       "vibro work-precision SCENE.json | - | --preset NAME [-o OUT.png|OUT.svg] [--repeats N]",
       work_precision_command},
      {"sweep",
       "vibro sweep SCENE.json | - | --preset NAME [-o OUT.json|.csv|.png|.svg] [--threads N] "
       "[--plot bifurcation|section|impact_map|regime_map|lyapunov|lyapunov_map] [--pellet I] "
       "[--coordinate dphi|phi]",
       sweep_command},
      {"orbit",
       "vibro orbit SCENE.json | - | --preset NAME [-o OUT.json|.png|.svg|.pdf] (the scene's periodic_orbit, "
       "or a period-1 orbit after 100 periods)",
       orbit_command},
      {"serve", "vibro serve [--host 127.0.0.1] [--port 8080] [--threads N] [--web DIR] "
                "[--quiet] (--help: every flag)",
       serve_command},
      {"presets", "vibro presets", presets_command},
      {"preset", "vibro preset NAME", preset_command},
  };
  return list;
}

}  // namespace vibro

int main(int argc, char** argv) {
  const vibro::Args all(argv + 1, argv + argc);
  if (all.empty() || all[0] == "help" || all[0] == "--help" || all[0] == "-h") {
    std::cout << "vibro: phase portraits of vibro-impact dynamics\n\nusage:\n";
    for (const auto& c : vibro::commands()) std::cout << "  " << c.usage << "\n";
    return all.empty() ? 2 : 0;
  }
  for (const auto& c : vibro::commands()) {
    if (c.name == all[0]) return c.run(vibro::Args(all.begin() + 1, all.end()));
  }
  std::cerr << "vibro: unknown command \"" << all[0] << "\" (try `vibro help`)\n";
  return 2;
}
