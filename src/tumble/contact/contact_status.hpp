#pragma once
// What a plane contact is doing during a run: its mode (apart, sliding, rolling or sticking), the
// part of the body that touches, where it sticks, how its slip has gone, and the scales, fixed at
// the run's start, that say what counts as touching, as no slip or as a settling landing. It is
// part of a run's state (HybridState): copying it with y checkpoints the contact exactly.
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "tumble/contact/contact_feature.hpp"
#include "tumble/contact/round_contact.hpp"

namespace tumble {

enum class ContactMode { Apart = 0, Sliding = 1, Rolling = 2 };  // rolling: or sticking

struct ContactStatus {
  ContactMode mode = ContactMode::Apart;
  ContactFeature feature;  // a polyhedron's touching vertex, edge or face (empty: apart)
  RoundPart round_part = RoundPart::None;  // a round body's touching part
  // Where a round body's rim points were at the last step (body axes, unit): refreshed after
  // each step near flat (the round pair's follow_direction), it fixes them where a face is flat
  // (round_contact.hpp's rim_direction).
  Vec3 rim_direction_B = Vec3::UnitX();
  // Slip direction (slip_W's) while the slip speed is ~0.
  Vec3 slide_direction_W = Vec3::UnitX();
  // A slip that starts from rolling turns from slide_direction_W at this rate (1/s, normal to
  // it) from slide_start_t on, until it is above slip_zero (slip_onset.cpp).
  Vec3 slide_turn_W = Vec3::Zero();
  double slide_start_t = 0.0;
  bool slip_grown = false;      // the slip has been above slip_zero at the end of a step
  bool slip_left_near = false;  // ... and above kSlipStoppedNear slip_zero
  double slip_last_step = 0.0;  // m/s, sliding: the slip at the end of the last step
  // A two-point part (an edge, a round body's side) slides with friction at each end against
  // that end's own slip. Per end (0: the first point, A; 1: the second): the direction its slip
  // had at the end of the last step once it has grown past slip_zero, or, where it starts from
  // none while the other end slides, the way it is pushed; zero while it has not grown and the
  // whole part's slide direction maps onto it (ContactSystem::end_slide_direction).
  std::array<Vec3, 2> end_slide_direction_W = {Vec3::Zero(), Vec3::Zero()};
  std::array<bool, 2> end_slip_grown = {false, false};
  // Sliding on a two-point part: the end that sticks while the other slides (the part pivots
  // about it: a cone on its side turning about its apex), or -1 where both slide.
  int pinned_end = -1;
  // Neither end's slip followed on its own, and neither pinned.
  void clear_end_slips() {
    end_slide_direction_W = {Vec3::Zero(), Vec3::Zero()};
    end_slip_grown = {false, false};
    pinned_end = -1;
  }
  // A grown slip left below slip_zero by the last step stops at slip_stop_by (s).
  bool slip_stop_armed = false;
  double slip_stop_by = 0.0;
  // Events in a row that the same instant undoes, from cascade_first_t (settled landings that
  // nothing held; slip stops that slid on at once); the last one's t.
  int cascade_events = 0;
  double cascade_first_t = 0.0, cascade_last_t = 0.0;
  double slip_zero = 0.0;        // m/s: slower slip counts as none
  double slip_floor = 0.0;       // m/s: a grown slip is followed down to this
  double settle_speed = 0.0;     // m/s: slower touchdowns settle instead of bouncing
  double touching_height = 0.0;  // m: nearer the plane counts as touching
  double landing_height = 0.0;   // m: vertices this near the plane land with a touchdown
  double time_scale = 0.0;       // s: the contact's size over its speed scale
  // Where a polyhedron (a cone on its apex, a round body on a face) sticks (mode rolling): the
  // points its rows hold (a vertex or face centroid, or an edge's ends) and the body's
  // orientation, so that projection keeps it exactly there rather than letting round-off walk it
  // away.
  std::array<Vec3, 2> anchor_W = {Vec3::Zero(), Vec3::Zero()};
  Mat3 anchor_R_WB = Mat3::Identity();
};

// What an impact did, at full precision (the event's text rounds it).
struct ContactImpactNumbers {
  double kinetic_energy_before = 0.0, kinetic_energy_after = 0.0;  // J, the whole system's
  // The landing point's speed into the plane before (> 0) and away from it after (>= 0), m/s.
  double approach_speed = 0.0, rebound_speed = 0.0;
  Vec3 impulse_W = Vec3::Zero();  // N s: what the plane gave the body, world
};

// A contact's mode change or impact, for the summary and the events CSV.
struct ContactEventRecord {
  double t = 0.0;
  std::size_t contact = 0;
  std::string what;  // "touchdown, rolls", "impact: normal speed 4.4 -> 3.5 m/s", "slides", ...
  std::optional<ContactImpactNumbers> impact;  // an impact's (and a settling touchdown's)
  // The whole system's kinetic energy before and after it, J: an impact's, or for a change of
  // modes (no impulse) the energy at it, twice. Then the contact point's velocity relative to
  // the plane in the state the event leaves, m/s: along the normal (away from the plane > 0) and
  // the size of its part along the plane (the slip; 0 where it rolls or sticks).
  double kinetic_energy_before = 0.0, kinetic_energy_after = 0.0;
  double normal_speed = 0.0, slip_speed = 0.0;
  // Where, in that state: the contact's reference point (the point of contact, a feature's
  // centroid; apart, the lowest point) and its normal (the plane's; between two bodies, from the
  // second body towards the first), world.
  Vec3 point_W = Vec3::Zero();
  Vec3 normal_W = Vec3::UnitZ();
};

// The contact subsystem's part of a run's state: every contact's status and what has happened.
struct ContactState {
  std::vector<ContactStatus> contacts;  // one per Model::contacts entry
  // The time of the last event handled, once it is done (a contact's watched height).
  double last_event_t = -std::numeric_limits<double>::infinity();
  std::vector<ContactEventRecord> events;
};

}  // namespace tumble
