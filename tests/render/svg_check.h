// A dependency-free well-formedness check for the SVG we write: tags balance, one root element,
// comments and declarations skipped.
#pragma once

#include <string>

namespace vibro::testing {

// Empty when well formed, else what is wrong.
std::string xml_balance_error(const std::string& xml);

// How many times `needle` occurs in `text`.
int count_of(const std::string& text, const std::string& needle);

}  // namespace vibro::testing
