// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Ctrl-C during a batch that runs without the GIL: Python's signal handlers run only when the
// interpreter gets control, so the calling thread lends it control now and then.

#include <pybind11/pybind11.h>

#include <chrono>

namespace clearjoint::python {

/// A poll for for_each_chunk, called without the GIL: at most every 50 ms (a GIL hand-over can
/// wait for another Python thread's switch interval, 5 ms by default), take the GIL and run the
/// pending signal handlers; one that raises (KeyboardInterrupt) throws error_already_set.
class SignalCheck {
 public:
  void operator()() {
    const auto now = std::chrono::steady_clock::now();
    if (now < next_) return;
    next_ = now + kPeriod;
    pybind11::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
  }

 private:
  static constexpr std::chrono::milliseconds kPeriod{50};
  // A batch shorter than one period never takes the GIL.
  std::chrono::steady_clock::time_point next_ = std::chrono::steady_clock::now() + kPeriod;
};

}  // namespace clearjoint::python
