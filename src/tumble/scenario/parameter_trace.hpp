#pragma once
// Which numbers of a scenario depend on some of its parameters. ScenarioDocument::read with a
// trace records each number whose expression names a followed parameter, or a parameter defined
// from one, with its key path and its text: a sweep reads from it that its runs differ only in
// the bodies' initial velocities (and can share one model), and how to compute those.
#include <algorithm>
#include <string>
#include <vector>

#include "tumble/scenario/expression.hpp"

namespace tumble {

struct ParameterTrace {
  // The names followed; read() adds each parameter defined from one of them.
  std::vector<std::string> followed;
  struct Use {
    std::string path;        // "bodies.disk.velocity[0]"; "parameters.w" for a parameter
    std::string expression;  // as written in the file, or as --set gives it
  };
  std::vector<Use> uses;  // in the order read

  // Records the use if `expression` may name a followed parameter; returns whether it did.
  bool note(const std::string& path, const std::string& expression) {
    for (const std::string_view name : expression_names(expression)) {
      if (std::find(followed.begin(), followed.end(), name) != followed.end()) {
        uses.push_back({path, expression});
        return true;
      }
    }
    return false;
  }
};

}  // namespace tumble
