// Long work (a sweep, a continuation) run from Python so that other Python threads go on meanwhile
// and Ctrl-C stops it: the work runs on a thread of its own while the calling thread waits with
// the GIL released, and every 50 ms takes the GIL to look for a signal and to report progress.
#pragma once

#include <atomic>
#include <functional>

namespace vibro::python {

// Runs `work` to its end and returns. Call with the GIL held; `work` must not touch Python.
// `report` (may be empty) is called on the calling thread, with the GIL held, every 50 ms and once
// after the work ends. When a signal handler raises (KeyboardInterrupt) or `report` does, sets
// `cancel`, waits for the work to stop, and raises that exception. An exception of `work` is
// raised too.
void run_interruptible(const std::function<void()>& work, std::atomic<bool>& cancel,
                       const std::function<void()>& report);

}  // namespace vibro::python
