#include "io/presets.h"

#include <algorithm>

#include "io/presets_data.h"

namespace vibro {

const std::vector<PresetText>& presets() {
  static const std::vector<PresetText> sorted = [] {
    std::vector<PresetText> list(std::begin(kPresetData), std::end(kPresetData));
    auto rank = [](std::string_view name) {
      if (name == "paper") return 0;
      if (name.starts_with("paper-")) return 1;
      return 2;
    };
    std::stable_sort(list.begin(), list.end(), [&](const PresetText& a, const PresetText& b) {
      return rank(a.name) != rank(b.name) ? rank(a.name) < rank(b.name) : a.name < b.name;
    });
    return list;
  }();
  return sorted;
}

std::optional<std::string_view> preset_json(std::string_view name) {
  for (const PresetText& p : presets())
    if (p.name == name) return p.json;
  return std::nullopt;
}

}  // namespace vibro
