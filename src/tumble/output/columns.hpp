#pragma once
// The trajectory's columns, their names and their values, defined in one place: for_each_column
// names each column in order with the function that gives its value in a row, so the CSV's header
// and its rows (and any other sink that wants columns by name) cannot disagree.
//   t, per body B: B.x B.y B.z (COM, world), B.vx B.vy B.vz, B.wx B.wy B.wz (world),
//   B.R11 ... B.R33 (row-major, body axes -> world), then KE PE E px py pz Lx Ly Lz (about the
//   world origin), then per joint J: J.Fx J.Fy J.Fz J.Mx J.My J.Mz (what its first body exerts on
//   its second, world, moment about the joint point), then per contact C: C.N C.Fx C.Fy C.Fz
//   C.slip C.mode (normal force, friction force on the body, world, slip speed, 0 apart /
//   1 sliding / 2 rolling), then per force element, motor, impulse, lock and contact E: E.P E.W
//   (power now, work since t0), then per body B: B.w1 B.w2 B.w3 (its angular velocity in its own
//   axes: the chapter's omega_1, omega_2, omega_3 of Euler's equations), then per joint J its own
//   coordinates as its kind names them (multibody/joints/: a hinge's J.angle J.rate (rad,
//   rad/s), a slider's J.travel J.speed (m, m/s), a ball joint's J.rx J.ry J.rz (the rotation
//   vector of its second body relative to its first, rad, the first's axes), a fixed joint
//   none); then, in a planar scenario, per body B: B.angle B.rate (its angle about z, rad, run
//   on past a turn, and its rate, rad/s); then per body B: B.speed (its COM's speed, |v|, m/s).
#include <cmath>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tumble/output/output_row.hpp"

namespace tumble {

// Whose columns a trajectory has: the names that head them.
struct ColumnLayout {
  std::vector<std::string> bodies;
  std::vector<std::string> joints;
  // As many as joints: the names of each one's own coordinates' columns (its kind's
  // coordinate_columns(), "angle", "rate").
  std::vector<std::vector<std::string>> joint_coordinates;
  std::vector<std::string> contacts;
  // Per contact, whether it has columns of its own (`bodies: all`'s pairs have none: their work
  // is their group's element). Empty: every contact has.
  std::vector<char> contact_columns;
  std::vector<std::string> elements;  // Formulation::element_names()
  bool planar = false;                // each body's angle and rate about z close the row
};

// Calls column(owner, field, value_of) for each column in order: owner is "" for t and the
// system's quantities (the column's name is the field), else the body, joint, contact or element
// whose column it is (the name is owner.field); value_of(row) is the column's value in a row, a
// function of the row alone, so a sink that wants a few columns can keep just theirs.
template <typename Column>
void for_each_column(const ColumnLayout& layout, Column&& column) {
  using Row = const OutputRow&;
  column(std::string_view(), "t", [](Row row) { return row.t; });
  static constexpr std::string_view kAxes[3] = {"x", "y", "z"};
  static constexpr std::string_view kVelocity[3] = {"vx", "vy", "vz"};
  static constexpr std::string_view kOmega[3] = {"wx", "wy", "wz"};
  static constexpr std::string_view kR[3][3] = {
      {"R11", "R12", "R13"}, {"R21", "R22", "R23"}, {"R31", "R32", "R33"}};
  for (std::size_t b = 0; b < layout.bodies.size(); ++b) {
    const std::string_view body = layout.bodies[b];
    for (int k = 0; k < 3; ++k) {
      column(body, kAxes[k], [b, k](Row row) { return row.states[b].r_G(k); });
    }
    for (int k = 0; k < 3; ++k) {
      column(body, kVelocity[k], [b, k](Row row) { return row.states[b].v_G(k); });
    }
    for (int k = 0; k < 3; ++k) {
      column(body, kOmega[k], [b, k](Row row) { return row.states[b].omega_W(k); });
    }
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        column(body, kR[r][c], [b, r, c](Row row) { return row.states[b].R_WB(r, c); });
      }
    }
  }
  column(std::string_view(), "KE", [](Row row) { return row.quantities->kinetic_energy; });
  column(std::string_view(), "PE", [](Row row) { return row.quantities->potential_energy; });
  column(std::string_view(), "E", [](Row row) { return row.quantities->total_energy; });
  static constexpr std::string_view kMomentum[3] = {"px", "py", "pz"};
  static constexpr std::string_view kL[3] = {"Lx", "Ly", "Lz"};
  for (int k = 0; k < 3; ++k) {
    column(std::string_view(), kMomentum[k],
           [k](Row row) { return row.quantities->linear_momentum(k); });
  }
  for (int k = 0; k < 3; ++k) {
    column(std::string_view(), kL[k],
           [k](Row row) { return row.quantities->angular_momentum_about_origin(k); });
  }
  // A row without extras (RowObserver's) has zeros in their columns.
  static constexpr std::string_view kForce[3] = {"Fx", "Fy", "Fz"};
  static constexpr std::string_view kMoment[3] = {"Mx", "My", "Mz"};
  for (std::size_t j = 0; j < layout.joints.size(); ++j) {
    for (int k = 0; k < 3; ++k) {
      column(layout.joints[j], kForce[k],
             [j, k](Row row) { return row.extras ? row.extras->joints[j].F_W(k) : 0.0; });
    }
    for (int k = 0; k < 3; ++k) {
      column(layout.joints[j], kMoment[k],
             [j, k](Row row) { return row.extras ? row.extras->joints[j].M_J_W(k) : 0.0; });
    }
  }
  for (std::size_t c = 0; c < layout.contacts.size(); ++c) {
    if (!layout.contact_columns.empty() && layout.contact_columns[c] == 0) continue;
    const std::string_view contact = layout.contacts[c];
    column(contact, "N",
           [c](Row row) { return row.extras ? row.extras->contacts[c].normal_force : 0.0; });
    for (int k = 0; k < 3; ++k) {
      column(contact, kForce[k],
             [c, k](Row row) { return row.extras ? row.extras->contacts[c].friction_W(k) : 0.0; });
    }
    column(contact, "slip",
           [c](Row row) { return row.extras ? row.extras->contacts[c].slip_speed : 0.0; });
    column(contact, "mode", [c](Row row) {
      return row.extras ? static_cast<double>(row.extras->contacts[c].mode) : 0.0;
    });
  }
  for (std::size_t i = 0; i < layout.elements.size(); ++i) {
    column(layout.elements[i], "P",
           [i](Row row) { return row.extras ? row.extras->elements[i].power : 0.0; });
    column(layout.elements[i], "W",
           [i](Row row) { return row.extras ? row.extras->elements[i].work : 0.0; });
  }
  static constexpr std::string_view kOmegaBody[3] = {"w1", "w2", "w3"};
  for (std::size_t b = 0; b < layout.bodies.size(); ++b) {
    for (int k = 0; k < 3; ++k) {
      // omega_B = R_WB^T omega_W: its k-th component is body axis k (R_WB's column k) dotted
      // with omega_W.
      column(layout.bodies[b], kOmegaBody[k], [b, k](Row row) {
        const BodyState& s = row.states[b];
        return s.R_WB.col(k).dot(s.omega_W);
      });
    }
  }
  for (std::size_t j = 0; j < layout.joints.size(); ++j) {
    const std::vector<std::string>& names = layout.joint_coordinates[j];
    for (std::size_t i = 0; i < names.size(); ++i) {
      column(layout.joints[j], names[i], [j, i](Row row) {
        return row.extras != nullptr && j < row.extras->coordinates.size()
                   ? row.extras->coordinates[j].values[i]
                   : 0.0;
      });
    }
  }
  if (layout.planar) {
    for (std::size_t b = 0; b < layout.bodies.size(); ++b) {
      column(layout.bodies[b], "angle", [b](Row row) {
        return row.extras != nullptr && b < row.extras->planar_angles.size()
                   ? row.extras->planar_angles[b]
                   : std::atan2(row.states[b].R_WB(1, 0), row.states[b].R_WB(0, 0));
      });
      column(layout.bodies[b], "rate", [b](Row row) { return row.states[b].omega_W.z(); });
    }
  }
  // Last, so that every column before keeps its place: what a student otherwise computes.
  for (std::size_t b = 0; b < layout.bodies.size(); ++b) {
    column(layout.bodies[b], "speed", [b](Row row) { return row.states[b].v_G.norm(); });
  }
}

// Calls column(owner, field, value) with each column's value in `row`, in order.
template <typename Column>
void walk_columns(const ColumnLayout& layout, const OutputRow& row, Column&& column) {
  for_each_column(layout, [&](std::string_view owner, std::string_view field, auto&& value_of) {
    column(owner, field, static_cast<double>(value_of(row)));
  });
}

// The columns' names in order.
std::vector<std::string> column_names(const ColumnLayout& layout);

}  // namespace tumble
