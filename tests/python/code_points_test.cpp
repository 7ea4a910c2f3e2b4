#include "python/code_points.h"

#include <gtest/gtest.h>

namespace vibro::python {
namespace {

TEST(CodePoints, DecodesOneToFourByteSequences) {
  EXPECT_EQ(code_points("limiter"), U"limiter");
  EXPECT_EQ(code_points("φ̇ ≥ 0 rad/s, Ω"), U"φ̇ ≥ 0 rad/s, Ω");
  EXPECT_EQ(code_points("\xF0\x9F\x98\x80"), U"\U0001F600");
  EXPECT_EQ(code_points(""), U"");
}

TEST(CodePoints, ReplacesMalformedSequencesAsPythonDoes) {
  // Each as bytes.decode("utf-8", "replace") gives it.
  EXPECT_EQ(code_points("a\x80z"), U"a\uFFFDz");                            // stray
  EXPECT_EQ(code_points("a\xCF"), U"a\uFFFD");                              // truncated
  EXPECT_EQ(code_points("\xE2\x89z"), U"\uFFFDz");                          // truncated
  EXPECT_EQ(code_points("\xC0\xAF"), U"\uFFFD\uFFFD");                      // overlong
  EXPECT_EQ(code_points("\xE0\x80\xAF"), U"\uFFFD\uFFFD\uFFFD");            // overlong
  EXPECT_EQ(code_points("\xED\xA0\x80"), U"\uFFFD\uFFFD\uFFFD");            // surrogate
  EXPECT_EQ(code_points("\xF4\x90\x80\x80"), U"\uFFFD\uFFFD\uFFFD\uFFFD");  // > U+10FFFF
  EXPECT_EQ(code_points("\xF5\x80\x80\x80"), U"\uFFFD\uFFFD\uFFFD\uFFFD");  // no lead
}

TEST(CodePoints, CountsAndWritesWhatItDecodes) {
  for (const char* text : {"limiter", "φ̇ ≥ 0 rad/s, Ω", "\xF0\x9F\x98\x80", "", "a\x80z", "a\xCF",
                           "\xE0\x80\xAF", "\xF4\x90\x80\x80"}) {
    const std::u32string expected = code_points(text);
    EXPECT_EQ(code_point_count(text), expected.size()) << text;
    std::u32string written(expected.size() + 1, U'#');
    const char32_t* end = write_code_points(text, written.data());
    EXPECT_EQ(end - written.data(), static_cast<std::ptrdiff_t>(expected.size())) << text;
    EXPECT_EQ(written, expected + U"#") << text;
  }
}

}  // namespace
}  // namespace vibro::python
