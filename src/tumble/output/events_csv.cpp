#include "tumble/output/events_csv.hpp"

#include <fmt/format.h>
#include <limits>
#include <optional>

#include "tumble/output/atomic_file.hpp"
#include "tumble/output/csv_text.hpp"

namespace tumble {

void write_events_csv(const std::filesystem::path& path, std::span<const std::string> contacts,
                      std::span<const std::string> joints,
                      std::span<const ContactEventRecord> contact_events,
                      std::span<const JumpRecord> jumps,
                      std::span<const UserEventRecord> user_events) {
  AtomicFile file(path);
  fmt::memory_buffer text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "t,source,what,KE_before,KE_after");
  for (const std::string& joint : joints) {
    for (const char* field : {"Fx", "Fy", "Fz", "Mx", "My", "Mz"}) {
      fmt::format_to(out, ",{}.{}", joint, field);
    }
  }
  // After the joints' columns, so that those keep their places: an impact's own numbers.
  fmt::format_to(out,
                 ",approach_speed,rebound_speed,Px,Py,Pz,normal_speed,slip_speed,point_x,point_y,"
                 "point_z,normal_x,normal_y,normal_z");
  text.push_back('\n');
  // The cells after a row's joint columns: a contact event's numbers (an impact's landing speeds
  // and impulse; a change of modes has no landing and no impulse), or none.
  const auto write_contact_cells = [&](const ContactEventRecord* e) {
    if (e == nullptr) {
      fmt::format_to(out, ",,,,,,,,,,,,,");
      return;
    }
    if (e->impact) {
      const ContactImpactNumbers& impact = *e->impact;
      fmt::format_to(out, ",{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}", impact.approach_speed,
                     impact.rebound_speed, impact.impulse_W.x(), impact.impulse_W.y(),
                     impact.impulse_W.z());
    } else {
      fmt::format_to(out, ",,,0,0,0");
    }
    fmt::format_to(out, ",{:.17g},{:.17g}", e->normal_speed, e->slip_speed);
    for (const Vec3* v : {&e->point_W, &e->normal_W}) {
      fmt::format_to(out, ",{:.17g},{:.17g},{:.17g}", v->x(), v->y(), v->z());
    }
  };
  // In time order; at one instant the jump comes first (the contacts' modes are decided again
  // after it).
  std::size_t next_event = 0;
  const auto write_contact_events_before = [&](double t, bool including) {
    for (; next_event < contact_events.size(); ++next_event) {
      const ContactEventRecord& e = contact_events[next_event];
      if (e.t > t || (e.t == t && !including)) break;
      fmt::format_to(out, "{:.17g},{},{},{:.17g},{:.17g}", e.t, csv_quoted(contacts[e.contact]),
                     csv_quoted(e.what), e.kinetic_energy_before, e.kinetic_energy_after);
      for (std::size_t k = 0; k < 6 * joints.size(); ++k) text.push_back(',');
      write_contact_cells(&e);
      text.push_back('\n');
    }
  };
  // The scenario's events come after the jumps and contact events of their instant.
  std::size_t next_user_event = 0;
  const auto write_user_events_before = [&](double t) {
    for (; next_user_event < user_events.size(); ++next_user_event) {
      const UserEventRecord& e = user_events[next_user_event];
      if (e.t >= t) break;
      fmt::format_to(out, "{:.17g},\"event\",{},,", e.t,
                     csv_quoted(e.stopped ? e.name + " (stops the run)" : e.name));
      for (std::size_t k = 0; k < 6 * joints.size(); ++k) text.push_back(',');
      write_contact_cells(nullptr);
      text.push_back('\n');
    }
  };
  const auto write_contact_events_until = [&](double t, bool including) {
    // Each contact event with its instant's user events before it (those strictly earlier).
    while (next_event < contact_events.size()) {
      const ContactEventRecord& e = contact_events[next_event];
      if (e.t > t || (e.t == t && !including)) break;
      write_user_events_before(e.t);
      write_contact_events_before(e.t, true);
    }
  };
  for (const JumpRecord& jump : jumps) {
    write_contact_events_until(jump.t, false);
    write_user_events_before(jump.t);
    fmt::format_to(out, "{:.17g},\"jump\",{},{:.17g},{:.17g}", jump.t, csv_quoted(jump.what),
                   jump.kinetic_energy_before, jump.kinetic_energy_after);
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const JointReaction r =
          j < jump.reaction_impulses.size() ? jump.reaction_impulses[j] : JointReaction{};
      for (int k = 0; k < 3; ++k) fmt::format_to(out, ",{:.17g}", r.F_W(k));
      for (int k = 0; k < 3; ++k) fmt::format_to(out, ",{:.17g}", r.M_J_W(k));
    }
    write_contact_cells(nullptr);
    text.push_back('\n');
  }
  write_contact_events_until(std::numeric_limits<double>::infinity(), true);
  write_user_events_before(std::numeric_limits<double>::infinity());
  file.write(std::string_view(text.data(), text.size()));
  file.finish();
}

}  // namespace tumble
