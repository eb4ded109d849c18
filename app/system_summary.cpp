#include "system_summary.hpp"

#include <fmt/core.h>

#include <algorithm>

namespace tumble::cli {

bool only_contacts_may_do_work(const Scenario& scenario) {
  if (!scenario.loads.empty() || !scenario.impulses.empty()) return false;
  for (const JointSpec& joint : scenario.joints) {
    if (joint.motor.kind != MotorSpec::Kind::None || std::isfinite(joint.lock_at)) return false;
  }
  for (const SpringSpec& spring : scenario.springs) {
    if (spring.damping > 0.0) return false;
  }
  for (const TorsionalSpringSpec& spring : scenario.torsional_springs) {
    if (spring.damping > 0.0) return false;
  }
  return true;
}

bool energy_changes(const Scenario& scenario) {
  if (!only_contacts_may_do_work(scenario)) return true;
  for (const ContactSpec& contact : scenario.contacts) {
    if (contact.friction > 0.0 || contact.restitution < 1.0) return true;
  }
  return false;
}

bool external_moments_act(const Scenario& scenario) {
  if (scenario.gravity_W.squaredNorm() > 0.0 || !scenario.loads.empty() ||
      !scenario.impulses.empty()) {
    return true;
  }
  // A plane is fixed; two bodies' contact is between bodies of the system (its impulses are
  // equal and opposite, on one line through the contact point).
  for (const ContactSpec& contact : scenario.contacts) {
    if (contact.other_body.empty()) return true;
  }
  const auto grounded = [](const std::string& a, const std::string& b) {
    return a == kGroundName || b == kGroundName;
  };
  for (const JointSpec& j : scenario.joints) {
    if (grounded(j.body_a, j.body_b)) return true;
  }
  for (const SpringSpec& s : scenario.springs) {
    if (grounded(s.body_a, s.body_b)) return true;
  }
  for (const TorsionalSpringSpec& s : scenario.torsional_springs) {
    if (grounded(s.body_a, s.body_b)) return true;
  }
  return false;
}

namespace {

// A jump at a breakpoint: its KE and L before and after, and each joint's reaction impulse.
void print_jump(const Scenario& scenario, const JumpRecord& jump, int digits) {
  fmt::print("  t = {:<14.12g} {}: KE {:.{}g} -> {:.{}g} J", jump.t, jump.what,
             jump.kinetic_energy_before, digits, jump.kinetic_energy_after, digits);
  const Vec3& L0 = jump.angular_momentum_before_W;
  const Vec3& L1 = jump.angular_momentum_after_W;
  fmt::print("; L (origin) [{:.{}g}, {:.{}g}, {:.{}g}] -> [{:.{}g}, {:.{}g}, {:.{}g}] kg m^2/s\n",
             L0.x(), digits, L0.y(), digits, L0.z(), digits, L1.x(), digits, L1.y(), digits, L1.z(),
             digits);
  for (std::size_t j = 0; j < jump.reaction_impulses.size(); ++j) {
    const Vec3& F = jump.reaction_impulses[j].F_W;
    const Vec3& M = jump.reaction_impulses[j].M_J_W;
    fmt::print(
        "                 reaction impulse at {}: [{:.{}g}, {:.{}g}, {:.{}g}] N s, "
        "[{:.{}g}, {:.{}g}, {:.{}g}] N m s\n",
        scenario.joints[j].name, F.x(), digits, F.y(), digits, F.z(), digits, M.x(), digits, M.y(),
        digits, M.z(), digits);
  }
}

// The run's contact events, jumps and the scenario's own events, as one list in time order (at
// one instant: the contact events, then the jumps, then the scenario's events, as the run met
// them). The first contact events and scenario events are shown in full (a bouncing ball has
// dozens); the rest are counted.
void print_events_in_time_order(const Scenario& scenario, const SimulationResult& result,
                                int digits) {
  constexpr std::size_t kContactEventsShown = 24;
  constexpr std::size_t kUserEventsShown = 24;
  const std::vector<ContactEventRecord>& contact = result.contact_events;
  const std::vector<JumpRecord>& jumps = result.jumps;
  const std::vector<UserEventRecord>& occurred = result.user_events;
  struct Line {
    double t;
    int source;  // 0 contact event, 1 jump, 2 the scenario's event
    std::size_t index;
  };
  std::vector<Line> lines;
  for (std::size_t i = 0; i < contact.size() && i < kContactEventsShown; ++i) {
    lines.push_back({contact[i].t, 0, i});
  }
  for (std::size_t i = 0; i < jumps.size(); ++i) lines.push_back({jumps[i].t, 1, i});
  for (std::size_t i = 0; i < occurred.size() && i < kUserEventsShown; ++i) {
    lines.push_back({occurred[i].t, 2, i});
  }
  std::stable_sort(lines.begin(), lines.end(), [](const Line& a, const Line& b) {
    return a.t < b.t || (a.t == b.t && a.source < b.source);
  });
  for (const Line& line : lines) {
    if (line.source == 0) {
      const ContactEventRecord& event = contact[line.index];
      fmt::print("  t = {:<14.12g} {}: {}\n", event.t, scenario.contacts[event.contact].name,
                 event.what);
    } else if (line.source == 1) {
      print_jump(scenario, jumps[line.index], digits);
    } else {
      const UserEventRecord& event = occurred[line.index];
      fmt::print("  t = {:<14.12g} event {}{}\n", event.t, event.name,
                 event.stopped ? ": the run stops here" : "");
    }
  }
  if (contact.size() > kContactEventsShown) {
    fmt::print(
        "  ...            {} more contact events (the events CSV has them all); the last at "
        "t = {:.12g}: {}: {}\n",
        contact.size() - kContactEventsShown, contact.back().t,
        scenario.contacts[contact.back().contact].name, contact.back().what);
  }
  if (occurred.size() > kUserEventsShown) {
    fmt::print("  ...            {} more events (the events CSV has them all)\n",
               occurred.size() - kUserEventsShown);
  }
}

}  // namespace

void print_system_summary(const Scenario& scenario, const PreparedSimulation& simulation,
                          const SimulationResult& result, int digits) {
  if (simulation.formulation->keeps_work_ledger()) {
    const std::vector<std::string> names = simulation.formulation->element_names();
    const ConservationReport& c = result.conservation;
    fmt::print(
        "  work-energy    max |KE - KE0 - W| {:.3e} J ({:.1e} of the largest KE; W: the "
        "work of gravity and of every element)\n",
        c.max_work_energy_residual,
        c.max_kinetic_energy > 0.0 ? c.max_work_energy_residual / c.max_kinetic_energy : 0.0);
    const std::vector<ElementWork>& works = result.last_extras.elements;
    for (std::size_t i = 0; i < names.size() && i < works.size(); ++i) {
      fmt::print("  work           {}: {:.{}g} J\n", names[i], works[i].work, digits);
    }
  }
  print_events_in_time_order(scenario, result, digits);
}

void print_scenario_events(const Scenario& scenario, const SimulationResult& result) {
  // The scenario's events that did not happen (those that did are in the summary's list).
  const std::vector<UserEventRecord>& occurred = result.user_events;
  for (const UserEventSpec& event : scenario.events) {
    const bool happened =
        std::any_of(occurred.begin(), occurred.end(),
                    [&](const UserEventRecord& r) { return r.name == event.name; });
    if (!happened) {
      fmt::print("  event {}: did not happen by t = {:.12g} s ({})\n", event.name,
                 result.report.t_reached, event.when);
    }
  }
}

}  // namespace tumble::cli
