#pragma once
// A scenario's text parsed once and read any number of times with other parameter values: the
// runs of a sweep. Parsing the YAML is most of what reading a scenario costs (about nine tenths
// for the examples); reading the parsed document again costs a few microseconds.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "tumble/scenario/parameter_trace.hpp"
#include "tumble/scenario/scenario.hpp"

namespace tumble {

// A scenario file's text; a file that cannot be read is a ScenarioError at line 0.
std::string read_scenario_file(const std::string& path);

class ScenarioDocument {
 public:
  // Throws ScenarioError for a file that cannot be read (line 0), a YAML syntax error, a second
  // document or a quote left open, as load_scenario does.
  static ScenarioDocument from_file(const std::string& path);
  // `path` names the text in messages and places the files it refers to (meshes).
  static ScenarioDocument from_text(const std::string& text, std::string path);

  // The scenario with these parameter values: what load_scenario gives. One thread at a time
  // reads a document (yaml-cpp does not promise that reading its nodes from two threads is
  // safe): threads that read in parallel parse a document each. With a trace, each number that
  // uses a parameter it follows is noted there.
  Scenario read(const std::vector<ParameterOverride>& overrides, bool needs_simulate = true,
                ParameterTrace* trace = nullptr) const;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  YAML::Node root_;
};

}  // namespace tumble
