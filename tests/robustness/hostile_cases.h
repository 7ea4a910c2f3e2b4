// Hostile scenes by class, each case with the field its refusal must name ("scene" for the
// document as a whole). Generated from one valid scene that uses every field, so a field
// added to the reader is covered by the generated classes once it is added to that scene.
#pragma once

#include <string>
#include <vector>

namespace vibro::robustness {

struct HostileCase {
  std::string what;   // for failure messages
  std::string text;   // the request body
  std::string field;  // the field the refusal must name
};

std::vector<HostileCase> wrong_type_cases();     // every field, every wrong JSON type
std::vector<HostileCase> non_finite_cases();     // every number as "NaN", "Infinity", 1e999...
std::vector<HostileCase> out_of_range_cases();   // negative, zero, too large, integer wrap
std::vector<HostileCase> huge_array_cases();     // 10^6 items in every array
std::vector<HostileCase> deep_nesting_cases();   // arrays and objects 17 to 10^6 deep
std::vector<HostileCase> long_string_cases();    // every string past its limit, up to 1 MB
std::vector<HostileCase> duplicate_key_cases();  // the last value is bad
std::vector<HostileCase> unicode_key_cases();    // unknown keys in many scripts, bad UTF-8
std::vector<HostileCase> empty_body_cases();     // empty, whitespace, non-object, truncated

}  // namespace vibro::robustness
