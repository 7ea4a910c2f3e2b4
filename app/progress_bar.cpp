#include "app/progress_bar.h"

#include <algorithm>
#include <cstdio>

namespace vibro {

void ProgressBar::operator()(double fraction, const std::string& done) {
  const std::lock_guard lock(mutex_);
  if (ended_) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  const bool finished = fraction >= 1.0;
  if (!finished && elapsed - drawn_ < 0.2) return;
  drawn_ = elapsed;
  const int width = 30;
  const int filled = static_cast<int>(width * std::clamp(fraction, 0.0, 1.0));
  const double left = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "\r[%s%s] %s, %.0f s left ", std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), done.c_str(), std::max(left, 0.0));
  if (finished) {
    std::fprintf(stderr, "\n");
    ended_ = true;
  }
}

}  // namespace vibro
