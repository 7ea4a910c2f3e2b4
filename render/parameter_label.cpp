#include "render/parameter_label.h"

#include <cstdlib>

namespace vibro::render {

std::string parameter_label(const std::string& path) {
  struct Name {
    const char* field;
    const char* symbol;
    const char* unit;
  };
  static const Name names[] = {{"F0", "F\u2080", "N"},
                               {"Omega", "\u03a9", "rad/s"},
                               {"psi", "\u03c8", "rad"},
                               {"m", "m", "kg"},
                               {"phi0", "\u03c6\u2080", "rad"},
                               {"dphi0", "\u03c6\u0307\u2080", "rad/s"},
                               {"c", "c", "1/s"},
                               {"angle", "angle", "rad"},
                               {"k", "k", ""},
                               {"R", "R", "m"},
                               {"g", "g", "m/s\u00b2"},
                               {"alpha0", "\u03b1\u2080", "rad"},
                               {"k_c", "k_c", ""},
                               {"mu_s", "\u03bc_s", ""}};
  const std::size_t dot = path.rfind('.');
  const std::string field = path.substr(dot + 1);
  std::string whose;
  for (const char* list : {"pellets[", "limiters["}) {
    const std::size_t at = path.find(list);
    if (at == std::string::npos) continue;
    const int index = std::atoi(path.c_str() + at + std::string(list).size());
    whose =
        std::string(" of ") + (list[0] == 'p' ? "pellet " : "limiter ") + std::to_string(index + 1);
  }
  for (const Name& n : names)
    if (field == n.field)
      return std::string(n.symbol) + whose + (*n.unit ? std::string(" [") + n.unit + "]" : "");
  return path;
}

}  // namespace vibro::render
