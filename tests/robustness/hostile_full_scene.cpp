#include "tests/robustness/hostile_full_scene.h"

#include <set>

namespace vibro::robustness {

using nlohmann::json;

json full_scene() {
  return json::parse(R"({
    "name": "full", "description": "every field", "assumptions": ["none"],
    "model": {"g": 9.81, "R": 0.5, "alpha0": 0.05, "mu_s": 0.1, "k_c": 1.0, "friction": "paper",
              "pellets": [{"m": 0.2, "phi0": 0.1, "dphi0": 1.0, "F0": 1.0, "Omega": 3.0, "psi": 0.5},
                          {"m": 0.3, "phi0": -0.2}],
              "limiters": [{"angle": 0.7, "k": 0.5, "mobile": true, "rearm_by": 1, "pellets": [0]},
                           {"angle": -0.7, "k": 0.5}]},
    "t_end": 2.0, "trajectories": false,
    "solver": {"method": "auto", "rtol": 1e-9, "atol": 1e-12},
    "plots": [{"kind": "phase", "pellet": 0, "t_from": 0.0, "t_to": 1.5, "branches": [1],
               "first_integral": {"phi": 0.0, "dphi": 1.0}, "friction_zone": true, "title": "t"},
              {"kind": "time", "pellets": [0, 1], "dphi": true},
              {"kind": "cylinder", "pellet": 1,
               "camera": {"azimuth": 30.0, "elevation": 20.0, "distance": 5.0}}],
    "width": 300, "height": 200
  })");
}

namespace {

void collect(const json& j, const json::json_pointer& at, const std::string& field,
             bool integer_items, std::vector<Leaf>& out) {
  static const std::set<std::string> integer_keys = {"pellet", "rearm_by", "width", "height"};
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string child = field.empty() ? it.key() : field + "." + it.key();
      const bool integer = integer_keys.count(it.key()) > 0;
      out.push_back({at / it.key(), child, integer});
      const bool index_list = it.key() == "pellets" || it.key() == "branches";
      collect(it.value(), at / it.key(), child, index_list, out);
    }
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) {
      const std::string child = field + "[" + std::to_string(i) + "]";
      out.push_back({at / i, child, integer_items && j[i].is_number()});
      collect(j[i], at / i, child, false, out);
    }
  }
}

}  // namespace

std::vector<Leaf> leaves(const json& j) {
  std::vector<Leaf> out;
  collect(j, json::json_pointer(), "", false, out);
  return out;
}

std::string with_raw(json scene, const json::json_pointer& pointer, const std::string& token) {
  const std::string sentinel = "\"@@hostile@@\"";
  scene[pointer] = "@@hostile@@";
  std::string text = scene.dump();
  text.replace(text.find(sentinel), sentinel.size(), token);
  return text;
}

}  // namespace vibro::robustness
