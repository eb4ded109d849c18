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

// A cylinder (a disk: of length 0; a tube: hollow within its inner radius a) in its own axes about
// its centre, the axis the third: in the half-plane of the axis and the point, its profile is
// the rectangle a <= rho <= R, |z| <= h, and the nearest point is the point clamped to it. Held
// at an end (|z| > h) and within the annulus, on that face; beyond the radius (or within the
// hole) and within the length, on the side (the bore); beyond both, on that end's rim (the inner
// rim, within the hole: a ball at a pipe's mouth). Within all (inside it, by round-off: the start
// refuses it), on the nearest of the side, the bore and the face.
CoreClosest cylinder_closest(const ContactSurface& surface, const Vec3& x_B) {
  CoreClosest closest;
  const Mat3& A = surface.axes_B;
  const Vec3 q = A.transpose() * (x_B - surface.centre_B);
  const bool cylinder = surface.kind == ContactSurface::Kind::Cylinder;
  const double R = surface.radius, h = cylinder ? surface.half_length : 0.0,
               a = cylinder ? surface.face_inner_radius : 0.0;
  const double rho = std::hypot(q.x(), q.y());
  // Out from the axis towards the centre, and round the axis (any, on the axis).
  const Vec3 out = rho > 0.0 ? Vec3(q.x() / rho, q.y() / rho, 0.0) : Vec3::UnitX();
  const Vec3 round(-out.y(), out.x(), 0.0);
  const bool beyond_end = std::abs(q.z()) > h, beyond_side = rho > R, in_bore = rho < a;
  Vec3 p = q;
  if (beyond_end) p.z() = std::copysign(h, q.z());
  if (beyond_side) p.head<2>() = R * out.head<2>();
  if (in_bore) p.head<2>() = a * out.head<2>();
  const auto slide = [&](const Vec3& e, double scale) {
    const std::size_t k = static_cast<std::size_t>(closest.slide_count++);
    closest.slide_B[k] = A * e;
    closest.slide_scale[k] = scale;
  };
  // Round a circle of radius r about the axis: at r / rho of the centre's motion round it (none
  // on the axis, where every point of the circle is as near).
  const auto slide_round = [&](double r) {
    if (rho > 0.0) slide(round, r / rho);
  };
  if (!beyond_end && !beyond_side && !in_bore) {
    // Inside: the nearest of the side, the bore and the face, at minus the depth.
    const double to_side = R - rho, to_bore = a > 0.0 ? rho - a : to_side,
                 to_face = h - std::abs(q.z());
    if (std::min(to_side, to_bore) < to_face) {
      const bool side = to_side <= to_bore;
      p.head<2>() = (side ? R : a) * out.head<2>();
      closest.n_B = A * (side ? out : Vec3(-out));
      closest.distance = -(side ? to_side : to_bore);
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
  if (!beyond_side && !in_bore) {  // a face: flat
    slide(Vec3::UnitX(), 1.0);
    slide(Vec3::UnitY(), 1.0);
  } else if (!beyond_end) {  // the side or the bore: along the axis, and round it
    slide(Vec3::UnitZ(), 1.0);
    slide_round(in_bore ? a : R);
  } else {  // a rim: round the axis
    slide_round(in_bore ? a : R);
  }
  closest.p_B = surface.centre_B + A * p;
  return measured_from_nearest(closest, x_B);
}

// A cone, in the half-plane of its axis and the point: its profile is the triangle of its apex
// (on the axis, H above the base), its base's rim (R out) and the base's centre, and the nearest
// point is that triangle's nearest point, turned round the axis. On the slant side it slides
// along the side's line as the centre does, and round the axis at rho_p / rho (rho_p its own
// distance from the axis); on the base, flat; on the rim, round; at the apex, nowhere.
CoreClosest cone_closest(const ContactSurface& surface, const Vec3& x_B) {
  CoreClosest closest;
  const Vec3 base_B = surface.rim_centre_B;
  const Vec3 axis_B = surface.axes_B.col(2);
  const double H = axis_B.dot(surface.vertices.front() - base_B), R = surface.radius;
  const Vec3 d_B = x_B - base_B;
  const double z = axis_B.dot(d_B);
  const Vec3 radial_B = d_B - z * axis_B;
  const double rho = radial_B.norm();
  // Out from the axis towards the point (any, on it), and round the axis.
  const Vec3 out_B = rho > 0.0 ? Vec3(radial_B / rho) : Vec3(surface.axes_B.col(0));
  const Vec3 round_B = axis_B.cross(out_B);
  // The slant side, from the rim (R, 0) to the apex (0, H) in (rho, z): its unit direction and
  // its outward normal; where along it the point falls, and how far out of it.
  const double slant = std::hypot(R, H);
  const double e_rho = -R / slant, e_z = H / slant;  // rim to apex
  const double n_rho = H / slant, n_z = R / slant;   // out of the side
  const double along = (rho - R) * e_rho + z * e_z;
  const double off_side = (rho - R) * n_rho + z * n_z;
  const auto at = [&](double p_rho, double p_z) { return base_B + p_rho * out_B + p_z * axis_B; };
  const auto slide = [&](const Vec3& e_B, double scale) {
    const std::size_t k = static_cast<std::size_t>(closest.slide_count++);
    closest.slide_B[k] = e_B;
    closest.slide_scale[k] = scale;
  };
  if (z < 0.0 && rho <= R) {  // below the base: on it, flat
    closest.p_B = at(rho, 0.0);
    slide(out_B, 1.0);
    slide(round_B, 1.0);
    return measured_from_nearest(closest, x_B);
  }
  if (off_side > 0.0 || z < 0.0) {
    if (along >= slant) {  // beyond the apex
      closest.p_B = at(0.0, H);
      return measured_from_nearest(closest, x_B);
    }
    if (along <= 0.0) {  // beyond the rim
      closest.p_B = at(R, 0.0);
      if (rho > 0.0) slide(round_B, R / rho);
      return measured_from_nearest(closest, x_B);
    }
    if (off_side > 0.0) {  // over the slant side
      const double p_rho = R + along * e_rho;
      closest.p_B = at(p_rho, along * e_z);
      slide(e_rho * out_B + e_z * axis_B, 1.0);
      if (rho > 0.0) slide(round_B, p_rho / rho);
      return measured_from_nearest(closest, x_B);
    }
  }
  // Inside (by round-off: the start refuses it): the nearer of the base and the side, at minus
  // the depth.
  if (z < -off_side) {
    closest.p_B = at(rho, 0.0);
    closest.n_B = -axis_B;
    closest.distance = -z;
    slide(out_B, 1.0);
    slide(round_B, 1.0);
  } else {
    closest.p_B = at(rho - off_side * n_rho, z - off_side * n_z);
    closest.n_B = n_rho * out_B + n_z * axis_B;
    closest.distance = off_side;
    slide(e_rho * out_B + e_z * axis_B, 1.0);
    slide(round_B, 1.0);
  }
  return closest;
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
  if (surface.kind == ContactSurface::Kind::Cone) return cone_closest(surface, x_B);
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
