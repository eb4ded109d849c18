#pragma once
// A run's state besides y: what the right-hand side's modes are (the last load-schedule edge
// reached, each contact's status) and what has happened so far (jumps at breakpoints, contact
// events). With y it is everything a run needs to go on, so a copy of both is a checkpoint.
#include <string>
#include <vector>

#include "tumble/contact/contact_status.hpp"
#include "tumble/dynamics/row_extras.hpp"

namespace tumble {

// A jump of the speeds at a breakpoint, for the summary.
struct JumpRecord {
  double t = 0.0;
  std::string what;  // "impulse hit", "lock knob", "motor wheel starts"
  double kinetic_energy_before = 0.0, kinetic_energy_after = 0.0;
  Vec3 angular_momentum_before_W = Vec3::Zero();  // about the world origin
  Vec3 angular_momentum_after_W = Vec3::Zero();
  std::vector<JointReaction> reaction_impulses;  // N s and N m s, one per Model::joints entry
};

// An occurrence of one of the scenario's `events:` (simulation/user_events.hpp), for the summary
// and events.csv. (The driver's own list has them; they are not part of the hybrid state.)
struct UserEventRecord {
  double t = 0.0;
  std::string name;
  bool stopped = false;  // the run ended here
};

struct HybridState {
  double schedule_time = 0.0;  // the last schedule edge reached: decides which loads act
  ContactState contact;        // each contact's status, and its events (contact/contact_status.hpp)
  std::vector<JumpRecord> jumps;
};

}  // namespace tumble
