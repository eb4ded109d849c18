// The command line as the contract states it: columns, rows, summary, exit statuses, error
// messages, atomic output and determinism, by running the real executable.
#include <gtest/gtest.h>

#include <algorithm>

#include "run_tumble.hpp"

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "prism_reference.hpp"
#include "test_files.hpp"

namespace tumble {
namespace {

namespace fs = std::filesystem;

using test::CommandResult;
using test::example;
using test::read_file;
using test::run_tumble;

fs::path fresh_run_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("tumble_cli_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path write_file(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p;
}

// The chapter's prism, spun near its intermediate axis with no gravity, with `simulate` keys.
std::string tumbling_box(const std::string& simulate) {
  return "tumble: 1\n"
         "gravity: [0, 0, 0]\n"
         "bodies:\n"
         "  b: {shape: box, size: [4, 1, 2], mass: 12, angular_velocity: [0, 0.01, 1]}\n"
         "simulate: " +
         simulate + "\n";
}

// Each line's fields, split at the commas outside quotes (an event's text may hold commas); a
// quoted field keeps its quotes.
std::vector<std::vector<std::string>> read_csv(const fs::path& p) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(p);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (const char ch : line) {
      if (ch == ',' && !quoted) {
        fields.emplace_back();
        continue;
      }
      if (ch == '"') quoted = !quoted;
      fields.back().push_back(ch);
    }
    rows.push_back(fields);
  }
  return rows;
}

TEST(Cli, VersionAndHelpOnEveryCommand) {
  for (const std::string cmd : {"--version", "run --version", "inertia --version"}) {
    const CommandResult r = run_tumble(cmd);
    EXPECT_EQ(r.status, 0) << cmd;
    EXPECT_NE(r.out.find("tumble 0."), std::string::npos) << cmd << ": " << r.out;
  }
  const CommandResult help = run_tumble("run --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("--set"), std::string::npos);
  EXPECT_NE(help.out.find("4 integration failed"), std::string::npos);
  EXPECT_EQ(run_tumble("inertia --help").status, 0);
}

TEST(Cli, BadCommandLinesExitWithStatusTwo) {
  EXPECT_EQ(run_tumble("").status, 2);
  EXPECT_EQ(run_tumble("fly").status, 2);
  EXPECT_EQ(run_tumble("run").status, 2);
  EXPECT_EQ(run_tumble("run " + example("tumbling_prism.yaml") + " --bogus").status, 2);
  const CommandResult bad_set = run_tumble("run " + example("tumbling_prism.yaml") + " --set a");
  EXPECT_EQ(bad_set.status, 2);
  EXPECT_NE(bad_set.out.find("--set a: expected NAME=VALUE"), std::string::npos) << bad_set.out;
  const CommandResult unknown_set =
      run_tumble("run " + example("tumbling_prism.yaml") + " --set zz=3");
  EXPECT_EQ(unknown_set.status, 2);
  EXPECT_NE(unknown_set.out.find("zz"), std::string::npos) << unknown_set.out;
  // An empty --out names no directory: a bad command line, not an unwritable output.
  const CommandResult empty_out = run_tumble("run " + example("tumbling_prism.yaml") + " --out ''");
  EXPECT_EQ(empty_out.status, 2) << empty_out.out;
  EXPECT_NE(empty_out.out.find("--out: an empty path names no directory"), std::string::npos)
      << empty_out.out;
}

// A row per adaptive step cannot be counted beforehand: the run stops at max_rows (exit 4), its
// CSV holding the rows so far.
TEST(Cli, ARunPastItsRowBudgetStopsWithTheRowsSoFar) {
  const fs::path dir = fresh_run_dir("rows");
  std::ofstream(dir / "spin.yaml")
      << "tumble: 1\nbodies:\n  top: {shape: box, size: [0.1, 0.2, 0.3], mass: 1, "
         "angular_velocity: [0, 1, 100]}\nsimulate: {duration: 1000, max_rows: 1000}\n";
  const CommandResult r =
      run_tumble("run " + (dir / "spin.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.status, 4) << r.out;
  EXPECT_NE(r.out.find("more than simulate.max_rows = 1000 output rows"), std::string::npos)
      << r.out;
  std::ifstream csv(dir / "out" / "spin.csv");
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 1 + 1000);  // the header and the budget's rows
}

// A scenario of format 2 that names no integrator runs `auto`: the stiff mount, its integrator
// line left out, switches to radau5 within its first millisecond and says so; the same file as
// format 1 runs dopri5, the contract's default, whose stability holds its steps.
TEST(Cli, AFormatTwoScenarioWithoutAnIntegratorFindsItsStiffnessByItself) {
  const fs::path dir = fresh_run_dir("format_two");
  std::string text = read_file(example("stiff_mount.yaml"));
  const std::size_t line = text.find("  integrator: radau5\n");
  ASSERT_NE(line, std::string::npos);
  text.erase(line, std::string("  integrator: radau5\n").size());
  const std::size_t version = text.find("\ntumble: 1\n");
  ASSERT_NE(version, std::string::npos);
  write_file(dir, "one.yaml", text);
  write_file(dir, "two.yaml", text.replace(version, 11, "\ntumble: 2\n"));
  const CommandResult two =
      run_tumble("run " + (dir / "two.yaml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(two.status, 0) << two.out;
  EXPECT_NE(two.out.find("integrator     auto "), std::string::npos) << two.out;
  EXPECT_NE(two.out.find("switch         to radau5 at t = 0.000140935 s: stiff"), std::string::npos)
      << two.out;
  const CommandResult one =
      run_tumble("run " + (dir / "one.yaml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(one.status, 0) << one.out;
  EXPECT_NE(one.out.find("integrator     dopri5 "), std::string::npos) << one.out;
}

// A video of more than 100,000 frames is refused before the run (exit 2), not after it.
TEST(Cli, AVideoOfTooManyFramesIsRefusedBeforeTheRun) {
  const fs::path dir = fresh_run_dir("frames");
  std::ofstream(dir / "long.yaml")
      << "tumble: 1\nbodies:\n  ball: {shape: sphere, radius: 0.1, mass: 1}\n"
         "simulate: {duration: 1e6, output_every: 10}\n";
  const CommandResult r =
      run_tumble("run " + (dir / "long.yaml").string() + " --out " + (dir / "out").string() +
                 " --video " + (dir / "long.mp4").string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("would take more than 100000 frames"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "out" / "long.csv"));  // no run
}

// A pendulum released level with its pivot, as near as round-off (E0 ~ 1e-16 J; a chain of 200
// links lying flat printed a relative drift of 2e+21): the drift is shown against the
// largest KE, not E0 (which printed 2e+21 for it), and against the largest |L|.
TEST(Cli, TheSummarysDriftsAreAgainstAScaleThatIsNotRoundOff) {
  const fs::path dir = fresh_run_dir("drift");
  std::ofstream(dir / "level.yaml")
      << "tumble: 1\nbodies:\n  bob: {shape: sphere, radius: 0.05, mass: 1, position: [1, 0, "
         "1e-17]}\n"
         "joints:\n  pivot: {type: hinge, body: bob, at: [0, 0, 0], axis: [0, 1, 0]}\n"
         "simulate: {duration: 1, rtol: 1e-10}\n";
  const CommandResult r =
      run_tumble("run " + (dir / "level.yaml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("of its scale"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(the larger of |E0| and the largest KE)"), std::string::npos) << r.out;
  // The energy's drift is the integration's (rtol 1e-10), not |dE| / 1e-16.
  const std::size_t line = r.out.find("energy E");
  ASSERT_NE(line, std::string::npos) << r.out;
  const std::size_t relative = r.out.find("J, ", line);
  ASSERT_NE(relative, std::string::npos) << r.out;
  EXPECT_LT(std::stod(r.out.substr(relative + 3)), 1e-8) << r.out;
}

// Two outputs at one path would leave only the last written: refused before the run, exit 3.
TEST(Cli, OutputsThatWouldShareAFileAreRefused) {
  const fs::path dir = fresh_run_dir("collide");
  const std::string ball =
      "tumble: 1\nbodies:\n  ball: {shape: sphere, radius: 0.1, mass: 1}\n"
      "simulate: {duration: 0.1}\n";
  std::ofstream(dir / "same.yaml")
      << ball + "output: {trajectory: base.csv, animation: base.csv}\n";
  const CommandResult same =
      run_tumble("run " + (dir / "same.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(same.status, 3) << same.out;
  EXPECT_NE(same.out.find("same.yaml:5:43: output.animation: 'base.csv' is output.trajectory too"),
            std::string::npos)
      << same.out;
  std::ofstream(dir / "page.yaml") << ball + "output: {trajectory: run.html}\n";
  const CommandResult page = run_tumble("run " + (dir / "page.yaml").string() +
                                        " --animate --out " + (dir / "out").string());
  EXPECT_EQ(page.status, 3) << page.out;
  EXPECT_NE(page.out.find("page.yaml:5:22: output.trajectory: 'run.html' is also the animation "
                          "page's name"),
            std::string::npos)
      << page.out;
  EXPECT_FALSE(fs::exists(dir / "out" / "run.html"));
}

// output.plots names trajectory columns: a name the run does not write is refused at its key,
// before the run and whether or not the page is asked for; a list that is not one of names too.
TEST(Cli, APlotOfAColumnTheRunDoesNotWriteIsRefusedAtItsKey) {
  const fs::path dir = fresh_run_dir("plots");
  const std::string ball =
      "tumble: 1\nbodies:\n  ball: {shape: sphere, radius: 0.1, mass: 1}\n"
      "simulate: {duration: 0.1}\n";
  std::ofstream(dir / "typo.yaml") << ball + "output:\n  plots: [ball.speed, [ball.z, bal.vz]]\n";
  const CommandResult typo =
      run_tumble("run " + (dir / "typo.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(typo.status, 3) << typo.out;
  EXPECT_NE(typo.out.find("typo.yaml:6:32: output.plots[1][1]: 'bal.vz' is not a column of this "
                          "run's trajectory"),
            std::string::npos)
      << typo.out;
  EXPECT_FALSE(fs::exists(dir / "out" / "typo.csv"));
  std::ofstream(dir / "nested.yaml") << ball + "output:\n  plots: [[ball.z, {a: 1}]]\n";
  const CommandResult nested = run_tumble("run " + (dir / "nested.yaml").string() +
                                          " --animate --out " + (dir / "out").string());
  EXPECT_EQ(nested.status, 3) << nested.out;
  EXPECT_NE(nested.out.find("output.plots[0][1]: expected a column's name"), std::string::npos)
      << nested.out;
  std::ofstream(dir / "good.yaml") << ball + "output:\n  plots: [ball.speed, [ball.z, ball.vz]]\n";
  const CommandResult good = run_tumble("run " + (dir / "good.yaml").string() +
                                        " --animate --out " + (dir / "out").string());
  EXPECT_EQ(good.status, 0) << good.out;
  EXPECT_TRUE(fs::exists(dir / "out" / "good.html"));
}

// Outputs that met only once the run knew its paths were written over each other with exit 0:
// the events file named as the page --animate derives (the events lost), a page named as the
// default events file, events written through a linked folder onto the trajectory. Each is now
// refused before the run, at the scenario's key, and nothing is written.
TEST(Cli, OutputsThatAreOneFileOnlyOnceResolvedAreRefusedBeforeTheRun) {
  const fs::path dir = fresh_run_dir("collide_resolved");
  const std::string ball =
      "tumble: 1\nbodies:\n  ball: {shape: sphere, radius: 0.1, mass: 1}\n"
      "simulate: {duration: 0.1}\n";
  fs::create_directories(dir / "out");
  fs::create_directory_symlink(".", dir / "out" / "here");
  const struct {
    std::string output, flags, expected;
  } cases[] = {
      {"output: {trajectory: run.csv, events: run.html}\n", " --animate",
       ":5:39: output.events: 'run.html' is also the animation page's name (--animate"},
      {"output: {animation: a_events.csv}\n", "",
       ":5:21: output.animation: 'a_events.csv' is also the events file's name (by default "
       "FILE_events.csv)"},
      {"output: {trajectory: run.csv, events: here/run.csv}\n", "",
       ":5:39: output.events: 'here/run.csv' is also the trajectory's file"},
      {"output: {trajectory: Run.csv, events: run.CSV}\n", "",
       ":5:39: output.events: 'run.CSV' is also the trajectory's file"},
  };
  for (const auto& c : cases) {
    std::ofstream(dir / "a.yaml") << ball + c.output;
    const CommandResult r = run_tumble("run " + (dir / "a.yaml").string() + c.flags + " --out " +
                                       (dir / "out").string());
    EXPECT_EQ(r.status, 3) << c.output << r.out;
    EXPECT_NE(r.out.find((dir / "a.yaml").string() + c.expected), std::string::npos)
        << c.output << r.out;
    std::set<std::string> written;
    for (const auto& entry : fs::directory_iterator(dir / "out")) {
      written.insert(entry.path().filename());
    }
    EXPECT_EQ(written, std::set<std::string>{"here"}) << c.output;
  }
}

// The chapter's prism end to end: the contract's columns, one row per output_every, the state
// at t = 20 within the tolerance the free-body tests establish (30 rtol), and a summary with
// every figure the contract lists.
TEST(Cli, RunsTheTumblingPrismAndWritesTheContractCsv) {
  const fs::path dir = fresh_run_dir("prism");
  const CommandResult r =
      run_tumble("run " + example("tumbling_prism.yaml") + " --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* figure :
       {"accepted", "rejected", "evaluations", "wall time", "energy E", "|L|", "|R^T R - I|"}) {
    EXPECT_NE(r.out.find(figure), std::string::npos) << figure << " missing from\n" << r.out;
  }
  const auto rows = read_csv(dir / "tumbling_prism.csv");
  ASSERT_EQ(rows.size(), 1u + 401u);  // header, t = 0, 0.05, ..., 20
  const std::vector<std::string> expected_header = {
      "t", "prism.x", "prism.y", "prism.z", "prism.vx", "prism.vy", "prism.vz", "prism.wx",
      "prism.wy", "prism.wz", "prism.R11", "prism.R12", "prism.R13", "prism.R21", "prism.R22",
      "prism.R23", "prism.R31", "prism.R32", "prism.R33", "KE", "PE", "E", "px", "py", "pz", "Lx",
      "Ly", "Lz",
      // After the contract's columns, tumble's own: omega in body axes (omega_1, omega_2,
      // omega_3 of Euler's equations), and the COM's speed.
      "prism.w1", "prism.w2", "prism.w3", "prism.speed"};
  EXPECT_EQ(rows[0], expected_header);
  for (std::size_t i = 1; i < rows.size(); ++i) ASSERT_EQ(rows[i].size(), expected_header.size());
  EXPECT_DOUBLE_EQ(std::stod(rows[200][0]), 9.95);
  EXPECT_EQ(std::stod(rows.back()[0]), 20.0);
  const auto& ref = testing::prism_case("unstable").states[0];
  Mat3 R;
  Vec3 w;
  for (int k = 0; k < 9; ++k) R(k / 3, k % 3) = std::stod(rows.back()[10 + k]);
  for (int k = 0; k < 3; ++k) w(k) = std::stod(rows.back()[7 + k]);
  EXPECT_LT(testing::state_error(R, w, ref), 30 * 1e-8);
  EXPECT_NEAR(std::stod(rows.back()[21]), 8.501, 1e-7);  // E
  // omega in body axes is R^T omega_W, row for row.
  for (std::size_t i = 1; i < rows.size(); i += 50) {
    for (int k = 0; k < 9; ++k) R(k / 3, k % 3) = std::stod(rows[i][10 + k]);
    for (int k = 0; k < 3; ++k) w(k) = std::stod(rows[i][7 + k]);
    const Vec3 omega_B = R.transpose() * w;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::stod(rows[i][28 + k]), omega_B(k), 1e-15);
  }
  // Nothing but the finished file is left behind.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++files;
    EXPECT_EQ(entry.path().filename(), "tumbling_prism.csv");
  }
  EXPECT_EQ(files, 1);
}

TEST(Cli, SameScenarioGivesBitIdenticalOutput) {
  const fs::path a = fresh_run_dir("det_a"), b = fresh_run_dir("det_b");
  ASSERT_EQ(
      run_tumble("run " + example("spinning_projectile.yaml") + " --out " + a.string()).status, 0);
  ASSERT_EQ(
      run_tumble("run " + example("spinning_projectile.yaml") + " --out " + b.string()).status, 0);
  const std::string csv_a = read_file(a / "spinning_projectile.csv");
  EXPECT_GT(csv_a.size(), 1000u);
  EXPECT_EQ(csv_a, read_file(b / "spinning_projectile.csv"));
}

TEST(Cli, InvalidScenarioExitsWithStatusThreeAndFileLineColumnKey) {
  const fs::path dir = fresh_run_dir("invalid");
  const fs::path p = write_file(dir, "bad.yaml",
                                "tumble: 1\n"
                                "bodies:\n"
                                "  b:\n"
                                "    shape: sphere\n"
                                "    radius: 0.1\n"
                                "    mass: -2\n"
                                "simulate: {duration: 1}\n");
  const CommandResult r = run_tumble("run " + p.string() + " --out " + dir.string());
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_NE(r.out.find(p.string() + ":6:11: bodies.b.mass:"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "bad.csv"));
}

// A run that fails part way (here: a step budget far too small) exits 4, says when and why, and
// leaves a valid CSV of the rows it reached.
TEST(Cli, FailedIntegrationLeavesAValidPartialCsvAndExitsFour) {
  const fs::path dir = fresh_run_dir("failed");
  const fs::path p =
      write_file(dir, "short.yaml", tumbling_box("{duration: 20, rtol: 1e-10, max_steps: 25}"));
  const CommandResult r = run_tumble("run " + p.string() + " --out " + dir.string());
  EXPECT_EQ(r.status, 4) << r.out;
  EXPECT_NE(r.out.find("integration failed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("max_steps"), std::string::npos) << r.out;
  const auto rows = read_csv(dir / "short.csv");
  ASSERT_GE(rows.size(), 2u);
  for (const auto& row : rows) EXPECT_EQ(row.size(), rows[0].size());
  EXPECT_LT(std::stod(rows.back()[0]), 20.0);
}

// The prism spun 1e100 times faster turns in 1e-100 s: its steps are of that size, and before it
// took them until simulate.max_steps (10 million: minutes) with exit 0 in the end. A thousand
// steps each under 1e-12 of the run's span end it at once, with exit 4, saying where and why, and
// with the rows it reached.
TEST(Cli, AStepSizeThatCollapsesEndsTheRunWithExitFour) {
  const fs::path dir = fresh_run_dir("collapsed");
  std::string text = read_file(example("tumbling_prism.yaml"));
  const std::string spin = "angular_velocity: [0, 0.01, 1]";
  ASSERT_NE(text.find(spin), std::string::npos);
  text.replace(text.find(spin), spin.size(), "angular_velocity: [0, 1e98, 1e100]");
  const fs::path p = write_file(dir, "extreme.yaml", text);
  const CommandResult r = run_tumble("run " + p.string() + " --out " + dir.string());
  EXPECT_EQ(r.status, 4) << r.out;
  EXPECT_NE(r.out.find("the step size collapsed at t = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the last 1000 steps were each shorter than 1e-12 of the run's 20 s"),
            std::string::npos)
      << r.out;
  const auto rows = read_csv(dir / "tumbling_prism.csv");
  ASSERT_GE(rows.size(), 2u);
  EXPECT_LT(std::stod(rows.back()[0]), 1e-9);
}

// A run whose contact no mode holds, or whose events come too fast to tell apart, ends with exit
// 4, saying where and why, and writes its rows and events so far. The first case: a box dropped
// on a 5.7 degree ramp (mu 1, e 0.6) bounces, slides and tips until, sticking on a vertex, a
// second vertex lands beside it still slipping: on that edge the first vertex cannot hold (its
// friction leaves its cone), and sliding on both the centre of pressure leaves the edge; on
// either vertex alone the other goes into the ramp. Apart, it lands again at once, a thousand
// times in 1e-7 s (Painleve's inconsistent case on two points): the run stops there. The second:
// a slender bar spinning at 40 rad/s with mu 5 lands on a vertex where friction so high leaves
// no mode (sliding, it presses the vertex on; apart, the vertex goes in), every 7e-10 s; its
// landings and their "apart"s, a thousand events within a millionth of the run's span, stop it
// first. (A spinning cone landing on its side used to chatter so, a thousand landings in 2e-7 s,
// until its side's friction was taken at each end: tests/pivot_test.cpp.)
TEST(Cli, ChatteringEventsEndTheRunWithExitFour) {
  const fs::path dir = fresh_run_dir("chatter");
  const fs::path cascade = write_file(
      dir, "cascade.yaml",
      "tumble: 1\n"
      "bodies:\n"
      "  b: {shape: box, size: [0.1, 0.06, 0.04], mass: 1, position: [0, 0, 0.2],\n"
      "      orientation: {axis: [1, 0.3, 0], angle: 25 deg}}\n"
      "contacts:\n"
      "  - {name: ramp, type: plane, body: b, plane: {point: [0, 0, 0], normal: [0.1, 0, 1]},\n"
      "     friction: 1, restitution: 0.6}\n"
      "simulate: {duration: 2, integrator: dop853, rtol: 1e-8, output_every: 0.001}\n");
  const CommandResult c = run_tumble("run " + cascade.string() + " --out " + dir.string());
  EXPECT_EQ(c.status, 4) << c.out;
  EXPECT_NE(c.out.find("that no contact mode holds"), std::string::npos) << c.out;
  const auto landings = read_csv(dir / "cascade_events.csv");
  ASSERT_GE(landings.size(), 1u + 2000u);  // each landing, then "apart"
  EXPECT_LT(landings.size(), 1u + 10000u);
  // Where: the message's first of the thousand landings is the events CSV's, 2000 events from
  // its end (when, after two seconds of bouncing, sliding and tipping on the ramp, depends on
  // every step before: it was 1.853 s before friction kept its direction past a slip's stop).
  const std::string from = "1000 landings from t = ";
  const std::size_t at = c.out.find(from);
  ASSERT_NE(at, std::string::npos) << c.out;
  const double first = std::stod(landings[landings.size() - 2000][0]);
  EXPECT_NEAR(std::stod(c.out.substr(at + from.size(), 12)), first, 1e-8 * first) << c.out;
  EXPECT_GT(first, 1.0);
  EXPECT_GT(read_csv(dir / "cascade.csv").size(), static_cast<std::size_t>(1000 * first));

  const fs::path p = write_file(
      dir, "chatter.yaml",
      "tumble: 1\n"
      "bodies:\n"
      "  b: {shape: box, size: [0.3, 0.02, 0.02], mass: 1, position: [0, 0, 0.2],\n"
      "      orientation: {axis: [1, 0.3, 0], angle: 45 deg},\n"
      "      angular_velocity: [3, -2, 40], velocity: [1, 0, 0]}\n"
      "contacts:\n"
      "  - {name: floor, type: plane, body: b, plane: {point: [0, 0, 0], normal: [0, 0, 1]},\n"
      "     friction: 5, restitution: 0.2}\n"
      "simulate: {duration: 1.5, integrator: dop853, rtol: 1e-9, output_every: 0.01}\n");
  const CommandResult r = run_tumble("run " + p.string() + " --out " + dir.string());
  EXPECT_EQ(r.status, 4) << r.out;
  EXPECT_NE(r.out.find("events chatter at t = 0.2893398"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the last 1000 came within"), std::string::npos) << r.out;
  const auto events = read_csv(dir / "chatter_events.csv");
  // The first thousand or so events, not millions; and the rows up to there.
  EXPECT_GE(events.size(), 1u + 1000u);
  EXPECT_LT(events.size(), 1u + 10000u);
  const auto rows = read_csv(dir / "chatter.csv");
  EXPECT_GT(rows.size(), 25u);  // to t = 0.29 s
}

TEST(Cli, ARunStoppedByASignalLeavesNoPartialFile) {
  // A run far longer than the half second it is given, stopped by SIGTERM, then by SIGINT (as
  // Ctrl-C does): it ends by the signal, and neither its CSV nor a temporary file is left.
  const fs::path dir = fresh_run_dir("stopped");
  const fs::path p = write_file(
      dir, "long.yaml", tumbling_box("{duration: 1000000, rtol: 1e-10, output_every: 1000}"));
  for (const char* signal_name : {"TERM", "INT"}) {
    const CommandResult r = run_tumble("run " + p.string() + " --out " + dir.string(),
                                       std::string("timeout -s ") + signal_name + " 0.5 ");
    EXPECT_EQ(r.status, 124) << signal_name << ": " << r.out;  // timeout's: it was stopped
    for (const auto& entry : fs::directory_iterator(dir)) {
      EXPECT_EQ(entry.path().filename(), "long.yaml") << signal_name << " left " << entry.path();
    }
  }
}

// `integrator: exact` with a scenario event (the prism's flip, on the closed form): the run
// completes (exit 0), names the event where it happened, writes it to the events CSV and leaves
// no temporary file.
TEST(Cli, TheExactIntegratorRunsAScenariosEvents) {
  const fs::path dir = fresh_run_dir("exact_event");
  std::string text = read_file(example("tumbling_prism.yaml"));
  const std::string dopri5 = "integrator: dopri5";
  ASSERT_NE(text.find(dopri5), std::string::npos);
  text.replace(text.find(dopri5), dopri5.size(), "integrator: exact");
  text.replace(text.find("simulate:"), 0, "events:\n  - {name: flip, when: prism.w3 < 0}\n");
  const fs::path p = write_file(dir, "exact_flip.yaml", text);
  const CommandResult r = run_tumble("run " + p.string() + " --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const std::size_t flip = r.out.find("event flip");
  ASSERT_NE(flip, std::string::npos) << r.out;
  const std::size_t line = r.out.rfind('\n', flip) + 1;
  EXPECT_EQ(r.out.substr(line, flip - line), "  t = 9.66409483408  ") << r.out;
  const auto events = read_csv(dir / "exact_flip_events.csv");
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[1][1], "\"event\"");  // texts are quoted
  EXPECT_NEAR(std::stod(events[1][0]), 9.664094834075236, 1e-9);
  std::set<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    files.insert(entry.path().filename().string());
  }
  EXPECT_EQ(files, (std::set<std::string>{"exact_flip.yaml", "exact_flip_events.csv",
                                          "tumbling_prism.csv"}));
}

TEST(Cli, UnwritableOutputDirectoryExitsFive) {
  const CommandResult r =
      run_tumble("run " + example("tumbling_prism.yaml") + " --out /proc/no_such_dir");
  EXPECT_EQ(r.status, 5) << r.out;
}

TEST(Cli, SetOverridesAParameter) {
  const fs::path dir = fresh_run_dir("set");
  // c = 1 makes the prism [4, 1, 1]: I0 = diag(2, 17, 17): the inertia command shows it.
  const CommandResult r = run_tumble("inertia " + example("tumbling_prism.yaml"));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("principal moments"), std::string::npos);
  EXPECT_NE(r.out.find("12 kg"), std::string::npos) << r.out;
  const CommandResult run = run_tumble("run " + example("tumbling_prism.yaml") +
                                       " --set c=1 --set 'a=2*2' --out " + dir.string());
  EXPECT_EQ(run.status, 0) << run.out;
  const auto rows = read_csv(dir / "tumbling_prism.csv");
  // KE at t = 0 with I0 = diag(2, 17, 17) and omega0 = (0, 0.01, 1): (17e-4 + 17) / 2.
  EXPECT_NEAR(std::stod(rows[1][19]), 0.5 * (17 * 1e-4 + 17), 1e-12);
}

TEST(Cli, InertiaOfOneBodyAndOfAnUnknownBody) {
  EXPECT_EQ(run_tumble("inertia " + example("tumbling_prism.yaml") + " prism").status, 0);
  const CommandResult r = run_tumble("inertia " + example("tumbling_prism.yaml") + " wheel");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("no body 'wheel'"), std::string::npos) << r.out;
}

// The column of `name` in a CSV's header row.
std::size_t column_of(const std::vector<std::string>& header, const std::string& name) {
  const auto it = std::find(header.begin(), header.end(), name);
  EXPECT_NE(it, header.end()) << name;
  return static_cast<std::size_t>(it - header.begin());
}

TEST(Cli, JointCoordinateColumnsAgreeWithTheBodiesPositions) {
  // The compound pendulum's hinge (axis y through O at the origin): its angle is the bat's turn
  // about y since t = 0, atan2(-x, -z) - theta0 from the COM's position, and its rate omega_y.
  const fs::path dir = fresh_run_dir("joint_columns");
  ASSERT_EQ(
      run_tumble("run " + example("compound_pendulum.yaml") + " --out " + dir.string()).status, 0);
  const auto rows = read_csv(dir / "compound_pendulum.csv");
  const auto& header = rows[0];
  const std::size_t x = column_of(header, "bat.x"), z = column_of(header, "bat.z");
  const std::size_t wy = column_of(header, "bat.wy");
  const std::size_t angle = column_of(header, "knob.angle"), rate = column_of(header, "knob.rate");
  const double theta0 = 5 * M_PI / 180;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double swing = std::atan2(-std::stod(rows[i][x]), -std::stod(rows[i][z])) - theta0;
    EXPECT_NEAR(std::stod(rows[i][angle]), swing, 1e-13) << rows[i][0];
    EXPECT_NEAR(std::stod(rows[i][rate]), std::stod(rows[i][wy]), 1e-13) << rows[i][0];
  }
  // The gyroscope's ball joint to ground: its rotation vector is R_WB's, as an angle and axis.
  ASSERT_EQ(run_tumble("run " + example("gyroscope.yaml") + " --out " + dir.string()).status, 0);
  const auto gyro = read_csv(dir / "gyroscope.csv");
  const std::size_t r11 = column_of(gyro[0], "wheel.R11"), rx = column_of(gyro[0], "pivot.rx");
  for (std::size_t i = 1; i < gyro.size(); i += 37) {
    Mat3 R;
    for (int k = 0; k < 9; ++k) R(k / 3, k % 3) = std::stod(gyro[i][r11 + k]);
    const Eigen::AngleAxisd turn(R);
    const Vec3 rotation = turn.angle() * turn.axis();
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(std::stod(gyro[i][rx + k]), rotation(k), 1e-12) << gyro[i][0];
    }
  }
}

TEST(Cli, TheEventsCsvHasEachJumpsReactionImpulses) {
  // The Cubli on the ground, its brake at t = 1 ms (equations.md, 6): angular momentum about O
  // carries over, the frame (at rest on the floor until then) and wheel turn together at
  // Omega = m R^2 w0 / I_total about -y, and the corner's impulse is what gives the pair its
  // momentum: (M + m) Omega L/2 (-1, 0, 1) (the centre at (L/2, 0, L/2) moving at
  // Omega L/2 (-1, 0, 1)); KE after, I_total Omega^2 / 2. The floor's events follow it.
  const fs::path dir = fresh_run_dir("events");
  const CommandResult r =
      run_tumble("run " + example("cubli_falls_back.yaml") + " --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const auto rows = read_csv(dir / "cubli_falls_back_events.csv");
  ASSERT_GE(rows.size(), 4u);
  const auto& header = rows[0];
  // (read_csv keeps the quotes.)
  EXPECT_EQ(rows[1][column_of(header, "what")], "\"sticks on a face\"");
  const auto& jump = rows[2];
  EXPECT_EQ(rows[3][column_of(header, "what")], "\"apart\"");
  EXPECT_EQ(jump[column_of(header, "t")], "0.001");
  EXPECT_EQ(jump[column_of(header, "source")], "\"jump\"");
  const double M = 0.8, m = 0.3, L = 0.15, R = 0.06, g = 9.81;
  const double I_total = M * L * L / 3 + (M + m) * L * L / 2 + m * R * R;
  const double w0_crit = std::sqrt((std::sqrt(2.0) - 1) * (M + m) * g * L * I_total) / (m * R * R);
  const double Omega = m * R * R * 0.95 * w0_crit / I_total;
  const double J = (M + m) * Omega * L / 2;
  EXPECT_NEAR(std::stod(jump[column_of(header, "corner.Fx")]), -J, 1e-9 * J);
  EXPECT_NEAR(std::stod(jump[column_of(header, "corner.Fz")]), J, 1e-9 * J);
  const double KE_after = 0.5 * I_total * Omega * Omega;
  EXPECT_NEAR(std::stod(jump[column_of(header, "KE_after")]), KE_after, 1e-9 * KE_after);
}

// The tennis ball dropped from h = 1 m onto a frictionless floor (no spin): it lands at
// v = sqrt(2 g h) (free flight is exact for dop853: a quadratic), leaves at e v (Newton's law,
// exact), and the floor's impulse is M (1 + e) v along the normal; the kinetic energy goes from
// M (vx^2 + v^2) / 2 to M (vx^2 + e^2 v^2) / 2. events.csv has them at full precision.
TEST(Cli, TheEventsCsvHasEachImpactsSpeedsImpulseAndEnergies) {
  const fs::path dir = fresh_run_dir("impact_numbers");
  const CommandResult r = run_tumble("run " + example("bouncing_ball.yaml") +
                                     " --set spin=0 --set mu=0 --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const auto rows = read_csv(dir / "bouncing_ball_events.csv");
  ASSERT_GE(rows.size(), 2u);
  const auto& header = rows[0];
  const auto& impact = rows[1];
  ASSERT_EQ(impact[column_of(header, "what")].rfind("\"impact", 0), 0u)
      << impact[column_of(header, "what")];
  const double M = 0.057, e = 0.75, g = 9.81, h = 1, vx = 0.5;
  const double v = std::sqrt(2 * g * h);
  const auto number = [&](const char* name) { return std::stod(impact[column_of(header, name)]); };
  EXPECT_NEAR(number("approach_speed"), v, 1e-12 * v);
  EXPECT_NEAR(number("rebound_speed"), e * v, 1e-12 * v);
  EXPECT_NEAR(number("Pz"), M * (1 + e) * v, 1e-12 * M * v);
  EXPECT_EQ(number("Px"), 0.0);
  EXPECT_EQ(number("Py"), 0.0);
  const double KE_before = 0.5 * M * (vx * vx + v * v);
  EXPECT_NEAR(number("KE_before"), KE_before, 1e-12 * KE_before);
  EXPECT_NEAR(number("KE_after"), 0.5 * M * (vx * vx + e * e * v * v), 1e-12 * KE_before);
  // The trajectory's speed column is |v| of the same row: vx throughout, vz falling and bouncing.
  const auto trajectory = read_csv(dir / "bouncing_ball.csv");
  const auto& columns = trajectory[0];
  for (std::size_t i = 1; i < trajectory.size(); i += 37) {
    double v2 = 0.0;
    for (const char* name : {"ball.vx", "ball.vy", "ball.vz"}) {
      v2 += std::pow(std::stod(trajectory[i][column_of(columns, name)]), 2);
    }
    const double speed = std::stod(trajectory[i][column_of(columns, "ball.speed")]);
    EXPECT_NEAR(speed, std::sqrt(v2), 1e-15 * speed) << "row " << i;
    EXPECT_GE(speed, vx);
  }
}

// The summary listed the contact events, then the jumps, then the scenario's events, each in its
// own order: a student reading it saw the blow after what it caused. Now one list in time order:
// the bat's swing past 0.05 s, the blow at 0.1 s, the swing past 0.2 s.
TEST(Cli, TheSummaryListsEventsAndJumpsInTimeOrder) {
  const fs::path dir = fresh_run_dir("time_order");
  std::string text = read_file(example("bat_struck.yaml"));
  const std::string simulate = "simulate:";
  ASSERT_NE(text.find(simulate), std::string::npos);
  text.insert(text.find(simulate),
              "events:\n  - {name: late, when: t > 0.2}\n  - {name: early, when: t > 0.05}\n");
  const fs::path p = write_file(dir, "bat_events.yaml", text);
  const CommandResult r = run_tumble("run " + p.string() + " --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const std::size_t early = r.out.find("t = 0.05 "), blow = r.out.find("t = 0.1 "),
                    late = r.out.find("t = 0.2 ");
  ASSERT_NE(early, std::string::npos) << r.out;
  ASSERT_NE(blow, std::string::npos) << r.out;
  ASSERT_NE(late, std::string::npos) << r.out;
  EXPECT_LT(early, blow) << r.out;
  EXPECT_LT(blow, late) << r.out;
  EXPECT_NE(r.out.find("t = 0.05           event early"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("t = 0.1            impulse ball"), std::string::npos) << r.out;
}

// The summary printed 6 digits (a jump's KE 1.66826 J) where students compare to 10: now 10 by
// default, and --digits 17 gives every double exactly. The bat struck at its centre of
// percussion (equations.md, 5) takes KE = (P d)^2 / (2 I_O) from the blow.
TEST(Cli, TheSummaryHasTenDigitsAndSeventeenOnRequest) {
  const double M = 0.9, length = 0.84, r = 0.03, L = length / 2, P = 1.5;
  const double I_O = M * (3 * r * r + length * length) / 12 + M * L * L;
  const double d = I_O / (M * L);
  const double KE = (P * d) * (P * d) / (2 * I_O);
  const fs::path dir = fresh_run_dir("digits");
  const auto ke_after = [&](const std::string& flags) {
    const CommandResult r_run =
        run_tumble("run " + example("bat_struck.yaml") + " --out " + dir.string() + flags);
    EXPECT_EQ(r_run.status, 0) << r_run.out;
    const std::string arrow = "impulse ball: KE 0 -> ";
    const std::size_t at = r_run.out.find(arrow);
    if (at == std::string::npos) {
      ADD_FAILURE() << r_run.out;
      return std::string();
    }
    const std::size_t from = at + arrow.size();
    return r_run.out.substr(from, r_run.out.find(' ', from) - from);
  };
  const std::string ten = ke_after(""), seventeen = ke_after(" --digits 17");
  EXPECT_EQ(ten.size(), std::string("1.668261054").size()) << ten;
  EXPECT_NEAR(std::stod(ten), KE, 5e-10 * KE);
  EXPECT_NEAR(std::stod(seventeen), KE, 1e-14 * KE);
  EXPECT_EQ(run_tumble("run " + example("bat_struck.yaml") + " --digits 18").status, 2);
}

TEST(Cli, TheSummarySaysEIsConservedWhereContactsOnlyRolled) {
  // Three bodies rolling down a ramp without slip: friction acts but does no work (equations.md,
  // rolling), so E is conserved; the backspin disk slides first, and its friction does work.
  const fs::path dir = fresh_run_dir("workless");
  const CommandResult rolls =
      run_tumble("run " + example("ramp_race.yaml") + " --out " + dir.string());
  EXPECT_EQ(rolls.status, 0) << rolls.out;
  EXPECT_NE(rolls.out.find("the contacts did no work"), std::string::npos) << rolls.out;
  EXPECT_NE(rolls.out.find("E is conserved)"), std::string::npos) << rolls.out;
  const CommandResult slides =
      run_tumble("run " + example("backspin_disk.yaml") + " --out " + dir.string());
  EXPECT_EQ(slides.status, 0) << slides.out;
  EXPECT_NE(slides.out.find("E is not conserved"), std::string::npos) << slides.out;
  // A ball sliding on a frictionless floor does no work either, and is not said to have rolled
  // (before: "they rolled or stuck").
  const fs::path p = write_file(dir, "frictionless.yaml",
                                "tumble: 1\n"
                                "bodies:\n"
                                "  ball: {shape: sphere, radius: 0.1, mass: 1, position: [0, 0, "
                                "0.1], velocity: [2, 0, 0], angular_velocity: [0, 0, 5]}\n"
                                "contacts:\n"
                                "  - {name: floor, type: plane, body: ball, plane: {point: [0, 0, "
                                "0], normal: [0, 0, 1]}, friction: 0}\n"
                                "simulate: {duration: 1}\n");
  const CommandResult frictionless = run_tumble("run " + p.string() + " --out " + dir.string());
  EXPECT_EQ(frictionless.status, 0) << frictionless.out;
  EXPECT_NE(frictionless.out.find("sliding without friction do none"), std::string::npos)
      << frictionless.out;
  EXPECT_EQ(frictionless.out.find("rolled"), std::string::npos) << frictionless.out;
  EXPECT_NE(frictionless.out.find("E is conserved)"), std::string::npos) << frictionless.out;
}

// Red-team finding: an event's `when: prism.w3 = -5` wrote -5 into the row the later events read,
// so that they did not happen. It is refused where it is written, as the reader's other errors.
TEST(Cli, AnEventThatAssignsIsRefusedWhereItIsWritten) {
  const fs::path dir = fresh_run_dir("event_assigns");
  const fs::path p = write_file(dir, "prism.yaml",
                                "tumble: 1\n"
                                "gravity: [0, 0, 0]\n"
                                "bodies:\n"
                                "  prism: {shape: box, size: [4, 1, 2], mass: 12, "
                                "angular_velocity: [0, 0.01, 1]}\n"
                                "events:\n"
                                "  - {name: spoil, when: prism.w3 = -5}\n"
                                "  - {name: flip, when: prism.w3 < 0}\n"
                                "simulate: {duration: 12, integrator: dop853, rtol: 1e-10}\n");
  const CommandResult r = run_tumble("run " + p.string() + " --out " + dir.string());
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_NE(r.out.find(p.string() +
                       ":6:25: events[0].when: expression 'prism.w3 = -5': '=' would assign a "
                       "value; an expression only reads its names"),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(dir / "prism.csv"));
}

TEST(Cli, InertiaAboutAPivotNeedsNoSimulateSection) {
  // A uniform rod of length L hung from its end O: I_O = M L^2/3 (+ M r^2/4 of its thickness)
  // about the axes across it, by the parallel axis theorem from I_G = M (3 r^2 + L^2)/12.
  const fs::path dir = fresh_run_dir("inertia_about");
  const fs::path p = write_file(dir, "rod.yaml",
                                "tumble: 1\nbodies:\n  rod: {shape: cylinder, radius: 0.01, "
                                "length: 1, mass: 3, position: [0, 0, -0.5]}\n");
  const CommandResult r = run_tumble("inertia " + p.string() + " --about 0 0 0");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("inertia about O = [0 0 0]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1.000075"), std::string::npos) << r.out;  // 3 (1/3 + 1e-4/4)
  EXPECT_EQ(run_tumble("inertia " + p.string() + " --about 0 0").status, 2);
  // Each coordinate must be a finite number: --about nan 0 0 printed NaN tensors with exit 0.
  for (const std::string bad : {"nan", "inf", "1e999"}) {
    const CommandResult refused = run_tumble("inertia " + p.string() + " --about 0 " + bad + " 0");
    EXPECT_EQ(refused.status, 2) << refused.out;
    EXPECT_NE(refused.out.find("--about: " + bad +
                               " is out of range: expected a finite number (m, world)"),
              std::string::npos)
        << refused.out;
    EXPECT_EQ(refused.out.find("inertia about O"), std::string::npos) << refused.out;
  }
  const CommandResult word = run_tumble("inertia " + p.string() + " --about 0 0 north");
  EXPECT_EQ(word.status, 2) << word.out;
  EXPECT_NE(word.out.find("--about: 'north' is not a number"), std::string::npos) << word.out;
  // `tumble run` still needs it.
  const CommandResult run = run_tumble("run " + p.string() + " --out " + dir.string());
  EXPECT_EQ(run.status, 3);
  EXPECT_NE(run.out.find("missing required key 'simulate'"), std::string::npos) << run.out;
}

// The red team's `tumble run /dev/zero` read until memory ran out (an abort, or the OOM killer):
// now each file read has a limit (docs/scenario.md, "Limits on input"), refused at once, and a
// command that runs out of memory all the same says so with exit 5, not an abort.
TEST(Cli, AFileWithoutEndOrTooLargeIsRefusedAtItsLimit) {
  const std::string limit =
      "the limit of 64 MiB (67108864 bytes) for a scenario file (set TUMBLE_MAX_SCENARIO_MIB to "
      "a larger number of MiB to raise it)";
  // /dev/zero under a limit lowered to 1 MiB, so that the test reads little (the default's read
  // is the same, 64 times longer).
  const std::string out = " --out " + fresh_run_dir("dev_zero").string();
  for (const std::string& command :
       {"run /dev/zero" + out, std::string("inertia /dev/zero"), "modes /dev/zero" + out}) {
    const CommandResult r = run_tumble(command, "TUMBLE_MAX_SCENARIO_MIB=1 ");
    EXPECT_EQ(r.status, 3) << command << "\n" << r.out;
    EXPECT_EQ(r.out,
              "/dev/zero:0:0: goes on past the limit of 1 MiB (1048576 bytes) for a scenario file "
              "(set TUMBLE_MAX_SCENARIO_MIB to a larger number of MiB to raise it)\n")
        << command;
  }
  const fs::path dir = fresh_run_dir("huge_scenario");
  const fs::path huge = dir / "huge.yaml";
  std::ofstream(huge) << "tumble: 1\n";
  fs::resize_file(huge, std::uintmax_t{64} << 30);  // sparse: 64 GiB that use no disk
  const CommandResult r = run_tumble("run " + huge.string() + " --out " + dir.string());
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_EQ(r.out, huge.string() + ":0:0: is 68719476736 bytes, larger than " + limit + "\n");
  const CommandResult sweep =
      run_tumble("sweep " + huge.string() + " --vary a=1:2:2 --out " + dir.string());
  EXPECT_EQ(sweep.status, 3) << sweep.out;
  EXPECT_NE(sweep.out.find("is 68719476736 bytes, larger than"), std::string::npos) << sweep.out;
  // tumble plot reads a CSV's header row, which /dev/zero never ends.
  const CommandResult plot =
      run_tumble("plot /dev/zero --columns a -o " + (dir / "zero.svg").string());
  EXPECT_EQ(plot.status, 2) << plot.out;
  EXPECT_NE(plot.out.find("/dev/zero: its header row goes on past the limit of 1 MiB (1048576 "
                          "bytes) for a CSV header row (set TUMBLE_MAX_CSV_HEADER_MIB"),
            std::string::npos)
      << plot.out;
}

TEST(Cli, RunningOutOfMemoryIsExitFiveWithOneLine) {
#ifdef TUMBLE_SANITIZER_BUILD
  GTEST_SKIP() << "a sanitizer's shadow memory does not fit under ulimit -v";
#endif
  // The limit raised past the memory there is: /dev/zero is read until an allocation fails.
  const CommandResult r = run_tumble("run /dev/zero --out " + fresh_run_dir("oom").string(),
                                     "ulimit -v 60000; TUMBLE_MAX_SCENARIO_MIB=1000000 ");
  EXPECT_EQ(r.status, 5) << r.out;
  EXPECT_EQ(r.out, "tumble run: out of memory\n");
}

}  // namespace
}  // namespace tumble
