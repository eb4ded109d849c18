#pragma once
// Running a helper program (gnuplot for `tumble plot`, the video renderer for `tumble run
// --video`) without a shell, so paths with spaces or quotes pass through untouched.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tumble::cli {

// The program could not be started or waited for, or tumble was interrupted while it ran.
class ChildProcessError : public std::runtime_error {
 public:
  ChildProcessError(const std::string& message, bool not_found)
      : std::runtime_error(message), not_found_(not_found) {}
  bool not_found() const { return not_found_; }  // no such program (on PATH)

 private:
  bool not_found_;
};

// tumble was stopped by SIGINT, SIGTERM or SIGHUP while the program ran; the program was passed
// the signal. Whoever catches it cleans up, then ends by that signal (end_by_signal).
class ChildInterrupted : public ChildProcessError {
 public:
  ChildInterrupted(const std::string& message, int signal_number)
      : ChildProcessError(message, false), signal_number_(signal_number) {}
  int signal_number() const { return signal_number_; }

 private:
  int signal_number_;
};

// Ends tumble as the signal would have (default action), so that its caller sees the same status
// as if no handler had been installed: a shell's 128 + N, `timeout`'s 124.
[[noreturn]] void end_by_signal(int signal_number);

enum class ChildOutput {
  Inherit,  // stdout and stderr shared with tumble: the program speaks to the user
  Capture,  // read into ChildOutcome::output (its last 8 KB), kept out of tumble's summary
};

struct ChildOutcome {
  int wait_status = 0;
  std::string output;

  bool succeeded() const;
  // "exit status 3" or "signal 9".
  std::string how_it_ended() const;
};

// Runs args[0] (searched on PATH unless it holds a '/') with stdin from /dev/null and waits for
// it. While it runs, SIGINT, SIGTERM and SIGHUP sent to tumble are passed on to it instead of
// ending tumble at once, so the program cleans up after itself and tumble then removes its own
// temporary files; ChildProcessError says the run was interrupted.
ChildOutcome run_child(std::vector<std::string> args, ChildOutput output);

// A fresh directory of tumble's own (mode 0700) under the system's temporary directory, removed
// with all it holds when this goes out of scope: where a helper program writes (a page, a
// figure, a video) before tumble installs the result (install_copy). No one else can plant a file
// or a link in it. Throws std::runtime_error if it cannot be made.
class TemporaryDirectory {
 public:
  // `prefix` starts its name: "tumble-video".
  explicit TemporaryDirectory(std::string_view prefix);
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  ~TemporaryDirectory();
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// The file's extension in lower case: ".png" for "Figure.PNG".
std::string lowercase_extension(const std::filesystem::path& path);

}  // namespace tumble::cli
