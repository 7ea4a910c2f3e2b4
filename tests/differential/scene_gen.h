// Random scenes over the space a user can reach (issue 9, "Differential testing"): 1–4 pellets,
// both friction laws, forced and unforced, at rest inside and outside the friction cone or
// moving, pellets nearly touching, 0–3 limiters fixed and mobile, k and k_c from 0 to 1,
// R from 1e-3 to 10 m, Ω from 0.1 to 1e4 rad/s. Every scene passes validate_model by
// construction, and its run stays cheap (t_end a few sqrt(R/g), a bounded number of forcing
// periods).
#pragma once

#include <rapidcheck.h>

#include <cstdint>
#include <iosfwd>
#include <string>

#include "core/model/model.h"
#include "core/run/sim_options.h"
#include "io/scene.h"

namespace vibro::differential {

struct RandomScene {
  Model model;
  double t_end = 1.0;
};

// The generator. Each choice is an integer that shrinks toward its simplest value (fewer
// pellets and limiters, no forcing, no friction, the first option of a list), so a failing
// scene shrinks to a small one.
rc::Gen<RandomScene> gen_scene();

// Scene i of a seed, from its own random stream (splitmix64 of the pair): the same scene whatever
// order threads take the indices in, so a scan's failure is re-run alone by its index.
// Thread-safe (RapidCheck's generation context is global: one scene is generated at a time).
RandomScene scene_at(std::uint64_t seed, long i);

// Event-time tolerances and run lengths scale with the scene's time scale (core/model/model.h).

// The run options the instrument uses: the scene's t_end, the method and tolerances, and the
// bounds on work (events, steps, wall clock) that keep a random run cheap.
SimOptions run_options(const RandomScene& scene, Method method, double rtol);

// The scene as a user would post it (API.md), ready for `vibro simulate -`.
Scene to_scene(const RandomScene& scene, Method method, double rtol,
               const std::string& description = "");
std::string scene_json_text(const RandomScene& scene, Method method, double rtol,
                            const std::string& description = "");

// How RapidCheck prints a (shrunk) counterexample: the scene JSON.
void showValue(const RandomScene& scene, std::ostream& os);

}  // namespace vibro::differential
