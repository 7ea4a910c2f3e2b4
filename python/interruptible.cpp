#include "python/interruptible.h"

#include <pybind11/pybind11.h>

#include <chrono>
#include <future>

namespace vibro::python {

namespace py = pybind11;

void run_interruptible(const std::function<void()>& work, std::atomic<bool>& cancel,
                       const std::function<void()>& report) {
  std::future<void> done = std::async(std::launch::async, work);
  for (;;) {
    bool finished = false;
    {
      py::gil_scoped_release release;
      finished = done.wait_for(std::chrono::milliseconds(50)) == std::future_status::ready;
    }
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (report) report();
    } catch (...) {
      cancel = true;
      {
        py::gil_scoped_release release;
        done.wait();
      }
      throw;
    }
    if (finished) return done.get();
  }
}

}  // namespace vibro::python
