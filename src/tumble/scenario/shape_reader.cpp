// The shape of a body or a part with its dimensions and mass, its inertia override and its
// orientation: the keys a body and a part share.
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <system_error>

#include "tumble/inertia/mesh.hpp"
#include "tumble/math/rotation.hpp"
#include "tumble/scenario/readers.hpp"

namespace tumble::scenario_reading {
namespace {

// An orientation matrix must be a rotation to this tolerance (max |R^T R - I| and |det R - 1|).
constexpr double kRotationTolerance = 1e-9;

const std::vector<ShapeKind> kAllShapes = {
    ShapeKind::Point, ShapeKind::Rod,    ShapeKind::Ring,  ShapeKind::Disk,   ShapeKind::Cylinder,
    ShapeKind::Tube,  ShapeKind::Sphere, ShapeKind::Shell, ShapeKind::Box,    ShapeKind::Cone,
    ShapeKind::Plate, ShapeKind::Mesh,   ShapeKind::Torus, ShapeKind::Capsule};

// What a density is per unit of: a curve's length, a surface's area, a solid's volume.
std::string_view density_unit(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::Rod:
    case ShapeKind::Ring:
      return "kg/m";
    case ShapeKind::Disk:
    case ShapeKind::Shell:
    case ShapeKind::Plate:
      return "kg/m^2";
    default:
      return "kg/m^3";
  }
}

// Words people use for the contract's shapes, to suggest the right name.
std::optional<std::string_view> synonym(std::string_view word) {
  static const std::vector<std::pair<std::string_view, std::string_view>> synonyms = {
      {"cube", "box"},
      {"cuboid", "box"},
      {"prism", "box"},
      {"brick", "box"},
      {"slab", "box"},
      {"ball", "sphere"},
      {"bar", "rod"},
      {"stick", "rod"},
      {"hoop", "ring"},
      {"pipe", "tube"},
      {"pill", "capsule"},
      {"spherocylinder", "capsule"},
      {"cylinder_shell", "tube"},
      {"sheet", "plate"},
      {"rectangle", "plate"},
      {"circle", "disk"},
      {"disc", "disk"},
      {"donut", "torus"},
      {"doughnut", "torus"},
      {"tyre", "torus"},
      {"tire", "torus"}};
  for (const auto& [alias, name] : synonyms) {
    if (alias == word) return name;
  }
  return std::nullopt;
}

std::string article_shape(ShapeKind kind) {
  return "a " + std::string(shape_name(kind));
}

double positive_length(const Reader& reader, const Field& field) {
  const double value = reader.number(field);
  if (!(value > 0.0)) {
    reader.fail_at_value(field, fmt::format("{} must be > 0 (m), got {}; give the size in metres",
                                            field.key(), format_number(value)));
  }
  return value;
}

// size: [a, b, c] of a box or [a, b] of a plate, each > 0.
Vec3 read_size(const Reader& reader, const Field& field, std::size_t count) {
  const std::string_view form = count == 3 ? "[a, b, c]" : "[a, b]";
  if (!field.node || !field.node.IsSequence() || field.node.size() != count) {
    reader.numbers(field, count, form);  // fails with the expected form
  }
  Vec3 size = Vec3::Zero();
  const std::vector<Field> items = reader.items(field, form);
  for (std::size_t i = 0; i < count; ++i) {
    const double value = reader.number(items[i]);
    if (!(value > 0.0)) {
      reader.fail_at_value(
          items[i], fmt::format("size[{}] must be > 0 (m), got {}", i, format_number(value)));
    }
    size(static_cast<int>(i)) = value;
  }
  return size;
}

void read_dimensions(const Reader& reader, const MapReader& map, Shape& shape,
                     const std::filesystem::path& directory) {
  const auto dimension = [&](std::string_view key) {
    return map.require(key, fmt::format("{}'s {}, m, > 0", article_shape(shape.kind), key));
  };
  switch (shape.kind) {
    case ShapeKind::Point:
      return;
    case ShapeKind::Rod:
      shape.length = positive_length(reader, dimension("length"));
      return;
    case ShapeKind::Ring:
    case ShapeKind::Disk:
    case ShapeKind::Sphere:
    case ShapeKind::Shell:
      shape.radius = positive_length(reader, dimension("radius"));
      return;
    case ShapeKind::Cylinder:
    case ShapeKind::Capsule:
      shape.radius = positive_length(reader, dimension("radius"));
      shape.length = positive_length(reader, dimension("length"));
      return;
    case ShapeKind::Cone:
      shape.radius = positive_length(reader, dimension("radius"));
      shape.height = positive_length(reader, dimension("height"));
      return;
    case ShapeKind::Tube: {
      const Field inner = dimension("inner_radius");
      shape.inner_radius = positive_length(reader, inner);
      shape.outer_radius = positive_length(reader, dimension("outer_radius"));
      shape.length = positive_length(reader, dimension("length"));
      if (!(shape.inner_radius < shape.outer_radius)) {
        reader.fail_at_value(
            inner,
            fmt::format("inner_radius {} must be less than outer_radius {}; a tube's bore "
                        "is inside its wall (use a cylinder for no bore)",
                        format_number(shape.inner_radius), format_number(shape.outer_radius)));
      }
      return;
    }
    case ShapeKind::Box:
      shape.size = read_size(reader, map.require("size", "a box's edges [a, b, c], m, > 0"), 3);
      return;
    case ShapeKind::Plate:
      shape.size = read_size(reader, map.require("size", "a plate's edges [a, b], m, > 0"), 2);
      return;
    case ShapeKind::Torus: {
      shape.radius = positive_length(reader, dimension("radius"));
      const Field tube = dimension("tube_radius");
      shape.tube_radius = positive_length(reader, tube);
      if (!(shape.tube_radius < shape.radius)) {
        reader.fail_at_value(
            tube, fmt::format("tube_radius {} must be less than radius {} (the radius of the "
                              "circle through the tube's centre): a torus whose tube reaches "
                              "its axis has no hole",
                              format_number(shape.tube_radius), format_number(shape.radius)));
      }
      return;
    }
    case ShapeKind::Mesh: {
      const Field file = map.require("file", "a closed triangle mesh, .obj or .stl");
      const std::filesystem::path relative(reader.text(file));
      const std::filesystem::path path = relative.is_absolute() ? relative : directory / relative;
      std::error_code error;
      if (!std::filesystem::is_regular_file(path, error)) {
        reader.fail_at_value(file, fmt::format("cannot read mesh file '{}' (looked for {}); the "
                                               "path is relative to the scenario's folder",
                                               relative.string(), path.string()));
      }
      shape.mesh_file = path.string();
      return;
    }
  }
}

}  // namespace

const std::vector<std::string>& dimension_keys(ShapeKind kind) {
  static const std::vector<std::string> none, length{"length"}, radius{"radius"},
      radius_length{"radius", "length"}, tube{"inner_radius", "outer_radius", "length"},
      size{"size"}, cone{"radius", "height"}, file{"file"}, torus{"radius", "tube_radius"};
  switch (kind) {
    case ShapeKind::Point:
      return none;
    case ShapeKind::Rod:
      return length;
    case ShapeKind::Ring:
    case ShapeKind::Disk:
    case ShapeKind::Sphere:
    case ShapeKind::Shell:
      return radius;
    case ShapeKind::Cylinder:
    case ShapeKind::Capsule:
      return radius_length;
    case ShapeKind::Tube:
      return tube;
    case ShapeKind::Box:
    case ShapeKind::Plate:
      return size;
    case ShapeKind::Cone:
      return cone;
    case ShapeKind::Mesh:
      return file;
    case ShapeKind::Torus:
      return torus;
  }
  return none;
}

const std::vector<std::string>& all_dimension_keys() {
  static const std::vector<std::string> keys{"length", "radius", "inner_radius", "outer_radius",
                                             "height", "size",   "file",         "tube_radius"};
  return keys;
}

std::string shape_list(bool with_point) {
  std::vector<std::string> names;
  for (ShapeKind kind : kAllShapes) {
    if (kind != ShapeKind::Point || with_point) names.emplace_back(shape_name(kind));
  }
  return join(names);
}

ShapeRead read_shape_and_mass(const Reader& reader, const MapReader& map,
                              const std::filesystem::path& directory, bool point_allowed,
                              const std::vector<std::string>& other_keys, const std::string& what) {
  ShapeRead result;
  if (!map.has("shape")) {
    // A misspelt `shape:` is more likely than a missing one: suggest it.
    std::vector<std::string> allowed = other_keys;
    for (const std::string& key : all_dimension_keys()) allowed.push_back(key);
    map.allow_only(allowed, what);
  }
  result.shape_field = map.require("shape", "one of " + shape_list(point_allowed));
  const std::string name = reader.text(result.shape_field);
  const std::optional<ShapeKind> kind = shape_kind_from_name(name);
  if (!kind) {
    std::vector<std::string> names;
    for (ShapeKind k : kAllShapes) names.emplace_back(shape_name(k));
    std::string why = "unknown shape '" + name + "'";
    if (const auto alias = synonym(name)) {
      why += "; did you mean '" + std::string(*alias) + "'?";
    } else if (const auto match = closest_match(name, names)) {
      why += "; did you mean '" + *match + "'?";
    }
    reader.fail_at_value(result.shape_field,
                         why + " (the shapes are " + shape_list(point_allowed) + ")");
  }
  if (*kind == ShapeKind::Point && !point_allowed) {
    reader.fail_at_value(result.shape_field,
                         "a point has no inertia and cannot be a body on its own; use it inside "
                         "`parts:` (a composite body) or choose a sphere");
  }
  result.shape.kind = *kind;

  std::vector<std::string> allowed = other_keys;
  for (const std::string& key : dimension_keys(*kind)) allowed.push_back(key);
  map.allow_only(allowed, what + " of shape " + name, [&](const std::string& key) {
    const auto& all = all_dimension_keys();
    if (std::find(all.begin(), all.end(), key) == all.end()) return std::string();
    const auto& mine = dimension_keys(*kind);
    return fmt::format("'{}' is not a dimension of {}, which takes {}", key, article_shape(*kind),
                       mine.empty() ? std::string("none") : join(mine, " and "));
  });
  read_dimensions(reader, map, result.shape, directory);

  const std::optional<Field> mass = map.find("mass");
  const std::optional<Field> density = map.find("density");
  if (mass && density) {
    const Field& later = density->key_mark.pos > mass->key_mark.pos ? *density : *mass;
    reader.fail_at_key(later,
                       "give mass or density, not both: mass: (kg) sets the mass, "
                       "density: multiplies the shape's size");
  }
  if (!mass && !density) {
    map.require("mass", *kind == ShapeKind::Point
                            ? "kg, > 0; a point needs a mass"
                            : fmt::format("kg, > 0; or density: in {}", density_unit(*kind)));
  }
  if (mass) {
    result.mass_field = *mass;
    result.mass = reader.number(*mass);
    if (!(result.mass > 0.0)) {
      reader.fail_at_value(*mass, fmt::format("mass must be > 0 (kg), got {}; give the mass in kg",
                                              format_number(result.mass)));
    }
    return result;
  }
  result.mass_field = *density;
  if (*kind == ShapeKind::Point) {
    reader.fail_at_key(*density,
                       "a point has no size, so a density gives it no mass; give mass: "
                       "(kg) instead");
  }
  const double rho = reader.number(*density);
  if (!(rho > 0.0)) {
    reader.fail_at_value(*density, fmt::format("density must be > 0 ({}), got {}",
                                               density_unit(*kind), format_number(rho)));
  }
  try {
    result.mass = rho * shape_measure(result.shape);
  } catch (const std::runtime_error& error) {  // InertiaError, MeshError
    reader.fail_at_value(result.shape_field, error.what());
  }
  return result;
}

Mat3 read_inertia(const Reader& reader, const Field& field) {
  Mat3 inertia = Mat3::Zero();
  const bool rows =
      field.node && field.node.IsSequence() && field.node.size() == 3 && field.node[0].IsSequence();
  if (rows) {
    inertia = reader.mat3(field);
  } else if (field.node && field.node.IsSequence() && field.node.size() == 3) {
    const Vec3 moments = reader.vec3(field);
    inertia = moments.asDiagonal();
  } else {
    reader.fail_at_value(field,
                         "expected 3 principal moments [Ixx, Iyy, Izz] (kg m^2, on the "
                         "body's axes) or a symmetric 3x3 [[..], [..], [..]]");
  }
  try {
    validate_inertia(inertia);
  } catch (const InertiaError& error) {
    reader.fail_at_value(field, std::string(error.what()) +
                                    "; correct `inertia:` or remove it to use the shape's own");
  }
  return inertia;
}

Mat3 read_orientation(const Reader& reader, const Field& field) {
  constexpr std::string_view forms =
      "identity, {axis: [x, y, z], angle: rad}, {matrix: [[..], [..], [..]]} or "
      "{quaternion: [w, x, y, z]}";
  if (field.node && field.node.IsScalar()) {
    if (field.node.Scalar() == "identity") return Mat3::Identity();
    reader.fail_at_value(field, fmt::format("expected {}, got '{}'", forms, field.node.Scalar()));
  }
  const MapReader map(reader, field, std::string("an orientation: ") + std::string(forms));
  map.allow_only({"axis", "angle", "matrix", "quaternion"}, "an orientation");
  if (map.fields().empty()) {
    reader.fail_at_value(field, fmt::format("empty orientation; give {}", forms));
  }
  // Exactly one form: the first key decides, any key of another form is an error.
  const std::string first = map.fields().front().key();
  const bool axis_angle = first == "axis" || first == "angle";
  for (const Field& other : map.fields()) {
    const bool same =
        axis_angle ? (other.key() == "axis" || other.key() == "angle") : other.key() == first;
    if (!same) {
      reader.fail_at_key(other, fmt::format("give one form of orientation, not both '{}' and "
                                            "'{}': {}",
                                            first, other.key(), forms));
    }
  }
  if (axis_angle) {
    const Field axis_field = map.require("axis", "the unit-free direction [x, y, z] to turn about");
    const Field angle_field = map.require("angle", "rad, or degrees as '30 deg'");
    const Vec3 given = reader.vec3(axis_field);
    const std::optional<Vec3> axis = unit_direction(given);
    const double angle = reader.angle(angle_field);
    if (!axis) {
      reader.fail_at_value(axis_field,
                           "axis [0, 0, 0] has no direction; give a nonzero vector "
                           "(it need not be unit length)");
    }
    // The axis as given where its norm is a number (rotation_from_axis_angle normalises it, and
    // normalising twice could move the last bit); the scaled unit vector where it is not.
    const double squared = given.squaredNorm();
    const bool well_scaled =
        std::isfinite(squared) && squared >= std::numeric_limits<double>::min();
    return rotation_from_axis_angle(well_scaled ? given : *axis, angle);
  }
  if (first == "matrix") {
    const Field matrix_field = *map.find("matrix");
    const Mat3 R = reader.mat3(matrix_field);
    const double error = orthonormality_error(R);
    if (!(error <= kRotationTolerance)) {
      reader.fail_at_value(
          matrix_field,
          fmt::format("matrix is not orthonormal: max|R^T R - I| = {:.3g} exceeds {:g}; give its "
                      "entries to 10 or more significant digits, or use {{axis, angle}} or "
                      "{{quaternion}}",
                      error, kRotationTolerance));
    }
    const double det = R.determinant();
    if (!(std::abs(det - 1.0) <= kRotationTolerance)) {
      reader.fail_at_value(matrix_field,
                           fmt::format("matrix has determinant {:.6g}: a reflection, not a "
                                       "rotation; change the sign of one row",
                                       det));
    }
    return R;
  }
  const Field q_field = *map.find("quaternion");
  const std::vector<double> q = reader.numbers(q_field, 4, "[w, x, y, z]");
  // Scaled by its largest component where its norm would overflow or underflow.
  const double largest = std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2]), std::abs(q[3])});
  const double squared = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  const double scale = std::isfinite(squared) && squared >= std::numeric_limits<double>::min()
                           ? 1.0
                           : (largest > 0.0 ? largest : 1.0);
  const Quat quaternion(q[0] / scale, q[1] / scale, q[2] / scale, q[3] / scale);
  if (!(quaternion.norm() > 0.0)) {
    reader.fail_at_value(q_field,
                         "quaternion [0, 0, 0, 0] is no rotation; give a nonzero "
                         "[w, x, y, z] (it is normalised), e.g. [1, 0, 0, 0]");
  }
  return rotation_from_quaternion(quaternion.normalized());
}

}  // namespace tumble::scenario_reading
