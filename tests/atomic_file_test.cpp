// The temporary file an output is written to before its rename: created new, never through a
// file or symlink that someone planted in the output directory.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_files.hpp"
#include "tumble/output/atomic_file.hpp"

namespace tumble {
namespace {

namespace fs = std::filesystem;
using test::read_file;

fs::path fresh_destination_dir(const std::string& name) {
  return test::fresh_test_dir("AtomicFile", name);
}

TEST(AtomicFile, ASymlinkPlantedAtTheTemporaryNameIsNotWrittenThrough) {
  // Another user of a shared output directory points the name tumble used to write to,
  // DEST.partial-PID, at a file of the victim's; writing must not touch that file.
  const fs::path dir = fresh_destination_dir("symlink");
  const fs::path victim = dir / "victim.txt";
  std::ofstream(victim) << "precious";
  const fs::path dest = dir / "run.csv";
  fs::path planted = dest;
  planted += ".partial-" + std::to_string(static_cast<long>(::getpid()));
  fs::create_symlink(victim, planted);
  {
    AtomicFile file(dest);
    file.write("t,x\n0,1\n");
    file.finish();
  }
  EXPECT_EQ(read_file(victim), "precious");
  EXPECT_EQ(read_file(dest), "t,x\n0,1\n");
  EXPECT_TRUE(fs::is_symlink(planted));  // left alone
  // Nothing else is left beside them.
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 3);
}

TEST(AtomicFile, TwoWritersOfOneDestinationDoNotShareATemporaryFile) {
  const fs::path dir = fresh_destination_dir("two");
  const fs::path dest = dir / "run.csv";
  {
    AtomicFile first(dest);
    AtomicFile second(dest);
    first.write("first\n");
    second.write("second\n");
    first.finish();
    EXPECT_EQ(read_file(dest), "first\n");
    second.finish();
  }
  EXPECT_EQ(read_file(dest), "second\n");
}

TEST(AtomicFile, AnUnfinishedFileLeavesNothing) {
  const fs::path dir = fresh_destination_dir("unfinished");
  {
    AtomicFile file(dir / "run.csv");
    file.write("half");
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace
}  // namespace tumble
