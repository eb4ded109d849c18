// libFuzzer target for the scenario reader, the model builder and the expressions over a run's
// columns (fuzz_input.hpp says what one input is). A valid scenario or a located refusal is a
// pass; a crash, a sanitizer report, a hang, a leak or any other exception is a finding. Seeds:
// examples/*.yaml and tests/data/fuzz/. scripts/fuzz.sh builds and runs it.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_input.hpp"

namespace {

// TUMBLE_FUZZ_LINEARISE=0 leaves out `tumble modes`' linearisation of each valid input, which
// costs more than reading, building and the bounded run together: a long run aimed at the
// expressions (records, events) and the runs gets about twice the executions. Read once.
bool linearise() {
  static const bool on = [] {
    const char* value = std::getenv("TUMBLE_FUZZ_LINEARISE");
    return value == nullptr || std::string(value) != "0";
  }();
  return on;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    tumble::fuzzing::read_input(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml",
                                linearise());
  } catch (const tumble::ScenarioError&) {
    // A located refusal: what bad input should get.
  }
  return 0;
}
