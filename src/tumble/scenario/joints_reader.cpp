// `joints:`: a mapping from each joint's name to {type: ball | hinge | prismatic | fixed |
// cylindrical | universal | distance, bodies: [a, b] (or body: b, held by ground), at: world point
// at t = 0 (distance: the rod's two ends), axis: (hinge, prismatic, cylindrical), axes:
// (universal), motor:, lock: (hinge, prismatic, cylindrical, universal)}.
#include <fmt/format.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <tuple>

#include "tumble/multibody/joints/joint_kind.hpp"
#include "tumble/scenario/readers.hpp"

namespace tumble::scenario_reading {
namespace {

// The types a scenario names, as the joints' kinds name themselves (multibody/joints/).
std::vector<std::string> joint_types() {
  std::vector<std::string> names;
  for (const std::string_view name : joint_type_names()) names.emplace_back(name);
  return names;
}
// "ball, hinge, prismatic and fixed" (with `last` "or": "... or fixed").
std::string joint_types_listed(std::string_view last) {
  std::vector<std::string> names = joint_types();
  const std::string final_name = names.back();
  names.pop_back();
  return join(names) + " " + std::string(last) + " " + final_name;
}

// A motor's from: and to: (s), to after from.
void read_motor_schedule(const Reader& reader, const MapReader& map, MotorSpec& motor) {
  if (const auto f = map.find("from")) motor.from = reader.number(*f);
  if (const auto f = map.find("to")) {
    motor.to = reader.number(*f);
    if (!(motor.from < motor.to)) {
      reader.fail_at_value(*f, fmt::format("to ({} s) must be later than from ({} s)",
                                           format_number(motor.to), format_number(motor.from)));
    }
  }
}

// A motor on a joint of two freedoms: an effort on one of them, named by its key (keys[0] drives
// the first freedom, keys[1] the second); `explain` says why another known key is out of place.
struct EffortKey {
  const char* key;
  const char* meaning;  // "N m, about the axis"
};
MotorSpec read_effort_motor(const Reader& reader, const Field& field,
                            const std::array<EffortKey, 2>& keys, const std::string& what,
                            const std::function<std::string(const std::string&)>& explain) {
  const MapReader map(
      reader, field,
      fmt::format("a motor {{{}: ...}} or {{{}: ...}}, with from:, to:", keys[0].key, keys[1].key));
  map.allow_only({keys[0].key, keys[1].key, "from", "to"}, what, explain);
  MotorSpec motor;
  motor.where = reader.location(field.key_mark);
  const auto first = map.find(keys[0].key);
  const auto second = map.find(keys[1].key);
  if (first && second) {
    reader.fail_at_key(*second, fmt::format("a motor drives one freedom: {} or {}, not both",
                                            keys[0].key, keys[1].key));
  }
  if (!first && !second) {
    reader.fail_at_value(field, fmt::format("give the motor's {}: ({}) or {}: ({})", keys[0].key,
                                            keys[0].meaning, keys[1].key, keys[1].meaning));
  }
  motor.kind = MotorSpec::Kind::Effort;
  motor.freedom = second ? 1 : 0;
  motor.value = reader.number(second ? *second : *first);
  read_motor_schedule(reader, map, motor);
  return motor;
}

// A cylindrical joint's torque: (N m, its turn) or force: (N, its slide).
MotorSpec read_cylindrical_motor(const Reader& reader, const Field& field) {
  return read_effort_motor(
      reader, field, {{{"torque", "N m, about the axis"}, {"force", "N, along it"}}},
      "a cylindrical joint's motor", [](const std::string& key) -> std::string {
        if (key != "speed") return "";
        return "a cylindrical joint's motor gives a torque: about its axis or a force: along it; "
               "a speed is prescribed on a hinge or a slider";
      });
}

// A universal joint's torque1: (N m, about its first axis) or torque2: (about its second).
MotorSpec read_universal_motor(const Reader& reader, const Field& field) {
  return read_effort_motor(
      reader, field,
      {{{"torque1", "N m, about the first axis"}, {"torque2", "N m, about the second"}}},
      "a universal joint's motor", [](const std::string& key) -> std::string {
        if (key == "speed") {
          return "a universal joint's motor gives a torque about one of its axes (torque1: or "
                 "torque2:); a speed is prescribed on a hinge or a slider";
        }
        if (key == "torque") return "say which axis: torque1: or torque2:";
        return "";
      });
}

// A hinge's motor gives speed: (rad/s) or torque: (N m); a slider's speed: (m/s) or force: (N).
MotorSpec read_motor(const Reader& reader, const Field& field, JointType type) {
  if (type == JointType::Cylindrical) return read_cylindrical_motor(reader, field);
  if (type == JointType::Universal) return read_universal_motor(reader, field);
  const bool slider = type == JointType::Prismatic;
  const std::string effort_key = slider ? "force" : "torque";
  const std::string speed_unit = slider ? "m/s" : "rad/s";
  const std::string effort_unit = slider ? "N" : "N m";
  const MapReader map(reader, field,
                      fmt::format("a motor {{speed: {}}} or {{{}: {}}}, with from:, to:",
                                  speed_unit, effort_key, effort_unit));
  map.allow_only({"speed", effort_key, "from", "to"}, "a motor");
  MotorSpec motor;
  motor.where = reader.location(field.key_mark);
  const auto speed = map.find("speed");
  const auto effort = map.find(effort_key);
  if (speed && effort) {
    reader.fail_at_key(*effort,
                       "a motor prescribes either the speed or the " + effort_key + ", not both");
  }
  if (!speed && !effort) {
    reader.fail_at_value(field, fmt::format("give the motor's speed: ({}, relative) or {}: ({})",
                                            speed_unit, effort_key, effort_unit));
  }
  motor.kind = speed ? MotorSpec::Kind::Speed : MotorSpec::Kind::Effort;
  motor.value = reader.number(speed ? *speed : *effort);
  read_motor_schedule(reader, map, motor);
  return motor;
}

// A distance joint's rod: its two ends, which it keeps at their distance at t = 0.
JointSpec read_rod_ends(const Reader& reader, const MapReader& map, JointSpec& joint) {
  const Field at = map.require("at",
                               "the rod's ends [[x, y, z], [x, y, z]], world at t = 0: the first "
                               "on body a, the second on body b");
  std::tie(joint.rod_end_a_W, joint.at_W) = reader.two_points(at);
  const double length = (joint.at_W - joint.rod_end_a_W).norm();
  const double largest_coordinate =
      std::max(joint.at_W.cwiseAbs().maxCoeff(), joint.rod_end_a_W.cwiseAbs().maxCoeff());
  // A rod shorter than the ends' own round-off has no direction to hold them along.
  if (!(length > 1e-9 * std::max(1.0, largest_coordinate))) {
    reader.fail_at_value(at,
                         fmt::format("a rod's ends are {} m apart: a rod holds two points apart "
                                     "(two points held together are a ball joint)",
                                     format_number(length)));
  }
  return joint;
}

// A hinge's, a slider's or a cylindrical joint's motor and lock, after its axis.
JointSpec read_drive(const Reader& reader, const MapReader& map, JointSpec& joint);
// A universal joint's two axes (the first fixed in body a, the second in body b, at right
// angles), its motor and its lock.
JointSpec read_universal_axes(const Reader& reader, const MapReader& map, JointSpec& joint);

JointSpec read_joint(const Reader& reader, const Field& field,
                     const std::vector<BodySpec>& bodies) {
  std::string types_alternatives;
  for (const std::string_view name : joint_type_names()) {
    types_alternatives += (types_alternatives.empty() ? "" : " | ") + std::string(name);
  }
  const MapReader map(reader, field,
                      "a joint {type: " + types_alternatives + ", bodies: [a, b], at: [x, y, z]}");
  JointSpec joint;
  joint.name = field.key();
  joint.where = reader.location(field.key_mark);
  check_name(reader, field, joint.name, "joint");
  if (joint.name == kGroundName) reader.fail_at_key(field, "ground names the fixed world");

  const Field type_field = map.require("type", joint_types_listed("or"));
  const std::string type = reader.text(type_field);
  const std::optional<JointType> named = joint_type_named(type);
  if (!named) {
    const std::vector<std::string> types = joint_types();
    std::string why = "unknown joint type '" + type + "'";
    if (const auto match = closest_match(type, types)) why += "; did you mean '" + *match + "'?";
    reader.fail_at_value(type_field, why + " (the types are " + joint_types_listed("and") + ")");
  }
  joint.type = *named;
  std::vector<std::string> keys = {"type", "bodies", "body", "at"};
  const bool universal = joint.type == JointType::Universal;
  if (has_axis(joint.type)) keys.insert(keys.end(), {"axis", "motor", "lock"});
  if (universal) keys.insert(keys.end(), {"axes", "motor", "lock"});
  map.allow_only(keys, "a " + type + " joint", [&](const std::string& key) -> std::string {
    if (universal && key == "axis") {
      return "a universal joint has two axes: axes: [[x, y, z], [x, y, z]]";
    }
    if (key == "axis") {
      return "only a hinge, a prismatic or a cylindrical joint has axis (this joint is a " + type +
             ")";
    }
    if (key == "motor") {
      return "a " + type +
             " joint takes no motor (a hinge, a prismatic, a cylindrical or a "
             "universal joint does)";
    }
    if (key == "lock") {
      return joint.type == JointType::Distance ? "a distance joint (a rod) takes no lock"
                                               : "a " + type + " joint has no freedom to lock";
    }
    if (key == "axes") {
      return "only a universal joint has axes (this joint is a " + type +
             (has_axis(joint.type) ? "; give its one axis: axis: [x, y, z])" : ")");
    }
    return "";
  });

  const auto bodies_field = map.find("bodies");
  const auto body_field = map.find("body");
  if (bodies_field && body_field) {
    reader.fail_at_key(*body_field, "give bodies: [a, b] or body: b (held by ground), not both");
  }
  if (bodies_field) {
    const std::vector<Field> items = reader.items(*bodies_field, "of two bodies [a, b]");
    if (items.size() != 2) {
      reader.fail_at_value(*bodies_field, fmt::format("a joint joins two bodies [a, b] (one may "
                                                      "be ground); got {}",
                                                      items.size()));
    }
    joint.body_a = read_body_or_ground(reader, items[0], bodies, true);
    joint.body_b = read_body_or_ground(reader, items[1], bodies, true);
    if (joint.body_a == joint.body_b) {
      reader.fail_at_value(*bodies_field, "a joint joins two different bodies");
    }
  } else if (body_field) {
    joint.body_b = read_body_or_ground(reader, *body_field, bodies, false);
  } else {
    reader.fail_at_value(field,
                         "give the bodies it joins: bodies: [a, b] or body: b (held by "
                         "ground)");
  }
  if (reader.planar() && (joint.type == JointType::Ball || joint.type == JointType::Universal ||
                          joint.type == JointType::Cylindrical)) {
    reader.fail_at_value(field,
                         "a planar scenario's joints are hinges (about z), sliders, welds and "
                         "rods (distance); a " +
                             type + " joint would let the bodies leave the plane");
  }
  if (joint.type == JointType::Distance) return read_rod_ends(reader, map, joint);
  joint.at_W =
      reader.point_or_vector(map.require("at", "the joint's point, world coordinates at t = 0"));

  if (universal) return read_universal_axes(reader, map, joint);
  if (!has_axis(joint.type)) return joint;
  if (reader.planar() && joint.type == JointType::Hinge) {
    // Its axis is the plane's normal.
    if (const auto f = map.find("axis")) {
      reader.fail_at_key(*f, "a planar scenario's hinges turn about z; leave `axis:` out");
    }
    joint.axis_W = Vec3::UnitZ();
    return read_drive(reader, map, joint);
  }
  const Field axis_field = map.require(
      "axis", joint.type == JointType::Hinge ? "the hinge's direction [x, y, z], world at t = 0"
              : joint.type == JointType::Prismatic
                  ? "the direction the slider moves along [x, y, z], world at t = 0"
                  : "the direction it turns about and slides along [x, y, z], world at t = 0");
  const std::optional<Vec3> axis = unit_direction(reader.point_or_vector(axis_field));
  if (!axis) reader.fail_at_value(axis_field, "the axis must not be zero");
  joint.axis_W = *axis;
  return read_drive(reader, map, joint);
}

JointSpec read_universal_axes(const Reader& reader, const MapReader& map, JointSpec& joint) {
  const Field axes_field =
      map.require("axes",
                  "its two axes [[x, y, z], [x, y, z]], world at t = 0: the first turns in body a, "
                  "the second in body b, at right angles");
  const std::vector<Field> items = reader.items(axes_field, "of two axes [[x, y, z], [x, y, z]]");
  if (items.size() != 2) {
    reader.fail_at_value(axes_field,
                         fmt::format("a universal joint has two axes, the first fixed in body a "
                                     "and the second in body b; got {}",
                                     items.size()));
  }
  std::array<Vec3, 2> axes;
  for (std::size_t i = 0; i < 2; ++i) {
    const std::optional<Vec3> axis = unit_direction(reader.point_or_vector(items[i]));
    if (!axis) reader.fail_at_value(items[i], "an axis must not be zero");
    axes[i] = *axis;
  }
  // The cross holds its arms at right angles: two axes that are not would not stay joined.
  const double cosine = axes[0].dot(axes[1]);
  if (!(std::abs(cosine) <= 1e-9)) {
    reader.fail_at_value(
        axes_field,
        fmt::format("the two axes of a universal joint are at right angles (its "
                    "cross holds them so); these are at {:.9g} degrees",
                    std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi));
  }
  joint.first_axis_W = axes[0];
  joint.axis_W = axes[1];
  return read_drive(reader, map, joint);
}

JointSpec read_drive(const Reader& reader, const MapReader& map, JointSpec& joint) {
  if (const auto f = map.find("motor")) joint.motor = read_motor(reader, *f, joint.type);
  if (const auto f = map.find("lock")) {
    const MapReader lock(reader, *f, "a lock {at: t}");
    lock.allow_only({"at"}, "a lock");
    const Field at = lock.require("at", "the time the joint locks, s");
    joint.lock_at = reader.number(at);
    if (!(joint.lock_at > 0.0)) {
      reader.fail_at_value(at,
                           "the lock acts at a time after the start (> 0 s); a joint rigid "
                           "from the start is a fixed joint");
    }
  }
  return joint;
}

}  // namespace

std::string read_body_or_ground(const Reader& reader, const Field& field,
                                const std::vector<BodySpec>& bodies, bool ground_allowed) {
  const std::string name = reader.text(field);
  if (reader.body_position(name)) return name;
  std::vector<std::string> names;  // for the message
  for (const BodySpec& body : bodies) names.push_back(body.name);
  if (name == kGroundName) {
    if (ground_allowed) return name;
    reader.fail_at_value(field,
                         "a load on ground does nothing (ground is the fixed world); name "
                         "one of the bodies: " +
                             join(names));
  }
  const std::string listed = join(names);
  if (ground_allowed) names.push_back(kGroundName);
  std::string why = "no body '" + name + "' in bodies";
  if (const auto match = closest_match(name, names)) why += "; did you mean '" + *match + "'?";
  reader.fail_at_value(
      field, why + " (the bodies are " + listed + (ground_allowed ? ", and ground)" : ")"));
}

std::vector<JointSpec> read_joints(const Reader& reader, const Field& field,
                                   const std::vector<BodySpec>& bodies) {
  std::vector<JointSpec> joints;
  const MapReader map(reader, field, "a mapping of joints {name: {type: ..., bodies: ...}}");
  // Which bodies are already connected (through ground too): a joint within one group closes a
  // loop. The joints listed before it form the tree; it becomes a constraint on that tree, so
  // the order the scenario lists them in chooses which joint of a loop is cut (docs/scenario.md).
  BodyGroups groups;
  ColumnHeads heads;
  for (const BodySpec& body : bodies) heads.note(body.name, "body", body.where);
  for (const Field& f : map.fields()) {
    JointSpec joint = read_joint(reader, f, bodies);
    // A rod is always a constraint on the tree, whether or not it closes a loop: it joins no
    // bodies in the tree's sense (its bodies keep five freedoms between them).
    joint.closes_loop =
        joint.type == JointType::Distance || !groups.join(joint.body_a, joint.body_b);
    // A closing joint's effort is a load on its bodies; a speed would be a row of its own.
    if (joint.closes_loop && joint.motor.kind == MotorSpec::Kind::Speed) {
      throw ScenarioError(joint.motor.where, "motor",
                          "this joint closes a loop (" + joint.body_a + " and " + joint.body_b +
                              " are already joined through the joints listed before it), and "
                              "a loop's closing joint takes no speed motor (a torque or a force "
                              "it does): list it before a joint of the loop that has no speed "
                              "motor, so that the tree drives it");
    }
    if (joint.closes_loop && joint.lock_at != std::numeric_limits<double>::infinity()) {
      reader.fail_at_key(f,
                         "this joint closes a loop and has a lock: a loop's closing joint "
                         "cannot lock; list it before a joint of the loop with no lock");
    }
    heads.claim(reader, f, joint.name, "joint", joint.where);
    joints.push_back(std::move(joint));
  }
  return joints;
}

void check_loop_system(const Scenario& scenario) {
  const auto loop = std::find_if(scenario.joints.begin(), scenario.joints.end(),
                                 [](const JointSpec& joint) { return joint.closes_loop; });
  if (loop == scenario.joints.end() || scenario.contacts.empty()) return;
  // A contact's forces and a loop's would have to be one solve (and their impacts one blow).
  throw ScenarioError(scenario.contacts.front().where, "contacts[0]",
                      "a contact in a system whose joints close a loop ('" + loop->name +
                          "' closes one) is not supported yet: the contact's and the loop's "
                          "forces are not yet solved together");
}

}  // namespace tumble::scenario_reading
