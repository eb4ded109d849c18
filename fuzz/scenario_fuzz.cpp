// libFuzzer target for the scenario reader, the model builder and the expressions over a run's
// columns (fuzz_input.hpp says what one input is). A valid scenario or a located refusal is a
// pass; a crash, a sanitizer report, a hang, a leak or any other exception is a finding. Seeds:
// examples/*.yaml and tests/data/fuzz/. scripts/fuzz.sh builds and runs it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    tumble::fuzzing::read_input(std::string(reinterpret_cast<const char*>(data), size),
                                "fuzz.yaml");
  } catch (const tumble::ScenarioError&) {
    // A located refusal: what bad input should get.
  }
  return 0;
}
