#pragma once
// The documented exit statuses of every tumble command (docs/cli.md).
namespace tumble::cli {

enum ExitStatus : int {
  kDone = 0,
  kBadCommandLine = 2,
  kInvalidScenario = 3,
  kIntegrationFailed = 4,
  kOutputError = 5,  // an output file or directory could not be written
};

}  // namespace tumble::cli
