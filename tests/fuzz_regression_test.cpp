// Inputs that fuzzing or hostile-input testing found, kept as regression tests: every file of
// tests/data/fuzz/ is read, built and its record compiled as the fuzz target does
// (fuzz/fuzz_input.hpp); one named refused-* must be refused with a located ScenarioError, never
// a crash or another exception. Every file of tests/data/fuzz-checkpoint/ is read as the
// checkpoint fuzz target reads it (fuzz/fuzz_checkpoint.hpp) and resumed where read: the seeds,
// states saved by `tumble run`, must be read, and one named refused-* refused with its line.
// Every file of tests/data/fuzz-expressions/ is built and run as the expression fuzz target does
// (fuzz/fuzz_expressions.hpp): the seeds must be, and one named refused-* refused at its line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../fuzz/fuzz_checkpoint.hpp"
#include "../fuzz/fuzz_expressions.hpp"
#include "../fuzz/fuzz_input.hpp"

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
      std::ostringstream text;
      text << std::ifstream(entry.path()).rdbuf();
      fuzzing::read_input(text.str(), entry.path().string());
      EXPECT_FALSE(must_refuse) << name << " was accepted";
    } catch (const ScenarioError& error) {
      EXPECT_GT(error.where().line, 0) << name << ": " << error.what();
    }
  }
  EXPECT_GE(files, 7);
}

TEST(FuzzRegressions, EverySavedStateIsResumedAndEveryFoundOneRefused) {
  const std::filesystem::path dir = std::filesystem::path(TUMBLE_TEST_DATA_DIR) / "fuzz-checkpoint";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    ++files;
    std::ostringstream text;
    text << std::ifstream(entry.path(), std::ios::binary).rdbuf();
    EXPECT_EQ(fuzzing::resume_input(text.str()), name.rfind("refused-", 0) != 0) << name;
  }
  EXPECT_GE(files, 5);
}

TEST(FuzzRegressions, EveryExpressionSeedIsRunAndEveryFoundOneRefusedAtItsLine) {
  const std::filesystem::path dir =
      std::filesystem::path(TUMBLE_TEST_DATA_DIR) / "fuzz-expressions";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    const bool must_refuse = name.rfind("refused-", 0) == 0;
    ++files;
    std::ostringstream text;
    text << std::ifstream(entry.path(), std::ios::binary).rdbuf();
    try {
      EXPECT_TRUE(fuzzing::run_expressions(text.str())) << name << " names no example";
      EXPECT_FALSE(must_refuse) << name << " was accepted";
    } catch (const ScenarioError& error) {
      EXPECT_TRUE(must_refuse) << name << ": " << error.what();
      EXPECT_GT(error.where().line, 1) << name << ": " << error.what();
    }
  }
  EXPECT_GE(files, 6);
}

}  // namespace
}  // namespace tumble
