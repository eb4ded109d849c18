#pragma once
// The files one `tumble run` writes, checked against each other before the run starts: two
// outputs that are one file (by name, through `..` or a symbolic link, or by case alone) would
// lose one's data to the other, with exit 0.
#include <filesystem>
#include <string>
#include <vector>

#include "tumble/scenario/scenario.hpp"

namespace tumble::cli {

struct OutputFile {
  std::string key;     // "output.trajectory", "--video"
  std::string value;   // the name as given: "run.csv"
  std::string called;  // for messages: "the trajectory's file", "the video's file (--video)"
  std::filesystem::path path;
  SourceLocation given_at;  // where the scenario gives it; line 0: a default or the command line
};

// Prints why, and returns the exit status, when two of `outputs` resolve to one file: invalid
// scenario (3) at the key the scenario gives, else a bad command line (2). kDone when they are
// all distinct.
int refuse_shared_outputs(const std::vector<OutputFile>& outputs, const Scenario& scenario);

}  // namespace tumble::cli
