#include "tumble/contact/plane_contact.hpp"

#include <algorithm>
#include <cmath>

#include "tumble/contact/round_contact.hpp"

namespace tumble {

Vec3 lowest_in_plane(const Vec3& n_B, double& projected_length) {
  const Vec3 projected(n_B.x(), n_B.y(), 0.0);
  projected_length = projected.norm();
  if (projected_length == 0.0) return Vec3::UnitX();
  return -projected / projected_length;
}

namespace {

// Which end of a round surface is the lower along -n_B (0: A, 1: B; B of equals), and the
// direction of its lowest rim point.
int lower_end(const RoundEnds& ends, const Vec3& n_B, Vec3& u_B) {
  double projected = 0.0;
  u_B = lowest_in_plane(n_B, projected);
  if (ends.one_rim) return 1;
  return rim_point(ends, 0, u_B).dot(n_B) < rim_point(ends, 1, u_B).dot(n_B) ? 0 : 1;
}

}  // namespace

double touching_height(const ContactSurface& surface) {
  return kTouchingHeightPerSize * std::max(contact_size(surface), 1e-300);
}

double contact_size(const ContactSurface& surface) {
  if (surface.kind == ContactSurface::Kind::Sphere) return surface.radius;
  double size = 0.0;
  if (is_round(surface)) {
    const RoundEnds ends = round_ends(surface);
    for (std::size_t k = 0; k < 2; ++k) {
      size = std::max(size, std::hypot(ends.radius[k], ends.centre_B[k].norm()));
    }
  }
  for (const Vec3& p : surface.vertices) size = std::max(size, p.norm());
  return size;
}

int lowest_vertex(const ContactSurface& surface, const Vec3& n_B) {
  int lowest = 0;
  for (std::size_t i = 1; i < surface.vertices.size(); ++i) {
    if (surface.vertices[i].dot(n_B) <
        surface.vertices[static_cast<std::size_t>(lowest)].dot(n_B)) {
      lowest = static_cast<int>(i);
    }
  }
  return lowest;
}

SupportPoint support_point(const PlaneContact& contact, const Vec3& r_G_W, const Mat3& R_WB) {
  const Vec3 n_B = R_WB.transpose() * contact.normal_W;
  const ContactSurface& s = contact.surface;
  SupportPoint support;
  switch (s.kind) {
    case ContactSurface::Kind::Sphere:
      support.p_GC_B = -s.radius * n_B;
      break;
    case ContactSurface::Kind::Polyhedron:
      support.p_GC_B = s.vertices[static_cast<std::size_t>(lowest_vertex(s, n_B))];
      break;
    default: {
      const RoundEnds ends = round_ends(s);
      Vec3 u = Vec3::UnitX();
      support.p_GC_B = rim_point(ends, lower_end(ends, n_B, u), u);
      break;
    }
  }
  support.height = (r_G_W + R_WB * support.p_GC_B - contact.point_W).dot(contact.normal_W);
  return support;
}

Vec3 support_rate_B(const PlaneContact& contact, const Vec3& n_B, const Vec3& omega_B) {
  const Vec3 n_rate_B = n_B.cross(omega_B);
  const ContactSurface& s = contact.surface;
  switch (s.kind) {
    case ContactSurface::Kind::Sphere:
      return -s.radius * n_rate_B;
    case ContactSurface::Kind::Polyhedron:
      return Vec3::Zero();  // a vertex: fixed in the body
    default: {
      const RoundEnds ends = round_ends(s);
      Vec3 u = Vec3::UnitX();
      const double r = ends.radius[static_cast<std::size_t>(lower_end(ends, n_B, u))];
      double projected = 0.0;
      lowest_in_plane(n_B, projected);
      if (projected == 0.0 || r == 0.0) return Vec3::Zero();
      // u = -P n / |P n| with P the projection on x-y: u' = -(1 - u u^T) P n' / |P n|.
      const Vec3 projected_rate(n_rate_B.x(), n_rate_B.y(), 0.0);
      const Vec3 u_rate = -(projected_rate - u * u.dot(projected_rate)) / projected;
      return r * u_rate;
    }
  }
}

}  // namespace tumble
