#include "python/code_points.h"

namespace vibro::python {

namespace {

constexpr char32_t kReplacement = U'\uFFFD';

// A lead byte's continuation bytes and the range its first one must lie in (Unicode's table 3-7 of
// well-formed UTF-8: no overlong form, no surrogate, nothing past U+10FFFF); extra 0: no lead.
struct Lead {
  int extra = 0;
  unsigned char low = 0x80, high = 0xBF;
};

Lead lead_form(unsigned char lead) {
  if (lead >= 0xC2 && lead <= 0xDF) return {1};
  if (lead == 0xE0) return {2, 0xA0};
  if (lead == 0xED) return {2, 0x80, 0x9F};
  if (lead >= 0xE1 && lead <= 0xEF) return {2};
  if (lead == 0xF0) return {3, 0x90};
  if (lead == 0xF4) return {3, 0x80, 0x8F};
  if (lead >= 0xF1 && lead <= 0xF3) return {3};
  return {};
}

// Calls put(c) for each code point of the text, in order. A malformed sequence gives one U+FFFD
// per maximal part of a well-formed one, as Python's errors="replace" does.
template <class Put>
void decode(std::string_view utf8, const Put& put) {
  std::size_t i = 0;
  while (i < utf8.size()) {
    const auto lead = static_cast<unsigned char>(utf8[i]);
    if (lead < 0x80) {
      put(lead);
      ++i;
      continue;
    }
    const Lead form = lead_form(lead);
    if (form.extra == 0) {
      put(kReplacement);
      ++i;
      continue;
    }
    char32_t c = lead & (0x3F >> form.extra);
    int k = 1;  // bytes of the sequence read: the lead and its continuation bytes
    for (; k <= form.extra && i + k < utf8.size(); ++k) {
      const auto next = static_cast<unsigned char>(utf8[i + k]);
      const bool in_range = k == 1 ? next >= form.low && next <= form.high : (next & 0xC0) == 0x80;
      if (!in_range) break;
      c = (c << 6) | (next & 0x3F);
    }
    put(k > form.extra ? c : kReplacement);
    i += k;
  }
}

}  // namespace

std::u32string code_points(std::string_view utf8) {
  std::u32string out;
  out.reserve(utf8.size());
  decode(utf8, [&](char32_t c) { out.push_back(c); });
  return out;
}

std::size_t code_point_count(std::string_view utf8) {
  std::size_t n = 0;
  decode(utf8, [&](char32_t) { ++n; });
  return n;
}

char32_t* write_code_points(std::string_view utf8, char32_t* out) {
  decode(utf8, [&](char32_t c) { *out++ = c; });
  return out;
}

}  // namespace vibro::python
