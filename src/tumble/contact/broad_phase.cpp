#include "tumble/contact/broad_phase.hpp"

#include <algorithm>
#include <numeric>

#include "tumble/contact/contact_pair.hpp"

namespace tumble {

SweepAndPrune::SweepAndPrune(std::size_t boxes) {
  order_.reserve(boxes);
}

void SweepAndPrune::for_each_overlap(std::span<const AlignedBox> boxes,
                                     FunctionRef<void(std::size_t, std::size_t)> overlap) {
  if (boxes.size() < 2) return;
  // The axis the centres spread most on: along it the fewest boxes overlap.
  Vec3 mean = Vec3::Zero(), square = Vec3::Zero();
  for (const AlignedBox& box : boxes) {
    const Vec3 centre = 0.5 * (box.lo + box.hi);
    mean += centre;
    square += centre.cwiseProduct(centre);
  }
  const double n = static_cast<double>(boxes.size());
  Eigen::Index axis = 0;
  (square / n - (mean / n).cwiseProduct(mean / n)).maxCoeff(&axis);
  order_.resize(boxes.size());
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
    return boxes[a].lo(axis) < boxes[b].lo(axis) ||
           (boxes[a].lo(axis) == boxes[b].lo(axis) && a < b);
  });
  for (std::size_t k = 0; k < order_.size(); ++k) {
    const AlignedBox& a = boxes[order_[k]];
    for (std::size_t m = k + 1; m < order_.size() && boxes[order_[m]].lo(axis) <= a.hi(axis); ++m) {
      const AlignedBox& b = boxes[order_[m]];
      if ((a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all()) {
        overlap(std::min(order_[k], order_[m]), std::max(order_[k], order_[m]));
      }
    }
  }
}

namespace {

// The box about a surface, body axes from the COM: its support points along each axis both ways.
AlignedBox surface_box_B(const ContactSurface& surface) {
  const ContactPair& pair = contact_pair(surface.kind);
  AlignedBox box;
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = Vec3::Unit(k);
    box.lo(k) = pair.lowest_point_B(surface, e)(k);
    box.hi(k) = pair.lowest_point_B(surface, -e)(k);
  }
  return box;
}

}  // namespace

PairScreen::PairScreen(std::span<const PlaneContact> contacts) : sweep_(0) {
  state_.assign(contacts.size(), kNear);
  watched_.reserve(contacts.size());
  std::vector<int> object_of_body;
  std::vector<AlignedBox> boxes_B;
  const auto object = [&](std::size_t body, const ContactSurface& surface) {
    if (body >= object_of_body.size()) object_of_body.resize(body + 1, -1);
    if (object_of_body[body] < 0) {
      object_of_body[body] = static_cast<int>(bodies_.size());
      bodies_.push_back(body);
      boxes_B.push_back(surface_box_B(surface));
    } else {
      // A composite's several parts: the box about them all.
      const AlignedBox part = surface_box_B(surface);
      AlignedBox& box = boxes_B[static_cast<std::size_t>(object_of_body[body])];
      box.lo = box.lo.cwiseMin(part.lo);
      box.hi = box.hi.cwiseMax(part.hi);
    }
    return static_cast<std::size_t>(object_of_body[body]);
  };
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const PlaneContact& contact = contacts[c];
    if (!contact.screened) {
      unscreened_.push_back(c);
      continue;
    }
    const std::size_t a = object(contact.body, contact.surface);
    const std::size_t b = object(contact.other_body, contact.other_surface);
    keyed.emplace_back(key(std::min(a, b), std::max(a, b)), c);
  }
  for (const AlignedBox& box : boxes_B) {
    const Vec3 centre = 0.5 * (box.lo + box.hi), half = 0.5 * (box.hi - box.lo);
    bounds_.push_back({centre, half, centre.norm() + half.norm()});
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t i = 0; i < keyed.size(); ++i) {
    auto& range = pair_range_[keyed[i].first];
    if (range.second == 0) range.first = i;
    ++range.second;
    pair_contacts_.push_back(keyed[i].second);
  }
  sweep_ = SweepAndPrune(bodies_.size());
  near_.reserve(pair_contacts_.size());
  was_near_.reserve(pair_contacts_.size());
  watch_all();
}

void PairScreen::watch_all() {
  // Until the first screening, every contact is watched (the start's checks see them all).
  std::fill(state_.begin(), state_.end(), kNear);
  watched_.resize(state_.size());
  std::iota(watched_.begin(), watched_.end(), std::size_t{0});
  near_.clear();
  was_near_.clear();
  screened_once_ = false;
}

void PairScreen::mark_near(std::size_t contact, FunctionRef<void(std::size_t)> entered) {
  if (state_[contact] == kMarked) return;
  if (state_[contact] == kFar) {
    entered(contact);
    entered_any_ = true;
  }
  state_[contact] = kMarked;
  near_.push_back(contact);
}

bool PairScreen::screen(std::span<const AlignedBox> boxes, FunctionRef<bool(std::size_t)> touching,
                        FunctionRef<void(std::size_t)> entered) {
  if (!active()) return false;
  // The pairs near before stay kNear until marked again or, unmarked, made far; at the first
  // screening every pair was near.
  std::swap(near_, was_near_);
  near_.clear();
  entered_any_ = false;
  if (!screened_once_) {
    was_near_.assign(pair_contacts_.begin(), pair_contacts_.end());
    screened_once_ = true;
  }
  for (const std::size_t c : was_near_) {
    if (touching(c)) mark_near(c, entered);
  }
  sweep_.for_each_overlap(boxes, [&](std::size_t a, std::size_t b) {
    const auto at = pair_range_.find(key(a, b));
    if (at == pair_range_.end()) return;  // a pair the group leaves out (two obstacles)
    for (std::size_t i = 0; i < at->second.second; ++i) {
      mark_near(pair_contacts_[at->second.first + i], entered);
    }
  });
  // The pairs near before and not now are far; those marked now are near.
  bool changed = entered_any_;
  for (const std::size_t c : was_near_) {
    if (state_[c] == kNear) {
      state_[c] = kFar;
      changed = true;
    }
  }
  for (const std::size_t c : near_) state_[c] = kNear;
  std::sort(near_.begin(), near_.end());
  watched_.clear();
  std::merge(unscreened_.begin(), unscreened_.end(), near_.begin(), near_.end(),
             std::back_inserter(watched_));
  return changed;
}

}  // namespace tumble
