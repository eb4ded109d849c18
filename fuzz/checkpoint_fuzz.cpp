// libFuzzer target for the checkpoint reader (`tumble run --resume FILE`, Python's
// Model.load_state) and the run it resumes (fuzz_checkpoint.hpp says what one input is). A state
// read and resumed, or one refused with its line and key, is a pass; a crash, a sanitizer report,
// a hang, a leak or any exception is a finding. Seeds: tests/data/fuzz-checkpoint/.
// scripts/fuzz.sh builds and runs it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_checkpoint.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tumble::fuzzing::resume_input(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
