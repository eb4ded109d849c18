#include "tumble/contact/landing_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tumble/contact/contact_pair.hpp"

namespace tumble {

double first_root(double c, double b, double A) {
  // In the form that keeps its digits when b^2 >> A c. A point already deeper has crossed the
  // plane where the event functions see it: it sets no bound.
  if (!(c > 0.0)) return kNever;
  const double denominator = -b + std::sqrt(b * b + 2.0 * A * c);
  return denominator > 0.0 ? 2.0 * c / denominator : kNever;
}

namespace {

// The circle's lowest point carried along by the velocity field, less A t^2 / 2, plus the depth:
// concave in t.
struct CircleHeight {
  double centre_height, centre_rate;  // its centre's height (plus the depth) and normal speed
  double a0, a1, b0, b1;              // n.e1(t) = a0 + a1 t, n.e2(t) = b0 + b1 t
  double radius, turning;
  double operator()(double t) const {
    return centre_height + centre_rate * t - radius * std::hypot(a0 + a1 * t, b0 + b1 * t) -
           0.5 * turning * t * t;
  }
};

double circle_time(const CircleHeight& f) {
  if (!(f(0.0) > 0.0)) return kNever;  // as first_root
  // A lower bound on the root, from |(a, b)(t)| <= |(a0, b0)| + t |(a1, b1)|: below it f > 0.
  double lo = first_root(f(0.0), f.centre_rate - f.radius * std::hypot(f.a1, f.b1), f.turning);
  if (!std::isfinite(lo)) return kNever;
  double hi = 2.0 * lo;
  for (int doubling = 0; f(hi) > 0.0; ++doubling) {
    if (doubling == 64) return lo;  // f keeps above zero this long (no turning, not approaching)
    lo = hi;
    hi *= 2.0;
  }
  // A step bound needs no more than a few digits; lo keeps f > 0.
  while (hi - lo > 1e-3 * hi) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

double point_time_to_depth(const PlaneContact& contact, const SurfaceMotion& motion,
                           const Vec3& p_B, double turning, double depth) {
  const Vec3& n = contact.normal_W;
  const Vec3 r_W = motion.R_WB * p_B;
  const Vec3 v_W = motion.v_G_W + motion.omega_W.cross(r_W);
  return first_root(n.dot(motion.r_G_W + r_W - contact.point_W) + depth, n.dot(v_W), turning);
}

double centre_time_to_depth(const PlaneContact& contact, const SurfaceMotion& motion, double radius,
                            double turning, double depth) {
  const Vec3& n = contact.normal_W;
  return first_root(n.dot(motion.r_G_W - contact.point_W) + depth - radius, n.dot(motion.v_G_W),
                    turning);
}

double circle_time_to_depth(const PlaneContact& contact, const SurfaceMotion& motion,
                            const Vec3& centre_B, const Mat3& axes_B, double radius, double turning,
                            double depth) {
  const Vec3& n = contact.normal_W;
  const bool turned = !axes_B.isIdentity(0.0);
  const Vec3 e1 = turned ? Vec3(motion.R_WB * axes_B.col(0)) : Vec3(motion.R_WB.col(0));
  const Vec3 e2 = turned ? Vec3(motion.R_WB * axes_B.col(1)) : Vec3(motion.R_WB.col(1));
  const Vec3 c_W = motion.R_WB * centre_B;
  const CircleHeight f{n.dot(motion.r_G_W + c_W - contact.point_W) + depth,
                       n.dot(motion.v_G_W + motion.omega_W.cross(c_W)),
                       n.dot(e1),
                       n.dot(motion.omega_W.cross(e1)),
                       n.dot(e2),
                       n.dot(motion.omega_W.cross(e2)),
                       radius,
                       turning};
  return circle_time(f);
}

double time_to_reach_depth(const PlaneContact& contact, const SurfaceMotion& motion, double turning,
                           double depth) {
  return contact_pair(contact.surface.kind).time_to_reach_depth(contact, motion, turning, depth);
}

}  // namespace tumble
