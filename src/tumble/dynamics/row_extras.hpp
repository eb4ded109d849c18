#pragma once
// What a row of output reports besides the bodies' states, for formulations with joints, force
// elements and contacts (empty otherwise).
#include <array>
#include <vector>

#include "tumble/math/types.hpp"

namespace tumble {

struct JointReaction {
  Vec3 F_W = Vec3::Zero();    // force the joint's first body exerts on its second, world, N
  Vec3 M_J_W = Vec3::Zero();  // moment of it about the joint point, world, N m
};
struct ElementWork {
  double power = 0.0;  // W, rate of work on the bodies now
  double work = 0.0;   // J, done since t0 (impulses and locks: at their instants)
};
// A contact's force and how it touches (docs/scenario.md, the CSV's C.* columns).
struct ContactOutput {
  double normal_force = 0.0;       // N, >= 0 (0 when apart)
  Vec3 friction_W = Vec3::Zero();  // N, the tangential force on the body, world
  double slip_speed = 0.0;         // m/s, of the body's material point at the contact
  int mode = 0;                    // 0 apart, 1 sliding, 2 rolling / sticking
};
// A joint's own coordinates, as its kind names them in the CSV (JointKind::coordinate_columns:
// a hinge's J.angle J.rate, a slider's J.travel J.speed, a ball joint's J.rx J.ry J.rz, ...), in
// that order.
struct JointCoordinates {
  std::array<double, 6> values{};
};
// How far the joints that close loops are from closing (0 where none does).
struct LoopErrors {
  double gap = 0.0;    // m: the largest distance of a joint's two points along a held direction
  double turn = 0.0;   // rad: the largest turn a joint forbids
  double speed = 0.0;  // the largest row velocity (m/s along a point row, rad/s about a turn row)
};
struct RowExtras {
  std::vector<JointReaction> joints;          // one per Model::joints entry
  std::vector<JointCoordinates> coordinates;  // one per Model::joints entry
  std::vector<ContactOutput> contacts;        // one per Model::contacts entry
  std::vector<ElementWork> elements;          // one per element_names() entry
  double elastic_energy = 0.0;                // J, stored in springs: part of PE
  LoopErrors loops;                           // of the joints that close loops
  // A planar scenario's bodies' angles about z (rad, counted on from the row before, so they run
  // on past a turn) and rates (rad/s), at the row's time `planar_t`; empty otherwise.
  std::vector<double> planar_angles, planar_rates;
  double planar_t = 0.0;

  // What a RowExtras{} holds, keeping the vectors' storage (a sweep makes a row at every step).
  void reset() {
    joints.clear();
    coordinates.clear();
    contacts.clear();
    elements.clear();
    elastic_energy = 0.0;
    loops = LoopErrors{};
    planar_angles.clear();
    planar_rates.clear();
    planar_t = 0.0;
  }
};

}  // namespace tumble
