#pragma once
// The fuzz targets' bound on a run: stopped after `steps` accepted steps or kRunWork of work,
// whichever comes first, through DriverOptions::stop_requested (as Python's Ctrl-C stops a run),
// so that one input stays well within libFuzzer's second: under the sanitizers and the fuzzer's
// instrumentation a step of Andrews' squeezer or of four wheels on a ramp costs some 10 ms.
#include <chrono>
#include <functional>

namespace tumble::fuzzing {

inline constexpr std::chrono::milliseconds kRunWork{100};

// Asked after each accepted step; true once the run has had its steps or its time.
inline std::function<bool()> bounded_run(long steps) {
  return [steps, taken = 0L, start = std::chrono::steady_clock::now()]() mutable {
    return ++taken >= steps || std::chrono::steady_clock::now() - start > kRunWork;
  };
}

}  // namespace tumble::fuzzing
