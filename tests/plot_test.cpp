// `tumble plot` as docs/plotting.md states it, by running the real executable: a PNG of the
// requested size, an SVG with the columns' titles, exit statuses and messages, user text that is
// drawn and never run, and no partial file on failure.
#include <gtest/gtest.h>

#include "run_tumble.hpp"
#include "test_files.hpp"

#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace tumble {
namespace {

namespace fs = std::filesystem;

using test::CommandResult;
using test::run_tumble;

using test::quote_for_shell;
using test::read_file;

std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename());
  return names;
}

std::uint32_t big_endian_u32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    value = (value << 8) | static_cast<unsigned char>(bytes[at + k]);
  }
  return value;
}

// Each test in its own directory (ctest runs them in parallel), holding the tumbling prism's
// trajectory; removed when the test passes.
class Plot : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ =
        fs::temp_directory_path() / ("tumble_plot_test_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  // Runs the chapter's prism into the test's directory; returns the CSV's path.
  fs::path prism_csv() {
    const CommandResult r =
        run_tumble("run " + std::string(TUMBLE_SOURCE_DIR) +
                   "/examples/tumbling_prism.yaml --out " + quote_for_shell(dir_.string()));
    EXPECT_EQ(r.status, 0) << r.out;
    return dir_ / "tumbling_prism.csv";
  }

  fs::path dir_;
};

TEST_F(Plot, HelpAndVersion) {
  const CommandResult version = run_tumble("plot --version");
  EXPECT_EQ(version.status, 0);
  EXPECT_NE(version.out.find("tumble 0."), std::string::npos) << version.out;
  const CommandResult help = run_tumble("plot --help");
  EXPECT_EQ(help.status, 0);
  for (const char* text : {"--columns", "--x-column", "--output", "--title", "--width", "--height",
                           "gnuplot", "5 output could not be produced"}) {
    EXPECT_NE(help.out.find(text), std::string::npos) << text << " missing from\n" << help.out;
  }
}

TEST_F(Plot, DrawsAPngOfTheRequestedSize) {
  const fs::path csv = prism_csv();
  const fs::path png = dir_ / "w.png";
  const CommandResult r = run_tumble("plot " + quote_for_shell(csv.string()) +
                                     " --columns prism.wx,prism.wy,prism.wz --width 640 "
                                     "--height 360 -o " +
                                     quote_for_shell(png.string()));
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string bytes = read_file(png);
  ASSERT_GT(bytes.size(), 24u);
  // The PNG signature, then the IHDR chunk: length, "IHDR", width and height (big-endian).
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(bytes.substr(12, 4), "IHDR");
  EXPECT_EQ(big_endian_u32(bytes, 16), 640u);
  EXPECT_EQ(big_endian_u32(bytes, 20), 360u);
  // Nothing but the trajectory and the finished figure (no script, no partial file).
  EXPECT_EQ(files_in(dir_), (std::set<std::string>{"tumbling_prism.csv", "w.png"}));
}

TEST_F(Plot, DrawsAnSvgWithTheColumnTitlesAndUnits) {
  const fs::path csv = prism_csv();
  const fs::path svg = dir_ / "w.svg";
  const CommandResult r =
      run_tumble("plot " + quote_for_shell(csv.string()) +
                 " --columns prism.wx,prism.wy,prism.wz -o " + quote_for_shell(svg.string()));
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string text = read_file(svg);
  EXPECT_EQ(text.rfind("<?xml", 0), 0u);
  for (const char* expected : {"<svg", "width=\"800\"", "height=\"500\"", ">prism.wx<",
                               ">prism.wy<", ">prism.wz<", ">t (s)<", ">rad/s<", "</svg>"}) {
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
  }
}

// Also: options before the CSV (`--columns` takes one argument each time, not the CSV).
TEST_F(Plot, PlotsAgainstAnotherColumn) {
  const fs::path csv = prism_csv();
  const fs::path svg = dir_ / "E.svg";
  const CommandResult r =
      run_tumble("plot -x prism.wz --columns E " + quote_for_shell(csv.string()) + " -o " +
                 quote_for_shell(svg.string()));
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string text = read_file(svg);
  EXPECT_NE(text.find(">prism.wz (rad/s)<"), std::string::npos);
  EXPECT_NE(text.find(">E (J)<"), std::string::npos);
}

TEST_F(Plot, UnknownColumnExitsTwoAndListsTheAvailableOnes) {
  const fs::path csv = prism_csv();
  for (const std::string option : {"--columns prism.wx,prism.wq", "-x time --columns E"}) {
    const CommandResult r = run_tumble("plot " + quote_for_shell(csv.string()) + " " + option +
                                       " -o " + quote_for_shell((dir_ / "w.png").string()));
    EXPECT_EQ(r.status, 2) << r.out;
    const std::string missing = option[1] == 'x' ? "time" : "prism.wq";
    EXPECT_NE(r.out.find("no column '" + missing + "' in " + csv.string()), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("available: t, prism.x, prism.y, prism.z, prism.vx"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("Ly, Lz"), std::string::npos) << r.out;
  }
  EXPECT_EQ(files_in(dir_), (std::set<std::string>{"tumbling_prism.csv"}));
}

TEST_F(Plot, MissingCsvAndBadOutputNamesExitTwo) {
  const fs::path missing = dir_ / "no_such.csv";
  const CommandResult r =
      run_tumble("plot " + quote_for_shell(missing.string()) + " --columns E -o " +
                 quote_for_shell((dir_ / "w.png").string()));
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("cannot read " + missing.string()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("No such file"), std::string::npos) << r.out;

  const fs::path csv = prism_csv();
  const CommandResult pdf =
      run_tumble("plot " + quote_for_shell(csv.string()) + " --columns E -o " +
                 quote_for_shell((dir_ / "w.pdf").string()));
  EXPECT_EQ(pdf.status, 2) << pdf.out;
  EXPECT_NE(pdf.out.find("must end in .png or .svg"), std::string::npos) << pdf.out;
  EXPECT_EQ(run_tumble("plot " + quote_for_shell(csv.string()) + " -o x.png").status, 2);
  EXPECT_EQ(files_in(dir_), (std::set<std::string>{"tumbling_prism.csv"}));
}

TEST_F(Plot, UnwritableOutputDirectoryExitsFive) {
  const fs::path csv = prism_csv();
  const CommandResult r = run_tumble("plot " + quote_for_shell(csv.string()) +
                                     " --columns E -o /proc/no_such_dir/w.png");
  EXPECT_EQ(r.status, 5) << r.out;
  EXPECT_NE(r.out.find("cannot write /proc/no_such_dir/w.png"), std::string::npos) << r.out;
}

// The title reaches gnuplot as a string and the SVG as text: quotes, backslashes, backquotes,
// $( ) and ; are drawn, and none of the commands in it runs.
TEST_F(Plot, TitleIsDrawnAsTextAndNeverRun) {
  const fs::path csv = prism_csv();
  const fs::path canary = dir_ / "canary";
  fs::create_directories(canary);
  const std::string c = canary.string();
  const std::string title = "it's \"spin\" \\ back\\slash `touch " + c + "/1` $(touch " + c +
                            "/2); touch " + c + "/3; rm -rf " + c + " & @ARG1";
  const fs::path svg = dir_ / "title.svg";
  const CommandResult r =
      run_tumble("plot " + quote_for_shell(csv.string()) + " --columns prism.wz --title " +
                 quote_for_shell(title) + " -o " + quote_for_shell(svg.string()));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(fs::exists(canary));
  EXPECT_TRUE(fs::is_empty(canary));
  // The SVG escapes & as &amp; and keeps the rest as it is.
  std::string drawn = title;
  drawn.replace(drawn.find(" & "), 3, " &amp; ");
  EXPECT_NE(read_file(svg).find(">" + drawn + "<"), std::string::npos) << drawn;
}

TEST_F(Plot, FailureLeavesNoPartialFile) {
  // gnuplot finds no number to plot: it fails, and the figure is not left half-written.
  const fs::path words = dir_ / "words.csv";
  std::ofstream(words) << "t,a\nx,y\nz,w\n";
  const CommandResult r =
      run_tumble("plot " + quote_for_shell(words.string()) + " --columns a -o " +
                 quote_for_shell((dir_ / "a.png").string()));
  EXPECT_EQ(r.status, 5) << r.out;
  EXPECT_NE(r.out.find("gnuplot failed"), std::string::npos) << r.out;
  EXPECT_EQ(files_in(dir_), (std::set<std::string>{"words.csv"}));
}

// gnuplot drew into <dest>.partial-<pid> opened without O_EXCL: a link planted there beforehand
// (the pids come in order) was written through, its target truncated and overwritten with the
// PNG. Links are planted at the names of the next hundred pids, each to a file of its own; none is
// written through, and the figure arrives as a file, not a link.
TEST_F(Plot, LinksPlantedBesideTheFigureAreNotWrittenThrough) {
  const fs::path csv = prism_csv();
  const fs::path png = dir_ / "E.png";
  long last_pid = 0;
  std::ifstream("/proc/sys/kernel/ns_last_pid") >> last_pid;
  ASSERT_GT(last_pid, 0);
  const fs::path targets = dir_ / "targets";
  fs::create_directories(targets);
  for (long pid = last_pid + 1; pid <= last_pid + 100; ++pid) {
    const fs::path target = targets / std::to_string(pid);
    std::ofstream(target) << "kept";
    fs::create_symlink(target, dir_ / ("E.png.partial-" + std::to_string(pid)));
  }
  const CommandResult r = run_tumble("plot " + quote_for_shell(csv.string()) + " --columns E -o " +
                                     quote_for_shell(png.string()));
  ASSERT_EQ(r.status, 0) << r.out;
  for (const auto& entry : fs::directory_iterator(targets)) {
    EXPECT_EQ(read_file(entry.path()), "kept") << entry.path() << " was written through";
  }
  EXPECT_FALSE(fs::is_symlink(png));
  EXPECT_EQ(read_file(png).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST_F(Plot, MissingGnuplotExitsFiveAndSaysHowToInstallIt) {
  const fs::path csv = prism_csv();
  const CommandResult r =
      run_tumble("plot " + quote_for_shell(csv.string()) + " --columns E -o " +
                     quote_for_shell((dir_ / "E.png").string()),
                 "env PATH=" + quote_for_shell((dir_ / "empty").string()) + " ");
  EXPECT_EQ(r.status, 5) << r.out;
  EXPECT_NE(r.out.find("gnuplot is not installed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("apt-get install gnuplot-nox"), std::string::npos) << r.out;
  EXPECT_EQ(files_in(dir_), (std::set<std::string>{"tumbling_prism.csv"}));
}

}  // namespace
}  // namespace tumble
