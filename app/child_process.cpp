#include "child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/core.h>
#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <system_error>

extern char** environ;

namespace tumble::cli {
namespace {

volatile std::sig_atomic_t g_child_pid = 0;
volatile std::sig_atomic_t g_signal = 0;

extern "C" void forward_signal(int signal_number) {
  g_signal = signal_number;
  if (g_child_pid > 0) ::kill(static_cast<pid_t>(g_child_pid), signal_number);
}

// Installs the forwarding handlers for its lifetime; restores the previous ones after.
class ForwardSignals {
 public:
  ForwardSignals() {
    g_signal = 0;
    g_child_pid = 0;
    struct sigaction action {};
    action.sa_handler = forward_signal;
    sigemptyset(&action.sa_mask);
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
      ::sigaction(kSignals[i], &action, &previous_[i]);
    }
  }
  ForwardSignals(const ForwardSignals&) = delete;
  ForwardSignals& operator=(const ForwardSignals&) = delete;
  ~ForwardSignals() {
    g_child_pid = 0;
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
      ::sigaction(kSignals[i], &previous_[i], nullptr);
    }
  }
  // Started: a signal that came before the pid was known is passed on now.
  void started(pid_t pid) {
    g_child_pid = pid;
    if (g_signal != 0) ::kill(pid, g_signal);
  }
  int received() const { return g_signal; }

 private:
  static constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};
  std::array<struct sigaction, 3> previous_{};
};

std::string errno_message(int error) {
  return std::generic_category().message(error);
}

}  // namespace

bool ChildOutcome::succeeded() const {
  return WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0;
}

std::string ChildOutcome::how_it_ended() const {
  return WIFEXITED(wait_status) ? fmt::format("exit status {}", WEXITSTATUS(wait_status))
                                : fmt::format("signal {}", WTERMSIG(wait_status));
}

ChildOutcome run_child(std::vector<std::string> args, ChildOutput output) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const bool capture = output == ChildOutput::Capture;
  std::array<int, 2> pipe_fds{-1, -1};
  if (capture && ::pipe2(pipe_fds.data(), O_CLOEXEC) != 0) {
    throw ChildProcessError("cannot make a pipe: " + errno_message(errno), false);
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  if (capture) {
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  }
  ForwardSignals forward;
  pid_t pid = 0;
  const int spawn_error = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (capture) ::close(pipe_fds[1]);
  if (spawn_error != 0) {
    if (capture) ::close(pipe_fds[0]);
    throw ChildProcessError(fmt::format("cannot run {}: {}", args[0], errno_message(spawn_error)),
                            spawn_error == ENOENT);
  }
  forward.started(pid);
  ChildOutcome outcome;
  if (capture) {
    std::array<char, 4096> buffer{};
    for (;;) {
      const ssize_t n = ::read(pipe_fds[0], buffer.data(), buffer.size());
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      outcome.output.append(buffer.data(), static_cast<std::size_t>(n));
      constexpr std::size_t kKeep = 8192;
      if (outcome.output.size() > 2 * kKeep) outcome.output.erase(0, outcome.output.size() - kKeep);
    }
    ::close(pipe_fds[0]);
  }
  while (::waitpid(pid, &outcome.wait_status, 0) < 0) {
    if (errno != EINTR) {
      throw ChildProcessError(fmt::format("waiting for {}: {}", args[0], errno_message(errno)),
                              false);
    }
  }
  if (forward.received() != 0) {
    throw ChildInterrupted(fmt::format("interrupted ({})", ::strsignal(forward.received())),
                           forward.received());
  }
  return outcome;
}

void end_by_signal(int signal_number) {
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
  std::_Exit(128 + signal_number);  // not reached: the default action of these signals ends us
}

TemporaryDirectory::TemporaryDirectory(std::string_view prefix) {
  std::error_code error;
  std::string name =
      (std::filesystem::temp_directory_path(error) / (std::string(prefix) + "-XXXXXX")).string();
  if (error || ::mkdtemp(name.data()) == nullptr) {
    throw std::runtime_error(
        fmt::format("cannot make a temporary directory: {}",
                    error ? error.message() : std::generic_category().message(errno)));
  }
  path_ = name;
}

TemporaryDirectory::~TemporaryDirectory() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::string lowercase_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace tumble::cli
