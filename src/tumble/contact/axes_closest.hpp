#pragma once
// Two capsules touch where their axes' segments (each between its caps' centres) come within the
// sum of their radii: the gap is the segments' least distance less the radii, and the normal runs
// along the line between their nearest points. Those points are found in closed form; each slides
// along its axis while it is strictly inside its segment (at an end it stays there: a cap), and
// how fast follows from keeping the line between them square to each axis that it slides along.
//
// Two axes within kParallelSine of parallel whose spans overlap touch along a line: the nearest
// points are then taken at the middle of the overlap, the first fixed in its body and the second
// the nearest to it (a line contact held at its middle, as the resultant of a load symmetric along
// it would be).
//
// Written over the scalar: a run's pairs take it in double (sphere_pairs.cpp), `tumble modes` in
// Dual, which differentiates it (modes/modal_pair.hpp), so that both hold the same geometry.
#include <cmath>

#include "tumble/body/rigid_body.hpp"
#include "tumble/contact/plane_contact.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

// The sine below which two axes count as parallel: the closed form divides by its square, and
// below this the nearest points are lost in round-off (the gap is not).
inline constexpr double kParallelSine = 1e-5;

// A capsule's axis between its caps' centres, in world axes.
template <typename S>
struct AxisSegmentOf {
  Vec3Of<S> centre_W = Vec3Of<S>::Zero();
  Vec3Of<S> axis_W = Vec3Of<S>::UnitZ();  // unit
  double half_length = 0.0;               // m
};
using AxisSegment = AxisSegmentOf<double>;

// The nearest points of two segments: at s along the first's axis from its centre, and t along the
// second's; each `slides` where it is strictly inside its segment (and the axes are not parallel,
// for the first).
template <typename S>
struct SegmentsClosestOf {
  S s = S(0.0);  // m
  S t = S(0.0);  // m
  bool s_slides = false;
  bool t_slides = false;
};
using SegmentsClosest = SegmentsClosestOf<double>;

// How fast the nearest points move along their axes, m/s.
template <typename S>
struct SlideRatesOf {
  S s = S(0.0);
  S t = S(0.0);
};
using SlideRates = SlideRatesOf<double>;

// A capsule's (a composite's capsule part's) axis for its body at r_G_W, turned by R_WB.
template <typename S>
AxisSegmentOf<S> capsule_axis_W(const ContactSurface& capsule, const Vec3Of<S>& r_G_W,
                                const Mat3Of<S>& R_WB) {
  return {r_G_W + R_WB * capsule.centre_B.cast<S>(), R_WB * capsule.axes_B.col(2).cast<S>(),
          capsule.half_length};
}

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
template <typename S>
SegmentsClosestOf<S> segments_closest(const AxisSegmentOf<S>& a, const AxisSegmentOf<S>& b) {
  const Vec3Of<S> d0 = a.centre_W - b.centre_W;
  const S cos_ab = a.axis_W.dot(b.axis_W);
  const S c = a.axis_W.dot(d0), f = b.axis_W.dot(d0);
  const S sine2 = 1.0 - cos_ab * cos_ab;
  const double ha = a.half_length, hb = b.half_length;
  const auto clamp_a = [&](const S& s) { return s < -ha ? S(-ha) : s > ha ? S(ha) : s; };
  SegmentsClosestOf<S> closest;
  const bool parallel = sine2 <= kParallelSine * kParallelSine;
  if (parallel) {
    // The span of the second's ends seen on the first's axis, clamped to the first's: the middle
    // of their overlap (or, where they do not overlap, the first's end nearest it, to which both
    // ends clamp).
    const S s1 = -c - cos_ab * hb, s2 = -c + cos_ab * hb;
    closest.s = 0.5 * (clamp_a(s1) + clamp_a(s2));
  } else {
    closest.s = clamp_a((cos_ab * f - c) / sine2);
  }
  closest.t = f + closest.s * cos_ab;
  if (closest.t > hb || closest.t < -hb) {
    closest.t = closest.t > 0.0 ? S(hb) : S(-hb);
    if (!parallel) closest.s = clamp_a(closest.t * cos_ab - c);
  }
  closest.s_slides = !parallel && closest.s > -ha && closest.s < ha;
  closest.t_slides = closest.t > -hb && closest.t < hb;
  return closest;
}

// The first's nearest point less the second's (world axes).
template <typename S>
Vec3Of<S> segments_apart_W(const AxisSegmentOf<S>& a, const AxisSegmentOf<S>& b,
                           const SegmentsClosestOf<S>& closest) {
  return a.centre_W + closest.s * a.axis_W - (b.centre_W + closest.t * b.axis_W);
}

// How fast the nearest points slide, from the first's point less the second's (apart_W), the
// velocity of the first body's material point there less the second body's at its point
// (relative_velocity_W), and how fast each axis turns (omega x axis).
template <typename S>
SlideRatesOf<S> segments_slide_rates(const AxisSegmentOf<S>& a, const AxisSegmentOf<S>& b,
                                     const SegmentsClosestOf<S>& closest, const Vec3Of<S>& apart_W,
                                     const Vec3Of<S>& relative_velocity_W,
                                     const Vec3Of<S>& a_axis_rate_W,
                                     const Vec3Of<S>& b_axis_rate_W) {
  const S r1 = -(a_axis_rate_W.dot(apart_W) + a.axis_W.dot(relative_velocity_W));
  const S r2 = -(b_axis_rate_W.dot(apart_W) + b.axis_W.dot(relative_velocity_W));
  SlideRatesOf<S> rates;
  if (closest.s_slides && closest.t_slides) {
    const S cos_ab = a.axis_W.dot(b.axis_W);
    rates.t = (r2 - cos_ab * r1) / (cos_ab * cos_ab - 1.0);
    rates.s = r1 + cos_ab * rates.t;
  } else if (closest.s_slides) {
    rates.s = r1;
  } else if (closest.t_slides) {
    rates.t = -r2;
  }
  return rates;
}

// Two capsules' line, as a run's pair and `tumble modes` take it: the axes' nearest points (world)
// and how fast they slide, the normal from the second's point towards the first's and how fast it
// turns, their distance, and the velocity of the first body's material point at its point less
// the second body's at its. The gap's rate is n . w (a point slides square to n); n turns with
// the rate of the points' difference, w plus the slides, across n.
template <typename S>
struct CapsulesLineOf {
  SegmentsClosestOf<S> closest;
  SlideRatesOf<S> rates;
  Vec3Of<S> p_a_W = Vec3Of<S>::Zero(), p_b_W = Vec3Of<S>::Zero();
  Vec3Of<S> n_W = Vec3Of<S>::UnitZ(), n_rate_W = Vec3Of<S>::Zero();
  S distance = S(0.0);  // m
  Vec3Of<S> relative_velocity_W = Vec3Of<S>::Zero();
};

template <typename S>
CapsulesLineOf<S> capsules_line(const ContactSurface& capsule_a, const BodyStateOf<S>& a,
                                const ContactSurface& capsule_b, const BodyStateOf<S>& b) {
  using V3 = Vec3Of<S>;
  const AxisSegmentOf<S> axis_a = capsule_axis_W<S>(capsule_a, a.r_G, a.R_WB);
  const AxisSegmentOf<S> axis_b = capsule_axis_W<S>(capsule_b, b.r_G, b.R_WB);
  CapsulesLineOf<S> line;
  line.closest = segments_closest<S>(axis_a, axis_b);
  line.p_a_W = axis_a.centre_W + line.closest.s * axis_a.axis_W;
  line.p_b_W = axis_b.centre_W + line.closest.t * axis_b.axis_W;
  const V3 apart_W = line.p_a_W - line.p_b_W;
  line.relative_velocity_W = a.v_G + a.omega_W.cross(V3(line.p_a_W - a.r_G)) -
                             (b.v_G + b.omega_W.cross(V3(line.p_b_W - b.r_G)));
  line.rates =
      segments_slide_rates<S>(axis_a, axis_b, line.closest, apart_W, line.relative_velocity_W,
                              a.omega_W.cross(axis_a.axis_W), b.omega_W.cross(axis_b.axis_W));
  using std::sqrt;
  line.distance = sqrt(apart_W.squaredNorm());
  if (line.distance > 0.0) {
    line.n_W = apart_W / line.distance;
    const V3 apart_rate_W =
        line.relative_velocity_W + line.rates.s * axis_a.axis_W - line.rates.t * axis_b.axis_W;
    line.n_rate_W = (apart_rate_W - line.n_W * line.n_W.dot(apart_rate_W)) / line.distance;
    return line;
  }
  // Axes that cross: square to both (any square to the first, where they are parallel too).
  V3 across = axis_a.axis_W.cross(axis_b.axis_W);
  if (!(across.squaredNorm() > 0.0)) {
    using std::abs;
    const V3 other = abs(axis_a.axis_W.x()) < 0.9 ? V3(V3::UnitX()) : V3(V3::UnitY());
    across = other.cross(axis_a.axis_W);
  }
  line.n_W = across / sqrt(across.squaredNorm());
  return line;
}

}  // namespace tumble
