#include "tumble/contact/cone_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tumble {

namespace {

// How much the rim direction leans towards the last one known, against the projection of n_B
// on the base's plane (the sine of the base's tilt from the plane).
constexpr double kRimLean = 1e-12;

// The unnormalised rim direction: the projection's opposite, leaning towards `previous`.
Vec3 leaning_direction(const Vec3& n_B, const Vec3& previous_B) {
  return Vec3(-n_B.x(), -n_B.y(), 0.0) + kRimLean * previous_B;
}

}  // namespace

Vec3 rim_direction(const Vec3& n_B, const Vec3& previous_B) {
  const Vec3 w = leaning_direction(n_B, previous_B);
  const double length = w.norm();
  return length > 0.0 ? Vec3(w / length) : previous_B;
}

Vec3 rim_direction_rate(const Vec3& n_B, const Vec3& omega_B, const Vec3& previous_B) {
  // u = w / |w| with w = -P n + lean: u' = (1 - u u^T) w' / |w|, w' = -P n', n' = n x omega.
  const Vec3 w = leaning_direction(n_B, previous_B);
  const double length = w.norm();
  if (!(length > 0.0)) return Vec3::Zero();
  const Vec3 u = w / length;
  const Vec3 n_rate = n_B.cross(omega_B);
  const Vec3 w_rate(-n_rate.x(), -n_rate.y(), 0.0);
  return (w_rate - u * u.dot(w_rate)) / length;
}

ConePartPoints cone_part_points(const ContactSurface& cone, ConePart part, const Vec3& n_B,
                                const Vec3& omega_B, const Vec3& rim_direction_B) {
  ConePartPoints p;
  const Vec3& apex = cone.vertices[0];
  const double r = cone.radius;
  const auto rim_point = [&] {
    return Vec3(cone.rim_centre_B + r * rim_direction(n_B, rim_direction_B));
  };
  const auto rim_rate = [&] { return Vec3(r * rim_direction_rate(n_B, omega_B, rim_direction_B)); };
  switch (part) {
    case ConePart::None:
    case ConePart::Apex:
      p.points_B[0] = apex;
      p.count = 1;
      break;
    case ConePart::Rim:
      p.points_B[0] = rim_point();
      p.rates_B[0] = rim_rate();
      p.count = 1;
      break;
    case ConePart::Side:
      p.points_B[0] = apex;
      p.points_B[1] = rim_point();
      p.rates_B[1] = rim_rate();
      p.count = 2;
      p.reference_B = 0.5 * (p.points_B[0] + p.points_B[1]);
      p.reference_rate_B = 0.5 * p.rates_B[1];
      p.spin_radius = 0.25 * (p.points_B[1] - p.points_B[0]).norm();  // mean |x| on [-L/2, L/2]
      return p;
    case ConePart::Base:
      for (int k = 0; k < 3; ++k) {
        const double angle = std::numbers::pi / 2 + 2 * std::numbers::pi * k / 3;
        p.points_B[static_cast<std::size_t>(k)] =
            cone.rim_centre_B + r * Vec3(std::cos(angle), std::sin(angle), 0.0);
      }
      p.count = 3;
      p.reference_B = cone.rim_centre_B;
      p.spin_radius = 2.0 * r / 3.0;  // int_0^r rho 2 pi rho d rho / (pi r^2)
      return p;
  }
  p.reference_B = p.points_B[0];
  p.reference_rate_B = p.rates_B[0];
  return p;
}

double cone_support_margin(const ContactSurface& cone, ConePart part, const Vec3& rim_point_B,
                           const Vec3& O_B, const Vec3& n_B, double N, const Vec3& M_O_B,
                           int& side) {
  side = -1;
  // N (c - O) = n x M_O for the resultant's CoP c (contact_feature.hpp's support_margin).
  const Vec3 N_offset = n_B.cross(M_O_B);
  if (part == ConePart::Base) {
    side = 0;
    return N * cone.radius - N_offset.norm();
  }
  if (part != ConePart::Side) return N;
  const Vec3 N_c = N_offset + N * O_B;
  const Vec3& apex = cone.vertices[0];
  const Vec3& rim = rim_point_B;
  const Vec3 along = (rim - apex).normalized();
  const double at_apex = along.dot(N_c - N * apex);
  const double at_rim = -along.dot(N_c - N * rim);
  side = at_apex <= at_rim ? 0 : 1;
  return std::min(at_apex, at_rim);
}

Vec3 base_tip_direction(const Vec3& n_B, const Vec3& M_O_B, const Vec3& otherwise_B) {
  const Vec3 N_offset = n_B.cross(M_O_B);
  const Vec3 in_base(N_offset.x(), N_offset.y(), 0.0);
  const double length = in_base.norm();
  return length > 0.0 ? Vec3(in_base / length) : otherwise_B;
}

const char* cone_part_name(ConePart part) {
  switch (part) {
    case ConePart::Apex:
      return "its apex";
    case ConePart::Rim:
      return "its rim";
    case ConePart::Side:
      return "its side";
    case ConePart::Base:
      return "its base";
    case ConePart::None:
      break;
  }
  return "nothing";
}

}  // namespace tumble
