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
#include "tumble/contact/plane_contact.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

// The sine below which two axes count as parallel: the closed form divides by its square, and
// below this the nearest points are lost in round-off (the gap is not).
inline constexpr double kParallelSine = 1e-5;

// A capsule's axis between its caps' centres, in world axes.
struct AxisSegment {
  Vec3 centre_W = Vec3::Zero();
  Vec3 axis_W = Vec3::UnitZ();  // unit
  double half_length = 0.0;     // m
};

// The nearest points of two segments: at s along the first's axis from its centre, and t along the
// second's; each `slides` where it is strictly inside its segment (and the axes are not parallel,
// for the first).
struct SegmentsClosest {
  double s = 0.0;  // m
  double t = 0.0;  // m
  bool s_slides = false;
  bool t_slides = false;
};

// A capsule's (a composite's capsule part's) axis for its body at r_G_W, turned by R_WB.
AxisSegment capsule_axis_W(const ContactSurface& capsule, const Vec3& r_G_W, const Mat3& R_WB);

SegmentsClosest segments_closest(const AxisSegment& a, const AxisSegment& b);
// The first's nearest point less the second's (world axes).
Vec3 segments_apart_W(const AxisSegment& a, const AxisSegment& b, const SegmentsClosest& closest);

// How fast the nearest points move along their axes (m/s), from the first's point less the
// second's (apart_W), the velocity of the first body's material point there less the second
// body's at its point (relative_velocity_W), and how fast each axis turns (omega x axis).
struct SlideRates {
  double s = 0.0;
  double t = 0.0;
};
SlideRates segments_slide_rates(const AxisSegment& a, const AxisSegment& b,
                                const SegmentsClosest& closest, const Vec3& apart_W,
                                const Vec3& relative_velocity_W, const Vec3& a_axis_rate_W,
                                const Vec3& b_axis_rate_W);

}  // namespace tumble
