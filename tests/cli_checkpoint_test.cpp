// `tumble run --stop-at T --save-state FILE` and `--resume FILE`: a run stopped part way and
// resumed from its file writes, in the stopped run's --out, the trajectory and events files of
// the run that never stopped, byte for byte; a file that is not that run's checkpoint (another
// scenario or --set value, an edited or cut file, another trajectory) is refused with exit 2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>

#include "run_tumble.hpp"
#include "test_files.hpp"
#include "tumble/simulation/checkpoint_file.hpp"

namespace tumble {
namespace {

namespace fs = std::filesystem;

using test::example;
using test::read_file;

// `tumble run ARGUMENTS`.
test::CommandResult run(const std::string& arguments) {
  return test::run_tumble("run " + arguments);
}

struct StopCase {
  const char* example;  // under examples/, without .yaml
  const char* stop_at;  // s
  const char* what;
  std::size_t files = 2;  // the whole run writes: a trajectory, and an events file if it has events
};

void PrintTo(const StopCase& c, std::ostream* os) {
  *os << c.example << " stopped at " << c.stop_at << " s";
}

std::string name_of(const StopCase& c) {
  std::string name = c.example;
  for (char& ch : name) {
    if (ch == '/' || ch == '.') ch = '_';
  }
  return name;
}

class CliCheckpoint : public ::testing::TestWithParam<StopCase> {};

TEST_P(CliCheckpoint, AResumedRunWritesTheUninterruptedRunsFiles) {
  const StopCase c = GetParam();
  const fs::path dir = test::fresh_test_dir("CliCheckpoint", name_of(c));
  const std::string scenario = example(std::string(c.example) + ".yaml");
  const fs::path whole = dir / "whole", part = dir / "part", rest = dir / "rest";
  const fs::path state = dir / "stopped.state";

  const auto whole_run = run(scenario + " --out " + whole.string());
  ASSERT_EQ(whole_run.status, 0) << whole_run.out;
  const auto stopped = run(scenario + " --out " + part.string() + " --stop-at " + c.stop_at +
                           " --save-state " + state.string());
  ASSERT_EQ(stopped.status, 0) << stopped.out;
  EXPECT_NE(stopped.out.find("stopped        at t = "), std::string::npos) << stopped.out;
  ASSERT_TRUE(fs::exists(state));
  std::string trajectory_name;
  for (const auto& entry : fs::directory_iterator(whole)) {
    const std::string name = entry.path().filename().string();
    if (name.ends_with(".csv") && !name.ends_with("_events.csv")) trajectory_name = name;
  }
  ASSERT_FALSE(trajectory_name.empty());
  const std::string expected = read_file(whole / trajectory_name);
  const std::string before = read_file(part / trajectory_name);
  ASSERT_LT(before.size(), expected.size()) << c.what << ": it did not stop";
  ASSERT_EQ(expected.compare(0, before.size(), before), 0);

  // Into another directory: the rows after the stop, under the header.
  const auto elsewhere = run(scenario + " --out " + rest.string() + " --resume " + state.string());
  ASSERT_EQ(elsewhere.status, 0) << elsewhere.out;
  const std::string after = read_file(rest / trajectory_name);
  const std::string header = expected.substr(0, expected.find('\n') + 1);
  EXPECT_TRUE(before + after.substr(header.size()) == expected)
      << c.what << ": the rows after the stop are not the uninterrupted run's";
  EXPECT_EQ(after.substr(0, header.size()), header);

  // In the stopped run's directory: its trajectory goes on; every file is the whole run's.
  const auto resumed = run(scenario + " --out " + part.string() + " --resume " + state.string());
  ASSERT_EQ(resumed.status, 0) << resumed.out;
  EXPECT_NE(resumed.out.find("resumed        from "), std::string::npos) << resumed.out;
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(whole)) {
    const fs::path name = entry.path().filename();
    EXPECT_TRUE(read_file(entry.path()) == read_file(part / name))
        << c.what << ": " << name << " differs from the uninterrupted run's";
    ++files;
  }
  EXPECT_EQ(files, c.files) << "a trajectory and, if it has events, an events file";
}

INSTANTIATE_TEST_SUITE_P(
    Examples, CliCheckpoint,
    ::testing::Values(
        StopCase{"box_slides_to_rest", "0.5", "a box stopped in mid-slide"},
        StopCase{"cubli_falls_back", "0.3",
                 "a Cubli stopped between its lock (1 ms) and its landing"},
        StopCase{"planar/backspin_disk", "0.7", "a disk in the plane, before its reversal event"},
        StopCase{"bricard", "4", "Bricard's mechanism, its loop closed at each step", 1}),
    [](const ::testing::TestParamInfo<StopCase>& param) { return name_of(param.param); });

// What is not the stopped run's checkpoint, or not its trajectory, is refused before any row.
TEST(CliCheckpoint, AFileThatIsNotThisRunsCheckpointIsRefusedWithExitTwo) {
  const fs::path dir = test::fresh_test_dir("CliCheckpoint", "refusals");
  const std::string scenario = example("box_slides_to_rest.yaml");
  const fs::path part = dir / "part", state = dir / "stopped.state";
  ASSERT_EQ(
      run(scenario + " --out " + part.string() + " --stop-at 0.5 --save-state " + state.string())
          .status,
      0);
  const std::string saved = read_file(state);
  const std::string resume = " --resume " + state.string();

  // Another --set value: another run.
  const auto other_mu = run(scenario + " --set mu=0.31 --out " + (dir / "a").string() + resume);
  EXPECT_EQ(other_mu.status, 2) << other_mu.out;
  EXPECT_NE(other_mu.out.find("--set values"), std::string::npos) << other_mu.out;
  EXPECT_FALSE(fs::exists(dir / "a"));

  // Another scenario.
  const auto other_scenario =
      run(example("backspin_disk.yaml") + " --out " + (dir / "b").string() + resume);
  EXPECT_EQ(other_scenario.status, 2) << other_scenario.out;

  // One digit changed, or the file cut short: the digest of its lines does not match.
  std::string edited = saved;
  const std::size_t at = edited.find("integrator.h ");
  ASSERT_NE(at, std::string::npos);
  edited[at + 13] = edited[at + 13] == '1' ? '2' : '1';
  for (const std::string& text : {edited, saved.substr(0, saved.size() / 2)}) {
    std::ofstream(dir / "bad.state", std::ios::binary) << text;
    const auto bad = run(scenario + " --out " + (dir / "c").string() + " --resume " +
                         (dir / "bad.state").string());
    EXPECT_EQ(bad.status, 2) << bad.out;
    EXPECT_NE(bad.out.find("bad.state:0: not a whole tumble checkpoint"), std::string::npos)
        << bad.out;
  }

  // A trajectory under --out that is not the one the stopped run wrote.
  const std::string trajectory = "box_slides_to_rest.csv";
  std::ofstream(part / trajectory, std::ios::app) << "1,2,3\n";
  const auto other_rows = run(scenario + " --out " + part.string() + resume);
  EXPECT_EQ(other_rows.status, 2) << other_rows.out;
  EXPECT_NE(other_rows.out.find("is not the trajectory the stopped run wrote"), std::string::npos)
      << other_rows.out;

  // --stop-at and --save-state go together.
  EXPECT_EQ(run(scenario + " --stop-at 0.5").status, 2);
  EXPECT_EQ(run(scenario + " --save-state " + (dir / "x.state").string()).status, 2);
  EXPECT_EQ(run(scenario + " --stop-at soon --save-state x.state").status, 2);
}

// A state file without end, and a trajectory or a sweep's file to go on with that is a link to
// one, are refused at once, not read until memory runs out (or for ever, for the trajectory's
// digest): each read has its limit (docs/scenario.md, "Limits on input"), lowered here to 1 MiB
// so that the test reads little.
TEST(CliCheckpoint, FilesWithoutEndAreRefusedAtTheirLimit) {
  const fs::path dir = test::fresh_test_dir("CliCheckpoint", "without_end");
  const std::string scenario = example("box_slides_to_rest.yaml");
  const auto zero =
      test::run_tumble("run " + scenario + " --out " + (dir / "a").string() + " --resume /dev/zero",
                       "TUMBLE_MAX_CHECKPOINT_MIB=1 ");
  EXPECT_EQ(zero.status, 2) << zero.out;
  EXPECT_EQ(zero.out,
            "tumble run: --resume /dev/zero:0: goes on past the limit of 1 MiB (1048576 bytes) "
            "for a checkpoint file (set TUMBLE_MAX_CHECKPOINT_MIB to a larger number of MiB to "
            "raise it)\n");
  EXPECT_FALSE(fs::exists(dir / "a"));

  const fs::path part = dir / "part", state = dir / "stopped.state";
  ASSERT_EQ(
      run(scenario + " --out " + part.string() + " --stop-at 0.5 --save-state " + state.string())
          .status,
      0);
  const fs::path trajectory = part / "box_slides_to_rest.csv";
  fs::remove(trajectory);
  fs::create_symlink("/dev/zero", trajectory);
  const auto linked = run(scenario + " --out " + part.string() + " --resume " + state.string());
  EXPECT_EQ(linked.status, 2) << linked.out;
  EXPECT_NE(linked.out.find("is not the trajectory the stopped run wrote"), std::string::npos)
      << linked.out;

  const fs::path sweep = dir / "sweep";
  fs::create_directories(sweep);
  fs::create_symlink("/dev/zero", sweep / "sweep.csv");
  const auto resumed = test::run_tumble(
      "sweep " + scenario + " --vary mu=0.2:0.4:3 --out " + sweep.string() + " --resume",
      "TUMBLE_MAX_SWEEP_CSV_MIB=1 ");
  EXPECT_EQ(resumed.status, 2) << resumed.out;
  EXPECT_NE(resumed.out.find("sweep.csv: goes on past the limit of 1 MiB (1048576 bytes) for a "
                             "sweep file to resume (set TUMBLE_MAX_SWEEP_CSV_MIB"),
            std::string::npos)
      << resumed.out;
}

// The digest is no secret: a crafted state can carry a matching one. The fuzzer's first finding,
// a state whose direction of integration is 0, made the resumed run's first step throw, and
// `tumble run --resume` abort; the reader now refuses it at its line and key.
TEST(CliCheckpoint, ACraftedStateWithAMatchingDigestIsRefusedAtItsField) {
  const fs::path dir = test::fresh_test_dir("CliCheckpoint", "crafted");
  const std::string body = read_file(fs::path(TUMBLE_TEST_DATA_DIR) / "fuzz-checkpoint" /
                                     "refused-direction-zero.state");
  const fs::path state = dir / "crafted.state";
  std::ofstream(state, std::ios::binary)
      << body << fmt::format("digest {:016x}\n", content_digest(body));
  const auto crafted = run(example("planar/backspin_disk.yaml") + " --out " +
                           (dir / "out").string() + " --resume " + state.string());
  EXPECT_EQ(crafted.status, 2) << crafted.out;
  EXPECT_NE(crafted.out.find("integrator.direction: 1 (forward in time) or -1 (backward)"),
            std::string::npos)
      << crafted.out;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// A run that ends before --stop-at saves nothing, and says so.
TEST(CliCheckpoint, ARunThatEndsBeforeTheStopSavesNoState) {
  const fs::path dir = test::fresh_test_dir("CliCheckpoint", "no_stop");
  const fs::path state = dir / "never.state";
  const auto result = run(example("box_slides_to_rest.yaml") + " --out " + dir.string() +
                          " --stop-at 1e6 --save-state " + state.string());
  EXPECT_EQ(result.status, 0) << result.out;
  EXPECT_NE(result.out.find("before --stop-at 1e+06: no state saved"), std::string::npos)
      << result.out;
  EXPECT_FALSE(fs::exists(state));
}

}  // namespace
}  // namespace tumble
