#pragma once
// A run's state besides y: what the right-hand side's modes are (the last load-schedule edge
// reached, each contact's status) and what has happened so far (jumps at breakpoints, contact
// events). With y it is everything a run needs to go on, so a copy of both is a checkpoint.
#include <limits>
#include <string>
#include <vector>

#include "tumble/contact/contact_status.hpp"
#include "tumble/dynamics/row_extras.hpp"

namespace tumble {

// A contact's mode change or impact, for the summary.
struct ContactEventRecord {
  double t = 0.0;
  std::size_t contact = 0;
  std::string what;  // "touchdown, rolls", "impact: normal speed 4.4 -> 3.5 m/s", "slides", ...
};

// A jump of the speeds at a breakpoint, for the summary.
struct JumpRecord {
  double t = 0.0;
  std::string what;  // "impulse hit", "lock knob", "motor wheel starts"
  double kinetic_energy_before = 0.0, kinetic_energy_after = 0.0;
  Vec3 angular_momentum_before_W = Vec3::Zero();  // about the world origin
  Vec3 angular_momentum_after_W = Vec3::Zero();
  std::vector<JointReaction> reaction_impulses;  // N s and N m s, one per Model::joints entry
};

struct HybridState {
  double schedule_time = 0.0;           // the last schedule edge reached: decides which loads act
  std::vector<ContactStatus> contacts;  // one per Model::contacts entry
  // The time of the last event handled, once on_event is done (a contact's watched height).
  double last_event_t = -std::numeric_limits<double>::infinity();
  std::vector<JumpRecord> jumps;
  std::vector<ContactEventRecord> contact_events;
};

}  // namespace tumble
