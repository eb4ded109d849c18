#pragma once
// Spatial (6D) vector algebra in Featherstone's convention ("Rigid Body Dynamics Algorithms",
// 2008, ch. 2), in the coordinates of one body with the origin at its COM:
//   motion vectors m = (omega; v_O), the angular velocity and the velocity of the body point at
//   the origin; force vectors f = (n_O; f), the moment about the origin and the force.
// A Transform X maps motion vectors from a parent's coordinates to a child's:
//   X = [E 0; -E [r]x E],  E = R_PC^T (child axes from parent axes), r = origin of the child from
//   the parent's origin, parent axes,
// and its transpose maps force vectors back from the child to the parent.
#include "tumble/math/rotation.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

using Mat6 = Eigen::Matrix<double, 6, 6>;

// v x m for motion vectors: (w x a; w x b + v x a) for v = (w; v), m = (a; b).
inline Vec6 cross_motion(const Vec6& v, const Vec6& m) {
  Vec6 out;
  out.head<3>() = v.head<3>().cross(m.head<3>());
  out.tail<3>() = v.head<3>().cross(m.tail<3>()) + v.tail<3>().cross(m.head<3>());
  return out;
}

// v x* f for force vectors: (w x n + v x f; w x f) for v = (w; v), f = (n; f).
inline Vec6 cross_force(const Vec6& v, const Vec6& f) {
  Vec6 out;
  out.head<3>() = v.head<3>().cross(f.head<3>()) + v.tail<3>().cross(f.tail<3>());
  out.tail<3>() = v.head<3>().cross(f.tail<3>());
  return out;
}

// The spatial inertia of a body about its COM, in its axes: diag(I_G, M 1).
inline Mat6 spatial_inertia_about_com(double mass, const Mat3& I_G) {
  Mat6 I = Mat6::Zero();
  I.topLeftCorner<3, 3>() = I_G;
  I.bottomRightCorner<3, 3>() = mass * Mat3::Identity();
  return I;
}

// (I_G omega; M v) without forming the 6x6 matrix.
inline Vec6 apply_inertia_about_com(double mass, const Mat3& I_G, const Vec6& v) {
  Vec6 h;
  h.head<3>() = I_G * v.head<3>();
  h.tail<3>() = mass * v.tail<3>();
  return h;
}

struct Transform {
  Mat3 E = Mat3::Identity();  // child axes from parent axes
  Vec3 r = Vec3::Zero();      // child origin from parent origin, parent axes

  // X m: (E w; E (v - r x w)).
  Vec6 apply_motion(const Vec6& m) const {
    Vec6 out;
    out.head<3>() = E * m.head<3>();
    out.tail<3>() = E * (m.tail<3>() - r.cross(m.head<3>()));
    return out;
  }
  // X^T f: a force vector of the child, in the parent's coordinates: (E^T n + r x E^T f; E^T f).
  Vec6 transpose_apply_force(const Vec6& f) const {
    Vec6 out;
    out.tail<3>() = E.transpose() * f.tail<3>();
    out.head<3>() = E.transpose() * f.head<3>() + r.cross(out.tail<3>());
    return out;
  }
  Mat6 matrix() const {
    Mat6 X = Mat6::Zero();
    X.topLeftCorner<3, 3>() = E;
    X.bottomRightCorner<3, 3>() = E;
    X.bottomLeftCorner<3, 3>() = -E * hat(r);
    return X;
  }
};

}  // namespace tumble
