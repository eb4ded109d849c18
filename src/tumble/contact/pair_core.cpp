#include "tumble/contact/pair_core.hpp"

#include <algorithm>
#include <cmath>

#include "tumble/math/dual.hpp"

namespace tumble {

namespace {

// The length of (x, y): the run's std::hypot, as it always was; sqrt of the squares over Dual
// (which has no hypot). At 0 (the centre on the axis) its derivatives are not numbers, and
// nothing takes them there: the nearest point is then on a face, or the circle's resultant
// (touching_all_round), neither of which depends on rho.
double planar_length(double x, double y) {
  return std::hypot(x, y);
}
Dual planar_length(const Dual& x, const Dual& y) {
  using std::sqrt;
  return sqrt(x * x + y * y);
}

// The magnitude m with the sign of x's value (as std::copysign: -0 counts as negative).
template <typename S>
S with_sign_of(double m, const S& x) {
  return S(std::copysign(m, value_of(x)));
}

template <typename S>
S length_of(const Vec3Of<S>& v) {
  using std::sqrt;
  return sqrt(v.squaredNorm());
}

// Within a billionth of R of the axis of a circle of radius R (CoreClosestOf::on_circle_axis).
template <typename S>
bool near_circle_axis(const S& rho, double R) {
  return value_of(rho) <= kTouchingHeightPerSize * R;
}

// A sphere whose centre is on the axis of the circle it touches (a ball dropped centred onto a
// ring, into a torus's hole, onto a pipe's mouth) touches the whole circle at once: the pushes
// round it add up to one along the axis, through the centre. So it is held as that resultant:
// the distance stays the circle's (the gap is true), but the point is the circle's centre
// (`circle_centre_B`, body axes) and the normal the axis, towards the sphere's side of the
// circle's plane (`q_z`: the centre's height over it), neither sliding nor turning as the
// centre moves along the axis. Off the axis by more than a billionth of the radius it touches
// at one point, as anywhere else.
template <typename S>
CoreClosestOf<S>& touching_all_round(CoreClosestOf<S>& closest, const Vec3Of<S>& circle_centre_B,
                                     const Vec3Of<S>& axis_B, const S& q_z) {
  closest.p_B = circle_centre_B;
  closest.n_B = with_sign_of(1.0, q_z) * axis_B;
  closest.slide_count = 0;
  return closest;
}

// Whether x is within a billionth of `size` of the seam at `at` (CoreClosestOf::on_feature_seam).
template <typename S>
bool near_seam(const S& x, double at, double size) {
  return std::abs(value_of(x) - at) <= kTouchingHeightPerSize * size;
}

// The centre x_B's distance from the nearest point p_B, set already, and the normal from it.
template <typename S>
CoreClosestOf<S>& measured_from_nearest(CoreClosestOf<S>& closest, const Vec3Of<S>& x_B) {
  const Vec3Of<S> apart_B = x_B - closest.p_B;
  closest.distance = length_of<S>(apart_B);
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
template <typename S>
CoreClosestOf<S> cylinder_closest(const ContactSurface& surface, const Vec3Of<S>& x_B) {
  using V3 = Vec3Of<S>;
  using std::abs;
  CoreClosestOf<S> closest;
  const Mat3Of<S> A = surface.axes_B.cast<S>();
  const V3 q = A.transpose() * (x_B - surface.centre_B.cast<S>());
  const bool cylinder = surface.kind == ContactSurface::Kind::Cylinder;
  const double R = surface.radius, h = cylinder ? surface.half_length : 0.0,
               a = cylinder ? surface.face_inner_radius : 0.0;
  const S rho = planar_length(q.x(), q.y());
  // Out from the axis towards the centre, and round the axis (any, on the axis).
  const V3 out = rho > 0.0 ? V3(q.x() / rho, q.y() / rho, S(0.0)) : V3(V3::UnitX());
  const V3 round(-out.y(), out.x(), S(0.0));
  const bool beyond_end = abs(q.z()) > h, beyond_side = rho > R, in_bore = rho < a;
  // Its seams: the ends' planes beside the side or the bore (a rim), the side's and the bore's
  // cylinders beyond an end.
  const double size = std::max(R, h);
  closest.on_feature_seam =
      ((beyond_side || in_bore) && near_seam(abs(q.z()), h, size)) ||
      (beyond_end && (near_seam(rho, R, size) || (a > 0.0 && near_seam(rho, a, size))));
  V3 p = q;
  if (beyond_end) p.z() = with_sign_of(h, q.z());
  if (beyond_side) p.template head<2>() = R * out.template head<2>();
  if (in_bore) p.template head<2>() = a * out.template head<2>();
  const auto slide = [&](const V3& e, const S& scale) {
    const std::size_t k = static_cast<std::size_t>(closest.slide_count++);
    closest.slide_B[k] = A * e;
    closest.slide_scale[k] = scale;
  };
  // Round a circle of radius r about the axis: at r / rho of the centre's motion round it (none
  // on the axis, where every point of the circle is as near).
  const auto slide_round = [&](double r) {
    closest.on_circle_axis = near_circle_axis(rho, r);
    if (rho > 0.0) slide(round, S(r / rho));
  };
  if (!beyond_end && !beyond_side && !in_bore) {
    // Inside: the nearest of the side, the bore and the face, at minus the depth.
    const S to_side = R - rho, to_bore = a > 0.0 ? S(rho - a) : to_side, to_face = h - abs(q.z());
    if (std::min(to_side, to_bore) < to_face) {
      const bool side = to_side <= to_bore;
      p.template head<2>() = (side ? R : a) * out.template head<2>();
      closest.n_B = A * (side ? out : V3(-out));
      closest.distance = -(side ? to_side : to_bore);
      slide(V3::UnitZ(), S(1.0));
      slide(round, S(1.0));
    } else {
      p.z() = with_sign_of(h, q.z());
      closest.n_B = with_sign_of(1.0, q.z()) * A.col(2);
      closest.distance = -to_face;
      slide(V3::UnitX(), S(1.0));
      slide(V3::UnitY(), S(1.0));
    }
    closest.p_B = surface.centre_B.cast<S>() + A * p;
    return closest;
  }
  if (!beyond_side && !in_bore) {  // a face: flat
    slide(V3::UnitX(), S(1.0));
    slide(V3::UnitY(), S(1.0));
  } else if (!beyond_end) {  // the side or the bore: along the axis, and round it
    slide(V3::UnitZ(), S(1.0));
    slide_round(in_bore ? a : R);
  } else {  // a rim: round the axis
    slide_round(in_bore ? a : R);
  }
  closest.p_B = surface.centre_B.cast<S>() + A * p;
  measured_from_nearest(closest, x_B);
  if (beyond_end && in_bore && closest.on_circle_axis) {  // centred on the bore's rim
    touching_all_round(closest, V3(surface.centre_B.cast<S>() + A.col(2) * S(p.z())), V3(A.col(2)),
                       q.z());
  }
  return closest;
}

// A cone, in the half-plane of its axis and the point: its profile is the triangle of its apex
// (on the axis, H above the base), its base's rim (R out) and the base's centre, and the nearest
// point is that triangle's nearest point, turned round the axis. On the slant side it slides
// along the side's line as the centre does, and round the axis at rho_p / rho (rho_p its own
// distance from the axis); on the base, flat; on the rim, round; at the apex, nowhere.
template <typename S>
CoreClosestOf<S> cone_closest(const ContactSurface& surface, const Vec3Of<S>& x_B) {
  using V3 = Vec3Of<S>;
  CoreClosestOf<S> closest;
  const V3 base_B = surface.rim_centre_B.cast<S>();
  const V3 axis_B = surface.axes_B.col(2).cast<S>();
  const double H = surface.axes_B.col(2).dot(surface.vertices.front() - surface.rim_centre_B),
               R = surface.radius;
  const V3 d_B = x_B - base_B;
  const S z = axis_B.dot(d_B);
  const V3 radial_B = d_B - z * axis_B;
  const S rho = length_of<S>(radial_B);
  // Out from the axis towards the point (any, on it), and round the axis.
  const V3 out_B = rho > 0.0 ? V3(radial_B / rho) : V3(surface.axes_B.col(0).cast<S>());
  const V3 round_B = axis_B.cross(out_B);
  // The slant side, from the rim (R, 0) to the apex (0, H) in (rho, z): its unit direction and
  // its outward normal; where along it the point falls, and how far out of it.
  const double slant = std::hypot(R, H);
  const double e_rho = -R / slant, e_z = H / slant;  // rim to apex
  const double n_rho = H / slant, n_z = R / slant;   // out of the side
  const S along = (rho - R) * e_rho + z * e_z;
  const S off_side = (rho - R) * n_rho + z * n_z;
  // Its seams: the base's rim below the base, the rim and the apex beyond the side.
  closest.on_feature_seam =
      (z < 0.0 && near_seam(rho, R, slant)) ||
      (off_side > 0.0 && (near_seam(along, 0.0, slant) || near_seam(along, slant, slant)));
  const auto at = [&](const S& p_rho, const S& p_z) {
    return V3(base_B + p_rho * out_B + p_z * axis_B);
  };
  const auto slide = [&](const V3& e_B, const S& scale) {
    const std::size_t k = static_cast<std::size_t>(closest.slide_count++);
    closest.slide_B[k] = e_B;
    closest.slide_scale[k] = scale;
  };
  if (z < 0.0 && rho <= R) {  // below the base: on it, flat
    closest.p_B = at(rho, S(0.0));
    slide(out_B, S(1.0));
    slide(round_B, S(1.0));
    return measured_from_nearest(closest, x_B);
  }
  if (off_side > 0.0 || z < 0.0) {
    if (along >= slant) {  // beyond the apex
      closest.p_B = at(S(0.0), S(H));
      return measured_from_nearest(closest, x_B);
    }
    if (along <= 0.0) {  // beyond the rim
      closest.p_B = at(S(R), S(0.0));
      if (rho > 0.0) slide(round_B, S(R / rho));
      return measured_from_nearest(closest, x_B);
    }
    if (off_side > 0.0) {  // over the slant side
      const S p_rho = R + along * e_rho;
      closest.p_B = at(p_rho, S(along * e_z));
      slide(V3(e_rho * out_B + e_z * axis_B), S(1.0));
      if (rho > 0.0) slide(round_B, S(p_rho / rho));
      return measured_from_nearest(closest, x_B);
    }
  }
  // Inside (by round-off: the start refuses it): the nearer of the base and the side, at minus
  // the depth.
  if (z < -off_side) {
    closest.p_B = at(rho, S(0.0));
    closest.n_B = -axis_B;
    closest.distance = -z;
    slide(out_B, S(1.0));
    slide(round_B, S(1.0));
  } else {
    closest.p_B = at(S(rho - off_side * n_rho), S(z - off_side * n_z));
    closest.n_B = n_rho * out_B + n_z * axis_B;
    closest.distance = off_side;
    slide(V3(e_rho * out_B + e_z * axis_B), S(1.0));
    slide(round_B, S(1.0));
  }
  return closest;
}

// A ring's or a torus's centre circle (its rim, radius R, about the third axis): the point of it
// nearest, out from the axis towards x_B, sliding round it at R / rho of the centre's motion
// round the axis (with the centre on the axis, every point of the circle is as near: the whole
// circle, touching_all_round).
template <typename S>
CoreClosestOf<S> circle_closest(const ContactSurface& surface, const Vec3Of<S>& x_B) {
  using V3 = Vec3Of<S>;
  CoreClosestOf<S> closest;
  const Mat3Of<S> A = surface.axes_B.cast<S>();
  const V3 q = A.transpose() * (x_B - surface.centre_B.cast<S>());
  const double R = surface.radius;
  const S rho = planar_length(q.x(), q.y());
  const V3 out = rho > 0.0 ? V3(q.x() / rho, q.y() / rho, S(0.0)) : V3(V3::UnitX());
  closest.p_B = surface.centre_B.cast<S>() + A * V3(R * out);
  closest.on_circle_axis = near_circle_axis(rho, R);
  if (rho > 0.0) {
    closest.slide_count = 1;
    closest.slide_B[0] = A * V3(-out.y(), out.x(), S(0.0));
    closest.slide_scale[0] = R / rho;
  }
  measured_from_nearest(closest, x_B);
  if (closest.on_circle_axis) {
    touching_all_round(closest, V3(surface.centre_B.cast<S>()), V3(A.col(2)), q.z());
  }
  return closest;
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

template <typename S>
CoreClosestOf<S> core_closest(const ContactSurface& surface, const Vec3Of<S>& x_B) {
  using V3 = Vec3Of<S>;
  using std::abs;
  CoreClosestOf<S> closest;
  if (surface.kind == ContactSurface::Kind::Sphere) {
    closest.p_B = surface.centre_B.cast<S>();
    measured_from_nearest(closest, x_B);
    if (surface.touched_inside) {
      closest.distance = -closest.distance;
      closest.n_B = -closest.n_B;
    }
    return closest;
  }
  if (surface.kind == ContactSurface::Kind::Capsule) {
    // The segment's point nearest: clamped to its ends, where it no longer slides.
    const V3 axis_B = surface.axes_B.col(2).cast<S>();
    const S along = axis_B.dot(x_B - surface.centre_B.cast<S>());
    const double h = surface.half_length;
    const S clamped = along < -h ? S(-h) : h < along ? S(h) : along;  // as std::clamp
    closest.p_B = surface.centre_B.cast<S>() + clamped * axis_B;
    closest.on_feature_seam = near_seam(abs(along), h, std::max(h, surface.radius));
    if (abs(along) < h) {
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
  const Mat3Of<S> A = surface.axes_B.cast<S>();
  const V3 q = A.transpose() * (x_B - surface.centre_B.cast<S>());
  const Vec3& h = surface.half_size;
  V3 p = q;
  int outside = 0;
  for (int i = 0; i < 3; ++i) {
    // A seam: a face's edge, where that coordinate passes from sliding to held.
    closest.on_feature_seam = closest.on_feature_seam || near_seam(abs(q(i)), h(i), h.maxCoeff());
    if (abs(q(i)) <= h(i)) continue;
    p(i) = with_sign_of(h(i), q(i));
    ++outside;
  }
  if (outside == 0) {
    // Inside: the nearest face, at minus the depth (the start refuses this; a run's step never
    // goes this deep but by round-off).
    int face = 0;
    S depth = h(0) - abs(q(0));
    for (int i = 1; i < 3; ++i) {
      if (h(i) - abs(q(i)) < depth) {
        depth = h(i) - abs(q(i));
        face = i;
      }
    }
    p(face) = with_sign_of(h(face), q(face));
    closest.p_B = surface.centre_B.cast<S>() + A * p;
    closest.n_B = with_sign_of(1.0, q(face)) * A.col(face);
    closest.distance = -depth;
    closest.slide_count = 2;
    closest.slide_B = {V3(A.col((face + 1) % 3)), V3(A.col((face + 2) % 3))};
    return closest;
  }
  for (int i = 0; i < 3; ++i) {
    if (abs(q(i)) > h(i)) continue;
    closest.slide_B[static_cast<std::size_t>(closest.slide_count++)] = A.col(i);
  }
  closest.p_B = surface.centre_B.cast<S>() + A * p;
  return measured_from_nearest(closest, x_B);
}

template <typename S>
CoreLineOf<S> core_line(const ContactSurface& surface, const Vec3Of<S>& x_B, const Vec3Of<S>& u_B) {
  CoreLineOf<S> line;
  line.closest = core_closest<S>(surface, x_B);
  const CoreClosestOf<S>& closest = line.closest;
  for (std::size_t k = 0; k < static_cast<std::size_t>(closest.slide_count); ++k) {
    const Vec3Of<S>& e = closest.slide_B[k];
    line.p_rate_B += e * (closest.slide_scale[k] * e.dot(u_B));
  }
  if (closest.distance > 0.0) {
    line.n_rate_B = (u_B - line.p_rate_B - closest.n_B * closest.n_B.dot(u_B)) / closest.distance;
  }
  return line;
}

template CoreClosestOf<double> core_closest(const ContactSurface&, const Vec3&);
template CoreClosestOf<Dual> core_closest(const ContactSurface&, const Vec3Of<Dual>&);
template CoreLineOf<double> core_line(const ContactSurface&, const Vec3&, const Vec3&);
template CoreLineOf<Dual> core_line(const ContactSurface&, const Vec3Of<Dual>&,
                                    const Vec3Of<Dual>&);

}  // namespace tumble
