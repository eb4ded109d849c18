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
      !scenario.impulses.empty() || !scenario.contacts.empty()) {
    return true;
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

void print_system_summary(const Scenario& scenario, const PreparedSimulation& simulation,
                          const SimulationResult& result) {
  const std::vector<std::string> names = simulation.formulation->element_names();
  if (!simulation.formulation->keeps_work_ledger()) return;
  const ConservationReport& c = result.conservation;
  fmt::print(
      "  work-energy    max |KE - KE0 - W| {:.3e} J ({:.1e} of the largest KE; W: the "
      "work of gravity and of every element)\n",
      c.max_work_energy_residual,
      c.max_kinetic_energy > 0.0 ? c.max_work_energy_residual / c.max_kinetic_energy : 0.0);
  const std::vector<ElementWork>& works = result.last_extras.elements;
  for (std::size_t i = 0; i < names.size() && i < works.size(); ++i) {
    fmt::print("  work           {}: {:.6g} J\n", names[i], works[i].work);
  }
  // Contact events in time order: the first ones in full (a bouncing ball has dozens).
  constexpr std::size_t kContactEventsShown = 24;
  const std::vector<ContactEventRecord>& events = result.contact_events;
  for (std::size_t i = 0; i < events.size() && i < kContactEventsShown; ++i) {
    fmt::print("  t = {:<14.12g} {}: {}\n", events[i].t, scenario.contacts[events[i].contact].name,
               events[i].what);
  }
  if (events.size() > kContactEventsShown) {
    fmt::print(
        "  ...            {} more contact events (the events CSV has them all); the last at "
        "t = {:.12g}: {}: {}\n",
        events.size() - kContactEventsShown, events.back().t,
        scenario.contacts[events.back().contact].name, events.back().what);
  }
  for (const JumpRecord& jump : result.jumps) {
    fmt::print("  t = {:<14.12g} {}: KE {:.6g} -> {:.6g} J", jump.t, jump.what,
               jump.kinetic_energy_before, jump.kinetic_energy_after);
    const Vec3& L0 = jump.angular_momentum_before_W;
    const Vec3& L1 = jump.angular_momentum_after_W;
    fmt::print("; L (origin) [{:.6g}, {:.6g}, {:.6g}] -> [{:.6g}, {:.6g}, {:.6g}] kg m^2/s\n",
               L0.x(), L0.y(), L0.z(), L1.x(), L1.y(), L1.z());
    for (std::size_t j = 0; j < jump.reaction_impulses.size(); ++j) {
      const Vec3& F = jump.reaction_impulses[j].F_W;
      const Vec3& M = jump.reaction_impulses[j].M_J_W;
      fmt::print(
          "                 reaction impulse at {}: [{:.6g}, {:.6g}, {:.6g}] N s, "
          "[{:.6g}, {:.6g}, {:.6g}] N m s\n",
          scenario.joints[j].name, F.x(), F.y(), F.z(), M.x(), M.y(), M.z());
    }
  }
}

void print_scenario_events(const Scenario& scenario, const SimulationResult& result) {
  // The scenario's events: each occurrence (a condition that turns often is summarised).
  constexpr std::size_t kUserEventsShown = 24;
  const std::vector<UserEventRecord>& occurred = result.user_events;
  for (std::size_t i = 0; i < occurred.size() && i < kUserEventsShown; ++i) {
    fmt::print("  t = {:<14.12g} event {}{}\n", occurred[i].t, occurred[i].name,
               occurred[i].stopped ? ": the run stops here" : "");
  }
  if (occurred.size() > kUserEventsShown) {
    fmt::print("  ...            {} more events (the events CSV has them all)\n",
               occurred.size() - kUserEventsShown);
  }
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
