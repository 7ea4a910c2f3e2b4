// The valid scene the hostile cases are made from, and its fields by path.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace vibro::robustness {

// A scene the reader accepts that sets every field it knows.
nlohmann::json full_scene();

struct Leaf {
  nlohmann::json::json_pointer pointer;
  std::string field;  // as a refusal names it: "model.pellets[0].m"
  bool integer;       // read as an integer (indices, sizes)
};

// Every value in `j` below the root, containers included, depth first.
std::vector<Leaf> leaves(const nlohmann::json& j);

// The scene with the value at `pointer` replaced by `token` spelled as raw JSON text, which
// may be one nlohmann::json cannot hold (1e999, NaN) or not JSON at all.
std::string with_raw(nlohmann::json scene, const nlohmann::json::json_pointer& pointer,
                     const std::string& token);

}  // namespace vibro::robustness
