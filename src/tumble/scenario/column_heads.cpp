#include <fmt/format.h>

#include <algorithm>

#include "tumble/scenario/readers.hpp"

namespace tumble::scenario_reading {

void check_name(const Reader& reader, const Field& where, const std::string& name,
                std::string_view what) {
  const bool control = std::any_of(name.begin(), name.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte < 0x20 || byte == 0x7F;
  });
  if (control) {
    reader.fail_at_key(where, fmt::format("{} name '{}' holds a control character; it heads CSV "
                                          "columns and shows in messages and on the page, so "
                                          "use letters, digits and _",
                                          what, printable(name)));
  }
  const bool bad = name.empty() || name.find_first_of(".,\"' ") != std::string::npos;
  if (bad) {
    reader.fail_at_key(where, fmt::format("{} name '{}' cannot be used: it prefixes CSV columns "
                                          "('{}.x'), so it may not be empty or hold '.', ',', "
                                          "quotes or spaces",
                                          what, name, name));
  }
}

ColumnHeads::ColumnHeads(const Scenario& scenario) {
  for (const BodySpec& body : scenario.bodies) note(body.name, "body", body.where);
  for (const JointSpec& joint : scenario.joints) note(joint.name, "joint", joint.where);
  for (const LoadSpec& load : scenario.loads) {
    note(load.name, load.kind == LoadSpec::Kind::Force ? "force" : "torque", load.where);
  }
  for (const SpringSpec& spring : scenario.springs) note(spring.name, "spring", spring.where);
  for (const TorsionalSpringSpec& spring : scenario.torsional_springs) {
    note(spring.name, "torsional_spring", spring.where);
  }
  for (const ImpulseSpec& impulse : scenario.impulses) {
    note(impulse.name, "impulse", impulse.where);
  }
  for (const ContactSpec& contact : scenario.contacts) note(contact.name, "contact", contact.where);
}

void ColumnHeads::note(const std::string& name, std::string_view what,
                       const SourceLocation& where) {
  heads_.try_emplace(name, Head{std::string(what), where});
}

void ColumnHeads::claim(const Reader& reader, const Field& where, const std::string& name,
                        std::string_view what, const SourceLocation& at) {
  const auto [it, fresh] = heads_.try_emplace(name, Head{std::string(what), at});
  if (fresh) return;
  const Head& first = it->second;
  const std::string place = first.where.line > 0 ? fmt::format(" (line {}, column {})",
                                                               first.where.line, first.where.column)
                                                 : "";
  reader.fail_at_key(
      where, fmt::format("'{}' already names a {}{}; bodies, joints, forces and contacts share one "
                         "set of names, since each heads CSV columns ('{}.W') and is what "
                         "expressions and plots refer to: give this {} its own",
                         name, first.what, place, name, what));
}

}  // namespace tumble::scenario_reading
