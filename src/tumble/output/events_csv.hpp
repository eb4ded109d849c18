#pragma once
// The run's events CSV: every contact event (mode change, impact), every jump at a breakpoint
// (impulse, lock, motor start) and every occurrence of the scenario's `events:`, in time order (at
// one instant: jumps, then contact events, then the scenario's events), at full precision (17
// significant digits, as the trajectory), with each jump's kinetic energy before and after and
// each joint's reaction impulse.
//   t, source (the contact's name, "jump", or "event"; texts are quoted), what (as the summary
//   says it; an event's name, with " (stops the run)" where it did),
//   KE_before, KE_after (J, the whole system's; jumps and contact events: a change of modes,
//   which gives no impulse, has the energy at it in both), then per joint J: J.Fx J.Fy J.Fz (N s)
//   J.Mx J.My J.Mz (N m s, about the joint point): the impulse its first body exerts on its
//   second (jumps only), then an impact's approach_speed and rebound_speed (m/s, the landing
//   point's speed into the plane before it and away from it after) and Px Py Pz (N s, world: the
//   impulse the plane gave the body; 0 for a change of modes), and every contact event's
//   normal_speed and slip_speed (m/s: the contact point's velocity relative to the plane in the
//   state the event leaves, along the normal, away > 0, and the size of its part along the
//   plane), and its point_x point_y point_z (m) and normal_x normal_y normal_z (world: where it
//   touches, or apart its lowest point; the plane's normal, or a pair's from its second body
//   towards its first); empty cells where a row has none.
// Written through an AtomicFile: it appears only when complete.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "tumble/dynamics/hybrid_state.hpp"

namespace tumble {

void write_events_csv(const std::filesystem::path& path, std::span<const std::string> contacts,
                      std::span<const std::string> joints,
                      std::span<const ContactEventRecord> contact_events,
                      std::span<const JumpRecord> jumps,
                      std::span<const UserEventRecord> user_events = {});

}  // namespace tumble
