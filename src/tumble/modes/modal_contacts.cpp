#include "tumble/modes/modal_contacts.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "tumble/contact/round_contact.hpp"
#include "tumble/modes/not_steady.hpp"

namespace tumble {

std::vector<ModalContact> touching_contacts(const Model& model, const std::vector<Vec3>& r_G_W,
                                            const std::vector<Mat3>& R_WB) {
  std::vector<ModalContact> touching;
  for (std::size_t c = 0; c < model.contacts.size(); ++c) {
    const PlaneContact& contact = model.contacts[c];
    const Mat3& R = R_WB[contact.body];
    const SupportPoint lowest = support_point(contact, r_G_W[contact.body], R);
    const double within = touching_height(contact.surface);
    if (lowest.height > within) continue;  // apart: no force, and none from a small change
    const std::string& name = contact.name;
    // The height over the plane of a point of the body (body axes, from the COM).
    const auto height_of = [&](const Vec3& p_B) {
      return lowest.height + (p_B - lowest.p_GC_B).dot(R.transpose() * contact.normal_W);
    };
    ModalContact held;
    held.contact = c;
    held.rolls = contact.friction > 0.0;
    const ContactSurface& surface = contact.surface;
    if (surface.kind == ContactSurface::Kind::Sphere) {
      held.point.kind = ContactPoint::Kind::Lowest;
      held.point.radius = surface.radius;
    } else if (surface.kind == ContactSurface::Kind::Polyhedron) {
      int count = 0;
      for (const Vec3& vertex : surface.vertices) count += height_of(vertex) <= within ? 1 : 0;
      if (count > 1) {
        throw NotSteady(fmt::format(
            "contact {}: the body rests on an edge or a face ({} vertices on the plane), where a "
            "small tilt moves the plane's force to one side: no linearisation; balance it on one "
            "vertex, or remove the contact",
            name, count));
      }
      held.point.kind = ContactPoint::Kind::Material;
      held.point.p_B = lowest.p_GC_B;
    } else {
      const RoundEnds ends = round_ends(surface);
      const Vec3 n_B = R.transpose() * contact.normal_W;
      double tilt = 0.0;
      const Vec3 u_B = lowest_in_plane(n_B, tilt);
      // A cone on its apex, the base's rim off the plane (a top, upright or leaning): a point of
      // the body, whatever the tilt.
      const bool apex_down =
          ends.radius[0] == 0.0 && !ends.one_rim && height_of(ends.centre_B[0]) <= within;
      if (apex_down && height_of(rim_point(ends, 1, u_B)) > within) {
        held.point.kind = ContactPoint::Kind::Material;
        held.point.p_B = ends.centre_B[0];
        touching.push_back(held);
        continue;
      }
      if (tilt <= 1e-9) {
        throw NotSteady(fmt::format(
            "contact {}: the body lies flat on an end face, where a small tilt moves the plane's "
            "force to its rim: no linearisation",
            name));
      }
      std::vector<int> ends_down;
      for (int k = ends.one_rim ? 1 : 0; k < 2; ++k) {
        if (height_of(rim_point(ends, k, u_B)) <= within) ends_down.push_back(k);
      }
      if (ends_down.size() != 1) {
        throw NotSteady(fmt::format(
            "contact {}: the body rests along a line of its side, where a small tilt moves the "
            "plane's force to one end: no linearisation",
            name));
      }
      const auto k = static_cast<std::size_t>(ends_down.front());
      held.point.p_B = ends.centre_B[k];
      held.point.radius = ends.radius[k];
      held.point.kind =
          held.point.radius > 0.0 ? ContactPoint::Kind::Rim : ContactPoint::Kind::Material;
    }
    touching.push_back(held);
  }
  return touching;
}

}  // namespace tumble
