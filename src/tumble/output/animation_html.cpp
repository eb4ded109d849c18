#include "tumble/output/animation_html.hpp"

#include "tumble/output/atomic_file.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "tumble/inertia/mesh.hpp"
#include "tumble/math/rotation.hpp"
#include "tumble/multibody/joints/joint_kind.hpp"
#include "tumble/output/animation_assets.hpp"

namespace tumble {
namespace {

// Meshes larger than this are drawn as their bounding box: the page stays small and fast.
constexpr std::size_t kMaxMeshTriangles = 200'000;

// Radius of a sphere about the part's origin that holds the drawn part, m.
double part_radius(const AnimationPart& part) {
  const Shape& s = part.shape;
  switch (s.kind) {
    case ShapeKind::Box:
    case ShapeKind::Plate:
      return 0.5 * s.size.norm();
    case ShapeKind::Cylinder:
      return std::hypot(s.radius, 0.5 * s.length);
    case ShapeKind::Capsule:
      return s.radius + 0.5 * s.length;
    case ShapeKind::Tube:
      return std::hypot(s.outer_radius, 0.5 * s.length);
    case ShapeKind::Rod:
      return 0.5 * s.length;
    case ShapeKind::Ring:
    case ShapeKind::Disk:
    case ShapeKind::Sphere:
    case ShapeKind::Shell:
      return s.radius;
    case ShapeKind::Cone:
      return std::max(std::hypot(s.radius, 0.25 * s.height), 0.75 * s.height);
    case ShapeKind::Mesh:
      return std::max(part.box_min.norm(), part.box_max.norm());
    case ShapeKind::Torus:
      return s.radius + s.tube_radius;
    case ShapeKind::Point:
      return 0.0;
  }
  return 0.0;
}

// A mesh in its part frame (the file's axes moved to the mesh's COM), or its bounding box.
void load_mesh_part(AnimationPart& part) {
  try {
    const TriangleMesh mesh = load_mesh(part.shape.mesh_file);
    const Vec3 com = mesh_mass_properties(mesh, 1.0).com;
    part.box_min = Vec3::Constant(std::numeric_limits<double>::infinity());
    part.box_max = -part.box_min;
    for (const Vec3& v : mesh.vertices) {
      part.box_min = part.box_min.cwiseMin(v - com);
      part.box_max = part.box_max.cwiseMax(v - com);
    }
    if (mesh.triangles.size() > kMaxMeshTriangles) {
      part.note = fmt::format("{} triangles, more than the page draws ({})", mesh.triangles.size(),
                              kMaxMeshTriangles);
      return;
    }
    part.vertices.reserve(mesh.vertices.size());
    for (const Vec3& v : mesh.vertices) part.vertices.push_back(v - com);
    part.triangles = mesh.triangles;
  } catch (const std::exception& e) {
    part.box_min = Vec3::Constant(-0.05);
    part.box_max = Vec3::Constant(0.05);
    part.note = e.what();
  }
}

// ---- Encoding ------------------------------------------------------------------------------

void append_base64(std::string& out, std::span<const unsigned char> bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    const unsigned n = (unsigned{bytes[i]} << 16) | (unsigned{bytes[i + 1]} << 8) | bytes[i + 2];
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += kAlphabet[(n >> 6) & 63];
    out += kAlphabet[n & 63];
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned n = (unsigned{bytes[i]} << 16) | (two ? unsigned{bytes[i + 1]} << 8 : 0u);
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += two ? kAlphabet[(n >> 6) & 63] : '=';
    out += '=';
  }
}

// The bytes of numbers as the page's typed arrays read them (little-endian, as x86 and ARM).
template <typename T>
void append_base64_of(std::string& out, const std::vector<T>& values) {
  std::vector<unsigned char> bytes(values.size() * sizeof(T));
  if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  out += '"';
  append_base64(out, bytes);
  out += '"';
}

std::string number(double x) {
  return std::isfinite(x) ? fmt::format("{:.9g}", x) : "0";
}

std::string vec(const Vec3& v) {
  return fmt::format("[{},{},{}]", number(v.x()), number(v.y()), number(v.z()));
}

// Three.js order (x, y, z, w).
std::string quaternion(const Mat3& R) {
  const Quat q = quaternion_from_rotation(R);
  return fmt::format("[{},{},{},{}]", number(q.x()), number(q.y()), number(q.z()), number(q.w()));
}

std::string html_text(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void append_part(std::string& json, const AnimationPart& part) {
  const Shape& s = part.shape;
  json +=
      fmt::format(R"({{"name":{},"shape":{},"position":{},"quaternion":{})", json_string(part.name),
                  json_string(shape_name(s.kind)), vec(part.position_GP_B), quaternion(part.R_BP));
  switch (s.kind) {
    case ShapeKind::Box:
    case ShapeKind::Plate:
      json += fmt::format(R"(,"size":{})", vec(s.size));
      break;
    case ShapeKind::Mesh:
      json += fmt::format(R"(,"size":{},"centre":{},"note":{})", vec(part.box_max - part.box_min),
                          vec(0.5 * (part.box_min + part.box_max)), json_string(part.note));
      if (!part.triangles.empty()) {
        std::vector<float> vertices;
        for (const Vec3& v : part.vertices) {
          for (int k = 0; k < 3; ++k) vertices.push_back(static_cast<float>(v(k)));
        }
        std::vector<std::uint32_t> indices;
        for (const auto& t : part.triangles) {
          for (const int k : t) indices.push_back(static_cast<std::uint32_t>(k));
        }
        json += R"(,"vertices":)";
        append_base64_of(json, vertices);
        json += R"(,"triangles":)";
        append_base64_of(json, indices);
      }
      break;
    default:
      json += fmt::format(
          R"(,"radius":{},"length":{},"inner_radius":{},"outer_radius":{},"height":{},"tube_radius":{})",
          number(s.radius), number(s.length), number(s.inner_radius), number(s.outer_radius),
          number(s.height), number(s.tube_radius));
  }
  json += '}';
}

// The page's data: see web/src/animation.js for the layout it reads.
std::string scene_json(const AnimationScene& scene, const RecordedTrajectory& rows,
                       std::span<const AnimationEvent> events) {
  const std::size_t n = rows.rows();
  const std::size_t nb = rows.body_count();
  std::string json =
      fmt::format(R"({{"format":"tumble-animation-1","name":{},"rows":{},"planar":{},)",
                  json_string(scene.name), n, scene.planar ? "true" : "false");
  json += R"("bodies":[)";
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const AnimationBody& body = scene.bodies[b];
    json += fmt::format(R"({}{{"name":{},"extent":{},"parts":[)", b == 0 ? "" : ",",
                        json_string(body.name), number(body.extent));
    for (std::size_t p = 0; p < body.parts.size(); ++p) {
      if (p > 0) json += ',';
      append_part(json, body.parts[p]);
    }
    json += "]}";
  }
  json += R"(],"planes":[)";
  for (std::size_t k = 0; k < scene.planes.size(); ++k) {
    const AnimationPlane& plane = scene.planes[k];
    json += fmt::format(R"({}{{"name":{},"point":{},"normal":{}}})", k == 0 ? "" : ",",
                        json_string(plane.name), vec(plane.point_W), vec(plane.normal_W));
  }
  json += R"(],"joints":[)";
  for (std::size_t k = 0; k < scene.joints.size(); ++k) {
    const AnimationJoint& joint = scene.joints[k];
    json += fmt::format(R"({}{{"name":{},"type":{},"body":{},"point":{},"axis":{}}})",
                        k == 0 ? "" : ",", json_string(joint.name), json_string(joint.type),
                        joint.body, vec(joint.point_GJ_B), vec(joint.axis_B));
  }
  json += R"(],"rods":[)";
  for (std::size_t k = 0; k < scene.rods.size(); ++k) {
    const AnimationRod& rod = scene.rods[k];
    json +=
        fmt::format(R"({}{{"name":{},"a":{},"end_a":{},"b":{},"end_b":{}}})", k == 0 ? "" : ",",
                    json_string(rod.name), rod.body_a, vec(rod.end_a), rod.body_b, vec(rod.end_b));
  }
  json += "],";

  std::vector<double> time(n);
  std::vector<double> system;
  system.reserve(4 * n);
  std::vector<float> body_rows;
  body_rows.reserve(16 * n * nb);
  const auto put = [&](const Vec3& v) {
    for (int k = 0; k < 3; ++k) body_rows.push_back(static_cast<float>(v(k)));
  };
  for (std::size_t i = 0; i < n; ++i) {
    time[i] = rows.t(i);
    const SystemQuantities& q = rows.quantities(i);
    system.insert(system.end(), {q.kinetic_energy, q.potential_energy, q.total_energy,
                                 q.angular_momentum_about_origin.norm()});
    for (std::size_t b = 0; b < nb; ++b) {
      const BodyState& s = rows.state(i, b);
      const Quat q_WB = quaternion_from_rotation(s.R_WB);
      put(s.r_G);
      for (const double c : {q_WB.x(), q_WB.y(), q_WB.z(), q_WB.w()}) {
        body_rows.push_back(static_cast<float>(c));
      }
      put(s.omega_W);
      put(s.R_WB.transpose() * s.omega_W);
      // L about the COM, world: R I_G_B R^T omega_W.
      put(s.R_WB * (scene.bodies[b].I_G_B * (s.R_WB.transpose() * s.omega_W)));
    }
  }
  json += R"("time":)";
  append_base64_of(json, time);
  json += R"(,"system":)";
  append_base64_of(json, system);
  json += R"(,"body_rows":)";
  append_base64_of(json, body_rows);
  // The scenario's plots: their titles and columns, and the columns' values row by row.
  json += R"(,"plots":[)";
  for (std::size_t p = 0; p < rows.plots().size(); ++p) {
    const AnimationPlot& plot = rows.plots()[p];
    json +=
        fmt::format(R"({}{{"title":{},"columns":[)", p == 0 ? "" : ",", json_string(plot.title));
    for (std::size_t c = 0; c < plot.columns.size(); ++c) {
      if (c > 0) json += ',';
      json += json_string(plot.columns[c]);
    }
    json += "]}";
  }
  json += R"(],"plot_values":)";
  append_base64_of(json, rows.plot_values());
  json += R"(,"events":[)";
  for (std::size_t e = 0; e < events.size(); ++e) {
    json += fmt::format(R"({}{{"t":{},"what":{}}})", e == 0 ? "" : ",", number(events[e].t),
                        json_string(events[e].what));
  }
  json += "]}";
  return json;
}

}  // namespace

std::string json_string(std::string_view text) {
  std::string out = "\"";
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (byte < 0x20 || c == '<' || c == '>' || c == '&') {
      // "<" as \u003c: no "</script>" or "<!--" can appear inside the data element.
      out += fmt::format("\\u{:04x}", static_cast<unsigned>(byte));
    } else if (byte == 0xE2 && i + 2 < text.size() &&
               static_cast<unsigned char>(text[i + 1]) == 0x80 &&
               (static_cast<unsigned char>(text[i + 2]) & 0xFE) == 0xA8) {
      // U+2028 and U+2029: valid in JSON, but line ends to older JavaScript parsers.
      out += fmt::format("\\u{:04x}", 0x2028u + (static_cast<unsigned char>(text[i + 2]) & 1u));
      i += 2;
    } else {
      out += c;
    }
  }
  out += '"';
  return out;
}

AnimationScene make_animation_scene(const Scenario& scenario) {
  AnimationScene scene;
  scene.name = scenario.name;
  scene.planar = scenario.planar;
  for (const BodySpec& spec : scenario.bodies) {
    AnimationBody body;
    body.name = spec.name;
    body.I_G_B = spec.mass_properties.inertia_about_com;
    const Vec3& com_B = spec.mass_properties.com;
    if (spec.parts.empty()) {
      AnimationPart part;
      part.name = spec.name;
      part.shape = spec.shape;
      body.parts.push_back(std::move(part));
    } else {
      for (const PartSpec& p : spec.parts) {
        AnimationPart part;
        part.name = p.name;
        part.shape = p.shape;
        part.position_GP_B = p.position_B - com_B;
        part.R_BP = p.R_BP;
        body.parts.push_back(std::move(part));
      }
    }
    double extent = 0.0;
    for (AnimationPart& part : body.parts) {
      if (part.shape.kind == ShapeKind::Mesh) load_mesh_part(part);
      extent = std::max(extent, part.position_GP_B.norm() + part_radius(part));
    }
    // A point mass (or a body of points) is drawn as a small sphere.
    if (!(extent > 0.0)) extent = 0.1;
    for (AnimationPart& part : body.parts) {
      if (part.shape.kind == ShapeKind::Point) part.shape.radius = 0.05 * extent;
    }
    body.extent = extent;
    scene.bodies.push_back(std::move(body));
  }
  // A world point at t = 0 from a body's COM, its axes (ground's: the point itself).
  const auto fixed_to = [&](const std::string& body_name, const Vec3& at_W, int& body) -> Vec3 {
    const auto it = std::find_if(scenario.bodies.begin(), scenario.bodies.end(),
                                 [&](const BodySpec& b) { return b.name == body_name; });
    if (it == scenario.bodies.end()) return at_W;
    body = static_cast<int>(it - scenario.bodies.begin());
    return it->R_WB.transpose() * (at_W - (it->position_W + it->R_WB * it->mass_properties.com));
  };
  for (const JointSpec& spec : scenario.joints) {
    if (spec.type == JointType::Distance) {
      AnimationRod rod;
      rod.name = spec.name;
      rod.end_a = fixed_to(spec.body_a, spec.rod_end_a_W, rod.body_a);
      rod.end_b = fixed_to(spec.body_b, spec.at_W, rod.body_b);
      scene.rods.push_back(std::move(rod));
      continue;
    }
    // At t = 0, from the body's COM in its axes (the rows carry the COM and the orientation).
    int held = -1;
    const Vec3 point_GJ_B = fixed_to(spec.body_b, spec.at_W, held);
    if (held < 0) continue;
    AnimationJoint joint;
    joint.name = spec.name;
    joint.type = std::string(joint_type_name(spec.type));
    joint.body = static_cast<std::size_t>(held);
    joint.point_GJ_B = point_GJ_B;
    joint.axis_B = scenario.bodies[joint.body].R_WB.transpose() * spec.axis_W;
    scene.joints.push_back(std::move(joint));
  }
  // One plane per distinct plane: bodies racing down one ramp each have a contact with it.
  for (const ContactSpec& contact : scenario.contacts) {
    if (!contact.other_body.empty()) continue;  // two bodies: their shapes are drawn already
    const Vec3& n = contact.plane_normal_W;
    const double offset = n.dot(contact.plane_point_W);
    const bool drawn = std::any_of(scene.planes.begin(), scene.planes.end(), [&](const auto& p) {
      const double scale = 1.0 + std::abs(offset);
      return (p.normal_W - n).norm() <= 1e-12 &&
             std::abs(p.normal_W.dot(p.point_W) - offset) <= 1e-12 * scale;
    });
    if (!drawn) scene.planes.push_back({contact.name, contact.plane_point_W, n});
  }
  return scene;
}

void RecordedTrajectory::record_plots(const ColumnLayout& layout,
                                      std::vector<AnimationPlot> plots) {
  std::vector<std::string> wanted;
  for (const AnimationPlot& plot : plots) {
    wanted.insert(wanted.end(), plot.columns.begin(), plot.columns.end());
  }
  std::vector<std::function<double(const OutputRow&)>> by_name(wanted.size());
  const std::vector<std::string> names = column_names(layout);
  std::size_t i = 0;
  for_each_column(layout, [&](std::string_view, std::string_view, auto&& value_of) {
    for (std::size_t k = 0; k < wanted.size(); ++k) {
      if (wanted[k] == names[i]) {
        by_name[k] = [value_of](const OutputRow& row) {
          return static_cast<double>(value_of(row));
        };
      }
    }
    ++i;
  });
  for (std::size_t k = 0; k < wanted.size(); ++k) {
    if (!by_name[k]) {
      throw std::invalid_argument("RecordedTrajectory: no column " + wanted[k]);
    }
  }
  plots_ = std::move(plots);
  plot_columns_ = std::move(by_name);
}

void RecordedTrajectory::write_row(const OutputRow& row) {
  record(row.t, row.states, *row.quantities);
  for (const auto& value_of : plot_columns_) plot_values_.push_back(value_of(row));
}

void RecordedTrajectory::record(double t, std::span<const BodyState> states,
                                const SystemQuantities& q) {
  if (states.size() != body_count_) {
    throw std::invalid_argument(fmt::format("RecordedTrajectory: a row of {} bodies, expected {}",
                                            states.size(), body_count_));
  }
  t_.push_back(t);
  states_.insert(states_.end(), states.begin(), states.end());
  quantities_.push_back(q);
}

void write_animation_html(const std::filesystem::path& path, const AnimationScene& scene,
                          const RecordedTrajectory& rows, std::span<const AnimationEvent> events) {
  if (scene.bodies.size() != rows.body_count()) {
    throw std::invalid_argument(
        fmt::format("write_animation_html: {} bodies in the scene, {} in "
                    "the rows",
                    scene.bodies.size(), rows.body_count()));
  }
  if (rows.rows() == 0) {
    throw std::invalid_argument("write_animation_html: no rows to animate");
  }
  const std::string json = scene_json(scene, rows, events);
  AtomicFile file(path);
  file.write("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
  file.write("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
  // No network: the page may load nothing but itself and data: URLs.
  file.write(
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
      "script-src 'unsafe-inline'; style-src 'unsafe-inline'; img-src data: blob:\">\n");
  file.write(fmt::format("<title>{}</title>\n<style>\n", html_text(scene.name)));
  file.write(animation_assets::style());
  file.write("</style>\n</head>\n<body>\n");
  file.write(animation_assets::markup());
  file.write("<script type=\"application/json\" id=\"tumble-data\">");
  file.write(json);
  file.write("</script>\n<script>\n");
  file.write(animation_assets::script());
  file.write("\n</script>\n</body>\n</html>\n");
  file.finish();
}

}  // namespace tumble
