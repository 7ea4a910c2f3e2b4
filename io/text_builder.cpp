#include "io/text_builder.h"

#include <stdexcept>

namespace vibro {

void append_general(std::string& out, double x, int precision) {
  if (precision < 0 || precision > 40)
    throw std::invalid_argument("append_general: precision " + std::to_string(precision) +
                                " is outside 0..40");
  // "%.40g" of a double is at most 47 characters: a sign, 40 digits, a point and "e-324".
  char digits[64];
  const auto end =
      std::to_chars(digits, digits + sizeof digits, x, std::chars_format::general, precision).ptr;
  out.append(digits, static_cast<std::size_t>(end - digits));
}

}  // namespace vibro
