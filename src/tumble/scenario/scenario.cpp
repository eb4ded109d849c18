// load_scenario: the file's top level. Reads the format version, the parameters (with --set
// overrides) that the expressions of every later number may use, then each section in turn.
#include "tumble/scenario/scenario.hpp"

#include <yaml-cpp/yaml.h>

#include <fmt/format.h>
#include <filesystem>
#include <fstream>

#include "tumble/scenario/expression.hpp"
#include "tumble/scenario/readers.hpp"
#include "tumble/scenario/yaml_reader.hpp"

namespace tumble {

ScenarioError::ScenarioError(SourceLocation where, std::string key, std::string why)
    : std::runtime_error(fmt::format("{}:{}:{}: {}{}", where.file, where.line, where.column,
                                     key.empty() ? std::string() : key + ": ", why)),
      where_(std::move(where)),
      key_(std::move(key)),
      why_(std::move(why)) {}

namespace {

using scenario_reading::Field;
using scenario_reading::MapReader;
using scenario_reading::Reader;

const std::vector<std::string> kTopLevelKeys = {"tumble",   "name",   "parameters", "gravity",
                                                "bodies",   "joints", "forces",     "contacts",
                                                "simulate", "output"};

YAML::Node load_yaml(const std::string& path) {
  std::error_code error;
  const SourceLocation nowhere{path, 0, 0};
  if (std::filesystem::is_directory(path, error)) {
    throw ScenarioError(nowhere, "", "cannot be read: it is a directory, not a scenario file");
  }
  if (!std::ifstream(path).good()) {
    throw ScenarioError(nowhere, "",
                        std::filesystem::exists(path, error)
                            ? "cannot be read: permission denied"
                            : "cannot be read: no such file (check the path)");
  }
  try {
    return YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw ScenarioError(nowhere, "", "cannot be read");
  } catch (const YAML::Exception& e) {
    const SourceLocation at =
        e.mark.is_null() ? nowhere : SourceLocation{path, e.mark.line + 1, e.mark.column + 1};
    throw ScenarioError(at, "", "YAML syntax error: " + e.msg);
  }
}

void check_version(const Reader& reader, const MapReader& root) {
  const Field version = root.require("tumble", "the format version: tumble: 1");
  const std::string text = version.node.IsScalar() ? version.node.Scalar() : "?";
  if (text != "1") {
    reader.fail_at_value(version, "unsupported format version " + text + "; this tumble reads 1");
  }
}

// Each parameter in file order, with the --set values in place of the file's; a parameter may use
// the ones above it. Returns the values by name.
std::map<std::string, double> read_parameters(const Reader& reader,
                                              const std::optional<Field>& field,
                                              const std::vector<ParameterOverride>& overrides,
                                              ExpressionEvaluator& expressions) {
  std::vector<Field> fields;
  if (field) {
    fields = MapReader(reader, *field, "a mapping of parameters {name: value, ...}").fields();
  }
  std::vector<std::string> names;
  for (const Field& f : fields) names.push_back(f.key());
  for (const ParameterOverride& o : overrides) {
    if (std::find(names.begin(), names.end(), o.name) == names.end()) {
      throw std::invalid_argument(
          "--set " + o.name + ": no parameter " + o.name + " in " + reader.file() +
          (names.empty() ? "; it has no parameters"
                         : "; its parameters are " + scenario_reading::join(names)));
    }
  }
  std::map<std::string, double> values;
  for (const Field& f : fields) {
    // The last --set of a name wins.
    const auto o = std::find_if(overrides.rbegin(), overrides.rend(),
                                [&](const ParameterOverride& p) { return p.name == f.key(); });
    double value = 0.0;
    if (o != overrides.rend()) {
      try {
        value = expressions.evaluate(o->value);
      } catch (const ExpressionError& error) {
        throw std::invalid_argument("--set " + o->name + "=" + o->value + ": " + error.what());
      }
    } else {
      value = reader.number(f);
    }
    try {
      expressions.define(f.key(), value);
    } catch (const ExpressionError& error) {
      reader.fail_at_key(f, error.what());
    }
    values[f.key()] = value;
  }
  return values;
}

}  // namespace

Scenario load_scenario(const std::string& path, const std::vector<ParameterOverride>& overrides) {
  const YAML::Node document = load_yaml(path);
  ExpressionEvaluator expressions;
  const Reader reader(path, expressions);
  if (!document || document.IsNull()) {
    reader.fail(YAML::Mark(), "", "the file is empty; a scenario begins with `tumble: 1`");
  }
  const MapReader root(reader, Field{document, "", YAML::Mark()},
                       "a mapping of the scenario's keys (tumble: 1, bodies:, simulate:, ...)");
  check_version(reader, root);
  root.allow_only(kTopLevelKeys, "a scenario");

  Scenario scenario;
  scenario.file = path;
  scenario.parameters = read_parameters(reader, root.find("parameters"), overrides, expressions);
  const std::string stem = std::filesystem::path(path).stem().string();
  scenario.name = stem;
  if (const auto f = root.find("name")) scenario.name = reader.text(*f);
  if (const auto f = root.find("gravity")) scenario.gravity_W = reader.vec3(*f);

  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  scenario.bodies = scenario_reading::read_bodies(
      reader, root.require("bodies", "the bodies, by name"), directory);
  if (const auto f = root.find("joints")) {
    scenario.joints = scenario_reading::read_joints(reader, *f, scenario.bodies);
  }
  if (const auto f = root.find("forces")) scenario_reading::read_forces(reader, *f, scenario);
  if (const auto f = root.find("contacts")) {
    scenario.contacts = scenario_reading::read_contacts(reader, *f, scenario);
  }
  const bool has_system = !scenario.joints.empty() || !scenario.impulses.empty() ||
                          !scenario.springs.empty() || !scenario.torsional_springs.empty() ||
                          !scenario.contacts.empty();
  scenario.simulate = scenario_reading::read_simulate(
      reader, root.require("simulate", "the run's settings, at least duration"),
      has_system || !scenario.loads.empty(), has_system);
  scenario.output = scenario_reading::read_output(reader, root.find("output"), stem);
  return scenario;
}

}  // namespace tumble
