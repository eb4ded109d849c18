#pragma once
// The trajectory's columns, their names and their values, defined in one place: walk_columns
// visits a row's values in column order and names each, so the CSV's header and its rows (and any
// other sink that wants columns by name) cannot disagree.
//   t, per body B: B.x B.y B.z (COM, world), B.vx B.vy B.vz, B.wx B.wy B.wz (world),
//   B.R11 ... B.R33 (row-major, body axes -> world), then KE PE E px py pz Lx Ly Lz (about the
//   world origin), then per joint J: J.Fx J.Fy J.Fz J.Mx J.My J.Mz (what its first body exerts on
//   its second, world, moment about the joint point), then per contact C: C.N C.Fx C.Fy C.Fz
//   C.slip C.mode (normal force, friction force on the body, world, slip speed, 0 apart /
//   1 sliding / 2 rolling), then per force element, motor, impulse, lock and contact E: E.P E.W
//   (power now, work since t0), then per body B: B.w1 B.w2 B.w3 (its angular velocity in its own
//   axes: the chapter's omega_1, omega_2, omega_3 of Euler's equations), then per joint J its own
//   coordinates: a hinge's J.angle J.rate (rad, rad/s), a slider's J.travel J.speed (m, m/s), a
//   ball joint's J.rx J.ry J.rz (the rotation vector of its second body relative to its first,
//   rad, the first's axes); a fixed joint none.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tumble/dynamics/joint_type.hpp"
#include "tumble/output/output_row.hpp"

namespace tumble {

// Whose columns a trajectory has: the names that head them.
struct ColumnLayout {
  std::vector<std::string> bodies;
  std::vector<std::string> joints;
  std::vector<JointType> joint_types;  // as many as joints: which coordinates each has
  std::vector<std::string> contacts;
  std::vector<std::string> elements;  // Formulation::element_names()
};

// Calls column(owner, field, value) for each column in order: owner is "" for t and the system's
// quantities (the column's name is the field), else the body, joint, contact or element whose
// column it is (the name is owner.field). With no row, the values are 0 (for the names alone).
template <typename Column>
void walk_columns(const ColumnLayout& layout, const OutputRow* row, Column&& column) {
  column(std::string_view(), "t", row != nullptr ? row->t : 0.0);
  static constexpr std::string_view kAxes[3] = {"x", "y", "z"};
  static constexpr std::string_view kVelocity[3] = {"vx", "vy", "vz"};
  static constexpr std::string_view kOmega[3] = {"wx", "wy", "wz"};
  static constexpr std::string_view kR[3][3] = {
      {"R11", "R12", "R13"}, {"R21", "R22", "R23"}, {"R31", "R32", "R33"}};
  for (std::size_t b = 0; b < layout.bodies.size(); ++b) {
    const BodyState* s = row != nullptr ? &row->states[b] : nullptr;
    const std::string_view body = layout.bodies[b];
    for (int k = 0; k < 3; ++k) column(body, kAxes[k], s ? s->r_G(k) : 0.0);
    for (int k = 0; k < 3; ++k) column(body, kVelocity[k], s ? s->v_G(k) : 0.0);
    for (int k = 0; k < 3; ++k) column(body, kOmega[k], s ? s->omega_W(k) : 0.0);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) column(body, kR[r][c], s ? s->R_WB(r, c) : 0.0);
    }
  }
  const SystemQuantities* q = row != nullptr ? row->quantities : nullptr;
  column(std::string_view(), "KE", q ? q->kinetic_energy : 0.0);
  column(std::string_view(), "PE", q ? q->potential_energy : 0.0);
  column(std::string_view(), "E", q ? q->total_energy : 0.0);
  static constexpr std::string_view kMomentum[3] = {"px", "py", "pz"};
  static constexpr std::string_view kL[3] = {"Lx", "Ly", "Lz"};
  for (int k = 0; k < 3; ++k)
    column(std::string_view(), kMomentum[k], q ? q->linear_momentum(k) : 0.0);
  for (int k = 0; k < 3; ++k) {
    column(std::string_view(), kL[k], q ? q->angular_momentum_about_origin(k) : 0.0);
  }
  const RowExtras* e = row != nullptr ? row->extras : nullptr;
  static constexpr std::string_view kForce[3] = {"Fx", "Fy", "Fz"};
  static constexpr std::string_view kMoment[3] = {"Mx", "My", "Mz"};
  for (std::size_t j = 0; j < layout.joints.size(); ++j) {
    const JointReaction* r = e != nullptr ? &e->joints[j] : nullptr;
    for (int k = 0; k < 3; ++k) column(layout.joints[j], kForce[k], r ? r->F_W(k) : 0.0);
    for (int k = 0; k < 3; ++k) column(layout.joints[j], kMoment[k], r ? r->M_J_W(k) : 0.0);
  }
  for (std::size_t c = 0; c < layout.contacts.size(); ++c) {
    const ContactOutput* o = e != nullptr ? &e->contacts[c] : nullptr;
    const std::string_view contact = layout.contacts[c];
    column(contact, "N", o ? o->normal_force : 0.0);
    for (int k = 0; k < 3; ++k) column(contact, kForce[k], o ? o->friction_W(k) : 0.0);
    column(contact, "slip", o ? o->slip_speed : 0.0);
    column(contact, "mode", o ? static_cast<double>(o->mode) : 0.0);
  }
  for (std::size_t i = 0; i < layout.elements.size(); ++i) {
    const ElementWork* w = e != nullptr ? &e->elements[i] : nullptr;
    column(layout.elements[i], "P", w ? w->power : 0.0);
    column(layout.elements[i], "W", w ? w->work : 0.0);
  }
  static constexpr std::string_view kOmegaBody[3] = {"w1", "w2", "w3"};
  for (std::size_t b = 0; b < layout.bodies.size(); ++b) {
    const BodyState* s = row != nullptr ? &row->states[b] : nullptr;
    const Vec3 omega_B = s ? Vec3(s->R_WB.transpose() * s->omega_W) : Vec3::Zero();
    for (int k = 0; k < 3; ++k) column(layout.bodies[b], kOmegaBody[k], omega_B(k));
  }
  static constexpr std::string_view kRotation[3] = {"rx", "ry", "rz"};
  for (std::size_t j = 0; j < layout.joints.size(); ++j) {
    const JointCoordinates* c =
        e != nullptr && j < e->coordinates.size() ? &e->coordinates[j] : nullptr;
    const std::string_view joint = layout.joints[j];
    switch (layout.joint_types[j]) {
      case JointType::Hinge:
        column(joint, "angle", c ? c->position : 0.0);
        column(joint, "rate", c ? c->rate : 0.0);
        break;
      case JointType::Prismatic:
        column(joint, "travel", c ? c->position : 0.0);
        column(joint, "speed", c ? c->rate : 0.0);
        break;
      case JointType::Ball:
        for (int k = 0; k < 3; ++k) column(joint, kRotation[k], c ? c->rotation(k) : 0.0);
        break;
      default:
        break;
    }
  }
}

// The columns' names in order.
std::vector<std::string> column_names(const ColumnLayout& layout);

}  // namespace tumble
