#include "tumble/contact/pair_core.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

double core_radius(const ContactSurface& surface) {
  if (surface.touched_inside) return -surface.radius;
  return surface.kind == ContactSurface::Kind::Sphere ||
                 surface.kind == ContactSurface::Kind::Capsule
             ? surface.radius
             : 0.0;
}

double pair_size(const PlaneContact& contact) {
  const double other = std::abs(core_radius(contact.other_surface));
  return other > 0.0 ? std::min(contact.surface.radius, other) : contact.surface.radius;
}

CoreClosest core_closest(const ContactSurface& surface, const Vec3& x_B) {
  CoreClosest closest;
  if (surface.kind == ContactSurface::Kind::Sphere) {
    closest.p_B = surface.centre_B;
    const Vec3 apart_B = x_B - surface.centre_B;
    closest.distance = apart_B.norm();
    if (closest.distance > 0.0) closest.n_B = apart_B / closest.distance;
    if (surface.touched_inside) {
      closest.distance = -closest.distance;
      closest.n_B = -closest.n_B;
    }
    return closest;
  }
  if (surface.kind == ContactSurface::Kind::Capsule) {
    // The segment's point nearest: clamped to its ends, where it no longer slides.
    const Vec3 axis_B = surface.axes_B.col(2);
    const double along = axis_B.dot(x_B - surface.centre_B);
    const double h = surface.half_length;
    closest.p_B = surface.centre_B + std::clamp(along, -h, h) * axis_B;
    if (std::abs(along) < h)
      closest.slide_B[static_cast<std::size_t>(closest.slide_count++)] = axis_B;
    const Vec3 apart_B = x_B - closest.p_B;
    closest.distance = apart_B.norm();
    if (closest.distance > 0.0) closest.n_B = apart_B / closest.distance;
    return closest;
  }
  // A box: in its own axes (about its centre), the point clamped to its half-sizes. Each
  // coordinate held at a side fixes the normal's component there; the others slide.
  const Mat3& A = surface.axes_B;
  const Vec3 q = A.transpose() * (x_B - surface.centre_B);
  const Vec3& h = surface.half_size;
  Vec3 p = q;
  int outside = 0;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(q(i)) <= h(i)) continue;
    p(i) = std::copysign(h(i), q(i));
    ++outside;
  }
  if (outside == 0) {
    // Inside: the nearest face, at minus the depth (the start refuses this; a run's step never
    // goes this deep but by round-off).
    int face = 0;
    double depth = h(0) - std::abs(q(0));
    for (int i = 1; i < 3; ++i) {
      if (h(i) - std::abs(q(i)) < depth) {
        depth = h(i) - std::abs(q(i));
        face = i;
      }
    }
    p(face) = std::copysign(h(face), q(face));
    closest.p_B = surface.centre_B + A * p;
    closest.n_B = std::copysign(1.0, q(face)) * A.col(face);
    closest.distance = -depth;
    closest.slide_count = 2;
    closest.slide_B = {A.col((face + 1) % 3), A.col((face + 2) % 3)};
    return closest;
  }
  for (int i = 0; i < 3; ++i) {
    if (std::abs(q(i)) > h(i)) continue;
    closest.slide_B[static_cast<std::size_t>(closest.slide_count++)] = A.col(i);
  }
  closest.p_B = surface.centre_B + A * p;
  const Vec3 apart_B = x_B - closest.p_B;
  closest.distance = apart_B.norm();
  if (closest.distance > 0.0) closest.n_B = apart_B / closest.distance;
  return closest;
}

}  // namespace tumble
