#pragma once
// Runs the built tumble executable as a user would, for the command-line tests.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace tumble::test {

struct CommandResult {
  int status = -1;  // the exit status, or -1 if it did not exit normally
  std::string out;  // stdout and stderr together
};

// `arguments` go through /bin/sh: quote anything the shell would read (quote_for_shell).
// `environment` is prefixed to the command line, e.g. "PATH=/nowhere ".
inline CommandResult run_tumble(const std::string& arguments, const std::string& environment = "") {
  const std::string command = environment + std::string(TUMBLE_EXE) + " " + arguments + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) {
    result.out += buffer.data();
  }
  const int raw = pclose(pipe);
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return result;
}

inline std::string quote_for_shell(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace tumble::test
