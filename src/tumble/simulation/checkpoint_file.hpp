#pragma once
// A run's checkpoint in a file, for `tumble run --stop-at T --save-state FILE` and `--resume
// FILE`: everything a SimulationCheckpoint holds (the integrator's memory, the driver's position,
// the hybrid state, the conservation report so far, the last row's extras), one field a line,
// every number exactly (shortest round-trip decimal: the saved double's bits come back). A run
// of the same scenario resumed from the file writes the rows of the run that never stopped, bit
// for bit (tests/checkpoint_test.cpp).
//
// The file says which scenario it belongs to (a fingerprint of the scenario's text and its --set
// values) and which trajectory the stopped run wrote (its rows, bytes and digest), and it ends
// with a digest of its own lines: a file changed after it was written, cut short, or brought to
// another scenario is refused with a message, never resumed into garbage.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {

// Where a checkpoint came from: what the run that resumes it must match.
struct CheckpointOrigin {
  std::string scenario;           // the scenario's path as the stopped run was given it
  std::uint64_t fingerprint = 0;  // scenario_fingerprint() of its text and --set values
  // The trajectory the stopped run wrote, whole: the resumed run goes on with it.
  long trajectory_rows = 0;
  std::uint64_t trajectory_bytes = 0;
  std::uint64_t trajectory_digest = 0;  // content_digest() of its bytes
};

// A bad checkpoint file: "FILE:LINE: KEY: why" (line 0: the file as a whole).
class CheckpointFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// FNV-1a, 64 bits: a digest to tell two files (or texts) apart, not a cryptographic hash.
std::uint64_t content_digest(std::string_view bytes, std::uint64_t digest = 14695981039346656037u);
// The digest of a file's bytes (and their count in *bytes). Throws std::runtime_error naming the
// file if it cannot be read or is not a regular file (a device may have no end).
std::uint64_t file_digest(const std::filesystem::path& path, std::uint64_t* bytes = nullptr);
// A scenario's identity for a checkpoint: its file's bytes and the --set values, in order.
std::uint64_t scenario_fingerprint(std::string_view scenario_text,
                                   const std::vector<ParameterOverride>& overrides);

// Writes the checkpoint under a temporary name beside `path` and renames it into place. Throws
// std::runtime_error naming the path if it cannot be written.
void write_checkpoint_file(const std::filesystem::path& path,
                           const SimulationCheckpoint& checkpoint, const CheckpointOrigin& origin);

// What read_checkpoint_file found.
struct LoadedCheckpoint {
  SimulationCheckpoint checkpoint;
  CheckpointOrigin origin;
};
// Reads a checkpoint for a run of the scenario `simulation` was prepared from (prepare_run() of
// it, not yet run; the formulation's scratch is used to size the integrator's memory, which the
// file then fills). Throws CheckpointFileError for a file that cannot be read, is not a
// checkpoint, was changed or cut short, or does not fit this run's model (its state's size, its
// contacts, joints and events); the caller checks the origin against its scenario.
LoadedCheckpoint read_checkpoint_file(const std::filesystem::path& path,
                                      PreparedSimulation& simulation);
// The same for a checkpoint's bytes, called `file` in messages (the fuzz target's input).
LoadedCheckpoint read_checkpoint_text(const std::string& text, const std::string& file,
                                      PreparedSimulation& simulation);

}  // namespace tumble
