#include "tumble/contact/plane_contact.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

// A disk or a ring lying flat touches along all of its rim: a face contact that these surface
// models do not resolve (a cone's base does: cone_contact.hpp; see rim_rise).
Vec3 lowest_in_plane(const Vec3& n_B, double& projected_length) {
  const Vec3 projected(n_B.x(), n_B.y(), 0.0);
  projected_length = projected.norm();
  if (projected_length == 0.0) return Vec3::UnitX();
  return -projected / projected_length;
}

namespace {

// A cylinder whose axis is within this angle (rad) of the plane lies on its side: it touches
// along a line. Rolling keeps the axis parallel to the plane to round-off (~1e-16), far inside.
constexpr double kLineContactTilt = 1e-9;

// Whether a cone's apex is lower along -n_B than every point of its base's rim.
bool apex_is_lowest(const ContactSurface& cone, const Vec3& n_B) {
  double projected = 0.0;
  const Vec3 rim = cone.rim_centre_B + cone.radius * lowest_in_plane(n_B, projected);
  return cone.vertices[0].dot(n_B) < rim.dot(n_B);
}

}  // namespace

double rim_rise(const ContactSurface& surface, const Vec3& n_B) {
  double projected = 0.0;
  lowest_in_plane(n_B, projected);
  return 2.0 * surface.radius * projected;
}

bool lies_flat_on_faces(const ContactSurface& surface) {
  return surface.kind == ContactSurface::Kind::Circle ||
         surface.kind == ContactSurface::Kind::Cylinder;
}

double contact_size(const ContactSurface& surface) {
  double size = 0.0;
  switch (surface.kind) {
    case ContactSurface::Kind::Polyhedron:
      break;
    case ContactSurface::Kind::Cone:
      size = std::hypot(surface.radius, surface.rim_centre_B.norm());
      break;
    default:
      return surface.radius;
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
    case ContactSurface::Kind::Circle:
    case ContactSurface::Kind::Cylinder: {
      double projected = 0.0;
      support.p_GC_B = s.radius * lowest_in_plane(n_B, projected);
      if (s.kind == ContactSurface::Kind::Cylinder && std::abs(n_B.z()) > kLineContactTilt) {
        // The end rim nearer the plane: z against the normal.
        support.p_GC_B.z() = n_B.z() > 0.0 ? -s.half_length : s.half_length;
      }
      break;
    }
    case ContactSurface::Kind::Polyhedron:
      support.p_GC_B = s.vertices[static_cast<std::size_t>(lowest_vertex(s, n_B))];
      break;
    case ContactSurface::Kind::Cone: {
      double projected = 0.0;
      support.p_GC_B = apex_is_lowest(s, n_B)
                           ? s.vertices[0]
                           : Vec3(s.rim_centre_B + s.radius * lowest_in_plane(n_B, projected));
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
    case ContactSurface::Kind::Cone:
      if (apex_is_lowest(s, n_B)) return Vec3::Zero();
      [[fallthrough]];
    case ContactSurface::Kind::Circle:
    case ContactSurface::Kind::Cylinder: {
      double projected = 0.0;
      const Vec3 u = lowest_in_plane(n_B, projected);
      if (projected == 0.0) return Vec3::Zero();
      // u = -P n / |P n| with P the projection on x-y: u' = -(1 - u u^T) P n' / |P n|.
      const Vec3 projected_rate(n_rate_B.x(), n_rate_B.y(), 0.0);
      const Vec3 u_rate = -(projected_rate - u * u.dot(projected_rate)) / projected;
      return s.radius * u_rate;
    }
    case ContactSurface::Kind::Polyhedron:
      return Vec3::Zero();  // a vertex: fixed in the body
  }
  return Vec3::Zero();
}

}  // namespace tumble
