#include "server/stop_signals.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>

namespace vibro::server {
namespace {

volatile std::sig_atomic_t write_end = -1;
struct sigaction previous_int, previous_term;

constexpr char kSignalled = 's';
constexpr char kDestroyed = 'd';

extern "C" void on_stop_signal(int) {
  const int saved = errno;  // write() may change errno under the interrupted code's feet
  const char byte = kSignalled;
  if (write_end >= 0) {
    [[maybe_unused]] const ssize_t n = ::write(write_end, &byte, 1);
  }
  errno = saved;
}

}  // namespace

StopOnSignals::StopOnSignals(std::function<void()> stop) {
  if (::pipe2(pipe_, O_CLOEXEC) != 0) return;  // no pipe: the default handlers stay
  write_end = pipe_[1];
  waiter_ = std::thread([fd = pipe_[0], stop = std::move(stop)] {
    char byte = 0;
    while (::read(fd, &byte, 1) < 0 && errno == EINTR) {
    }
    if (byte == kSignalled) stop();
  });
  struct sigaction action = {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

StopOnSignals::~StopOnSignals() {
  if (pipe_[1] < 0) return;
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
  write_end = -1;
  const char byte = kDestroyed;
  [[maybe_unused]] const ssize_t n = ::write(pipe_[1], &byte, 1);
  waiter_.join();
  ::close(pipe_[0]);
  ::close(pipe_[1]);
}

}  // namespace vibro::server
