// The scene the periodic-orbit tests share: the impact oscillator preset at Ω = 6 with a guess
// near its stable period-1 motion (one impact per period, complex multipliers of modulus 0.8, the
// stop's k), without the preset's sweep, whose own checks are not these.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "io/presets.h"

namespace vibro::testing {

inline nlohmann::json impact_oscillator_orbit() {
  nlohmann::json s = nlohmann::json::parse(std::string(*preset_json("impact-oscillator")));
  s.erase("sweep");
  s["model"]["pellets"][0]["Omega"] = 6.0;
  s["periodic_orbit"] = {{"guess", {{{"phi", 0.15}, {"dphi", 0.1}}}}};
  return s;
}

}  // namespace vibro::testing
