#pragma once
// The documented exit statuses of every tumble command (README.md, "Commands"; each command's
// --help).
namespace tumble::cli {

enum ExitStatus : int {
  kDone = 0,
  kBadCommandLine = 2,
  kInvalidScenario = 3,
  kIntegrationFailed = 4,
  kOutputError = 5,  // an output file or directory could not be written
  // tumble modes: the initial state is neither an equilibrium nor a steady motion, or the
  // model has what a linearisation does not cover yet (contacts)
  kNoLinearisation = 6,
};

}  // namespace tumble::cli
