#include "output_files.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <system_error>

#include "exit_status.hpp"

namespace tumble::cli {
namespace {

namespace fs = std::filesystem;

// The file a path names: absolute, with `..` and every symbolic link of its existing part
// resolved, in lower case (two names that differ in case alone are one file on a file system
// that ignores case, as macOS's and Windows' do by default).
std::string resolved(const fs::path& path) {
  std::error_code error;
  fs::path canonical = fs::weakly_canonical(fs::absolute(path, error), error);
  if (error) canonical = path.lexically_normal();  // no working directory: as given
  std::string text = canonical.string();
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

}  // namespace

int refuse_shared_outputs(const std::vector<OutputFile>& outputs, const Scenario& scenario) {
  std::vector<std::string> files;
  for (const OutputFile& output : outputs) files.push_back(resolved(output.path));
  for (std::size_t j = 0; j < outputs.size(); ++j) {
    for (std::size_t i = 0; i < j; ++i) {
      if (files[i] != files[j]) continue;
      // The scenario's key is blamed where it gives one: that is where the fix goes.
      const bool second_given = outputs[j].given_at.line > 0;
      const OutputFile& blamed = second_given ? outputs[j] : outputs[i];
      const OutputFile& other = second_given ? outputs[i] : outputs[j];
      const std::string why =
          fmt::format("'{}' is also {} ({}): one would overwrite the other; give each its own file",
                      blamed.value, other.called, other.path.string());
      if (blamed.given_at.line > 0) {
        fmt::print(stderr, "{}\n", ScenarioError(blamed.given_at, blamed.key, why).what());
        return kInvalidScenario;
      }
      // Neither is the scenario's own key: the command line (--video, --out) made them collide.
      fmt::print(stderr, "tumble run: {} {}: {}\n", blamed.key, blamed.value,
                 fmt::format("it is also {} ({}) of {}: give each its own file", other.called,
                             other.path.string(), scenario.file));
      return kBadCommandLine;
    }
  }
  return kDone;
}

}  // namespace tumble::cli
