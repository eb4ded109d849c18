// `events:`: moments the run locates and reports, and may stop at.
//   events:
//     - {name: slid_d, when: box.x > d, stop: true}
//     - {name: flip, when: prism.w3, direction: down}
#include <algorithm>

#include "tumble/scenario/expression.hpp"
#include "tumble/scenario/readers.hpp"

namespace tumble::scenario_reading {
std::vector<UserEventSpec> read_events(const Reader& reader, const Field& field,
                                       const Scenario& scenario) {
  std::vector<UserEventSpec> events;
  const std::vector<Field> items =
      reader.items(field, "of events, each {name:, when:, direction:, stop:}");
  for (const Field& item : items) {
    const MapReader map(reader, item, "an event {name:, when: CONDITION, direction:, stop:}");
    map.allow_only({"name", "when", "direction", "stop"}, "an event");
    UserEventSpec event;
    const Field name = map.require("name", "the event's name, for the summary and events.csv");
    event.name = reader.text(name);
    check_name(reader, name, event.name, "event");
    const bool taken = std::any_of(events.begin(), events.end(),
                                   [&](const UserEventSpec& e) { return e.name == event.name; });
    if (taken) reader.fail_at_value(name, "two events are named '" + event.name + "'");
    const bool contact_named =
        std::any_of(scenario.contacts.begin(), scenario.contacts.end(),
                    [&](const ContactSpec& c) { return c.name == event.name; });
    if (contact_named || event.name == "jump") {
      reader.fail_at_value(name, "'" + event.name +
                                     "' names a contact (or the jumps) in events.csv's source "
                                     "column; give the event another name");
    }
    const Field when =
        map.require("when",
                    "the condition: an expression of the trajectory's columns and the parameters "
                    "whose zero is the event (box.x - d), or a comparison (box.x > d)");
    event.when = reader.text(when);
    event.when_where = reader.location(when.value_mark());
    // Its parameters are read when the run compiles it: a trace must see them here.
    if (ParameterTrace* trace = reader.trace()) trace->note(when.path, event.when);
    // An event's condition only reads the row: refused here, in the user's words, for every
    // command that reads the scenario (the run compiles it only when it starts).
    try {
      check_read_only(event.when);
    } catch (const ExpressionError& error) {
      reader.fail_at_value(when, error.what());
    }
    for (const char* op : {"&&", "||", "==", "!="}) {
      if (event.when.find(op) == std::string::npos) continue;
      reader.fail_at_value(when, std::string("an event is where one quantity crosses another: "
                                             "one comparison (box.x > d) or one expression "
                                             "(box.x - d), not ") +
                                     op);
    }
    if (const auto f = map.find("direction")) {
      const std::string direction = reader.text(*f);
      // As the run reads it (UserEventSystem): one comparison says its own direction.
      if (split_comparison(event.when)) {
        reader.fail_at_value(*f, "a comparison says its own direction ('" + event.when +
                                     "' happens as it becomes true); leave direction out, or "
                                     "write the expression whose zero it is");
      }
      if (direction == "up") {
        event.direction = UserEventSpec::Direction::Up;
      } else if (direction == "down") {
        event.direction = UserEventSpec::Direction::Down;
      } else if (direction != "both") {
        reader.fail_at_value(*f,
                             "expected up (the expression rising through zero), down or "
                             "both, got '" +
                                 direction + "'");
      }
    }
    if (const auto f = map.find("stop")) {
      const std::string stop = reader.text(*f);
      if (stop != "true" && stop != "false") {
        reader.fail_at_value(
            *f, "expected true (the run ends at the event) or false, got '" + stop + "'");
      }
      event.stop = stop == "true";
    }
    event.where = reader.location(item.key_mark);
    events.push_back(std::move(event));
  }
  return events;
}

}  // namespace tumble::scenario_reading
