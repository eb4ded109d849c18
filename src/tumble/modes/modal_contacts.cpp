#include "tumble/modes/modal_contacts.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "tumble/contact/contact_pair.hpp"
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
    const std::string why = contact_pair(contact.surface.kind)
                                .resting_point(contact.surface, R.transpose() * contact.normal_W,
                                               lowest, within, height_of, held.point);
    if (!why.empty()) throw NotSteady(fmt::format("contact {}: {}", name, why));
    touching.push_back(held);
  }
  return touching;
}

}  // namespace tumble
