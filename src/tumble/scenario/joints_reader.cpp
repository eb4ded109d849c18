// `joints:`: a mapping from each joint's name to {type: ball | hinge | prismatic | fixed,
// bodies: [a, b] (or body: b, held by ground), at: world point at t = 0, axis:, motor:, lock:
// (hinge and prismatic)}.
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <map>

#include "tumble/scenario/readers.hpp"

namespace tumble::scenario_reading {
namespace {

const std::vector<std::string> kJointTypes = {"ball", "hinge", "prismatic", "fixed"};

// A hinge's motor gives speed: (rad/s) or torque: (N m); a slider's speed: (m/s) or force: (N).
MotorSpec read_motor(const Reader& reader, const Field& field, JointType type) {
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
  if (const auto f = map.find("from")) motor.from = reader.number(*f);
  if (const auto f = map.find("to")) {
    motor.to = reader.number(*f);
    if (!(motor.from < motor.to)) {
      reader.fail_at_value(*f, fmt::format("to ({} s) must be later than from ({} s)",
                                           format_number(motor.to), format_number(motor.from)));
    }
  }
  return motor;
}

// A hinge's or a slider's motor and lock, after its axis.
JointSpec read_drive(const Reader& reader, const MapReader& map, JointSpec& joint);

JointSpec read_joint(const Reader& reader, const Field& field,
                     const std::vector<BodySpec>& bodies) {
  const MapReader map(reader, field,
                      "a joint {type: ball | hinge | prismatic | fixed, bodies: [a, b], at: [x, "
                      "y, z]}");
  JointSpec joint;
  joint.name = field.key();
  joint.where = reader.location(field.key_mark);
  check_name(reader, field, joint.name, "joint");
  if (joint.name == kGroundName) reader.fail_at_key(field, "ground names the fixed world");

  const Field type_field = map.require("type", "ball, hinge, prismatic or fixed");
  const std::string type = reader.text(type_field);
  if (std::find(kJointTypes.begin(), kJointTypes.end(), type) == kJointTypes.end()) {
    std::string why = "unknown joint type '" + type + "'";
    if (const auto match = closest_match(type, kJointTypes))
      why += "; did you mean '" + *match + "'?";
    reader.fail_at_value(type_field, why + " (the types are ball, hinge, prismatic and fixed)");
  }
  joint.type = type == "ball"        ? JointType::Ball
               : type == "hinge"     ? JointType::Hinge
               : type == "prismatic" ? JointType::Prismatic
                                     : JointType::Fixed;
  std::vector<std::string> keys = {"type", "bodies", "body", "at"};
  if (has_axis(joint.type)) keys.insert(keys.end(), {"axis", "motor", "lock"});
  map.allow_only(keys, "a " + type + " joint", [&](const std::string& key) -> std::string {
    if (key == "axis" || key == "motor" || key == "lock") {
      return "only a hinge or a prismatic joint has " + key + " (this joint is a " + type + ")";
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
  joint.at_W =
      reader.point_or_vector(map.require("at", "the joint's point, world coordinates at t = 0"));
  if (reader.planar() && joint.type == JointType::Ball) {
    reader.fail_at_value(field,
                         "a planar scenario's joints are hinges (about z), sliders and "
                         "welds; a ball joint would let the bodies leave the plane");
  }

  if (!has_axis(joint.type)) return joint;
  if (reader.planar() && joint.type == JointType::Hinge) {
    // Its axis is the plane's normal.
    if (const auto f = map.find("axis")) {
      reader.fail_at_key(*f, "a planar scenario's hinges turn about z; leave `axis:` out");
    }
    joint.axis_W = Vec3::UnitZ();
    return read_drive(reader, map, joint);
  }
  const Field axis_field =
      map.require("axis", joint.type == JointType::Hinge
                              ? "the hinge's direction [x, y, z], world at t = 0"
                              : "the direction the slider moves along [x, y, z], world at t = 0");
  const Vec3 axis = reader.point_or_vector(axis_field);
  if (!(axis.norm() > 0.0)) reader.fail_at_value(axis_field, "the axis must not be zero");
  joint.axis_W = axis.normalized();
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
  std::vector<std::string> names;
  for (const BodySpec& body : bodies) names.push_back(body.name);
  if (std::find(names.begin(), names.end(), name) != names.end()) return name;
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
  // Which bodies are already connected (through ground too): a joint within one group would
  // close a loop, which joint coordinates cannot describe.
  std::map<std::string, std::string> group;
  const auto root = [&](std::string name) {
    while (group.count(name) && group[name] != name) name = group[name];
    return name;
  };
  for (const Field& f : map.fields()) {
    JointSpec joint = read_joint(reader, f, bodies);
    const std::string a = root(joint.body_a), b = root(joint.body_b);
    if (a == b) {
      reader.fail_at_key(f, "this joint closes a loop: " + joint.body_a + " and " + joint.body_b +
                                " are already connected through other joints" +
                                (a == kGroundName ? " and ground" : "") +
                                "; tumble solves systems whose joints form a tree");
    }
    group[a] = b;
    group[b] = b;
    for (const BodySpec& body : bodies) {
      if (body.name == joint.name) {
        reader.fail_at_key(f, "a body is named '" + joint.name +
                                  "' too; names head CSV columns, "
                                  "so give the joint its own");
      }
    }
    joints.push_back(std::move(joint));
  }
  return joints;
}

}  // namespace tumble::scenario_reading
