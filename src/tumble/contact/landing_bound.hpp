#pragma once
// How long a body that touches nothing may fly before some point of its contact surface could
// be below a plane by more than a given depth. An event function sees a landing only if the
// height of the lowest point has changed sign between the ends of a step; a tumbling body's end
// can dip through the plane and come back within one long step of a free flight (steady rotation
// is smooth, and an error-controlled method takes steps of a radian or more), so the driver keeps
// each step within this time.
//
// The bound: every point p of the surface moves over a time t as
//     h_p(t) >= h_p(0) + h_p'(0) t - A t^2 / 2,
// with A a bound on how fast any point's normal velocity can turn towards the plane (the COM's
// acceleration into it, and |alpha| r + |omega|^2 r for a point r from the COM). The minimum over
// the surface of the first two terms is the support height of the surface carried along by its
// velocity field: over a polyhedron's vertices (and a cone's apex) each term is linear in t; over
// a rim circle it is the circle's centre term less r |(n.e1(t), n.e2(t))|, with e_i(t) = e_i +
// t omega x e_i (a concave function). The first root of that minimum less A t^2 / 2 plus the depth
// is the time returned.
#include <limits>

#include "tumble/contact/plane_contact.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

// The body's motion now: COM position and velocity, rotation, angular velocity (world).
struct SurfaceMotion {
  Vec3 r_G_W = Vec3::Zero();
  Mat3 R_WB = Mat3::Identity();
  Vec3 v_G_W = Vec3::Zero();
  Vec3 omega_W = Vec3::Zero();
};

// The first time (s, > 0) at which a point of the contact's surface could be `depth` (m, > 0)
// below the plane, for points whose normal velocities turn towards the plane at most at
// `turning` (m/s^2, >= 0); +infinity if none could. Points that deep already are left out.
// Each surface's bound is its contact pair's (contact_pair.hpp), from the pieces below.
double time_to_reach_depth(const PlaneContact& contact, const SurfaceMotion& motion, double turning,
                           double depth);

inline constexpr double kNever = std::numeric_limits<double>::infinity();
// The first t > 0 with c + b t - A t^2 / 2 = 0, for c > 0 (a height above the depth), b its
// rate, A >= 0 (how fast the rate can turn down); kNever where there is none, or where c <= 0.
double first_root(double c, double b, double A);
// The bound for one point of the body (p_B, body axes from the COM); for the COM less `radius`
// along the normal (a sphere's lowest point, which turning does not move); for a circle of the
// body about the third of axes_B (centre_B, radius: a rim; axes_B the body's own but for a
// composite's part).
double point_time_to_depth(const PlaneContact& contact, const SurfaceMotion& motion,
                           const Vec3& p_B, double turning, double depth);
double centre_time_to_depth(const PlaneContact& contact, const SurfaceMotion& motion, double radius,
                            double turning, double depth);
double circle_time_to_depth(const PlaneContact& contact, const SurfaceMotion& motion,
                            const Vec3& centre_B, const Mat3& axes_B, double radius, double turning,
                            double depth);

}  // namespace tumble
