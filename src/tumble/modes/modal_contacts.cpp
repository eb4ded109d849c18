#include "tumble/modes/modal_contacts.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "tumble/contact/axes_closest.hpp"
#include "tumble/contact/contact_pair.hpp"
#include "tumble/contact/pair_core.hpp"
#include "tumble/modes/modal_pair.hpp"
#include "tumble/modes/not_steady.hpp"

namespace tumble {

namespace {

// Where contact c touches at one point, into `held`, its body turned by R_WB (per body) and
// `lowest` its support point; why not where it rests on more (empty if it does not).
std::string point_contact(const Model& model, std::size_t c, const std::vector<Mat3>& R_WB,
                          const SupportPoint& lowest, ModalContact& held) {
  const PlaneContact& contact = model.contacts[c];
  const Mat3& R = R_WB[contact.body];
  // The height over the plane of a point of the body (body axes, from the COM).
  const auto height_of = [&](const Vec3& p_B) {
    return lowest.height + (p_B - lowest.p_GC_B).dot(R.transpose() * contact.normal_W);
  };
  held.contact = c;
  return contact_pair(contact.surface.kind)
      .resting_point(contact.surface, R.transpose() * contact.normal_W, lowest,
                     touching_height(contact.surface), height_of, held.point);
}

// Contact c between two bodies held at the point where they touch, with the bodies at r_G_W,
// R_WB (per body): its normal there.
ModalContact pair_contact(const Model& model, std::size_t c, const std::vector<Vec3>& r_G_W,
                          const std::vector<Mat3>& R_WB) {
  const PlaneContact& contact = model.contacts[c];
  BodyState on_body, on_other;  // their poses (the normal does not depend on the speeds)
  on_body.r_G = r_G_W[contact.body];
  on_body.R_WB = R_WB[contact.body];
  on_other.r_G = r_G_W[contact.other_body];
  on_other.R_WB = R_WB[contact.other_body];
  ModalContact held;
  held.contact = c;
  held.pair = true;
  held.normal_W = modal_pair_point<double>(contact, on_body, on_other).n_W;
  return held;
}

}  // namespace

std::vector<ModalContact> touching_contacts(const Model& model, const std::vector<Vec3>& r_G_W,
                                            const std::vector<Mat3>& R_WB) {
  std::vector<ModalContact> touching;
  for (std::size_t c = 0; c < model.contacts.size(); ++c) {
    const PlaneContact& contact = model.contacts[c];
    if (contact.touches_a_body()) {
      // Two bodies: apart, no force; touching, their points at the contact held together. The
      // sphere's centre from the other body's core (pair_core.hpp), or two capsules' axes from
      // each other (axes_closest.hpp), less the radii.
      const std::size_t a = contact.body, b = contact.other_body;
      double distance = 0.0;
      bool parallel_touch = false;
      bool circle_touch = false, on_seam = false;
      if (contact.surface.kind == ContactSurface::Kind::Capsule) {
        // Their poses (the line's distance does not depend on the speeds).
        const CapsulesLineOf<double> line =
            capsules_line<double>(contact.surface, BodyState{r_G_W[a], R_WB[a]},
                                  contact.other_surface, BodyState{r_G_W[b], R_WB[b]});
        distance = line.distance;
        // Parallel: the first's point does not slide, though it is inside its segment.
        parallel_touch =
            !line.closest.s_slides && std::abs(line.closest.s) < contact.surface.half_length;
      } else {
        const Vec3 centre_W = r_G_W[a] + R_WB[a] * contact.surface.centre_B;
        const CoreClosest closest = core_closest<double>(
            contact.other_surface, Vec3(R_WB[b].transpose() * (centre_W - r_G_W[b])));
        distance = closest.distance;
        circle_touch = closest.on_circle_axis;
        on_seam = closest.on_feature_seam;
      }
      const double gap = distance - contact.surface.radius - core_radius(contact.other_surface);
      if (gap > kTouchingHeightPerSize * pair_size(contact)) continue;
      const bool capsules = contact.surface.kind == ContactSurface::Kind::Capsule;
      if (capsules && parallel_touch) {
        throw NotSteady(fmt::format(
            "contact {}: its two capsules lie along each other (their axes within {:g} rad of "
            "parallel), touching along a line, where a small tilt moves the push to one end: no "
            "linearisation; cross them, or remove the contact",
            contact.name, kParallelSine));
      }
      if (circle_touch) {
        throw NotSteady(fmt::format(
            "contact {}: the sphere's centre is on the axis of the circle it touches (a ring's, a "
            "torus's, a rim or a bore), touching all round it, where a small shift moves the push "
            "to one side: no linearisation; move it off the axis, or remove the contact",
            contact.name));
      }
      if (on_seam) {
        throw NotSteady(fmt::format(
            "contact {}: the sphere's centre is over a seam of the surface it touches, where its "
            "nearest point passes from one feature to the next (a face to an edge, a side to a "
            "rim, a side to a cap or an apex): the push turns as it moves to one side and not to "
            "the other, so the motion has no linearisation; move it off the seam, or remove the "
            "contact",
            contact.name));
      }
      ModalContact held = pair_contact(model, c, r_G_W, R_WB);
      held.rolls = contact.friction > 0.0;
      touching.push_back(held);
      continue;
    }
    const SupportPoint lowest = support_point(contact, r_G_W[contact.body], R_WB[contact.body]);
    if (lowest.height > touching_height(contact.surface)) {
      continue;  // apart: no force, and none from a small change
    }
    ModalContact held;
    const std::string why = point_contact(model, c, R_WB, lowest, held);
    if (!why.empty()) throw NotSteady(fmt::format("contact {}: {}", contact.name, why));
    held.normal_W = contact.normal_W;
    held.rolls = contact.friction > 0.0;
    touching.push_back(held);
  }
  return touching;
}

std::vector<ModalContact> held_contacts(const Model& model, std::span<const ContactHold> holds,
                                        const std::vector<Vec3>& r_G_W,
                                        const std::vector<Mat3>& R_WB) {
  std::vector<ModalContact> held;
  for (std::size_t c = 0; c < model.contacts.size(); ++c) {
    const ContactHold& hold = holds[c];
    if (hold.kind == ContactHold::Kind::Apart) continue;
    const PlaneContact& contact = model.contacts[c];
    if (hold.kind == ContactHold::Kind::Points) {
      for (int k = 0; k < hold.point_count; ++k) {
        const ContactHold::BodyPoint& body_point = hold.points[static_cast<std::size_t>(k)];
        ModalContact point;
        point.contact = c;
        point.normal_W = contact.normal_W;
        point.point = ContactPoint{ContactPoint::Kind::Material, body_point.p_B, 0.0};
        point.rolls = body_point.kind == ContactHold::Kind::Point;
        if (!point.rolls) {
          point.sliding.kind = ContactHold::Kind::Normal;
          point.sliding.friction = body_point.friction;
          point.sliding.follows_slip = body_point.follows_slip;
          point.sliding.slide_W = body_point.slide_W;
        }
        held.push_back(point);
      }
      continue;
    }
    if (contact.touches_a_body()) {  // any pair (ContactSystem::calc_holds)
      ModalContact point = pair_contact(model, c, r_G_W, R_WB);
      point.rolls = hold.kind == ContactHold::Kind::Point;
      if (!point.rolls) point.sliding = hold;
      held.push_back(point);
      continue;
    }
    const SupportPoint lowest = support_point(contact, r_G_W[contact.body], R_WB[contact.body]);
    ModalContact point;
    point.normal_W = contact.normal_W;
    if (!point_contact(model, c, R_WB, lowest, point).empty()) {
      // The run holds it at one point where another of its points is within the touching
      // height too (a cylinder on one rim, its other rim just above the plane): the support
      // point, as a point of the body. A Jacobian without that point's motion over the body
      // costs Newton a little, not the answer.
      point.point = ContactPoint{ContactPoint::Kind::Material, lowest.p_GC_B, 0.0};
    }
    point.rolls = hold.kind == ContactHold::Kind::Point;
    if (!point.rolls) point.sliding = hold;
    held.push_back(point);
  }
  return held;
}

}  // namespace tumble
