#include "io/text_builder.h"

namespace vibro {

void append_general(std::string& out, double x, int precision) {
  // "%.40g" of a double is at most 48 characters: a sign, 40 digits, a point and "e-308".
  char digits[64];
  const auto end =
      std::to_chars(digits, digits + sizeof digits, x, std::chars_format::general, precision).ptr;
  out.append(digits, static_cast<std::size_t>(end - digits));
}

}  // namespace vibro
