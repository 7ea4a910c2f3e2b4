// `vibro orbit SCENE | - | --preset NAME [-o OUT.json]`: finds the periodic motion the scene's
// "periodic_orbit" asks for (the defaults without one), follows it in a parameter when it asks
// for a continuation, and writes the result as JSON (API.md, "Periodic motions and their
// stability"), to stdout without -o. While a branch is followed, a progress bar shows on stderr
// when that is a terminal. Exits 1 when no orbit was found: the JSON then says why.
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>

#include "app/commands.h"
#include "app/progress_bar.h"
#include "io/orbit_json.h"

namespace vibro {

int orbit_command(const Args& args) {
  const auto job = scene_and_output(args, "orbit");
  if (!job) return 2;
  const Scene& scene = job->scene;
  const std::string& out = job->out;
  // The orbit's figures (PNG, SVG, PDF) are to come from render/; until then only JSON.
  if (!out.empty() && !out.ends_with(".json")) {
    print_error("-o", "name the output OUT.json (orbits are not drawn as images yet)");
    return 2;
  }
  const OrbitRequest request = scene.periodic_orbit.value_or(OrbitRequest{});
  if (auto e = validate_orbit_request(scene.model, request)) {
    print_error(e->field, e->message);
    return 2;
  }
  ProgressBar bar;
  std::function<void(double)> progress;
  if (request.continuation && isatty(STDERR_FILENO))
    progress = [&bar](double done) {
      bar(done, std::to_string(std::lround(100.0 * done)) + "% of the way");
    };
  const OrbitResult result = run_orbit_request(scene.model, scene.sim, request, progress);
  if (progress) bar(1.0, "finished");
  const std::string text = orbit_result_json(result).dump(2) + "\n";
  if (out.empty()) {
    std::cout << text;
  } else if (!(std::ofstream(out, std::ios::binary) << text)) {
    print_error("-o", "cannot write " + out);
    return 1;
  }
  return result.orbit.converged ? 0 : 1;
}

}  // namespace vibro
