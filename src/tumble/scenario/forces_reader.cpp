// `forces:`: a list of loads and force elements, each {type: ...}: force and torque (constant,
// optionally on a from/to schedule), impulse (at one instant), spring (linear spring-damper
// between two body points) and torsional_spring (between two bodies, or about a hinge's axis).
#include <fmt/format.h>
#include <algorithm>

#include "tumble/scenario/readers.hpp"

namespace tumble::scenario_reading {
namespace {

const std::vector<std::string> kTypes = {"force", "torque", "impulse", "spring",
                                         "torsional_spring"};

// `from:` and `to:` of a schedule.
void read_schedule(const Reader& reader, const MapReader& map, double& from, double& to) {
  if (const auto f = map.find("from")) from = reader.number(*f);
  if (const auto f = map.find("to")) {
    to = reader.number(*f);
    if (!(from < to)) {
      reader.fail_at_value(*f, fmt::format("to ({} s) must be later than from ({} s)",
                                           format_number(to), format_number(from)));
    }
  }
}

bool read_frame(const Reader& reader, const MapReader& map) {
  const auto f = map.find("frame");
  if (!f) return false;
  const std::string frame = reader.text(*f);
  if (frame != "world" && frame != "body") {
    reader.fail_at_value(*f, "unknown frame '" + frame +
                                 "'; give world (the default: value is fixed in space) or body "
                                 "(value turns with the body)");
  }
  return frame == "body";
}

double read_non_negative(const Reader& reader, const MapReader& map, std::string_view key,
                         std::string_view unit, bool required) {
  const std::optional<Field> f =
      required ? std::optional<Field>(map.require(key, unit)) : map.find(key);
  if (!f) return 0.0;
  const double value = reader.number(*f);
  if (!(value >= 0.0)) {
    reader.fail_at_value(
        *f, fmt::format("{} must be >= 0 ({}); got {}", key, unit, format_number(value)));
  }
  return value;
}

// `bodies: [a, b]` of a force element; either may be ground, not both.
std::pair<std::string, std::string> read_pair(const Reader& reader, const MapReader& map,
                                              const std::vector<BodySpec>& bodies) {
  const Field field = map.require("bodies", "the two bodies it joins, [a, b] (one may be ground)");
  const std::vector<Field> items = reader.items(field, "of two bodies [a, b]");
  if (items.size() != 2) {
    reader.fail_at_value(field, fmt::format("give two bodies [a, b]; got {}", items.size()));
  }
  const std::string a = read_body_or_ground(reader, items[0], bodies, true);
  const std::string b = read_body_or_ground(reader, items[1], bodies, true);
  if (a == b) reader.fail_at_value(field, "the two bodies must differ");
  return {a, b};
}

LoadSpec read_load(const Reader& reader, const MapReader& map, const std::string& type,
                   const std::vector<BodySpec>& bodies) {
  LoadSpec load;
  load.kind = type == "force" ? LoadSpec::Kind::Force : LoadSpec::Kind::Torque;
  load.body =
      read_body_or_ground(reader, map.require("body", "the body it acts on"), bodies, false);
  const Field value = map.require("value", type == "force" ? "N, [x, y, z]" : "N m, [x, y, z]");
  load.value = type == "force" ? reader.point_or_vector(value) : reader.spin_vector(value);
  if (const auto f = map.find("at")) {
    load.at_W = reader.point_or_vector(*f);
    load.has_point = true;
  }
  load.body_frame = read_frame(reader, map);
  read_schedule(reader, map, load.from, load.to);
  return load;
}

ImpulseSpec read_impulse(const Reader& reader, const MapReader& map,
                         const std::vector<BodySpec>& bodies) {
  ImpulseSpec impulse;
  impulse.body =
      read_body_or_ground(reader, map.require("body", "the body it strikes"), bodies, false);
  impulse.value = reader.point_or_vector(map.require("value", "N s, [x, y, z]"));
  if (const auto f = map.find("at")) {
    impulse.at_W = reader.point_or_vector(*f);
    impulse.has_point = true;
  }
  impulse.body_frame = read_frame(reader, map);
  const Field time = map.require("time", "the instant it acts, s");
  impulse.time = reader.number(time);
  if (!(impulse.time > 0.0)) {
    reader.fail_at_value(time, fmt::format("an impulse acts after the start (time > 0 s); got {}",
                                           format_number(impulse.time)));
  }
  return impulse;
}

SpringSpec read_spring(const Reader& reader, const MapReader& map,
                       const std::vector<BodySpec>& bodies) {
  SpringSpec spring;
  std::tie(spring.body_a, spring.body_b) = read_pair(reader, map, bodies);
  std::tie(spring.at_a_W, spring.at_b_W) = reader.two_points(
      map.require("at", "the two attachment points [[x, y, z], [x, y, z]], world"));
  spring.stiffness = read_non_negative(reader, map, "stiffness", "N/m", true);
  spring.damping = read_non_negative(reader, map, "damping", "N s/m", false);
  if (map.has("rest_length")) {
    spring.rest_length = read_non_negative(reader, map, "rest_length", "m", false);
  }
  return spring;
}

TorsionalSpringSpec read_torsional_spring(const Reader& reader, const MapReader& map,
                                          const std::vector<BodySpec>& bodies,
                                          const std::vector<JointSpec>& joints) {
  TorsionalSpringSpec spring;
  std::tie(spring.body_a, spring.body_b) = read_pair(reader, map, bodies);
  spring.stiffness = read_non_negative(reader, map, "stiffness", "N m/rad", true);
  spring.damping = read_non_negative(reader, map, "damping", "N m s/rad", false);
  const auto rest = map.find("rest");
  if (!rest) return spring;
  const bool across_hinge = std::any_of(joints.begin(), joints.end(), [&](const JointSpec& j) {
    return j.type == JointType::Hinge &&
           ((j.body_a == spring.body_a && j.body_b == spring.body_b) ||
            (j.body_a == spring.body_b && j.body_b == spring.body_a));
  });
  if (rest->node.IsScalar() && rest->node.Scalar() != "identity") {
    if (!across_hinge) {
      reader.fail_at_value(*rest,
                           "an angle as rest needs a hinge between the two bodies; give an "
                           "orientation {axis: [x, y, z], angle: ...} of the second "
                           "body's frame relative to the first's");
    }
    spring.rest_angle = reader.angle(*rest);
  } else {
    spring.rest_orientation = read_orientation(reader, *rest);
  }
  return spring;
}

}  // namespace

void read_forces(const Reader& reader, const Field& field, Scenario& scenario) {
  const std::vector<Field> items = reader.items(field, "of forces, each {type: ..., ...}");
  ColumnHeads heads(scenario);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const MapReader map(reader, items[i],
                        "a force {type: force | torque | impulse | spring | "
                        "torsional_spring, ...}");
    const Field type_field = map.require("type", join(kTypes, " | "));
    const std::string type = reader.text(type_field);
    if (std::find(kTypes.begin(), kTypes.end(), type) == kTypes.end()) {
      std::string why = "unknown type '" + type + "'";
      if (const auto match = closest_match(type, kTypes)) why += "; did you mean '" + *match + "'?";
      reader.fail_at_value(type_field, why + " (the types are " + join(kTypes) + ")");
    }
    std::vector<std::string> keys = {"type", "name"};
    if (type == "force") keys.insert(keys.end(), {"body", "value", "at", "frame", "from", "to"});
    if (type == "torque") keys.insert(keys.end(), {"body", "value", "frame", "from", "to"});
    if (type == "impulse") keys.insert(keys.end(), {"body", "value", "at", "frame", "time"});
    if (type == "spring") {
      keys.insert(keys.end(), {"bodies", "at", "stiffness", "damping", "rest_length"});
    }
    if (type == "torsional_spring") {
      keys.insert(keys.end(), {"bodies", "stiffness", "damping", "rest"});
    }
    map.allow_only(keys, "a " + type, [&](const std::string& key) -> std::string {
      if (type == "torque" && key == "at") {
        return "a torque has no point of application; remove `at:` (a force with `at:` away from "
               "the COM gives a moment)";
      }
      if ((type == "spring" || type == "torsional_spring") && key == "body") {
        return "a " + type + " joins two bodies: bodies: [a, b] (one may be ground)";
      }
      return "";
    });

    std::string name = type + std::to_string(i + 1);
    const SourceLocation where = reader.location(items[i].key_mark);
    if (const auto f = map.find("name")) {
      name = reader.text(*f);
      check_name(reader, *f, name, type);
      heads.claim(reader, *f, name, type, where);
    } else {
      heads.claim(reader, items[i], name, type, where);
    }

    if (type == "force" || type == "torque") {
      LoadSpec load = read_load(reader, map, type, scenario.bodies);
      load.name = name;
      load.where = where;
      scenario.loads.push_back(std::move(load));
    } else if (type == "impulse") {
      ImpulseSpec impulse = read_impulse(reader, map, scenario.bodies);
      impulse.name = name;
      impulse.where = where;
      scenario.impulses.push_back(std::move(impulse));
    } else if (type == "spring") {
      SpringSpec spring = read_spring(reader, map, scenario.bodies);
      spring.name = name;
      spring.where = where;
      scenario.springs.push_back(std::move(spring));
    } else {
      TorsionalSpringSpec spring =
          read_torsional_spring(reader, map, scenario.bodies, scenario.joints);
      spring.name = name;
      spring.where = where;
      scenario.torsional_springs.push_back(std::move(spring));
    }
  }
}

}  // namespace tumble::scenario_reading
