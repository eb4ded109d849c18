// libFuzzer target for the expressions a user adds to a scenario: a sweep's record and the
// events' conditions, compiled against an example's columns and read over a few steps of its run
// (fuzz_expressions.hpp says what one input is). A run recorded, or a located refusal, is a pass;
// a crash, a sanitizer report, a hang, a leak or any other exception is a finding. Seeds:
// tests/data/fuzz-expressions/. scripts/fuzz.sh builds and runs it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_expressions.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    tumble::fuzzing::run_expressions(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const tumble::ScenarioError&) {
    // A condition refused where it is: what bad input should get.
  }
  return 0;
}
