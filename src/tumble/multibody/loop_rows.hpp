#pragma once
// A loop's closing joint as constraint rows on the kinematic tree (docs/design.md, "Closed
// loops"), written once over the scalar: double for a run (loop_joints.hpp, which holds them),
// AutoDiff for `tumble modes` (modes/modal_equations.hpp, which linearises on them). Both hold
// the same rows, so the modes are those of the motion a run integrates.
//
// A row is direction . (velocity of B's joint point less A's velocity there) or
// direction . (omega_B - omega_A), and its error the same direction's component of the gap or of
// the turn it forbids. Each joint's rows: its joint point on the second body held on the first
// body's point (every direction but a slider's axis; a ball, hinge, weld and Hooke joint: all
// three), and the turns its kind forbids (a hinge: about the two directions across its axis; a
// weld and a slider: all three; a Hooke joint: about the direction across both its axes). The
// directions are fixed in the first body (the world's for ground), so a row's rate of change has
// the first body's turn. A distance joint's one row is along its rod, and turns with the rod.
#include "tumble/body/rigid_body.hpp"
#include "tumble/dynamics/joint_model.hpp"
#include "tumble/math/rotation.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

// What of a closing joint its rows read: its geometry fixed to its bodies at t = 0.
struct LoopShape {
  int body_a = kGround, body_b = 0;
  Vec3 p_AJ_A = Vec3::Zero(), p_BJ_B = Vec3::Zero();
  Mat3 R_AB0 = Mat3::Identity();
  Vec3 axis_A = Vec3::UnitZ();  // hinge, slider, cylindrical: the axis; universal: the first
  Vec3 axis_B = Vec3::UnitZ();  // hinge, slider, cylindrical: the axis; universal: the second
  // Directions across the axis, A's axes (a slider's and a cylindrical joint's point rows, a
  // hinge's and a cylindrical joint's turn rows).
  Vec3 across1_A = Vec3::UnitX(), across2_A = Vec3::UnitY();
  bool all_point_rows = true;  // else the two across the axis
  int turn_rows = 0;           // 0, 1 (universal), 2 (across the axis) or 3 (A's axes)
  // A distance joint's rod, m (> 0): its one row holds the distance from p_AJ_A to p_BJ_B.
  double rod_length = 0.0;

  int rows() const { return rod_length > 0.0 ? 1 : (all_point_rows ? 3 : 2) + turn_rows; }
};

// Throws std::logic_error for a free joint (which closes no loop).
LoopShape loop_shape_of(const JointModel& joint);

template <typename S>
struct LoopRowOf {
  bool turn = false;
  Vec3Of<S> direction_W = Vec3Of<S>::Zero();
  Vec3Of<S> direction_rate_W = Vec3Of<S>::Zero();
  S error = S(0.0);  // m or rad
};

// A side of a loop is its body's state, world axes (ground: at rest at the origin, BodyStateOf's
// default).

// The joint point on B, world.
template <typename S>
Vec3Of<S> loop_point_W(const LoopShape& shape, const BodyStateOf<S>& b) {
  return b.r_G + b.R_WB * shape.p_BJ_B.cast<S>();
}

// The velocity of B's material point at p_W less A's there, world.
template <typename S>
Vec3Of<S> loop_relative_velocity_W(const BodyStateOf<S>& a, const BodyStateOf<S>& b,
                                   const Vec3Of<S>& p_W) {
  return b.v_G + b.omega_W.cross(p_W - b.r_G) - (a.v_G + a.omega_W.cross(p_W - a.r_G));
}

// Calls add(row) for each of the joint's rows, in order (point rows, then turn rows).
template <typename S, typename Add>
void for_each_loop_row(const LoopShape& shape, const BodyStateOf<S>& a, const BodyStateOf<S>& b,
                       Add&& add) {
  using V3 = Vec3Of<S>;
  const V3 p_A_W = a.r_G + a.R_WB * shape.p_AJ_A.cast<S>();
  const V3 gap_W = loop_point_W(shape, b) - p_A_W;
  if (shape.rod_length > 0.0) {
    // A rod holds |gap| at its length: its row is along u = gap / |gap|, which turns as its ends
    // move apart across it, u' = (I - u u^T) gap' / |gap|. Read at B's end, A's velocity field
    // gives the row's velocity as at A's own (u . (omega_A x gap) = 0), and a force along the rod
    // has the same moment on A at either end: B's end serves both bodies, as a joint point does.
    const S length = gap_W.norm();
    const V3 gap_rate_W = b.v_G + b.omega_W.cross(V3(gap_W + p_A_W - b.r_G)) -
                          (a.v_G + a.omega_W.cross(V3(p_A_W - a.r_G)));
    LoopRowOf<S> row;
    row.direction_W = gap_W / length;
    row.direction_rate_W =
        (gap_rate_W - row.direction_W * row.direction_W.dot(gap_rate_W)) / length;
    row.error = length - S(shape.rod_length);
    add(row);
    return;
  }
  // Directions fixed in A turn with it.
  const auto fixed_in_a = [&](bool turn, const Vec3& direction_A, const V3& along_W) {
    LoopRowOf<S> row;
    row.turn = turn;
    row.direction_W = a.R_WB * direction_A.cast<S>();
    row.direction_rate_W = a.omega_W.cross(row.direction_W);
    row.error = row.direction_W.dot(along_W);
    add(row);
  };
  if (shape.all_point_rows) {
    for (int k = 0; k < 3; ++k) fixed_in_a(false, Vec3::Unit(k), gap_W);
  } else {
    fixed_in_a(false, shape.across1_A, gap_W);
    fixed_in_a(false, shape.across2_A, gap_W);
  }
  if (shape.turn_rows == 3) {
    // B's turn from where the joint holds it, as a rotation vector.
    const V3 turn_W = log_so3<S>(Mat3Of<S>(b.R_WB * (a.R_WB * shape.R_AB0.cast<S>()).transpose()));
    for (int k = 0; k < 3; ++k) fixed_in_a(true, Vec3::Unit(k), turn_W);
  } else if (shape.turn_rows == 2) {
    // B's axis tilted from A's: a_A x a_B is the small turn that takes one to the other.
    const V3 tilt_W = (a.R_WB * shape.axis_A.cast<S>()).cross(V3(b.R_WB * shape.axis_B.cast<S>()));
    fixed_in_a(true, shape.across1_A, tilt_W);
    fixed_in_a(true, shape.across2_A, tilt_W);
  } else if (shape.turn_rows == 1) {
    // A Hooke joint keeps its axes at right angles: a1 . a2 = 0, whose rate is
    // -(a1 x a2) . (omega_B - omega_A).
    const V3 a1 = a.R_WB * shape.axis_A.cast<S>();
    const V3 a2 = b.R_WB * shape.axis_B.cast<S>();
    LoopRowOf<S> row;
    row.turn = true;
    row.direction_W = a1.cross(a2);
    row.direction_rate_W = a.omega_W.cross(a1).cross(a2) + a1.cross(V3(b.omega_W.cross(a2)));
    row.error = -a1.dot(a2);
    add(row);
  }
}

// The row's velocity.
template <typename S>
S loop_row_velocity(const LoopShape& shape, const LoopRowOf<S>& row, const BodyStateOf<S>& a,
                    const BodyStateOf<S>& b) {
  if (row.turn) return row.direction_W.dot(b.omega_W - a.omega_W);
  return row.direction_W.dot(loop_relative_velocity_W(a, b, loop_point_W(shape, b)));
}

// The row's acceleration from `response`, direction . (B's acceleration less A's, at the joint
// point or of the turn): with the rates of its direction and of the point it reads A's field at.
template <typename S>
S loop_row_acceleration(const LoopShape& shape, const LoopRowOf<S>& row, const BodyStateOf<S>& a,
                        const BodyStateOf<S>& b, const S& response) {
  if (row.turn) return response + row.direction_rate_W.dot(b.omega_W - a.omega_W);
  // d/dt of u . (v_B(p) - v_A(p)) with p moving with B: A's velocity field read at a moving
  // point gains omega_A x (v_B(p) - v_A(p)).
  const Vec3Of<S> relative = loop_relative_velocity_W(a, b, loop_point_W(shape, b));
  return response + row.direction_rate_W.dot(relative) -
         row.direction_W.dot(a.omega_W.cross(relative));
}

}  // namespace tumble
