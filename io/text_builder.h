// Text with numbers in it, written as std::ostringstream writes it under the classic locale with
// a precision and the default floatfield (a double as printf's "%.*g", an integer in decimals),
// but by std::to_chars: no locale, no stream, and no printf. The printf family takes a slow path
// for every call once any library in the process registers printf handlers (numpy loads
// libquadmath, which does), and a stream adds its own setup to each call.
#pragma once

#include <charconv>
#include <concepts>
#include <string>
#include <string_view>

namespace vibro {

// `x` as `std::ostringstream` with precision(precision) writes it ("%.*g"): "0.03407", "2.26e-09",
// "1e+100", "-0", "inf", "nan", "-nan". `precision` in 0…40 (std::invalid_argument otherwise);
// 0 writes as 1 does, as "%.0g" does.
void append_general(std::string& out, double x, int precision);

// A string built by appending text, integers and doubles, as `s << ...` on an std::ostringstream
// with the same precision would build it.
class TextBuilder {
 public:
  explicit TextBuilder(int precision) : precision_(precision) {}
  int precision() const { return precision_; }
  void precision(int digits) { precision_ = digits; }
  void reserve(std::size_t bytes) { text_.reserve(bytes); }

  TextBuilder& operator<<(std::string_view s) {
    text_ += s;
    return *this;
  }
  TextBuilder& operator<<(double x) {
    append_general(text_, x, precision_);
    return *this;
  }
  // Integers only: a char or a bool would be text or a word to a stream.
  template <std::integral I>
  requires(!std::same_as<I, char> && !std::same_as<I, bool>) TextBuilder& operator<<(I i) {
    char digits[24];
    const auto end = std::to_chars(digits, digits + sizeof digits, i).ptr;
    text_.append(digits, static_cast<std::size_t>(end - digits));
    return *this;
  }

  const std::string& str() const& { return text_; }
  std::string str() && { return std::move(text_); }

 private:
  std::string text_;
  int precision_;
};

}  // namespace vibro
