// Inputs that fuzzing or hostile-input testing found, kept as regression tests: every file of
// tests/data/fuzz/ is read and, if valid, built into a model, as the fuzz target does; one named
// refused-* must be refused with a located ScenarioError, never a crash or another exception.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/model_from_scenario.hpp"

namespace tumble {
namespace {

TEST(FuzzRegressions, EveryFoundInputIsReadOrRefusedWithItsLocation) {
  const std::filesystem::path dir = std::filesystem::path(TUMBLE_TEST_DATA_DIR) / "fuzz";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    const bool must_refuse = name.rfind("refused-", 0) == 0;
    ++files;
    try {
      const Scenario scenario = load_scenario(entry.path().string(), {});
      (void)build_model(scenario);
      EXPECT_FALSE(must_refuse) << name << " was accepted";
    } catch (const ScenarioError& error) {
      EXPECT_GT(error.where().line, 0) << name << ": " << error.what();
    }
  }
  EXPECT_GE(files, 7);
}

}  // namespace
}  // namespace tumble
