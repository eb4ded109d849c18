// `bodies:`: each body is one shape (its frame at the COM) or a composite of `parts:` (its frame
// where the parts' positions are measured from), with its initial position, orientation and
// velocities. Mass properties come from the inertia module: shape_mass_properties for one shape;
// express_in_parent and combine (the parallel axis theorem) for parts.
#include <fmt/format.h>

#include <Eigen/Eigenvalues>

#include "tumble/inertia/mesh.hpp"
#include "tumble/math/rotation.hpp"
#include "tumble/multibody/joints/joint_kind.hpp"
#include "tumble/scenario/readers.hpp"

namespace tumble::scenario_reading {
namespace {

const std::vector<std::string> kMotionKeys = {"position", "orientation", "angle", "velocity",
                                              "angular_velocity"};

// A body's or a part's turn from the world's (or the body's) axes: `orientation:` in 3D, `angle:`
// about z in a planar scenario (each refused in the other, where it would be a mistake).
Mat3 read_turn(const Reader& reader, const MapReader& map) {
  const std::optional<Field> orientation = map.find("orientation");
  const std::optional<Field> angle = map.find("angle");
  if (reader.planar()) {
    if (orientation) {
      reader.fail_at_key(*orientation,
                         "a planar scenario turns its bodies about z: give "
                         "`angle:` (rad, or with deg), not `orientation:`");
    }
    return angle ? rotation_from_axis_angle(Vec3::UnitZ(), reader.angle(*angle)) : Mat3::Identity();
  }
  if (angle) {
    reader.fail_at_key(*angle,
                       "`angle:` is a planar scenario's (planar: true); in 3D give "
                       "`orientation: {axis: [x, y, z], angle: ...}`");
  }
  return orientation ? read_orientation(reader, *orientation) : Mat3::Identity();
}

std::vector<std::string> with(std::vector<std::string> keys, const std::vector<std::string>& more) {
  keys.insert(keys.end(), more.begin(), more.end());
  return keys;
}

// A rod's, a point's or a line of parts' inertia about the COM: finite, symmetric, positive
// semi-definite and singular (a principal moment zero to 1e-12 of the largest; a point's all zero).
// Such a body is slender: valid where its joints make its motion well-posed
// (check_slender_bodies).
bool slender_inertia(const Mat3& inertia) {
  if (!inertia.allFinite() || !inertia.isApprox(inertia.transpose(), 1e-12)) return false;
  const double largest = inertia.cwiseAbs().maxCoeff();
  if (largest == 0.0) return true;  // a point
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(inertia);
  const Vec3 moments = solver.eigenvalues();  // ascending
  return moments(0) >= -1e-12 * largest && moments(0) <= 1e-12 * largest &&
         moments(1) + moments(0) >= moments(2) - 1e-9 * largest;
}

// Mass properties of one shape of the given mass in its own frame; a mesh that cannot be read
// or is not closed is reported at `shape:` or `file:`.
MassProperties shape_properties(const Reader& reader, const MapReader& map, const ShapeRead& read) {
  try {
    return shape_mass_properties(read.shape, read.mass);
  } catch (const std::runtime_error& error) {  // InertiaError, MeshError
    const std::optional<Field> file = map.find("file");
    reader.fail_at_value(file ? *file : read.shape_field, error.what());
  }
}

PartSpec read_part(const Reader& reader, const Field& field, const std::filesystem::path& directory,
                   std::size_t index) {
  const MapReader map(reader, field, "a part {shape: ..., mass: ..., position: [x, y, z]}");
  const std::vector<std::string> keys = {"name",    "shape",    "mass",        "density",
                                         "inertia", "position", "orientation", "angle"};
  PartSpec part;
  part.name = "parts[" + std::to_string(index) + "]";
  if (const auto name = map.find("name")) part.name = reader.text(*name);
  const ShapeRead read = read_shape_and_mass(reader, map, directory, true, keys, "a part");
  part.shape = read.shape;
  MassProperties own = shape_properties(reader, map, read);
  if (const auto inertia = map.find("inertia"))
    own.inertia_about_com = read_inertia(reader, *inertia);
  Vec3 position = Vec3::Zero();
  Mat3 R_BP = Mat3::Identity();
  if (const auto f = map.find("position")) position = reader.point_or_vector(*f);
  R_BP = read_turn(reader, map);
  part.mass_properties = express_in_parent(own, R_BP, position);
  part.position_B = position;
  part.R_BP = R_BP;
  return part;
}

// A single shape: the body's frame is the shape's, at the COM.
void read_single_shape(const Reader& reader, const MapReader& map,
                       const std::filesystem::path& directory, BodySpec& body) {
  const std::vector<std::string> keys =
      with({"shape", "mass", "density", "inertia", "parts"}, kMotionKeys);
  const ShapeRead read = read_shape_and_mass(reader, map, directory, true, keys, "a body");
  body.shape = read.shape;
  body.mass_properties = shape_properties(reader, map, read);
  if (const auto inertia = map.find("inertia")) {
    body.mass_properties.inertia_about_com = read_inertia(reader, *inertia);
    body.inertia_overridden = true;
    return;
  }
  if (slender_inertia(body.mass_properties.inertia_about_com)) {
    body.slender = true;
    body.slender_where = reader.location(read.shape_field.value_mark());
    body.slender_key = read.shape_field.path;
    return;
  }
  try {
    validate_inertia(body.mass_properties.inertia_about_com);
  } catch (const InertiaError& error) {
    const std::string fix =
        read.shape.kind == ShapeKind::Rod
            ? "a lone rod has no inertia about its own axis, so it cannot be a body: give "
              "`inertia:` (three principal moments, all > 0) or make it a thin cylinder"
            : "give `inertia:` or choose another shape";
    reader.fail_at_value(read.shape_field,
                         fmt::format("the {}'s inertia is not valid: {}; {}",
                                     shape_name(read.shape.kind), error.what(), fix));
  }
}

// A composite: the parts' mass properties, each expressed in the body's frame, summed.
void read_composite(const Reader& reader, const MapReader& map,
                    const std::filesystem::path& directory, BodySpec& body) {
  map.allow_only(with({"parts", "inertia"}, kMotionKeys), "a composite body (with parts)",
                 [](const std::string& key) -> std::string {
                   if (key == "mass" || key == "density") {
                     return "a composite body's mass is the sum of its parts'; give mass or "
                            "density on each part";
                   }
                   if (key == "shape") {
                     return "a body is one shape or a composite of parts, not both; move the "
                            "shape into `parts:`";
                   }
                   const auto& dims = all_dimension_keys();
                   if (std::find(dims.begin(), dims.end(), key) != dims.end()) {
                     return "'" + key + "' belongs to a shape: give it on the part";
                   }
                   return "";
                 });
  const Field parts_field = *map.find("parts");
  const std::vector<Field> items =
      reader.items(parts_field, "of parts, each {shape: ..., mass: ..., position: [x, y, z]}");
  if (items.empty()) {
    reader.fail_at_value(parts_field, "a composite body needs at least one part");
  }
  std::vector<MassProperties> in_body;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < items.size(); ++i) {
    PartSpec part = read_part(reader, items[i], directory, i);
    if (std::find(names.begin(), names.end(), part.name) != names.end()) {
      reader.fail_at_value(*MapReader(reader, items[i], "a part").find("name"),
                           "part name '" + part.name + "' is used twice in this body");
    }
    names.push_back(part.name);
    in_body.push_back(part.mass_properties);
    body.parts.push_back(std::move(part));
  }
  body.shape = Shape{};  // kind Point marks a composite
  body.mass_properties = combine(in_body);
  if (const auto inertia = map.find("inertia")) {
    body.mass_properties.inertia_about_com = read_inertia(reader, *inertia);
    body.inertia_overridden = true;
    return;
  }
  if (slender_inertia(body.mass_properties.inertia_about_com)) {
    body.slender = true;
    body.slender_where = reader.location(parts_field.key_mark);
    body.slender_key = parts_field.path;
    return;
  }
  try {
    validate_inertia(body.mass_properties.inertia_about_com);
  } catch (const InertiaError& error) {
    reader.fail_at_key(parts_field,
                       fmt::format("the parts together have no valid inertia: {}; add a part "
                                   "off their common line (points on one line cannot turn it "
                                   "about that line) or give `inertia:`",
                                   error.what()));
  }
}

BodySpec read_body(const Reader& reader, const Field& field,
                   const std::filesystem::path& directory) {
  BodySpec body;
  body.name = field.key();
  body.where = reader.location(field.key_mark);
  if (body.name == "ground") {
    reader.fail_at_key(field,
                       "'ground' is the reserved name of the fixed world; give the body "
                       "another name");
  }
  check_name(reader, field, body.name, "body");
  const MapReader map(reader, field, "a body {shape: ..., mass: ..., ...} or {parts: [...]}");
  if (map.has("parts")) {
    read_composite(reader, map, directory, body);
  } else {
    read_single_shape(reader, map, directory, body);
  }
  if (const auto f = map.find("position")) body.position_W = reader.point_or_vector(*f);
  body.R_WB = read_turn(reader, map);
  if (const auto f = map.find("velocity")) {
    body.velocity_W = reader.point_or_vector(*f);
    body.velocity_where = reader.location(f->value_mark());
  }
  if (const auto f = map.find("angular_velocity")) {
    body.angular_velocity_W = reader.spin_vector(*f);
    body.angular_velocity_where = reader.location(f->value_mark());
  }
  return body;
}

}  // namespace

std::vector<BodySpec> read_bodies(const Reader& reader, const Field& field,
                                  const std::filesystem::path& directory) {
  const MapReader map(reader, field, "a mapping of bodies by name, {prism: {shape: box, ...}}");
  if (map.fields().empty()) {
    reader.fail_at_key(field,
                       "no bodies; give at least one, e.g. prism: {shape: box, size: "
                       "[4, 1, 2], mass: 12}");
  }
  std::vector<BodySpec> bodies;
  for (const Field& body : map.fields()) bodies.push_back(read_body(reader, body, directory));
  return bodies;
}

void check_slender_bodies(const Scenario& scenario) {
  const std::unordered_map<std::string, std::size_t> inboard =
      inboard_joints(scenario, scenario.contacts);
  for (const BodySpec& body : scenario.bodies) {
    if (!body.slender) continue;
    const MassProperties& mp = body.mass_properties;
    const bool point = mp.inertia_about_com.cwiseAbs().maxCoeff() == 0.0;
    const std::string what = point ? "a point has no inertia at all"
                             : body.shape.kind == ShapeKind::Rod
                                 ? "a rod has no inertia about its own axis"
                                 : "parts on one line have no inertia about it";
    const auto fail = [&](const std::string& why) {
      throw ScenarioError(body.slender_where, body.slender_key, what + ": " + why);
    };
    const auto holder = inboard.find(body.name);
    if (holder == inboard.end()) {
      fail(std::string("free, nothing would say how it turns about ") +
           (point ? "its COM" : "that line") +
           "; hold it with a hinge across it (away from a point), a slider or a weld, or give "
           "`inertia:`");
    }
    const Mat3 I_G_W = body.R_WB * mp.inertia_about_com * body.R_WB.transpose();
    const Vec3 r_G_W = body.position_W + body.R_WB * mp.com;
    // Only the joint that moves it: the joints it carries move the bodies beyond it (the lower
    // hinge of a double pendulum of points sits on the upper bob and turns the lower one).
    const JointSpec& joint = scenario.joints[holder->second];
    if (joint.type == JointType::Ball && point) {
      // A point away from its pivot: turning about the line through both moves no mass, so
      // its motion is the point's (the spherical pendulum), whatever that turn does.
      const double reach = (r_G_W - joint.at_W).norm();
      if (!(reach > 1e-9 * std::max(1.0, joint.at_W.norm()))) {
        fail(
            fmt::format("it sits on the ball joint '{}': nothing holds it away from the "
                        "pivot, so it cannot swing; put the pivot away from it",
                        joint.name));
      }
      continue;
    }
    if (joint.type == JointType::Ball || joint.type == JointType::Free) {
      fail(
          fmt::format("on the ball joint '{}' it could turn about the line from the pivot "
                      "through it with nothing to say how; hinge it, or give `inertia:`",
                      joint.name));
    }
    // The axes the joint turns it about: a hinge's or a cylindrical joint's one, a universal
    // joint's two (the first as it is at t = 0).
    std::vector<Vec3> axes;
    if (joint.type == JointType::Hinge || joint.type == JointType::Cylindrical) {
      axes = {joint.axis_W};
    } else if (joint.type == JointType::Universal) {
      axes = {joint.first_axis_W, joint.axis_W};
    }
    for (const Vec3& n : axes) {
      // Its inertia about the axis n through the joint point: n.I_G.n + m |n x d|^2.
      const Vec3 d = r_G_W - joint.at_W;
      const double about_axis = n.dot(I_G_W * n) + mp.mass * n.cross(d).squaredNorm();
      const double scale = I_G_W.trace() / 2.0 + mp.mass * d.squaredNorm();
      if (!(about_axis > 1e-9 * scale)) {
        fail(fmt::format(
            "the {} '{}' turns it about an axis it has no inertia about (along it, through "
            "it), so nothing says how fast; hinge it across that line, or give `inertia:`",
            joint.type == JointType::Hinge ? "hinge"
                                           : std::string(joint_type_name(joint.type)) + " joint",
            joint.name));
      }
    }
  }
}

}  // namespace tumble::scenario_reading
