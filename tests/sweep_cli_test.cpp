// tumble sweep and tumble find as a user runs them: sweep.csv the same bytes on 1 and 2 threads,
// and each bad argument refused with its exit status and its name.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_tumble.hpp"
#include "test_files.hpp"

namespace tumble {
namespace {

using test::quote_for_shell;
using test::run_tumble;

const std::string kExamples = std::string(TUMBLE_SOURCE_DIR) + "/examples/";

TEST(SweepCommand, SameFileOnOneAndTwoThreads) {
  const auto dir = test::fresh_test_dir("SweepCommand", "threads");
  const std::string common = "sweep " + kExamples +
                             "tumbling_prism.yaml --vary a=3:5:4 --vary c=1.5:2.5:3 --record "
                             "'flip=time_of_max(-prism.w3)' --record 'top=max(prism.w1)' --out ";
  const auto one = run_tumble(common + (dir / "one").string() + " --threads 1");
  ASSERT_EQ(one.status, 0) << one.out;
  const auto two = run_tumble(common + (dir / "two").string() + " --threads 2");
  ASSERT_EQ(two.status, 0) << two.out;
  const std::string csv = test::read_file(dir / "one" / "sweep.csv");
  EXPECT_EQ(csv, test::read_file(dir / "two" / "sweep.csv"));
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "run,a,c,status,steps,E_drift,L_drift,flip,top,message");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 13);
  EXPECT_NE(one.out.find("12 (a grid), all ok"), std::string::npos) << one.out;
}

TEST(SweepCommand, RandomPointsAreSeeded) {
  const auto dir = test::fresh_test_dir("SweepCommand", "random");
  const std::string common =
      "sweep " + kExamples + "tumbling_prism.yaml --vary a=3:5 --random 5 --record 'w=final(E)'";
  ASSERT_EQ(run_tumble(common + " --seed 7 --out " + (dir / "a").string()).status, 0);
  ASSERT_EQ(run_tumble(common + " --seed 7 --threads 1 --out " + (dir / "b").string()).status, 0);
  ASSERT_EQ(run_tumble(common + " --seed 8 --out " + (dir / "c").string()).status, 0);
  EXPECT_EQ(test::read_file(dir / "a" / "sweep.csv"), test::read_file(dir / "b" / "sweep.csv"));
  EXPECT_NE(test::read_file(dir / "a" / "sweep.csv"), test::read_file(dir / "c" / "sweep.csv"));
}

TEST(SweepCommand, BadArgumentsExitTwoAndNameThem) {
  const std::string prism = kExamples + "tumbling_prism.yaml";
  const struct {
    std::string arguments, named;
  } cases[] = {
      {"sweep " + prism + " --vary q=1:2:3", "no parameter q"},
      {"sweep " + prism + " --vary a=2:2:3", "--vary a=2:2:3: empty range"},
      {"sweep " + prism + " --vary a=2:1", "--vary a=2:1"},
      {"sweep " + prism + " --vary a=1:2:0", "empty range"},
      {"sweep " + prism + " --vary a=1:2:3 --vary a=1:2:2", "varied twice"},
      {"sweep " + prism + " --vary a=1:2:3 --record 'x=max(prism.w3'", "is not closed"},
      {"sweep " + prism + " --vary a=1:2:3 --record 'x=prism.w3'", "names no reduction"},
      {"sweep " + prism + " --vary a=1:2:3 --record 'x=max(prism.w9)'", "prism.w9"},
      {"sweep " + prism + " --vary a=1:2:3 --record 'x=first(floor.rolls)'", "floor.rolls"},
      {"sweep " + prism + " --vary a=1:2:3 --record 'max(prism.w3)'", "NAME=REDUCTION"},
      // A record named like a column of sweep.csv, a parameter or another record gave two
      // columns of one name (exit 0), of which Python and `tumble plot` picked different ones.
      {"sweep " + prism + " --vary a=1:2:3 --record 'a=max(prism.w3)'",
       "--record a=max(prism.w3): 'a' is a parameter of"},
      {"sweep " + prism + " --vary a=1:2:3 --record 'b=max(prism.w3)'", "'b' is a parameter"},
      {"sweep " + prism + " --vary a=1:2:3 --record 'status=max(prism.w3)'",
       "'status' heads one of sweep.csv's own columns"},
      {"sweep " + prism + " --vary a=1:2:3 --record 'x=max(E)' --record 'x=min(E)'",
       "--record x=min(E): 'x' is given twice"},
      {"sweep " + prism + " --vary a=1:3:2 --out ''", "--out"},
      {"find " + prism + " --vary a=1:2:3 --when 'max(prism.w3) > 0'", "NAME=LO:HI"},
      {"find " + prism + " --vary a=3:5 --when 'prism.w3 > 0'", "--when"},
      {"find " + prism + " --vary a=3:5 --when 'min(prism.w3) > 2'", "false at both ends"},
  };
  for (const auto& c : cases) {
    const auto result = run_tumble(c.arguments);
    EXPECT_EQ(result.status, 2) << c.arguments << "\n" << result.out;
    EXPECT_NE(result.out.find(c.named), std::string::npos) << c.arguments << "\n" << result.out;
  }
}

TEST(SweepCommand, ScenarioErrorExitsThree) {
  const auto dir = test::fresh_test_dir("SweepCommand", "invalid");
  const auto bad = dir / "bad.yaml";
  {
    std::ofstream out(bad);
    out << "tumble: 1\nparameters: {m: 1}\nbodies:\n  b: {shape: sphere, radius: 1, mass: -m}\n"
           "simulate: {duration: 1}\n";
  }
  for (const std::string command : {"sweep", "find"}) {
    const std::string vary = command == "sweep" ? " --vary m=1:2:2" : " --vary m=1:2";
    const std::string when = command == "sweep" ? "" : " --when 'max(b.z) > 0'";
    const auto result = run_tumble(command + " " + bad.string() + vary + when);
    EXPECT_EQ(result.status, 3) << result.out;
    EXPECT_NE(result.out.find("bad.yaml:4:"), std::string::npos) << result.out;
  }
}

// Red-team finding: muParser's `=` wrote into the row the sweep's other records read (y came out
// 100 instead of 1, z nan instead of 9.66, exit 0). An expression that assigns is refused, in any
// reduction, in the expression over them, and in find's condition, with the flag and the text.
TEST(SweepCommand, AnExpressionThatAssignsIsRefused) {
  const std::string prism = kExamples + "tumbling_prism.yaml";
  const std::string refused = "'=' would assign a value; an expression only reads its names";
  const struct {
    std::string arguments, named;
  } cases[] = {
      {"sweep " + prism +
           " --vary a=3:5:2 --record 'x=max(prism.w3 = 100)' --record 'y=final(prism.w3)' "
           "--record 'z=first(prism.w3 < 0)'",
       "--record max(prism.w3 = 100): expression 'prism.w3 = 100': " + refused},
      {"sweep " + prism + " --vary a=3:5:2 --record 'x=first(prism.w3 = 5)'",
       "--record first(prism.w3 = 5): expression 'prism.w3 = 5': " + refused},
      {"sweep " + prism + " --vary a=3:5:2 --record 'x=final(prism.w3) + (a = 1)'",
       "--record final(prism.w3) + (a = 1): expression '__r0 + (a = 1)': " + refused},
      {"sweep " + prism + " --vary a=3:5:2 --record 'x=min(prism.w1 += 1)'",
       "--record min(prism.w1 += 1): expression 'prism.w1 += 1': " + refused},
      {"find " + prism + " --vary a=3:5 --when 'max(prism.w3) = 1'",
       "--when max(prism.w3) = 1: expression '__r0 = 1': " + refused},
      {"find " + prism + " --vary a=3:5 --when 'max(prism.w3 = 1) > 0'",
       "--when max(prism.w3 = 1) > 0: expression 'prism.w3 = 1': " + refused},
      {"sweep " + prism + " --vary 'a=3:b=5:2' --record 'x=max(prism.w3)'",
       "--vary a=3:b=5:2: STOP: expression 'b=5': " + refused},
      {"sweep " + prism + " --vary a=3:5:2 --set 'b=c=1' --record 'x=max(prism.w3)'",
       "--set b=c=1: expression 'c=1': " + refused},
  };
  for (const auto& c : cases) {
    const auto result = run_tumble(c.arguments);
    EXPECT_EQ(result.status, 2) << c.arguments << "\n" << result.out;
    EXPECT_NE(result.out.find(c.named), std::string::npos) << c.arguments << "\n" << result.out;
  }
  // == still compares, as it did.
  const auto dir = test::fresh_test_dir("SweepCommand", "equals");
  const auto equal = run_tumble("sweep " + prism +
                                " --vary a=4:4:1 --record 'same=final(prism.w3) == "
                                "final(prism.w3)' --record 'w=final(prism.w3)' --out " +
                                dir.string());
  ASSERT_EQ(equal.status, 0) << equal.out;
  const std::string csv = test::read_file(dir / "sweep.csv");
  ASSERT_EQ(csv.substr(0, csv.find('\n')), "run,a,status,steps,E_drift,L_drift,same,w,message");
  std::vector<std::string> cells;
  std::stringstream row(csv.substr(csv.find('\n') + 1));
  for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
  ASSERT_GE(cells.size(), 8u) << csv;
  EXPECT_EQ(cells[2], "ok") << csv;
  EXPECT_EQ(cells[6], "1") << csv;
}

// A reduction takes one argument: final(a, E) was read as final(E), muParser keeping the last of
// its values.
TEST(SweepCommand, AReductionOfTwoArgumentsIsRefused) {
  const std::string prism = kExamples + "tumbling_prism.yaml";
  const struct {
    std::string arguments, named;
  } cases[] = {
      {"sweep " + prism + " --vary a=3:5:2 --record 'x=final(a, E)'",
       "--record 'final(a, E)': final() takes one argument (a column or an expression of "
       "columns), got 2: 'a, E'"},
      {"sweep " + prism + " --vary a=3:5:2 --record 'x=max(prism.w1, max(E, KE), 2)'",
       "max() takes one argument (a column or an expression of columns), got 3"},
      {"sweep " + prism + " --vary a=3:5:2 --record 'x=first(prism.w3 < 0, 1)'",
       "first() takes one argument (an event or a condition), got 2"},
      {"find " + prism + " --vary a=3:5 --when 'count(prism.w3 < 0, E) > 0'",
       "--when 'count(prism.w3 < 0, E) > 0': count() takes one argument"},
      {"sweep " + prism + " --vary a=3:5:2 --record 'x=final(prism.w3), 2'",
       "gives 2 values (a comma outside a function's brackets)"},
  };
  for (const auto& c : cases) {
    const auto result = run_tumble(c.arguments);
    EXPECT_EQ(result.status, 2) << c.arguments << "\n" << result.out;
    EXPECT_NE(result.out.find(c.named), std::string::npos) << c.arguments << "\n" << result.out;
  }
}

// Numbers on the command line are checked, not replaced: find --tol 0, -1 or nan took the default
// width, sweep --seed -1 or 2^64 became 2^64 - 1.
TEST(SweepCommand, NumericFlagsOutOfRangeAreRefused) {
  const std::string prism = kExamples + "tumbling_prism.yaml";
  const std::string find = "find " + prism + " --vary a=3:5 --when 'min(prism.w3) > 2' --tol ";
  const std::string tol_range = "expected a finite number > 0 (the final bracket's width)";
  const std::string sweep = "sweep " + prism + " --vary a=3:5 --random 2 --seed ";
  const std::string seed_range = "expected a whole number from 0 to 18446744073709551615";
  const struct {
    std::string arguments, named;
  } cases[] = {
      {find + "0", "--tol: 0 is out of range: " + tol_range},
      {find + "-1", "--tol: -1 is out of range: " + tol_range},
      {find + "nan", "--tol: nan is out of range: " + tol_range},
      {find + "inf", "--tol: inf is out of range: " + tol_range},
      {find + "-0", "--tol: -0 is out of range: " + tol_range},
      {find + "1e-400", "--tol: 1e-400 is out of range: " + tol_range},
      {find + "wide", "--tol: 'wide' is not a number: " + tol_range},
      {find + "0x10", "--tol: '0x10' is not a number: " + tol_range},
      {sweep + "-1", "--seed: -1 is out of range: " + seed_range},
      {sweep + "18446744073709551616",
       "--seed: 18446744073709551616 is out of range: " + seed_range},
      {sweep + "1.5", "--seed: 1.5 is not a whole number: " + seed_range},
      {sweep + "seven", "--seed: seven is not a whole number: " + seed_range},
  };
  for (const auto& c : cases) {
    const auto result = run_tumble(c.arguments);
    EXPECT_EQ(result.status, 2) << c.arguments << "\n" << result.out;
    EXPECT_NE(result.out.find(c.named), std::string::npos) << c.arguments << "\n" << result.out;
  }
  // The largest seed is one.
  const auto dir = test::fresh_test_dir("SweepCommand", "largest_seed");
  const auto largest =
      run_tumble(sweep + "18446744073709551615 --record 'w=final(E)' --out " + dir.string());
  EXPECT_EQ(largest.status, 0) << largest.out;
  EXPECT_NE(largest.out.find("random points, seed 18446744073709551615"), std::string::npos)
      << largest.out;
}

// --threads 1024 under a memory limit aborted (an uncaught std::system_error, exit 134); a count
// over the limit is refused before any run. 256 itself is taken (a sweep of two points runs on
// two of them).
TEST(SweepCommand, ThreadsOverTheLimitAreRefused) {
  const std::string sweep =
      "sweep " + kExamples + "tumbling_prism.yaml --vary a=3:5:2 --record 'w=final(E)' --threads ";
  for (const std::string threads : {"257", "1024", "10000", "0", "-1", "2.5"}) {
    const auto result = run_tumble(sweep + threads);
    EXPECT_EQ(result.status, 2) << threads << "\n" << result.out;
    EXPECT_NE(result.out.find("--threads: " + threads + " is "), std::string::npos) << result.out;
    EXPECT_NE(result.out.find(": expected a whole number from 1 to 256 (the limit on a sweep's "
                              "threads)"),
              std::string::npos)
        << result.out;
  }
  const auto dir = test::fresh_test_dir("SweepCommand", "threads_256");
  const auto largest = run_tumble(sweep + "256 --out " + dir.string());
  EXPECT_EQ(largest.status, 0) << largest.out;
}

// A sweep whose --out could not be written ran every point, then exited 5 with the results lost:
// --out is checked before the first run. Under a regular file, so that root cannot write it.
TEST(SweepCommand, AnOutThatCannotBeWrittenIsRefusedBeforeTheRuns) {
  const auto dir = test::fresh_test_dir("SweepCommand", "unwritable_out");
  const std::string file = (dir / "a_file").string();
  std::ofstream(file) << "not a directory\n";
  const auto result =
      run_tumble("sweep " + kExamples +
                 "tumbling_prism.yaml --vary a=3:5:4 --record 'w=final(E)' --out " + file + "/sub");
  EXPECT_EQ(result.status, 5) << result.out;
  EXPECT_EQ(result.out, "tumble sweep: --out " + file + "/sub: cannot create the directory " +
                            file + "/sub: Not a directory\n");
}

// sweep.csv was written once every run was done: a sweep killed part way left nothing (hours of
// a real study). Now it is in place with its header before the first run and each row is added
// as it and the runs before it finish: killed (SIGKILL, so nothing of tumble's runs after it) 2 s
// into a million runs, it leaves a valid sweep.csv of its first runs, in order. (Twenty thousand
// took 1.2 s on a fast machine, which finished them before the kill; a million take a minute.)
TEST(SweepCommand, ASweepKilledPartWayLeavesTheRowsItFinished) {
  const auto dir = test::fresh_test_dir("SweepCommand", "killed");
  const auto result =
      run_tumble("sweep " + kExamples +
                     "sweeps/prism_flip_time.yaml --vary decades=2:8:1000000 --record "
                     "'flip=first(prism.w3 < 0)' --threads 2 --out " +
                     dir.string(),
                 "timeout -s KILL 2 ");
  ASSERT_EQ(result.status, 137) << "not killed: " << result.out;  // timeout: 128 + SIGKILL
  std::ifstream in(dir / "sweep.csv");
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(line, "run,decades,status,steps,E_drift,L_drift,flip,message");
  long rows = 0;
  while (std::getline(in, line)) {
    EXPECT_EQ(line.rfind(std::to_string(rows) + ",", 0), 0u) << "row " << rows << ": " << line;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 7) << line;
    EXPECT_NE(line.find(",ok,"), std::string::npos) << line;
    ++rows;
  }
  EXPECT_TRUE(in.eof());
  EXPECT_GE(rows, 1);
  EXPECT_LT(rows, 1000000);
}

// A sweep stopped part way (here: its sweep.csv cut after 123 whole rows and part of the next,
// as a kill leaves it) goes on with --resume: the rows there are kept, the rest run, and the
// file is the uninterrupted sweep's, byte for byte. A sweep.csv of another sweep (other
// records, another range) is refused with exit 2, untouched.
TEST(SweepCommand, AStoppedSweepResumesToTheUninterruptedFile) {
  const auto dir = test::fresh_test_dir("SweepCommand", "resume");
  const std::string sweep = "sweep " + kExamples +
                            "sweeps/prism_flip_time.yaml --record 'flip=first(prism.w3 < 0)' "
                            "--threads 2 --vary decades=2:8:";
  ASSERT_EQ(run_tumble(sweep + "300 --out " + (dir / "whole").string()).status, 0);
  const std::string whole = test::read_file(dir / "whole" / "sweep.csv");
  std::size_t cut = 0;
  for (int line = 0; line < 1 + 123; ++line) cut = whole.find('\n', cut) + 1;
  std::filesystem::create_directories(dir / "stopped");
  std::ofstream(dir / "stopped" / "sweep.csv") << whole.substr(0, cut + 7);  // + "123,5.4"
  const auto resumed = run_tumble(sweep + "300 --resume --out " + (dir / "stopped").string());
  ASSERT_EQ(resumed.status, 0) << resumed.out;
  EXPECT_NE(resumed.out.find("the first 123 kept from sweep.csv"), std::string::npos)
      << resumed.out;
  EXPECT_EQ(test::read_file(dir / "stopped" / "sweep.csv"), whole);
  // Resumed again, there is nothing left to run: the same file.
  ASSERT_EQ(run_tumble(sweep + "300 --resume --out " + (dir / "stopped").string()).status, 0);
  EXPECT_EQ(test::read_file(dir / "stopped" / "sweep.csv"), whole);
  const auto other_range = run_tumble(sweep + "200 --resume --out " + (dir / "whole").string());
  EXPECT_EQ(other_range.status, 2) << other_range.out;
  EXPECT_NE(other_range.out.find("is another sweep's: its row 2 is not this sweep's run 1"),
            std::string::npos)
      << other_range.out;
  const auto other_records =
      run_tumble("sweep " + kExamples +
                 "sweeps/prism_flip_time.yaml --record 'w=final(E)' --vary decades=2:8:300 "
                 "--resume --out " +
                 (dir / "whole").string());
  EXPECT_EQ(other_records.status, 2) << other_records.out;
  EXPECT_NE(other_records.out.find("is another sweep's (its header is"), std::string::npos)
      << other_records.out;
  EXPECT_EQ(test::read_file(dir / "whole" / "sweep.csv"), whole);
}

TEST(FindCommand, PrintsTheBracketAndTheRuns) {
  const auto result =
      run_tumble("find " + kExamples + "sweeps/mast_critical_spring.yaml --vary k=20:40 --when " +
                 quote_for_shell("max(abs(base.angle)) > theta_seen") + " --tol 1e-4");
  ASSERT_EQ(result.status, 0) << result.out;
  // M g L / 2 = 29.43 N m/rad (the middle of a bracket 1e-4 wide is within 5e-5 of it);
  // bisection from a width of 20 to 1e-4 takes 18 halvings and the
  // two ends.
  EXPECT_NE(result.out.find("k              29.4299"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("runs           20\n"), std::string::npos) << result.out;
}

// --max-steps: the prism needs about 170 dop853 steps to t = 20 s; with a budget of 10 each run
// stops after its tenth step and fails, naming the budget. A sweep writes the failed rows and
// exits 0; a search cannot bisect on a failed run, so it ends with exit 4 at the value it was at.
TEST(SweepCommand, APerRunBudgetOfStepsMakesFailedRowsAndEndsAFind) {
  const auto dir = test::fresh_test_dir("SweepCommand", "max_steps");
  const auto sweep = run_tumble("sweep " + kExamples +
                                "tumbling_prism.yaml --vary a=3:5:2 --record 'e=final(E)' "
                                "--max-steps 10 --out " +
                                dir.string());
  ASSERT_EQ(sweep.status, 0) << sweep.out;
  std::istringstream rows(test::read_file(dir / "sweep.csv"));
  std::string line;
  std::getline(rows, line);
  int failed = 0;
  while (std::getline(rows, line)) {
    EXPECT_NE(line.find(",failed,10,"), std::string::npos) << line;
    EXPECT_NE(line.find("after --max-steps = 10 steps"), std::string::npos) << line;
    ++failed;
  }
  EXPECT_EQ(failed, 2);

  const auto find =
      run_tumble("find " + kExamples + "sweeps/mast_critical_spring.yaml --vary k=20:40 --when " +
                 quote_for_shell("max(abs(base.angle)) > theta_seen") + " --max-steps 10");
  EXPECT_EQ(find.status, 4) << find.out;
  EXPECT_NE(find.out.find("the run at k = 20 failed"), std::string::npos) << find.out;
  EXPECT_NE(find.out.find("after --max-steps = 10 steps"), std::string::npos) << find.out;
}

}  // namespace
}  // namespace tumble
