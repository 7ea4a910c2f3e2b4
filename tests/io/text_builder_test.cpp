// TextBuilder writes what std::ostringstream writes with the same precision, character for
// character: the run's answer sentence (io/result_json.cpp) is built with it, and its text is
// part of every run's JSON.
#include "io/text_builder.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vibro {
namespace {

// The precisions the answer sentence uses (3, 4, 7), the stream's default (6), and the range
// around them up to every double's shortest round trip (17) and past it.
const std::vector<int> kPrecisions = {0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 15, 16, 17, 20, 40};

std::string streamed(double x, int precision) {
  std::ostringstream s;
  s.precision(precision);
  s << x;
  return s.str();
}

std::string built(double x, int precision) {
  std::string out;
  append_general(out, x, precision);
  return out;
}

// The number of values of `xs` written differently, the first few shown.
int mismatches(const std::vector<double>& xs, const std::vector<int>& precisions) {
  int wrong = 0;
  for (double x : xs) {
    for (int p : precisions) {
      const std::string expected = streamed(x, p), got = built(x, p);
      if (expected == got) continue;
      if (++wrong <= 10)
        ADD_FAILURE() << "bits " << std::hex << std::bit_cast<std::uint64_t>(x) << std::dec
                      << " precision " << p << ": stream \"" << expected << "\", built \"" << got
                      << "\"";
    }
  }
  return wrong;
}

TEST(TextBuilder, WritesSpecialValuesAsTheStream) {
  using L = std::numeric_limits<double>;
  std::vector<double> xs = {0.0,    1.0,        0.1,  1e-300, 1e300, 123456789.0, 99999.5,
                            9.9995, 0.00012345, 1e-5, 1e-4,   1e5,   1e6,         1e7};
  for (double x : {L::infinity(), L::quiet_NaN(), L::signaling_NaN(), L::max(), L::min(),
                   L::denorm_min(), L::epsilon()})
    xs.push_back(x);
  const std::size_t n = xs.size();
  for (std::size_t i = 0; i < n; ++i) xs.push_back(-xs[i]);
  // The largest denormal, and the doubles on either side of the smallest normal.
  xs.push_back(std::nextafter(L::min(), 0.0));
  xs.push_back(std::nextafter(L::min(), 1.0));
  EXPECT_EQ(mismatches(xs, kPrecisions), 0);
  EXPECT_EQ(built(2.257618204928655e-09, 3), "2.26e-09");
  EXPECT_EQ(built(0.034068, 4), "0.03407");
  EXPECT_EQ(built(-0.0, 4), "-0");
  EXPECT_EQ(built(1e100, 4), "1e+100");
}

// Any 64 bits as a double: every exponent (denormals, NaNs with payloads) as often as any other.
TEST(TextBuilder, WritesRandomBitPatternsAsTheStream) {
  std::mt19937_64 random(35);
  std::vector<double> xs(60000);
  for (double& x : xs) x = std::bit_cast<double>(random());
  EXPECT_EQ(mismatches(xs, kPrecisions), 0);
}

// Where rounding decides: exact ties (a few bits over a power of two: 0.125, 2.5, 1234.5),
// decimal halfway points and their neighbours, which the two must round alike, and the numbers
// of a run's answer (times of seconds, angles of a few radians).
TEST(TextBuilder, RoundsAsTheStream) {
  std::vector<double> xs;
  for (int m = 1; m < 4096; m += 5)
    for (int k = -12; k <= 12; ++k) xs.push_back(std::ldexp(m, k));
  for (int e = -310; e <= 308; ++e) {
    for (int d = 1; d <= 99; d += 14) {
      const double half = (d + 0.5) * std::pow(10.0, e);
      xs.insert(xs.end(), {half, std::nextafter(half, 0.0), std::nextafter(half, HUGE_VAL)});
      const double power = std::pow(10.0, e);
      xs.insert(xs.end(), {power, std::nextafter(power, 0.0), std::nextafter(power, HUGE_VAL)});
    }
  }
  std::mt19937_64 random(4);
  std::uniform_real_distribution<double> seconds(0.0, 1000.0), angle(-7.0, 7.0);
  for (int i = 0; i < 5000; ++i) xs.insert(xs.end(), {seconds(random), angle(random)});
  const std::size_t n = xs.size();
  for (std::size_t i = 0; i < n; ++i) xs.push_back(-xs[i]);
  EXPECT_EQ(mismatches(xs, kPrecisions), 0);
}

TEST(TextBuilder, RefusesAPrecisionOutsideItsRange) {
  std::string out;
  EXPECT_THROW(append_general(out, 1.0, -1), std::invalid_argument);
  EXPECT_THROW(append_general(out, 1.0, 41), std::invalid_argument);
  EXPECT_TRUE(out.empty());
}

TEST(TextBuilder, BuildsTextAsTheStream) {
  const long big = std::numeric_limits<long>::min();
  const std::size_t size = std::numeric_limits<std::size_t>::max();
  std::ostringstream expected;
  expected.precision(4);
  expected << "t = " << 7.259264890843294 << " s, " << -3 << "π/" << 2 << ' ' << big << ' ' << size
           << " φ̇ = " << -1234567.0;
  expected.precision(7);
  expected << " until " << 5.839092782997403;
  TextBuilder built(4);
  built << "t = " << 7.259264890843294 << " s, " << -3 << "π/" << 2 << " " << big << " " << size
        << " φ̇ = " << -1234567.0;
  built.precision(7);
  built << " until " << 5.839092782997403;
  EXPECT_EQ(built.str(), expected.str());
  EXPECT_EQ(built.str(),
            "t = 7.259 s, -3π/2 -9223372036854775808 18446744073709551615 φ̇ = "
            "-1.235e+06 until 5.839093");
}

}  // namespace
}  // namespace vibro
