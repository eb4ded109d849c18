#pragma once
// The coordinates a linearisation is written in (`tumble modes`): small departures z from the
// initial state y0, one per freedom the joints leave, named as the scenario names them.
//   hinge J:      J.angle (rad) and J.rate (rad/s), signed as the scenario states the joint;
//   slider J:     J.travel (m) and J.speed (m/s);
//   ball J:       J.rx J.ry J.rz, a small turn of the body it holds about that body's axes
//                 (R = R0 exp([r]x)), and J.wx J.wy J.wz, its angular velocity relative to the
//                 other body, in its axes;
//   free body B:  B.x B.y B.z, its COM's displacement (world), B.rx B.ry B.rz, a small turn about
//                 its axes, B.vx B.vy B.vz, its COM's velocity (world), and B.wx B.wy B.wz, its
//                 angular velocity in its axes.
// A turn is a vector, not a quaternion: three numbers for three freedoms, so a linearisation
// has no direction that leaves the unit sphere. Joints that are fixed, locked or driven at a
// speed at t0 have no coordinates: they hold or drive what they join (hybrid dynamics). The
// positions come first, then the speeds, each in the tree's order.
#include <string>
#include <vector>

#include "tumble/multibody/articulated_model.hpp"

namespace tumble {

struct ModalCoordinate {
  std::string name;  // "base.angle", "pivot.wx", "prism.vz"
  std::string unit;  // "rad", "m", "rad/s", "m/s"
  bool is_speed = false;
  std::size_t tree_joint = 0;
};

struct ModalLayout {
  std::vector<ModalCoordinate> coordinates;  // positions, then speeds
  Eigen::Index position_count = 0;
  // Per tree joint: where its positions and its speeds start in z (-1: it has none), and +1 or
  // -1: the scenario's sign of a hinge's angle or a slider's travel (the tree may list the joint's
  // bodies the other way round).
  std::vector<Eigen::Index> position_offset, speed_offset;
  std::vector<double> sign;

  Eigen::Index size() const { return static_cast<Eigen::Index>(coordinates.size()); }
};

// The layout at the model's schedule time t0 (which joints are held or driven then).
ModalLayout make_modal_layout(const ArticulatedModel& model, double t0);

// y0 moved by the positions of z, turns as exact rotations (its speeds are left as they are): the
// configuration a mode shape shows, for the animation page.
VecX displace_positions(const ArticulatedModel& model, const ModalLayout& layout, const VecX& y0,
                        const VecX& z);

}  // namespace tumble
