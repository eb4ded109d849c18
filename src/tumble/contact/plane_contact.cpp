#include "tumble/contact/plane_contact.hpp"

#include <algorithm>
#include <cmath>

#include "tumble/contact/contact_pair.hpp"

namespace tumble {

Vec3 lowest_in_plane(const Vec3& n_B, double& projected_length) {
  const Vec3 projected(n_B.x(), n_B.y(), 0.0);
  projected_length = projected.norm();
  if (projected_length == 0.0) return Vec3::UnitX();
  return -projected / projected_length;
}

double touching_height(const ContactSurface& surface) {
  return kTouchingHeightPerSize * std::max(contact_size(surface), 1e-300);
}

double contact_size(const ContactSurface& surface) {
  return contact_pair(surface.kind).size(surface);
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
  SupportPoint support;
  support.p_GC_B = contact_pair(contact.surface.kind).lowest_point_B(contact.surface, n_B);
  support.height = (r_G_W + R_WB * support.p_GC_B - contact.point_W).dot(contact.normal_W);
  return support;
}

Vec3 support_rate_B(const PlaneContact& contact, const Vec3& n_B, const Vec3& omega_B) {
  return contact_pair(contact.surface.kind).lowest_point_rate_B(contact.surface, n_B, omega_B);
}

}  // namespace tumble
