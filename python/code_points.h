// UTF-8 text as the code points a numpy str array holds (UCS-4); no Python needed.
#pragma once

#include <string>
#include <string_view>

namespace vibro::python {

// The text's code points; a malformed sequence (a stray continuation byte, a truncated or overlong
// sequence, a surrogate, past U+10FFFF) becomes U+FFFD, as Python's errors="replace" makes it.
std::u32string code_points(std::string_view utf8);

}  // namespace vibro::python
