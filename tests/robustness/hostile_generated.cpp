// The hostile classes generated from full_scene(): every field with every wrong JSON type,
// every number spelled non-finite, every array with a million items.
#include <string>
#include <vector>

#include "tests/robustness/hostile_cases.h"
#include "tests/robustness/hostile_full_scene.h"

namespace vibro::robustness {

using nlohmann::json;

std::vector<HostileCase> wrong_type_cases() {
  const json scene = full_scene();
  std::vector<HostileCase> cases;
  for (const Leaf& leaf : leaves(scene)) {
    const json& v = scene[leaf.pointer];
    std::vector<std::string> wrong;  // raw JSON of every type but the field's own
    if (!v.is_string()) wrong.push_back("\"1\"");
    if (!v.is_number()) wrong.push_back("1");
    if (!v.is_boolean()) wrong.push_back("true");
    if (!v.is_object()) wrong.push_back("{}");
    if (!v.is_array()) wrong.push_back("[]");
    if (leaf.integer) wrong.push_back("0.5");
    for (const std::string& w : wrong)
      cases.push_back({leaf.field + " = " + w, with_raw(scene, leaf.pointer, w), leaf.field});
  }
  return cases;
}

std::vector<HostileCase> non_finite_cases() {
  const json scene = full_scene();
  // Strings that strtod would read as non-finite: refused as not numbers.
  const std::vector<std::string> strings = {"\"NaN\"", "\"nan\"", "\"Infinity\"", "\"-inf\"",
                                            "\"1e999\""};
  // Literals that overflow a double (nlohmann::json refuses them as invalid JSON rather than
  // reading infinity), and the bare words, which are not JSON at all.
  const std::vector<std::string> not_json = {"1e999", "-1e999",   "1E+400",
                                             "NaN",   "Infinity", "-Infinity"};
  std::vector<HostileCase> cases;
  for (const Leaf& leaf : leaves(scene)) {
    if (!scene[leaf.pointer].is_number()) continue;
    for (const std::string& s : strings)
      cases.push_back({leaf.field + " = " + s, with_raw(scene, leaf.pointer, s), leaf.field});
    for (const std::string& s : not_json)
      cases.push_back({leaf.field + " = " + s, with_raw(scene, leaf.pointer, s), "scene"});
  }
  return cases;
}

std::vector<HostileCase> huge_array_cases() {
  const json scene = full_scene();
  std::string million = "[0";
  for (int i = 1; i < 1000000; ++i) million += ",0";
  million += "]";
  std::vector<HostileCase> cases;
  for (const Leaf& leaf : leaves(scene))
    if (scene[leaf.pointer].is_array())
      cases.push_back(
          {leaf.field + " with 10^6 items", with_raw(scene, leaf.pointer, million), leaf.field});
  return cases;
}

}  // namespace vibro::robustness
