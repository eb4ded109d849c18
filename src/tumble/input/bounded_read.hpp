#pragma once
// Every file tumble reads is read through read_bounded: a scenario of a few gigabytes, or a
// device without end (/dev/zero, a FIFO), would otherwise be read until memory runs out. The
// size is checked before reading where the file has one (a regular file), and the read stops one
// byte past the limit where it has none, so the refusal comes at once and costs at most the limit.
#include <cstdint>
#include <iosfwd>
#include <stdexcept>
#include <string>

namespace tumble {

// A kind of file and its limit in MiB (1 MiB = 2^20 bytes): `default_mib` unless the environment
// variable `variable` holds another whole number of MiB (docs/scenario.md, "Limits on input").
struct ReadLimit {
  const char* what;      // the kind of file, for messages: "a scenario file"
  const char* variable;  // the environment variable that raises it: "TUMBLE_MAX_SCENARIO_MIB"
  std::uint64_t default_mib;
};

inline constexpr ReadLimit kScenarioReadLimit{"a scenario file", "TUMBLE_MAX_SCENARIO_MIB", 64};
inline constexpr ReadLimit kMeshReadLimit{"a mesh file", "TUMBLE_MAX_MESH_MIB", 1024};
// A run's saved state (`tumble run --resume`, Python's Model.load_state): its size grows with the
// state and the method's stages, about 25 bytes a number.
inline constexpr ReadLimit kCheckpointReadLimit{"a checkpoint file", "TUMBLE_MAX_CHECKPOINT_MIB",
                                                1024};
// The sweep.csv that `tumble sweep --resume` goes on from.
inline constexpr ReadLimit kSweepCsvReadLimit{"a sweep file to resume", "TUMBLE_MAX_SWEEP_CSV_MIB",
                                              1024};
// The header row that tumble plot reads from a CSV.
inline constexpr ReadLimit kCsvHeaderReadLimit{"a CSV header row", "TUMBLE_MAX_CSV_HEADER_MIB", 1};

// Why a file was not read: too large (over its limit), or the limit's variable is not a number.
// The message does not name the file; the caller's error does (FILE: message).
class ReadLimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The limit in bytes: the variable's value if set (a whole number of MiB from 1 to 2^40),
// otherwise the default. Throws ReadLimitError naming the variable if it is set to anything else.
std::uint64_t limit_bytes(const ReadLimit& limit);

// The message for a file over its limit (`size`: its size in bytes where known, else 0).
std::string too_large_message(const ReadLimit& limit, std::uint64_t size);

// The whole of an open stream's file at `path` (opened by the caller, so that its own messages
// for a missing or unreadable file stay its own), read up to the limit. Throws ReadLimitError
// when the file is larger, std::runtime_error("read error") on an I/O error.
std::string read_bounded(const std::string& path, std::istream& in, const ReadLimit& limit);

}  // namespace tumble
