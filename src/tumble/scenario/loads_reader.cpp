// `forces:`: a list of loads. This release runs constant forces and torques, each optionally on a
// from/to schedule; the other types of the contract are recognised and refused by name.
#include <fmt/format.h>
#include <algorithm>

#include "tumble/scenario/readers.hpp"

namespace tumble::scenario_reading {
namespace {

const std::vector<std::string> kSupportedTypes = {"force", "torque"};
const std::vector<std::string> kComingTypes = {"spring", "torsional_spring", "impulse"};

std::string read_body_name(const Reader& reader, const Field& field,
                           const std::vector<BodySpec>& bodies) {
  const std::string name = reader.text(field);
  std::vector<std::string> names;
  for (const BodySpec& body : bodies) names.push_back(body.name);
  if (std::find(names.begin(), names.end(), name) != names.end()) return name;
  if (name == "ground") {
    reader.fail_at_value(field,
                         "a load on ground does nothing (ground is the fixed world); name "
                         "one of the bodies: " +
                             join(names));
  }
  std::string why = "no body '" + name + "' in bodies";
  if (const auto match = closest_match(name, names)) why += "; did you mean '" + *match + "'?";
  reader.fail_at_value(field, why + " (the bodies are " + join(names) + ")");
}

LoadSpec read_load(const Reader& reader, const Field& field, std::size_t index,
                   const std::vector<BodySpec>& bodies) {
  const MapReader map(reader, field, "a force {type: force | torque, body: ..., value: [x, y, z]}");
  if (!map.has("type")) {
    map.allow_only({"type", "name", "body", "value", "at", "frame", "from", "to"}, "a force");
  }
  const Field type_field = map.require("type", "force or torque");
  const std::string type = reader.text(type_field);
  if (std::find(kComingTypes.begin(), kComingTypes.end(), type) != kComingTypes.end()) {
    reader.fail_at_value(type_field, fmt::format("type '{}' is not supported yet (this release "
                                                 "runs force and torque); remove the entry to "
                                                 "run the rest",
                                                 type));
  }
  if (std::find(kSupportedTypes.begin(), kSupportedTypes.end(), type) == kSupportedTypes.end()) {
    std::vector<std::string> all = kSupportedTypes;
    all.insert(all.end(), kComingTypes.begin(), kComingTypes.end());
    std::string why = "unknown type '" + type + "'";
    if (const auto match = closest_match(type, all)) why += "; did you mean '" + *match + "'?";
    reader.fail_at_value(type_field, why + " (the types are force and torque; " +
                                         join(kComingTypes) + " are coming)");
  }

  LoadSpec load;
  load.kind = type == "force" ? LoadSpec::Kind::Force : LoadSpec::Kind::Torque;
  load.where = reader.location(field.key_mark);
  std::vector<std::string> keys = {"type", "name", "body", "value", "frame", "from", "to"};
  if (load.kind == LoadSpec::Kind::Force) keys.push_back("at");
  map.allow_only(keys, "a " + type, [](const std::string& key) {
    return key == "at" ? "a torque has no point of application; remove `at:` (a force with `at:` "
                         "away from the COM gives a moment)"
                       : "";
  });

  load.name = type + std::to_string(index + 1);
  if (const auto f = map.find("name")) {
    load.name = reader.text(*f);
    check_name(reader, *f, load.name, type);
  }
  load.body = read_body_name(reader, map.require("body", "the body it acts on"), bodies);
  load.value =
      reader.vec3(map.require("value", type == "force" ? "N, [x, y, z]" : "N m, [x, y, z]"));
  if (const auto f = map.find("at")) {
    load.at_W = reader.vec3(*f);
    load.has_point = true;
  }
  if (const auto f = map.find("frame")) {
    const std::string frame = reader.text(*f);
    if (frame != "world" && frame != "body") {
      reader.fail_at_value(*f, "unknown frame '" + frame +
                                   "'; give world (the default: value is "
                                   "fixed in space) or body (value turns with the body)");
    }
    load.body_frame = frame == "body";
  }
  if (const auto f = map.find("from")) load.from = reader.number(*f);
  if (const auto f = map.find("to")) {
    load.to = reader.number(*f);
    if (!(load.from < load.to)) {
      reader.fail_at_value(*f, fmt::format("to ({} s) must be later than from ({} s)",
                                           format_number(load.to), format_number(load.from)));
    }
  }
  return load;
}

}  // namespace

std::vector<LoadSpec> read_forces(const Reader& reader, const Field& field,
                                  const std::vector<BodySpec>& bodies) {
  std::vector<LoadSpec> loads;
  const std::vector<Field> items =
      reader.items(field, "of loads, each {type: force | torque, body: ..., value: [x, y, z]}");
  for (std::size_t i = 0; i < items.size(); ++i) {
    LoadSpec load = read_load(reader, items[i], i, bodies);
    for (const LoadSpec& earlier : loads) {
      if (earlier.name == load.name) {
        reader.fail_at_value(items[i], "two forces are named '" + load.name +
                                           "'; give each its own name (it heads CSV columns)");
      }
    }
    loads.push_back(std::move(load));
  }
  return loads;
}

}  // namespace tumble::scenario_reading
