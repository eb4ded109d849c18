#pragma once
// Which numbers of a scenario depend on some of its parameters. ScenarioDocument::read with a
// trace records each number whose expression names a followed parameter, or a parameter defined
// from one, with its key path and its text: a sweep reads from it that its runs differ only in
// the bodies' initial velocities (and can share one model), and how to compute those.
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <unordered_set>
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
    // The names followed, by hash, taken from `followed` as it grows: a chain of parameters each
    // defined from the one above follows every one, and a search of the list would make reading
    // a million of them quadratic.
    for (; indexed < followed.size(); ++indexed) followed_index.insert(followed[indexed]);
    for (const std::string_view name : expression_names(expression)) {
      if (followed_index.contains(name)) {
        uses.push_back({path, expression});
        return true;
      }
    }
    return false;
  }

  struct NameHash {
    using is_transparent = void;  // looked up by string_view, without a string made
    std::size_t operator()(std::string_view name) const {
      return std::hash<std::string_view>{}(name);
    }
  };
  std::unordered_set<std::string, NameHash, std::equal_to<>> followed_index{};
  std::size_t indexed = 0;  // the first names of `followed` in followed_index
};

}  // namespace tumble
