#include "tumble/contact/pair_core.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

namespace {

// The centre x_B's distance from the nearest point p_B, set already, and the normal from it.
CoreClosest& measured_from_nearest(CoreClosest& closest, const Vec3& x_B) {
  const Vec3 apart_B = x_B - closest.p_B;
  closest.distance = apart_B.norm();
  if (closest.distance > 0.0) closest.n_B = apart_B / closest.distance;
  return closest;
}

// A cylinder (a disk: of length 0) in its own axes about its centre, the axis the third: the
// point clamped to its length and to its radius. Held at an end (|z| > h) and within the radius,
// on that face; beyond the radius and within the length, on the side; beyond both, on that end's
// rim. Within both (inside it, by round-off: the start refuses it), on the nearer of the side and
// the face.
CoreClosest cylinder_closest(const ContactSurface& surface, const Vec3& x_B) {
  CoreClosest closest;
  const Mat3& A = surface.axes_B;
  const Vec3 q = A.transpose() * (x_B - surface.centre_B);
  const double R = surface.radius,
               h = surface.kind == ContactSurface::Kind::Cylinder ? surface.half_length : 0.0;
  const double rho = std::hypot(q.x(), q.y());
  // Out from the axis towards the centre, and round the axis (any, on the axis).
  const Vec3 out = rho > 0.0 ? Vec3(q.x() / rho, q.y() / rho, 0.0) : Vec3::UnitX();
  const Vec3 round(-out.y(), out.x(), 0.0);
  const bool beyond_end = std::abs(q.z()) > h, beyond_side = rho > R;
  Vec3 p = q;
  if (beyond_end) p.z() = std::copysign(h, q.z());
  if (beyond_side) p.head<2>() = R * out.head<2>();
  const auto slide = [&](const Vec3& e, double scale) {
    const std::size_t k = static_cast<std::size_t>(closest.slide_count++);
    closest.slide_B[k] = A * e;
    closest.slide_scale[k] = scale;
  };
  if (!beyond_end && !beyond_side) {
    // Inside: the nearer of the side and the face, at minus the depth.
    const double to_side = R - rho, to_face = h - std::abs(q.z());
    if (to_side < to_face) {
      p.head<2>() = R * out.head<2>();
      closest.n_B = A * out;
      closest.distance = -to_side;
      slide(Vec3::UnitZ(), 1.0);
      slide(round, 1.0);
    } else {
      p.z() = std::copysign(h, q.z());
      closest.n_B = std::copysign(1.0, q.z()) * A.col(2);
      closest.distance = -to_face;
      slide(Vec3::UnitX(), 1.0);
      slide(Vec3::UnitY(), 1.0);
    }
    closest.p_B = surface.centre_B + A * p;
    return closest;
  }
  if (!beyond_side) {  // a face: flat
    slide(Vec3::UnitX(), 1.0);
    slide(Vec3::UnitY(), 1.0);
  } else if (!beyond_end) {  // the side: along the axis, and round it
    slide(Vec3::UnitZ(), 1.0);
    slide(round, R / rho);
  } else {  // a rim: round the axis
    slide(round, R / rho);
  }
  closest.p_B = surface.centre_B + A * p;
  return measured_from_nearest(closest, x_B);
}

// A ring's or a torus's centre circle (its rim, radius R, about the third axis): the point of it
// nearest, out from the axis towards x_B, sliding round it at R / rho of the centre's motion
// round the axis (any, with the centre on the axis: every point of the circle is as near).
CoreClosest circle_closest(const ContactSurface& surface, const Vec3& x_B) {
  CoreClosest closest;
  const Mat3& A = surface.axes_B;
  const Vec3 q = A.transpose() * (x_B - surface.centre_B);
  const double R = surface.radius, rho = std::hypot(q.x(), q.y());
  const Vec3 out = rho > 0.0 ? Vec3(q.x() / rho, q.y() / rho, 0.0) : Vec3::UnitX();
  closest.p_B = surface.centre_B + A * (R * out);
  if (rho > 0.0) {
    closest.slide_count = 1;
    closest.slide_B[0] = A * Vec3(-out.y(), out.x(), 0.0);
    closest.slide_scale[0] = R / rho;
  }
  return measured_from_nearest(closest, x_B);
}

// A ring (or a torus) touches only along its rim: its face is hollow all the way out.
bool rim_only(const ContactSurface& surface) {
  return surface.kind == ContactSurface::Kind::Circle &&
         surface.face_inner_radius >= surface.radius;
}

}  // namespace

double core_radius(const ContactSurface& surface) {
  if (surface.touched_inside) return -surface.radius;
  if (rim_only(surface)) return surface.tube_radius;  // a ring's 0
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
    measured_from_nearest(closest, x_B);
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
    if (std::abs(along) < h) {
      closest.slide_B[static_cast<std::size_t>(closest.slide_count++)] = axis_B;
    }
    return measured_from_nearest(closest, x_B);
  }
  if (rim_only(surface)) return circle_closest(surface, x_B);
  if (surface.kind == ContactSurface::Kind::Cylinder ||
      surface.kind == ContactSurface::Kind::Circle) {
    return cylinder_closest(surface, x_B);
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
  return measured_from_nearest(closest, x_B);
}

}  // namespace tumble
