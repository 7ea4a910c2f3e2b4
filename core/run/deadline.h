// A moment on the steady clock by which a piece of work must end. A search or a measurement made
// of many runs holds one, and gives each run what is left of it (left_ms), so that one budget
// bounds them all.
#pragma once

#include <algorithm>
#include <chrono>
#include <limits>

namespace vibro {

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;

  // One that never passes.
  Deadline() = default;

  // `ms` from now; a negative one has passed already. None past 1e12 ms (31 years), infinity
  // and NaN included, and none earlier than 1e12 ms ago: the clock's arithmetic would overflow.
  static Deadline in_ms(double ms) {
    Deadline d;
    if (ms < 1e12)
      d.at_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                 std::chrono::duration<double, std::milli>(std::max(ms, -1e12)));
    return d;
  }

  bool never() const { return at_ == Clock::time_point::max(); }
  bool passed() const { return !never() && Clock::now() > at_; }

  // What is left, ms: negative once passed, infinity for one that never passes.
  double left_ms() const {
    if (never()) return std::numeric_limits<double>::infinity();
    return std::chrono::duration<double, std::milli>(at_ - Clock::now()).count();
  }

 private:
  Clock::time_point at_ = Clock::time_point::max();
};

}  // namespace vibro
