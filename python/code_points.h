// UTF-8 text as the code points a numpy str array holds (UCS-4); no Python needed.
#pragma once

#include <string>
#include <string_view>

namespace vibro::python {

// The text's code points; a malformed sequence (a stray continuation byte, a truncated or overlong
// sequence, a surrogate, past U+10FFFF) becomes U+FFFD, as Python's errors="replace" makes it.
std::u32string code_points(std::string_view utf8);

// code_points(utf8).size(), nothing allocated.
std::size_t code_point_count(std::string_view utf8);

// Writes code_points(utf8) from `out`, which has room for code_point_count(utf8) of them;
// returns the end of what it wrote.
char32_t* write_code_points(std::string_view utf8, char32_t* out);

}  // namespace vibro::python
