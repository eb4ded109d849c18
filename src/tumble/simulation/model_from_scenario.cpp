#include "tumble/simulation/model_from_scenario.hpp"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

#include "tumble/inertia/mesh.hpp"
#include "tumble/math/rotation.hpp"

namespace tumble {

namespace {

// The part of a shape that touches a plane (the reader admits only these shapes).
ContactSurface contact_surface(const Shape& shape) {
  ContactSurface surface;
  switch (shape.kind) {
    case ShapeKind::Sphere:
    case ShapeKind::Shell:
      surface.kind = ContactSurface::Kind::Sphere;
      surface.radius = shape.radius;
      break;
    case ShapeKind::Disk:
    case ShapeKind::Ring:
      surface.kind = ContactSurface::Kind::Circle;
      surface.radius = shape.radius;
      // A ring lying flat touches along its rim only (its face's torsional friction).
      if (shape.kind == ShapeKind::Ring) surface.face_inner_radius = shape.radius;
      break;
    case ShapeKind::Torus:
      // Its centre circle, as a ring's rim, with its tube about it: lying flat it bears along
      // that circle, as a ring does.
      surface.kind = ContactSurface::Kind::Circle;
      surface.radius = shape.radius;
      surface.face_inner_radius = shape.radius;
      surface.tube_radius = shape.tube_radius;
      break;
    case ShapeKind::Cylinder:
    case ShapeKind::Tube:
      surface.kind = ContactSurface::Kind::Cylinder;
      surface.radius = shape.kind == ShapeKind::Tube ? shape.outer_radius : shape.radius;
      surface.half_length = shape.length / 2;
      if (shape.kind == ShapeKind::Tube) surface.face_inner_radius = shape.inner_radius;
      break;
    case ShapeKind::Capsule:
      // Its axis's segment between the caps' centres, swept by its radius (pair_core.hpp).
      surface.kind = ContactSurface::Kind::Capsule;
      surface.radius = shape.radius;
      surface.half_length = shape.length / 2;
      break;
    case ShapeKind::Box:
    case ShapeKind::Plate: {
      // The corners; a plate's two faces share its four.
      surface.kind = ContactSurface::Kind::Polyhedron;
      const Vec3 half = shape.size / 2;
      if (shape.kind == ShapeKind::Box) surface.half_size = half;
      for (const double z : shape.kind == ShapeKind::Box ? std::vector<double>{-1.0, 1.0}
                                                         : std::vector<double>{0.0}) {
        for (const double y : {-1.0, 1.0}) {
          for (const double x : {-1.0, 1.0}) {
            surface.vertices.emplace_back(x * half.x(), y * half.y(), z * half.z());
          }
        }
      }
      break;
    }
    case ShapeKind::Cone:
      // Apex and base centre from the COM, a quarter of the height above the base.
      surface.kind = ContactSurface::Kind::Cone;
      surface.radius = shape.radius;
      surface.vertices.emplace_back(0.0, 0.0, 0.75 * shape.height);
      surface.rim_centre_B = Vec3(0.0, 0.0, -0.25 * shape.height);
      break;
    case ShapeKind::Mesh: {
      // The mesh's vertices from its COM (the body's frame): a plane touches only those of its
      // convex hull, at a vertex, along an edge or on a face.
      surface.kind = ContactSurface::Kind::Polyhedron;
      const TriangleMesh mesh = load_mesh(shape.mesh_file);
      const Vec3 com = mesh_mass_properties(mesh, 1.0).com;
      for (const Vec3& p : mesh.vertices) surface.vertices.push_back(p - com);
      break;
    }
    default:
      throw std::logic_error("no contact surface for this shape; the reader checks this");
  }
  return surface;
}

// The surface of a composite's part in the body's axes from the body's COM.
ContactSurface part_contact_surface(const BodySpec& body, const PartSpec& part) {
  ContactSurface surface = contact_surface(part.shape);
  // The surface is the part's from its own COM (a sphere's or box's centre; a mesh's vertices
  // less its COM in its file's frame; a disk's or cylinder's centre; a cone's, a quarter of its
  // height above its base): a sphere's centre, a polyhedron's vertices and a cone's apex and
  // base centre turned into the body's axes about the part's COM there, and a round part's (a
  // capsule's) axes those of the part.
  const Vec3 centre_B = part.mass_properties.com - body.mass_properties.com;
  surface.centre_B = centre_B;
  for (Vec3& p : surface.vertices) p = centre_B + part.R_BP * p;
  if (!surface.half_size.isZero(0.0)) surface.axes_B = part.R_BP;  // a box part, turned
  if (surface.kind == ContactSurface::Kind::Circle ||
      surface.kind == ContactSurface::Kind::Cylinder ||
      surface.kind == ContactSurface::Kind::Cone || surface.kind == ContactSurface::Kind::Capsule) {
    surface.rim_centre_B = centre_B + part.R_BP * surface.rim_centre_B;
    surface.axes_B = part.R_BP;
    surface.turned = true;
  }
  return surface;
}

Vec3 com_position_W(const BodySpec& body) {
  return body.position_W + body.R_WB * body.mass_properties.com;
}

// Whether the sphere (sphere_body's surface) starts inside the shell (shell_body's, the shell
// its shape or its `shell_part`): then it touches the shell's inside, as a ball in a bowl.
bool starts_inside(const BodySpec& shell_body, int shell_part, const ContactSurface& shell,
                   const BodySpec& sphere_body, const ContactSurface& sphere) {
  const ShapeKind kind = shell_part < 0
                             ? shell_body.shape.kind
                             : shell_body.parts[static_cast<std::size_t>(shell_part)].shape.kind;
  if (kind != ShapeKind::Shell || sphere.kind != ContactSurface::Kind::Sphere) return false;
  const Vec3 shell_centre_W = com_position_W(shell_body) + shell_body.R_WB * shell.centre_B;
  const Vec3 sphere_centre_W = com_position_W(sphere_body) + sphere_body.R_WB * sphere.centre_B;
  return (sphere_centre_W - shell_centre_W).norm() < shell.radius;
}

// The bodies' numbers by name (ground's is kGround), found in constant time: building stays
// linear in the number of joints, forces and contacts.
class BodyNumbers {
 public:
  explicit BodyNumbers(const Scenario& scenario) {
    for (std::size_t i = 0; i < scenario.bodies.size(); ++i) {
      numbers_.emplace(scenario.bodies[i].name, static_cast<int>(i));
    }
  }
  int operator()(const std::string& name) const {
    if (name == kGroundName) return kGround;
    const auto it = numbers_.find(name);
    if (it == numbers_.end()) {
      throw std::logic_error("'" + name + "' names no body; the reader checks this");
    }
    return it->second;
  }

 private:
  std::unordered_map<std::string, int> numbers_;
};

// A world point at t = 0 fixed to a body: its offset from the COM in body axes (for ground, the
// world point itself).
Vec3 fixed_point(const Scenario& scenario, int body, const Vec3& at_W) {
  if (body == kGround) return at_W;
  const BodySpec& spec = scenario.bodies[static_cast<std::size_t>(body)];
  return spec.R_WB.transpose() * (at_W - com_position_W(spec));
}

Mat3 orientation(const Scenario& scenario, int body) {
  return body == kGround ? Mat3::Identity() : scenario.bodies[static_cast<std::size_t>(body)].R_WB;
}

JointModel joint_model(const Scenario& scenario, const BodyNumbers& body_number,
                       const JointSpec& spec) {
  JointModel joint;
  joint.type = spec.type;
  joint.name = spec.name;
  joint.body_a = body_number(spec.body_a);
  joint.body_b = body_number(spec.body_b);
  const bool rod = spec.type == JointType::Distance;
  joint.p_AJ_A = fixed_point(scenario, joint.body_a, rod ? spec.rod_end_a_W : spec.at_W);
  joint.p_BJ_B = fixed_point(scenario, joint.body_b, spec.at_W);
  if (rod) joint.rod_length = (spec.at_W - spec.rod_end_a_W).norm();
  const Mat3 R_WA = orientation(scenario, joint.body_a);
  const Mat3 R_WB = orientation(scenario, joint.body_b);
  joint.R_AB0 = R_WA.transpose() * R_WB;
  joint.axis_B = R_WB.transpose() * spec.axis_W;
  joint.axis_A = R_WA.transpose() * spec.first_axis_W;
  joint.motor.kind = spec.motor.kind == MotorSpec::Kind::Speed    ? JointMotor::Kind::Speed
                     : spec.motor.kind == MotorSpec::Kind::Effort ? JointMotor::Kind::Effort
                                                                  : JointMotor::Kind::None;
  joint.motor.value = spec.motor.value;
  joint.motor.freedom = spec.motor.freedom;
  joint.motor.from = spec.motor.from;
  joint.motor.to = spec.motor.to;
  joint.lock_at = spec.lock_at;
  joint.closes_loop = spec.closes_loop;
  return joint;
}

TorsionalSpring torsional_spring_model(const Scenario& scenario, const BodyNumbers& body_number,
                                       const Model& model, const TorsionalSpringSpec& spec) {
  TorsionalSpring spring;
  spring.name = spec.name;
  spring.body_a = body_number(spec.body_a);
  spring.body_b = body_number(spec.body_b);
  spring.stiffness = spec.stiffness;
  spring.damping = spec.damping;
  const Mat3 R_AB0 =
      orientation(scenario, spring.body_a).transpose() * orientation(scenario, spring.body_b);
  spring.R_AB_rest = spec.rest_orientation.value_or(R_AB0);
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const JointModel& joint = model.joints[j];
    // A loop's closing hinge has no angle in the state: the spring takes the bodies' turn.
    if (joint.type != JointType::Hinge || joint.closes_loop) continue;
    const bool same = joint.body_a == spring.body_a && joint.body_b == spring.body_b;
    const bool swapped = joint.body_a == spring.body_b && joint.body_b == spring.body_a;
    if (!same && !swapped) continue;
    // Across a hinge the spring turns with the hinge angle, taken in the joint's order: the pair
    // of moments is the same whichever body is named first. A rest angle is the hinge's angle as
    // the joint states it; a rest orientation is the spring's second body relative to its first,
    // so turned into the joint's order before its angle about the joint's axis is taken.
    spring.hinge = static_cast<int>(j);
    if (swapped) std::swap(spring.body_a, spring.body_b);
    const Mat3 R_AB_rest_joint = swapped ? Mat3(spring.R_AB_rest.transpose()) : spring.R_AB_rest;
    const double rest = spec.rest_angle.value_or(
        spec.rest_orientation ? joint.axis_B.dot(log_so3(joint.R_AB0.transpose() * R_AB_rest_joint))
                              : 0.0);
    spring.rest_angle = rest;
    spring.R_AB_rest = R_AB_rest_joint;
    break;
  }
  return spring;
}

}  // namespace

Model build_model(const Scenario& scenario) {
  Model model;
  model.gravity_W = scenario.gravity_W;
  if (scenario.simulate.integrator == "rk4" || scenario.simulate.integrator == "rkmk4") {
    model.fixed_step = scenario.simulate.step;
  }
  for (const BodySpec& body : scenario.bodies) {
    model.bodies.push_back(RigidBody::make(body.name, body.mass_properties.mass,
                                           body.mass_properties.inertia_about_com));
  }
  const BodyNumbers body_number(scenario);
  for (const LoadSpec& spec : scenario.loads) {
    const auto it = scenario.bodies.begin() + body_number(spec.body);
    AppliedLoad load;
    load.kind =
        spec.kind == LoadSpec::Kind::Force ? AppliedLoad::Kind::Force : AppliedLoad::Kind::Torque;
    load.name = spec.name;
    load.body = static_cast<std::size_t>(it - scenario.bodies.begin());
    load.value = spec.value;
    load.body_frame = spec.body_frame;
    // `at:` is a world point at t = 0; fix it to the body as an offset from the COM in body axes.
    if (spec.has_point) load.p_GP_B = it->R_WB.transpose() * (spec.at_W - com_position_W(*it));
    load.from = spec.from;
    load.to = spec.to;
    model.loads.push_back(load);
  }
  for (const JointSpec& spec : scenario.joints)
    model.joints.push_back(joint_model(scenario, body_number, spec));
  for (const SpringSpec& spec : scenario.springs) {
    LinearSpring spring;
    spring.name = spec.name;
    spring.body_a = body_number(spec.body_a);
    spring.body_b = body_number(spec.body_b);
    spring.p_A_A = fixed_point(scenario, spring.body_a, spec.at_a_W);
    spring.p_B_B = fixed_point(scenario, spring.body_b, spec.at_b_W);
    spring.stiffness = spec.stiffness;
    spring.damping = spec.damping;
    spring.rest_length = spec.rest_length.value_or((spec.at_b_W - spec.at_a_W).norm());
    model.springs.push_back(spring);
  }
  for (const TorsionalSpringSpec& spec : scenario.torsional_springs) {
    model.torsional_springs.push_back(torsional_spring_model(scenario, body_number, model, spec));
  }
  for (const ImpulseSpec& spec : scenario.impulses) {
    ImpulseLoad impulse;
    impulse.name = spec.name;
    impulse.body = static_cast<std::size_t>(body_number(spec.body));
    impulse.value = spec.value;
    impulse.body_frame = spec.body_frame;
    if (spec.has_point) {
      impulse.p_GP_B = fixed_point(scenario, static_cast<int>(impulse.body), spec.at_W);
    }
    impulse.time = spec.time;
    model.impulses.push_back(impulse);
  }
  std::unordered_map<std::string, std::size_t> pool_entries;  // a pool's ledger entry
  for (const ContactSpec& spec : scenario.contacts) {
    PlaneContact contact;
    contact.name = spec.name;
    contact.body = static_cast<std::size_t>(body_number(spec.body));
    const BodySpec& body = scenario.bodies[contact.body];
    contact.surface =
        spec.part < 0 ? contact_surface(body.shape)
                      : part_contact_surface(body, body.parts[static_cast<std::size_t>(spec.part)]);
    if (!spec.other_body.empty()) {
      contact.other_body = static_cast<std::size_t>(body_number(spec.other_body));
      contact.screened = spec.screened;
      const BodySpec& other = scenario.bodies[contact.other_body];
      contact.other_surface =
          spec.other_part < 0
              ? contact_surface(other.shape)
              : part_contact_surface(other, other.parts[static_cast<std::size_t>(spec.other_part)]);
      // A sphere inside a shell touches its inside, and is the contact's body whichever of the
      // two `bodies:` names first.
      if (starts_inside(other, spec.other_part, contact.other_surface, body, contact.surface)) {
        contact.other_surface.touched_inside = true;
      } else if (starts_inside(body, spec.part, contact.surface, other, contact.other_surface)) {
        std::swap(contact.body, contact.other_body);
        std::swap(contact.surface, contact.other_surface);
        contact.other_surface.touched_inside = true;
      }
    }
    contact.point_W = spec.plane_point_W;
    contact.normal_W = spec.plane_normal_W;
    contact.friction = spec.friction;
    contact.restitution = spec.restitution;
    model.contacts.push_back(contact);
    // Its work-ledger entry: its own, or its pool's, which the first of the pool's pairs opens.
    const auto [pool, opened] =
        spec.pool.empty() ? std::pair{pool_entries.end(), true}
                          : pool_entries.emplace(spec.pool, model.contact_ledger_names.size());
    if (opened) {
      model.contact_ledger.push_back(model.contact_ledger_names.size());
      model.contact_ledger_names.push_back(spec.pool.empty() ? spec.name : spec.pool);
    } else {
      model.contact_ledger.push_back(pool->second);
    }
  }
  return model;
}

std::vector<BodyState> initial_states(const Scenario& scenario) {
  std::vector<BodyState> states;
  for (const BodySpec& body : scenario.bodies) {
    BodyState s;
    s.r_G = com_position_W(body);
    s.R_WB = body.R_WB;
    s.v_G = body.velocity_W;
    s.omega_W = body.angular_velocity_W;
    states.push_back(s);
  }
  return states;
}

}  // namespace tumble
