// Scenes for the render fuzzer (issue 31): the differential generator's scenes
// (tests/differential/scene_gen.h), stretched to what makes drawing hard: long runs (t_end in
// the hundreds of seconds), up to 8 pellets, several panels of every kind a scene can ask for
// (phase, time, mechanism, and cylinder where the build draws 3-D), windows, axis ranges and
// figure sizes from the tiny to the large, odd sizes included. A few scenes carry a value the
// reader or the renderer must refuse by its field.
#pragma once

#include <cstdint>

#include "io/scene.h"

namespace vibro::fuzz {

// Scene i of a seed: the same scene whatever else runs, so a failure is replayed by its index.
// Not thread-safe (the differential generator draws one scene at a time).
Scene render_scene_at(std::uint64_t seed, long i);

}  // namespace vibro::fuzz
