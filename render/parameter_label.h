// How a swept or continued parameter is named on an axis.
#pragma once

#include <string>

namespace vibro::render {

// "Ω of pellet 1 [rad/s]" for "model.pellets[0].Omega": the symbol, whose it is, and the unit;
// the path itself for a field it does not know.
std::string parameter_label(const std::string& path);

}  // namespace vibro::render
