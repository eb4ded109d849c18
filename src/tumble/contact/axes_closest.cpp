// Two segments' nearest points and how fast they slide (axes_closest.hpp).
//
// With d0 the first's centre less the second's, b = u_a . u_b, c = u_a . d0 and f = u_b . d0, the
// points a(s) = c_a + s u_a and b(t) = c_b + t u_b are nearest where d = a(s) - b(t) is square to
// both axes: s = (b f - c) / (1 - b^2), t = f + s b. Clamped to the segments, a point held at an
// end makes the other the nearest to that end (the clamping of Ericson, Real-Time Collision
// Detection, 5.1.9).
//
// As the bodies move, u_a . d = 0 (while s slides) and u_b . d = 0 (while t slides) hold, with
// d' = w + s' u_a - t' u_b (w the material points' relative velocity):
//   s' - b t' = -(u_a' . d + u_a . w) = r1,   b s' - t' = -(u_b' . d + u_b . w) = r2,
// and a point held at an end has no rate.
#include "tumble/contact/axes_closest.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

AxisSegment capsule_axis_W(const ContactSurface& capsule, const Vec3& r_G_W, const Mat3& R_WB) {
  return {r_G_W + R_WB * capsule.centre_B, R_WB * capsule.axes_B.col(2), capsule.half_length};
}

Vec3 segments_apart_W(const AxisSegment& a, const AxisSegment& b, const SegmentsClosest& closest) {
  return a.centre_W + closest.s * a.axis_W - (b.centre_W + closest.t * b.axis_W);
}

SegmentsClosest segments_closest(const AxisSegment& a, const AxisSegment& b) {
  const Vec3 d0 = a.centre_W - b.centre_W;
  const double cos_ab = a.axis_W.dot(b.axis_W);
  const double c = a.axis_W.dot(d0), f = b.axis_W.dot(d0);
  const double sine2 = 1.0 - cos_ab * cos_ab;
  const double ha = a.half_length, hb = b.half_length;
  SegmentsClosest closest;
  const bool parallel = sine2 <= kParallelSine * kParallelSine;
  if (parallel) {
    // The span of the second's ends seen on the first's axis, and the middle of its overlap with
    // the first's (or the first's end nearest it, where they do not overlap).
    const double s1 = -c - cos_ab * hb, s2 = -c + cos_ab * hb;
    const double lo = std::max(std::min(s1, s2), -ha), hi = std::min(std::max(s1, s2), ha);
    closest.s = lo <= hi ? 0.5 * (lo + hi) : (hi < -ha ? -ha : ha);
  } else {
    closest.s = std::clamp((cos_ab * f - c) / sine2, -ha, ha);
  }
  closest.t = f + closest.s * cos_ab;
  if (std::abs(closest.t) > hb) {
    closest.t = std::copysign(hb, closest.t);
    if (!parallel) closest.s = std::clamp(closest.t * cos_ab - c, -ha, ha);
  }
  closest.s_slides = !parallel && std::abs(closest.s) < ha;
  closest.t_slides = std::abs(closest.t) < hb;
  return closest;
}

SlideRates segments_slide_rates(const AxisSegment& a, const AxisSegment& b,
                                const SegmentsClosest& closest, const Vec3& apart_W,
                                const Vec3& relative_velocity_W, const Vec3& a_axis_rate_W,
                                const Vec3& b_axis_rate_W) {
  const double r1 = -(a_axis_rate_W.dot(apart_W) + a.axis_W.dot(relative_velocity_W));
  const double r2 = -(b_axis_rate_W.dot(apart_W) + b.axis_W.dot(relative_velocity_W));
  SlideRates rates;
  if (closest.s_slides && closest.t_slides) {
    const double cos_ab = a.axis_W.dot(b.axis_W);
    rates.t = (r2 - cos_ab * r1) / (cos_ab * cos_ab - 1.0);
    rates.s = r1 + cos_ab * rates.t;
  } else if (closest.s_slides) {
    rates.s = r1;
  } else if (closest.t_slides) {
    rates.t = -r2;
  }
  return rates;
}

}  // namespace tumble
