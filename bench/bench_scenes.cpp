#include "bench_scenes.h"

#include <cstdio>
#include <cstdlib>
#include <variant>

#include "io/presets.h"
#include "io/scene_json.h"

namespace vibro::bench {

Scene preset_scene(const char* name) {
  const auto text = preset_json(name);
  if (!text) {
    std::fprintf(stderr, "no preset named %s\n", name);
    std::exit(1);
  }
  SceneOrError parsed = scene_from_text(*text);
  if (auto* error = std::get_if<FieldError>(&parsed)) {
    std::fprintf(stderr, "preset %s: %s: %s\n", name, error->field.c_str(), error->message.c_str());
    std::exit(1);
  }
  return std::get<Scene>(std::move(parsed));
}

Scene forced_pellet_scene(double t_end) {
  Scene scene;
  scene.name = "forced-pellet";
  Model& m = scene.model;
  m.g = 9.81;
  m.R = 0.5;
  m.alpha0 = 0.05;
  m.friction = FrictionLaw::paper;
  Pellet p;
  p.m = 0.2;
  p.phi0 = 0.0;
  p.dphi0 = 3.0;
  p.force = {2.5, 4.0, 0.0};
  m.pellets = {p};
  Limiter left, right;
  left.angle = -kTwoPi / 6.0;
  right.angle = kTwoPi / 6.0;
  left.k = right.k = 0.7;
  m.limiters = {left, right};
  scene.sim.t_end = t_end;
  scene.sim.record = {false};
  return scene;
}

SimOptions unrecorded(const Scene& scene) {
  SimOptions options = scene.sim;
  options.record.assign(scene.model.size(), false);
  return options;
}

}  // namespace vibro::bench
