// libFuzzer target for the scenario reader and the model builder: any bytes are read as a
// scenario and, if valid, built into the model a run would use. A valid scenario or a
// ScenarioError (a located refusal) is a pass; a crash, a sanitizer report, a hang, a leak or
// any other exception is a finding. Seeds: examples/*.yaml. scripts/fuzz.sh builds and runs it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/model_from_scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const tumble::Scenario scenario = tumble::load_scenario_text(text, "fuzz.yaml", {});
    (void)tumble::build_model(scenario);
  } catch (const tumble::ScenarioError&) {
    // A located refusal: what bad input should get.
  }
  return 0;
}
