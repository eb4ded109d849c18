#include "tumble/contact/round_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tumble {

namespace {

// How much the rim direction leans towards the last one known, against the projection of n_B
// on the ends' plane (the sine of the ends' tilt from the plane).
constexpr double kRimLean = 1e-12;

// The unnormalised rim direction: the projection's opposite, leaning towards `previous`.
Vec3 leaning_direction(const RoundEnds& ends, const Vec3& n_B, const Vec3& previous_B) {
  if (!ends.turned) return Vec3(-n_B.x(), -n_B.y(), 0.0) + kRimLean * previous_B;
  return -in_ends_plane(ends, n_B) + kRimLean * in_ends_plane(ends, previous_B);
}

// The mean distance from the centre of an even pressure on a face: 2r/3 on a disk, r on a ring,
// (2/3)(r^3 - q^3)/(r^2 - q^2) on an annulus of inner radius q.
double face_spin_radius(double r, double q) {
  if (!(q > 0.0)) return 2.0 * r / 3.0;
  if (q >= r) return r;
  return 2.0 * (r * r * r - q * q * q) / (3.0 * (r * r - q * q));
}

}  // namespace

RoundEnds round_ends(const ContactSurface& surface) {
  RoundEnds ends;
  ends.face_inner_radius = surface.face_inner_radius;
  ends.axes_B = surface.axes_B;
  ends.turned = surface.turned;
  ends.tube = surface.tube_radius;
  switch (surface.kind) {
    case ContactSurface::Kind::Cone:
      ends.centre_B = {surface.vertices[0], surface.rim_centre_B};
      ends.radius = {0.0, surface.radius};
      break;
    case ContactSurface::Kind::Cylinder:
    case ContactSurface::Kind::Capsule:
      if (surface.turned) {
        const Vec3 half = surface.half_length * surface.axes_B.col(2);
        ends.centre_B = {surface.centre_B - half, surface.centre_B + half};
      } else {
        ends.centre_B = {Vec3(0.0, 0.0, -surface.half_length), Vec3(0.0, 0.0, surface.half_length)};
      }
      if (surface.kind == ContactSurface::Kind::Capsule) {
        // Its caps' centres, circles of radius 0, swept by its radius as a torus's rim by its
        // tube: what touches is a cap's lowest point, or the side's line between the two.
        ends.radius = {0.0, 0.0};
        ends.tube = surface.radius;
      } else {
        ends.radius = {surface.radius, surface.radius};
      }
      break;
    default:  // a disk or ring: one rim about its centre (the COM, but for a composite's part)
      ends.centre_B = {surface.centre_B, surface.centre_B};
      ends.radius = {surface.radius, surface.radius};
      ends.one_rim = true;
      break;
  }
  return ends;
}

Vec3 in_ends_plane(const RoundEnds& ends, const Vec3& v_B) {
  if (!ends.turned) return Vec3(v_B.x(), v_B.y(), 0.0);
  const Vec3 axis = ends.axes_B.col(2);
  return v_B - axis * axis.dot(v_B);
}

Vec3 ends_plane_direction(const RoundEnds& ends, double x, double y) {
  if (!ends.turned) return Vec3(x, y, 0.0);
  return x * ends.axes_B.col(0) + y * ends.axes_B.col(1);
}

Vec3 lowest_rim_direction(const RoundEnds& ends, const Vec3& n_B, double& projected_length) {
  if (!ends.turned) return lowest_in_plane(n_B, projected_length);
  const Vec3 projected = in_ends_plane(ends, n_B);
  projected_length = projected.norm();
  if (projected_length == 0.0) return ends.axes_B.col(0);
  return -projected / projected_length;
}

double tilt_sine(const RoundEnds& ends, const Vec3& n_B) {
  if (!ends.turned) return std::hypot(n_B.x(), n_B.y());
  return in_ends_plane(ends, n_B).norm();
}

int end_of(RoundPart part) {
  return part == RoundPart::EndA || part == RoundPart::FaceA ? 0 : 1;
}

bool is_face(RoundPart part) {
  return part == RoundPart::FaceA || part == RoundPart::FaceB;
}

bool is_end(RoundPart part) {
  return part == RoundPart::EndA || part == RoundPart::EndB;
}

bool holds_rim_point(const ContactSurface& surface, RoundPart part) {
  if (is_face(part) || part == RoundPart::None) return false;
  const RoundEnds ends = round_ends(surface);
  return (part != RoundPart::EndB && ends.radius[0] > 0.0) ||
         (part != RoundPart::EndA && ends.radius[1] > 0.0);
}

Vec3 rim_direction(const RoundEnds& ends, const Vec3& n_B, const Vec3& previous_B) {
  const Vec3 w = leaning_direction(ends, n_B, previous_B);
  const double length = w.norm();
  return length > 0.0 ? Vec3(w / length) : previous_B;
}

void rim_direction_and_rate(const RoundEnds& ends, const Vec3& n_B, const Vec3& omega_B,
                            const Vec3& previous_B, Vec3& u_B, Vec3& u_rate_B) {
  // u = w / |w| with w = -P n + lean: u' = (1 - u u^T) w' / |w|, w' = -P n', n' = n x omega.
  const Vec3 w = leaning_direction(ends, n_B, previous_B);
  const double length = w.norm();
  if (!(length > 0.0)) {
    u_B = previous_B;
    u_rate_B.setZero();
    return;
  }
  u_B = w / length;
  const Vec3 n_rate = n_B.cross(omega_B);
  const Vec3 w_rate =
      ends.turned ? Vec3(-in_ends_plane(ends, n_rate)) : Vec3(-n_rate.x(), -n_rate.y(), 0.0);
  u_rate_B = (w_rate - u_B * u_B.dot(w_rate)) / length;
}

Vec3 rim_point(const RoundEnds& ends, int k, const Vec3& u_B) {
  const auto i = static_cast<std::size_t>(k);
  return ends.centre_B[i] + ends.radius[i] * u_B;
}

Vec3 on_surface(const RoundEnds& ends, const Vec3& circle_point_B, const Vec3& n_B) {
  if (!(ends.tube > 0.0)) return circle_point_B;
  return circle_point_B - ends.tube * n_B;
}

Vec3 surface_point(const RoundEnds& ends, int k, const Vec3& u_B, const Vec3& n_B) {
  return on_surface(ends, rim_point(ends, k, u_B), n_B);
}

Vec3 surface_point_rate(const RoundEnds& ends, const Vec3& rim_rate_B, const Vec3& n_B,
                        const Vec3& omega_B) {
  if (!(ends.tube > 0.0)) return rim_rate_B;
  return rim_rate_B - ends.tube * n_B.cross(omega_B);
}

RoundPartPoints round_part_points(const RoundEnds& ends, RoundPart part, const Vec3& n_B,
                                  const Vec3& omega_B, const Vec3& rim_direction_B) {
  RoundPartPoints p;
  Vec3 u = Vec3::UnitX(), u_rate = Vec3::Zero();
  if (!is_face(part)) rim_direction_and_rate(ends, n_B, omega_B, rim_direction_B, u, u_rate);
  const int k = end_of(part);
  const auto r = ends.radius[static_cast<std::size_t>(k)];
  switch (part) {
    case RoundPart::None:
    case RoundPart::EndA:
    case RoundPart::EndB:
      p.points_B[0] = surface_point(ends, k, u, n_B);
      p.rates_B[0] = surface_point_rate(ends, r * u_rate, n_B, omega_B);
      p.count = 1;
      break;
    case RoundPart::Side:
      for (std::size_t e = 0; e < 2; ++e) {
        p.points_B[e] = surface_point(ends, static_cast<int>(e), u, n_B);
        p.rates_B[e] = surface_point_rate(ends, ends.radius[e] * u_rate, n_B, omega_B);
      }
      p.count = 2;
      p.reference_B = 0.5 * (p.points_B[0] + p.points_B[1]);
      p.reference_rate_B = 0.5 * (p.rates_B[0] + p.rates_B[1]);
      p.spin_radius = 0.25 * (p.points_B[1] - p.points_B[0]).norm();  // mean |x| on [-L/2, L/2]
      return p;
    case RoundPart::FaceA:
    case RoundPart::FaceB:
      for (std::size_t j = 0; j < 3; ++j) {
        const double angle =
            std::numbers::pi / 2 + 2 * std::numbers::pi * static_cast<double>(j) / 3;
        p.points_B[j] = surface_point(
            ends, k, ends_plane_direction(ends, std::cos(angle), std::sin(angle)), n_B);
      }
      p.count = 3;
      p.reference_B = on_surface(ends, ends.centre_B[static_cast<std::size_t>(k)], n_B);
      p.spin_radius = face_spin_radius(r, ends.face_inner_radius);
      return p;
  }
  p.reference_B = p.points_B[0];
  p.reference_rate_B = p.rates_B[0];
  return p;
}

double round_support_margin(const ContactSurface& surface, RoundPart part,
                            const std::array<Vec3, 3>& points_B, const Vec3& O_B, const Vec3& n_B,
                            double N, const Vec3& M_O_B, int& side) {
  side = -1;
  // N (c - O) = n x M_O for the resultant's CoP c (contact_feature.hpp's support_margin).
  const Vec3 N_offset = n_B.cross(M_O_B);
  if (is_face(part)) {
    side = 0;
    const RoundEnds ends = round_ends(surface);
    return N * ends.radius[static_cast<std::size_t>(end_of(part))] - N_offset.norm();
  }
  if (part != RoundPart::Side) return N;
  const Vec3 N_c = N_offset + N * O_B;
  const Vec3& a = points_B[0];
  const Vec3& b = points_B[1];
  const Vec3 along = (b - a).normalized();
  const double at_a = along.dot(N_c - N * a);
  const double at_b = -along.dot(N_c - N * b);
  side = at_a <= at_b ? 0 : 1;
  return std::min(at_a, at_b);
}

Vec3 face_tip_direction(const RoundEnds& ends, const Vec3& n_B, const Vec3& M_O_B,
                        const Vec3& otherwise_B) {
  const Vec3 N_offset = n_B.cross(M_O_B);
  const Vec3 in_face = in_ends_plane(ends, N_offset);
  const double length = in_face.norm();
  return length > 0.0 ? Vec3(in_face / length) : otherwise_B;
}

const char* round_part_name(const ContactSurface& surface, RoundPart part) {
  const bool cone = surface.kind == ContactSurface::Kind::Cone;
  const bool cylinder = surface.kind == ContactSurface::Kind::Cylinder;
  const bool capsule = surface.kind == ContactSurface::Kind::Capsule;
  switch (part) {
    case RoundPart::EndA:
      return cone ? "its apex" : cylinder ? "its -z rim" : capsule ? "its -z cap" : "its rim";
    case RoundPart::EndB:
      return cylinder ? "its +z rim" : capsule ? "its +z cap" : "its rim";
    case RoundPart::Side:
      return "its side";
    case RoundPart::FaceA:
      return cylinder ? "its -z face" : "its face";
    case RoundPart::FaceB:
      return cone ? "its base" : cylinder ? "its +z face" : "its face";
    case RoundPart::None:
      break;
  }
  return "nothing";
}

}  // namespace tumble
