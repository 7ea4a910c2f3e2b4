// A progress bar on stderr, redrawn in place: how far the work is, what is done in words, and the
// time left at the rate so far. Safe to call from several threads.
#pragma once

#include <chrono>
#include <mutex>
#include <string>

namespace vibro {

class ProgressBar {
 public:
  // `fraction` of the work done (0 to 1), `done` that in words ("12/400 runs"). Redraws at most
  // five times a second, and always at the end (fraction 1), after which it is silent: work that
  // may stop short can be ended by the caller without a second bar.
  void operator()(double fraction, const std::string& done);

 private:
  std::mutex mutex_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  double drawn_ = -1.0;
  bool ended_ = false;
};

}  // namespace vibro
