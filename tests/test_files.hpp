#pragma once
// Files for tests: an example's path, a whole file's bytes, and an empty directory of the test's
// own under the system's temporary directory (ctest runs tests in parallel, so each names its own).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace tumble::test {

// examples/NAME in the source tree.
inline std::string example(const std::string& name) {
  return std::string(TUMBLE_SOURCE_DIR) + "/examples/" + name;
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// An empty directory tumble_tests/SUITE/NAME under the temporary directory.
inline std::filesystem::path fresh_test_dir(const std::string& suite, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "tumble_tests" / suite / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace tumble::test
