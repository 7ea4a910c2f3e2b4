// The named scenes: the paper's scene, its figures, and the hard cases. Each is a JSON file in
// presets/, compiled into the program.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vibro {

struct PresetText {
  std::string_view name;
  std::string_view json;
};

// In a fixed order: the paper scene first, then its figures, then the hard cases.
const std::vector<PresetText>& presets();
std::optional<std::string_view> preset_json(std::string_view name);

}  // namespace vibro
