// load_scenario: the file's top level. Reads the format version, the parameters (with --set
// overrides) that the expressions of every later number may use, then each section in turn.
#include "tumble/scenario/scenario.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>
#include <yaml-cpp/yaml.h>

#include <fmt/format.h>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "tumble/input/bounded_read.hpp"
#include "tumble/scenario/expression.hpp"
#include "tumble/scenario/readers.hpp"
#include "tumble/scenario/scenario_document.hpp"
#include "tumble/scenario/yaml_reader.hpp"

namespace tumble {

// The key is the file's text (a body's name in "bodies.NAME"): a control character in it is shown
// escaped, so that the message is one clean line.
ScenarioError::ScenarioError(SourceLocation where, std::string key, std::string why)
    : std::runtime_error(
          fmt::format("{}:{}:{}: {}{}", where.file, where.line, where.column,
                      key.empty() ? std::string() : scenario_reading::printable(key) + ": ", why)),
      where_(std::move(where)),
      key_(scenario_reading::printable(key)),
      why_(std::move(why)) {}

namespace {

using scenario_reading::Field;
using scenario_reading::MapReader;
using scenario_reading::Reader;

const std::vector<std::string> kTopLevelKeys = {"tumble",   "name",   "planar",   "parameters",
                                                "gravity",  "bodies", "joints",   "forces",
                                                "contacts", "events", "simulate", "output"};

// The line of `text` that starts at line index `line` (0-based), without its end.
std::string_view line_of(std::string_view text, int line) {
  std::size_t start = 0;
  for (int i = 0; i < line && start != std::string_view::npos; ++i) {
    start = text.find('\n', start);
    if (start != std::string_view::npos) ++start;
  }
  if (start == std::string_view::npos || start > text.size()) return {};
  const std::size_t end = text.find('\n', start);
  return text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
}

// Whether the quoted scalar opening at `column` of `line` closes on that line.
bool closes_on_its_line(std::string_view line, std::size_t column) {
  if (column >= line.size()) return true;
  const char quote = line[column];
  if (quote != '"' && quote != '\'') return true;
  for (std::size_t i = column + 1; i < line.size(); ++i) {
    if (quote == '"' && line[i] == '\\') {
      ++i;  // an escaped character
    } else if (line[i] == quote) {
      if (quote == '\'' && i + 1 < line.size() && line[i + 1] == '\'') {
        ++i;  // '' is a quote inside single quotes
      } else {
        return true;
      }
    }
  }
  return false;
}

}  // namespace

std::string read_scenario_file(const std::string& path) {
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
  std::ifstream in(path, std::ios::binary);
  try {
    return read_bounded(path, in, kScenarioReadLimit);
  } catch (const ReadLimitError& e) {
    throw ScenarioError(nowhere, "", e.what());
  } catch (const std::runtime_error&) {
    throw ScenarioError(nowhere, "", "cannot be read");
  }
}

namespace {

// A quote left open runs on over the following lines and swallows their keys, which the parser
// accepts as text; the scenario would then be refused for a missing key far from the mistake.
// A quoted scalar of the first document that does not close on its own line and has taken in a
// `key: value` is such a quote, refused where it opens. The check reads the parser's events, so
// aliases are not followed (an anchor may refer to itself).
bool swallows_keys(std::string_view text, const YAML::Mark& mark, const std::string& tag,
                   const std::string& value) {
  if (tag != "!" || mark.is_null()) return false;
  if (value.find(": ") == std::string::npos && value.find(":\n") == std::string::npos) {
    return false;
  }
  return !closes_on_its_line(line_of(text, mark.line), static_cast<std::size_t>(mark.column));
}

// Where each document starts, and the first quoted scalar that swallows keys.
class DocumentEvents : public YAML::EventHandler {
 public:
  explicit DocumentEvents(std::string_view text) : text_(text) {}
  std::optional<YAML::Mark> last_start;
  std::optional<YAML::Mark> open_quote;
  void OnDocumentStart(const YAML::Mark& mark) override { last_start = mark; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t,
                const std::string& value) override {
    if (!open_quote && swallows_keys(text_, mark, tag, value)) open_quote = mark;
  }
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}

 private:
  std::string_view text_;
};

// The first document's open quote, if any, and where a second document starts, if there is one.
// The parser is asked for two documents and no more: yaml-cpp's LoadAll can go on finding empty
// documents without end on some inputs (the fuzzer found one:
// tests/data/fuzz/refused-endless-documents.yaml).
struct DocumentsSeen {
  std::optional<YAML::Mark> open_quote, second;
};
DocumentsSeen scan_documents(const std::string& text) {
  std::istringstream stream(text);
  YAML::Parser parser(stream);
  DocumentEvents events(text);
  DocumentsSeen seen;
  if (!parser.HandleNextDocument(events)) return seen;
  seen.open_quote = events.open_quote;
  events.last_start.reset();
  if (parser.HandleNextDocument(events)) seen.second = events.last_start.value_or(YAML::Mark());
  return seen;
}

// The one YAML document of `text` (read from `path`, for locations).
YAML::Node parse_yaml(const std::string& text, const std::string& path) {
  const SourceLocation nowhere{path, 0, 0};
  YAML::Node document;
  DocumentsSeen seen;
  try {
    document = YAML::Load(text);
    seen = scan_documents(text);
  } catch (const YAML::Exception& e) {
    const SourceLocation at =
        e.mark.is_null() ? nowhere : SourceLocation{path, e.mark.line + 1, e.mark.column + 1};
    throw ScenarioError(at, "", "YAML syntax error: " + e.msg);
  }
  // A second document (after `---`) would be ignored: say so rather than run half a file.
  if (const auto& second = seen.second) {
    throw ScenarioError(
        second->is_null() ? nowhere : SourceLocation{path, second->line + 1, second->column + 1},
        "",
        "the file holds 2 YAML documents (separated by ---); a scenario is one document: put "
        "each scenario in a file of its own");
  }
  if (const auto& mark = seen.open_quote) {
    throw ScenarioError(SourceLocation{path, mark->line + 1, mark->column + 1}, "",
                        "YAML syntax error: this quoted text is not closed on its line and runs "
                        "on over the lines after it, taking in their keys; add the closing quote");
  }
  return document;
}

// The format's version, 1 or 2 (docs/scenario.md, "Format versions").
int read_version(const Reader& reader, const MapReader& root) {
  const Field version = root.require("tumble", "the format version: tumble: 1 or tumble: 2");
  const std::string text = version.node.IsScalar() ? version.node.Scalar() : "?";
  if (text == "1") return 1;
  if (text == "2") return 2;
  reader.fail_at_value(version,
                       "unsupported format version " + text + "; this tumble reads 1 and 2");
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
  names.reserve(fields.size());
  for (const Field& f : fields) names.push_back(f.key());
  // Each --set found by its name's hash (a file may hold a million parameters); the last --set of
  // a name wins.
  std::unordered_map<std::string_view, const ParameterOverride*> override_of;
  if (!overrides.empty()) {
    const std::unordered_set<std::string_view> defined(names.begin(), names.end());
    for (const ParameterOverride& o : overrides) {
      if (!defined.contains(o.name)) {
        throw std::invalid_argument(
            "--set " + o.name + ": no parameter " + o.name + " in " + reader.file() +
            (names.empty() ? "; it has no parameters"
                           : "; its parameters are " + listed_names(names)));
      }
      override_of[o.name] = &o;
    }
  }
  std::map<std::string, double> values;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const Field& f = fields[i];
    const auto set = override_of.find(names[i]);
    const ParameterOverride* o = set != override_of.end() ? set->second : nullptr;
    double value = 0.0;
    ParameterTrace* trace = reader.trace();
    const std::size_t uses_before = trace != nullptr ? trace->uses.size() : 0;
    if (o != nullptr) {
      try {
        value = expressions.evaluate(o->value);
      } catch (const ExpressionError& error) {
        throw std::invalid_argument("--set " + o->name + "=" + o->value + ": " + error.what());
      }
      if (trace != nullptr) trace->note(f.path, o->value);
    } else {
      value = reader.number(f);
    }
    // A parameter defined from a followed one is followed too.
    if (trace != nullptr && trace->uses.size() > uses_before) trace->followed.push_back(names[i]);
    try {
      expressions.define(names[i], value);
    } catch (const ExpressionError& error) {
      reader.fail_at_key(f, error.what());
    }
    values.emplace(names[i], value);
  }
  return values;
}

}  // namespace

Scenario load_scenario(const std::string& path, const std::vector<ParameterOverride>& overrides,
                       bool needs_simulate) {
  return ScenarioDocument::from_file(path).read(overrides, needs_simulate);
}

Scenario load_scenario_text(const std::string& text, const std::string& path,
                            const std::vector<ParameterOverride>& overrides, bool needs_simulate) {
  return ScenarioDocument::from_text(text, path).read(overrides, needs_simulate);
}

ScenarioDocument ScenarioDocument::from_file(const std::string& path) {
  return from_text(read_scenario_file(path), path);
}

ScenarioDocument ScenarioDocument::from_text(const std::string& text, std::string path) {
  ScenarioDocument document;
  document.root_ = parse_yaml(text, path);
  document.path_ = std::move(path);
  return document;
}

Scenario ScenarioDocument::read(const std::vector<ParameterOverride>& overrides,
                                bool needs_simulate, ParameterTrace* trace) const {
  const std::string& path = path_;
  const YAML::Node& document = root_;
  ExpressionEvaluator expressions;
  std::vector<std::string> warnings;
  Reader reader(path, expressions, &warnings, trace);
  if (!document || document.IsNull()) {
    reader.fail(YAML::Mark(), "", "the file is empty; a scenario begins with `tumble: 1`");
  }
  const MapReader root(reader, Field{document, "", YAML::Mark()},
                       "a mapping of the scenario's keys (tumble: 1, bodies:, simulate:, ...)");
  const int format_version = read_version(reader, root);
  root.allow_only(kTopLevelKeys, "a scenario");

  Scenario scenario;
  scenario.file = path;
  scenario.format_version = format_version;
  scenario.parameters = read_parameters(reader, root.find("parameters"), overrides, expressions);
  const std::string stem = std::filesystem::path(path).stem().string();
  scenario.name = stem;
  if (const auto f = root.find("name")) scenario.name = reader.text(*f);
  if (const auto f = root.find("planar")) {
    const std::string planar = reader.text(*f);
    if (planar != "true" && planar != "false") {
      reader.fail_at_value(
          *f, "expected true (everything moves in the x-y plane) or false, got '" + planar + "'");
    }
    scenario.planar = planar == "true";
    reader.set_planar(scenario.planar);
  }
  // A planar scenario's y is up.
  if (scenario.planar) scenario.gravity_W = Vec3(0.0, -9.81, 0.0);
  if (const auto f = root.find("gravity")) scenario.gravity_W = reader.point_or_vector(*f);

  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  scenario.bodies = scenario_reading::read_bodies(
      reader, root.require("bodies", "the bodies, by name"), directory);
  for (std::size_t i = 0; i < scenario.bodies.size(); ++i) {
    reader.index_body(scenario.bodies[i].name, i);
  }
  if (const auto f = root.find("joints")) {
    scenario.joints = scenario_reading::read_joints(reader, *f, scenario.bodies);
  }
  if (const auto f = root.find("forces")) scenario_reading::read_forces(reader, *f, scenario);
  if (const auto f = root.find("contacts")) {
    scenario.contacts = scenario_reading::read_contacts(reader, *f, scenario);
  }
  if (const auto f = root.find("events")) {
    scenario.events = scenario_reading::read_events(reader, *f, scenario);
  }
  const bool has_system = !scenario.joints.empty() || !scenario.impulses.empty() ||
                          !scenario.springs.empty() || !scenario.torsional_springs.empty() ||
                          !scenario.contacts.empty();
  if (needs_simulate) scenario_reading::check_slender_bodies(scenario);
  scenario_reading::check_loop_system(scenario);
  if (needs_simulate || root.has("simulate")) {
    scenario.simulate = scenario_reading::read_simulate(
        reader, root.require("simulate", "the run's settings, at least duration"),
        has_system || !scenario.loads.empty(), has_system, format_version);
  }
  scenario.output = scenario_reading::read_output(reader, root.find("output"), stem);
  scenario.warnings = std::move(warnings);
  return scenario;
}

}  // namespace tumble
