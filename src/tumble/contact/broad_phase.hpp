#pragma once
// The broad phase (docs/design.md, "Broad phase"): of a group's pairs of bodies (`bodies:` naming
// more than two, or `all`), which are near enough that the narrow phase must watch them (their
// gap, its touchdown event and step bound). The others are far: their two bodies' boxes, each
// grown by how far the body can move before the next screening, do not overlap, so they cannot
// touch before it, and no step looks at them.
//
// Sweep and prune: the boxes sorted by their lower ends along the axis their centres spread
// most on, and each box's overlaps found by sweeping forward while the sorted lower ends are
// below its upper end. n log n for the sort, plus the pairs that overlap along that axis.
#include <cstddef>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "tumble/contact/plane_contact.hpp"
#include "tumble/math/function_ref.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

// An axis-aligned box, world axes, m.
struct AlignedBox {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
};

class SweepAndPrune {
 public:
  // Room for this many boxes: a sweep allocates nothing.
  explicit SweepAndPrune(std::size_t boxes);
  // Calls overlap(i, j), i < j, for each pair of the boxes that overlap (touching counts).
  void for_each_overlap(std::span<const AlignedBox> boxes,
                        FunctionRef<void(std::size_t, std::size_t)> overlap);

 private:
  std::vector<std::size_t> order_;
};

// Where a body's touching surfaces lie in its own axes: the box about them (centre and half
// sizes, from the COM) and the radius of the ball about the COM that holds them.
struct BodyBounds {
  Vec3 centre_B = Vec3::Zero();
  Vec3 half_B = Vec3::Zero();
  double radius = 0.0;
};

// Which contacts a step watches: every contact but a group's pairs that the last screening found
// far. Without such pairs, all of them, in order, always.
class PairScreen {
 public:
  explicit PairScreen(std::span<const PlaneContact> contacts);

  // Whether any contact is a group's pair.
  bool active() const { return !bodies_.empty(); }
  // The bodies the group's pairs are between, each once (the screening's boxes, in this order),
  // and where their surfaces lie.
  std::span<const std::size_t> bodies() const { return bodies_; }
  const BodyBounds& bounds(std::size_t object) const { return bounds_[object]; }

  // The group's pairs near from now on: those between bodies whose boxes (world, grown by how far
  // each may move until the next screening) overlap, and those `touching` says are (which are
  // near whatever their boxes). Each pair that was far and is near now goes to `entered`.
  // Returns whether the watched contacts changed.
  bool screen(std::span<const AlignedBox> boxes, FunctionRef<bool(std::size_t)> touching,
              FunctionRef<void(std::size_t)> entered);

  // Every contact watched again, as before the first screening (a run's start: a prepared run
  // serves run after run).
  void watch_all();

  // The contacts watched, in increasing order; and whether one is not.
  std::span<const std::size_t> watched() const { return watched_; }
  bool far(std::size_t contact) const { return state_[contact] == kFar; }

 private:
  static std::uint64_t key(std::size_t a, std::size_t b) {
    return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
  }
  void mark_near(std::size_t contact, FunctionRef<void(std::size_t)> entered);

  std::vector<std::size_t> bodies_;
  std::vector<BodyBounds> bounds_;
  // Per pair of objects (key(i, j), i < j): its contacts, a range of pair_contacts_.
  std::unordered_map<std::uint64_t, std::pair<std::size_t, std::size_t>> pair_range_;
  std::vector<std::size_t> pair_contacts_;
  std::vector<std::size_t> unscreened_;  // every contact not a group's pair, in order
  SweepAndPrune sweep_;
  // The screening's result: the watched list, each contact's state, and the group's pairs near
  // (to make far at the next screening without a pass over all of them). kMarked: found near in
  // the screening under way.
  enum State : char { kNear, kFar, kMarked };
  std::vector<std::size_t> watched_;
  std::vector<State> state_;
  std::vector<std::size_t> near_, was_near_;
  bool screened_once_ = false;
  bool entered_any_ = false;  // this screening's
};

}  // namespace tumble
