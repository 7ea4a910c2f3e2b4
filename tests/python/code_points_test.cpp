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

}  // namespace
}  // namespace vibro::python
