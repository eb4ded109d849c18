// Every file tumble reads has a size limit (docs/scenario.md, "Limits on input"): a file over it
// is refused by its size before a byte is read, one without a size (/dev/zero) one byte past the
// limit, and the variable that raises a limit is checked. The red team's /dev/zero read until
// memory ran out. The large files here are sparse: no disk is used.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "expect_throw.hpp"
#include "test_files.hpp"
#include "tumble/inertia/mesh.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/scenario_document.hpp"
#include "tumble/sweep/sweep.hpp"

namespace tumble {
namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMiB = std::uintmax_t{1} << 20;

fs::path sparse_file(const std::string& test, const std::string& name, std::uintmax_t size) {
  const fs::path path = test::fresh_test_dir("BoundedRead", test) / name;
  std::ofstream(path).put('#');
  fs::resize_file(path, size);
  return path;
}

// Sets an environment variable for one test and unsets it after.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, const char* value) : name_(name) { ::setenv(name, value, 1); }
  ~ScopedVariable() { ::unsetenv(name_); }
  ScopedVariable(const ScopedVariable&) = delete;
  ScopedVariable& operator=(const ScopedVariable&) = delete;

 private:
  const char* name_;
};

TEST(BoundedRead, AScenarioFileOverItsLimitIsRefusedByItsSize) {
  const fs::path huge = sparse_file("scenario_size", "huge.yaml", 64 * kMiB + 1);
  test::expect_throw_containing<ScenarioError>(
      [&] { read_scenario_file(huge.string()); },
      huge.string() +
          ":0:0: is 67108865 bytes, larger than the limit of 64 MiB (67108864 bytes) for a "
          "scenario file (set TUMBLE_MAX_SCENARIO_MIB to a larger number of MiB to raise it)");
  test::expect_throw_containing<ScenarioError>([&] { load_scenario(huge.string(), {}); },
                                               "is 67108865 bytes, larger than the limit");
}

// Lowered to 2 MiB, so that the test reads little; the default is the same read, 32 times longer.
TEST(BoundedRead, DevZeroIsReadNoFurtherThanTheLimit) {
  const ScopedVariable two_mib("TUMBLE_MAX_SCENARIO_MIB", "2");
  test::expect_throw_containing<ScenarioError>(
      [] { read_scenario_file("/dev/zero"); },
      "/dev/zero:0:0: goes on past the limit of 2 MiB (2097152 bytes) for a scenario file "
      "(set TUMBLE_MAX_SCENARIO_MIB to a larger number of MiB to raise it)");
  // A mesh must be a regular file: /dev/zero under a mesh's name is refused unread.
  const fs::path zero_obj = test::fresh_test_dir("BoundedRead", "zero_mesh") / "zero.obj";
  fs::create_symlink("/dev/zero", zero_obj);
  test::expect_throw_containing<MeshError>([&] { load_mesh(zero_obj.string()); },
                                           "zero.obj': is not a regular file");
}

TEST(BoundedRead, TheVariableRaisesOrLowersTheLimitToTheByte) {
  const ScopedVariable one_mib("TUMBLE_MAX_SCENARIO_MIB", "1");
  const fs::path at_limit = sparse_file("variable", "at_limit.yaml", kMiB);
  EXPECT_EQ(read_scenario_file(at_limit.string()).size(), kMiB);
  const fs::path over = sparse_file("variable_over", "over.yaml", kMiB + 1);
  test::expect_throw_containing<ScenarioError>(
      [&] { read_scenario_file(over.string()); },
      "is 1048577 bytes, larger than the limit of 1 MiB (1048576 bytes) for a scenario file");
  test::expect_throw_containing<ScenarioError>(
      [] { read_scenario_file("/dev/zero"); },
      "goes on past the limit of 1 MiB (1048576 bytes) for a scenario file");
}

TEST(BoundedRead, AVariableThatIsNotALimitIsRefusedByName) {
  const fs::path small = sparse_file("bad_variable", "small.yaml", 10);
  for (const char* bad : {"lots", "0", "-1", "1.5", "1099511627777"}) {
    const ScopedVariable set("TUMBLE_MAX_SCENARIO_MIB", bad);
    test::expect_throw_containing<ScenarioError>(
        [&] { read_scenario_file(small.string()); },
        std::string("cannot be read: TUMBLE_MAX_SCENARIO_MIB=") + bad +
            " is not a limit: expected a whole number of MiB from 1 to 1099511627776 (unset it "
            "for the default, 64 MiB)");
  }
}

TEST(BoundedRead, AMeshFileOverItsLimitIsRefusedByItsSize) {
  const fs::path huge = sparse_file("mesh_size", "huge.obj", 1024 * kMiB + 1);
  test::expect_throw_containing<MeshError>(
      [&] { load_mesh(huge.string()); },
      "mesh file '" + huge.string() +
          "': is 1073741825 bytes, larger than the limit of 1024 MiB (1073741824 bytes) for a "
          "mesh file (set TUMBLE_MAX_MESH_MIB to a larger number of MiB to raise it)");
}

TEST(BoundedRead, AScenarioThatNamesAHugeMeshIsInvalidAtItsKey) {
  const fs::path huge = sparse_file("mesh_in_scenario", "huge.stl", 1024 * kMiB + 1);
  const fs::path scenario = huge.parent_path() / "uses_mesh.yaml";
  std::ofstream(scenario)
      << "tumble: 1\nbodies:\n  b: {shape: mesh, file: huge.stl, density: 600}\n";
  test::expect_throw_containing<ScenarioError>([&] { load_scenario(scenario.string(), {}, false); },
                                               "larger than the limit of 1024 MiB");
}

// threads=10000 started threads until one could not be (std::system_error, an abort).
TEST(BoundedRead, ASweepOfMoreThreadsThanTheLimitIsRefusedBeforeAnyRun) {
  SweepSpec spec;
  spec.text = "tumble: 1\n";
  spec.path = "threads.yaml";
  const std::vector<std::vector<double>> points(3);
  for (const int threads : {kMaxSweepThreads + 1, 10000, 0, -1}) {
    test::expect_throw_containing<std::invalid_argument>(
        [&] { run_points(spec, points, threads); },
        "threads: " + std::to_string(threads) + " is out of range: expected 1 to 256");
  }
}

}  // namespace
}  // namespace tumble
