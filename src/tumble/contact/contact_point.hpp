#pragma once
// Where a body touching a plane at one point touches it, as its pose changes, and how fast that
// point moves over the body: the offset p_GP_W from the body's COM G to the contact point P and
// its rate (world axes), written over the scalar (double, or `tumble modes`' Dual, which
// differentiates it). A point of each kind:
//  - Lowest: a sphere's or shell's lowest point, p = R c - r n with c its centre (0: the COM);
//  - Rim: the lowest point of a disk's, ring's, cylinder's or cone's rim, p = R c + rho u, with c
//    the rim's centre and u the unit vector in the rim's plane (across its axis) most opposed to
//    n;
//  - Material: a point of the body (a polyhedron's vertex, a cone's apex), p = R p_B.
// A rim's lowest point moves along the rim's tangent, which is parallel to the plane: the offset's
// rate has the normal component of the body's point there, so the height's rate is the normal
// velocity of that point, and a rolling constraint's rate is its acceleration's.
#include <cmath>

#include "tumble/math/types.hpp"

namespace tumble {

struct ContactPoint {
  enum class Kind { Lowest, Rim, Material } kind = Kind::Lowest;
  // Lowest: the sphere's centre; Rim: the rim's centre; Material: the point (body axes, from the
  // COM)
  Vec3 p_B = Vec3::Zero();
  double radius = 0.0;  // Lowest: the sphere's; Rim: the rim's (m)
  // Rim: the rim's axis (body axes): the body's z but for a composite's turned part.
  Vec3 axis_B = Vec3::UnitZ();
  // Rim: a torus's tube (m): the point is this much further along -n (fixed in the world, so
  // its rate is the rim point's).
  double tube = 0.0;
};

// The body turned by R_WB and turning at omega_W over a plane of unit normal n_W.
template <typename S>
void calc_contact_offset(const ContactPoint& point, const Vec3& n_W, const Mat3Of<S>& R_WB,
                         const Vec3Of<S>& omega_W, Vec3Of<S>& p_GP_W, Vec3Of<S>& p_GP_rate_W) {
  using V3 = Vec3Of<S>;
  using std::sqrt;
  switch (point.kind) {
    case ContactPoint::Kind::Lowest:
      p_GP_W = -point.radius * n_W.cast<S>();
      p_GP_rate_W = V3::Zero();
      if (!point.p_B.isZero(0.0)) {  // a sphere's centre away from the COM moves with the body
        const V3 centre_W = R_WB * point.p_B.cast<S>();
        p_GP_W += centre_W;
        p_GP_rate_W = omega_W.cross(centre_W);
      }
      return;
    case ContactPoint::Kind::Material:
      p_GP_W = R_WB * point.p_B.cast<S>();
      p_GP_rate_W = omega_W.cross(p_GP_W);
      return;
    case ContactPoint::Kind::Rim: {
      const V3 n = n_W.cast<S>();
      const V3 axis =
          point.axis_B == Vec3::UnitZ() ? V3(R_WB.col(2)) : V3(R_WB * point.axis_B.cast<S>());
      const V3 axis_rate = omega_W.cross(axis);
      const V3 w = n - n.dot(axis) * axis;  // n's part in the rim's plane
      const V3 w_rate = -n.dot(axis_rate) * axis - n.dot(axis) * axis_rate;
      const S length = sqrt(w.squaredNorm());
      const V3 w_unit = w / length;
      const V3 centre_W = R_WB * point.p_B.cast<S>();
      p_GP_W = centre_W - point.radius * w_unit;
      if (point.tube > 0.0) p_GP_W -= point.tube * n;
      p_GP_rate_W =
          omega_W.cross(centre_W) - point.radius * (w_rate - w_unit.dot(w_rate) * w_unit) / length;
      return;
    }
  }
}

}  // namespace tumble
