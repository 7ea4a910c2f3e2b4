// The scenes the benchmarks run: the paper preset, and a long forced run of one pellet between
// two fixed limiters (no chatter, no sticking: every event is a limiter impact or a reversal,
// so peers with plain root finding can follow it too).
#pragma once

#include "io/scene.h"

namespace vibro::bench {

// The named preset, parsed; aborts the benchmark program if it does not parse.
Scene preset_scene(const char* name);

// One pellet (paper friction law, m = 0.2 kg, R = 0.5 m, alpha0 = 0.05), forced with
// F0 = 2.5 N at Omega = 4 rad/s, between fixed limiters at −π/3 and +π/3 (k = 0.7).
Scene forced_pellet_scene(double t_end);

// The scene's options with no branch recorded: the engine alone, without the recorder.
SimOptions unrecorded(const Scene& scene);

}  // namespace vibro::bench
