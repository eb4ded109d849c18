#include "tumble/simulation/user_events.hpp"

#include <fmt/format.h>

#include "tumble/simulation/simulation.hpp"

namespace tumble {

UserEventSystem::UserEventSystem(Formulation& formulation,
                                 std::shared_ptr<const UserEventDefinitions> definitions)
    : formulation_(&formulation),
      definitions_(std::move(definitions)),
      own_count_(formulation.events().size()),
      specs_(formulation.events().begin(), formulation.events().end()),
      row_(std::make_unique<RowVariables>(definitions_->columns, definitions_->parameters)),
      own_g_(static_cast<Eigen::Index>(own_count_)),
      states_(formulation.body_count()) {
  std::vector<const BoundExpression*> compiled;
  for (std::size_t i = 0; i < definitions_->events.size(); ++i) {
    const UserEventSpec& event = definitions_->events[i];
    // A comparison's function is its margin, which crosses zero as the comparison turns.
    const std::optional<Comparison> comparison = split_comparison(event.when);
    EventSpec spec{event.name, EventDirection::Both, true};
    if (comparison) {
      spec.direction = comparison->greater ? EventDirection::Rising : EventDirection::Falling;
    } else if (event.direction == UserEventSpec::Direction::Up) {
      spec.direction = EventDirection::Rising;
    } else if (event.direction == UserEventSpec::Direction::Down) {
      spec.direction = EventDirection::Falling;
    }
    try {
      functions_.push_back(std::make_unique<BoundExpression>(
          comparison ? comparison->margin() : event.when, row_->variables()));
    } catch (const ExpressionError& error) {
      throw ScenarioError(event.when_where, fmt::format("events[{}].when", i),
                          std::string(error.what()) +
                              (error.unknown_name().empty()
                                   ? ""
                                   : "; an event reads the trajectory's columns (t, BODY.x, "
                                     "BODY.w1, JOINT.angle, CONTACT.slip, E, ...) and the "
                                     "parameters"));
    }
    compiled.push_back(functions_.back().get());
    specs_.push_back(std::move(spec));
  }
  row_->read_by(compiled);
  // The row's extras sized now, so that no evaluation allocates.
  const ColumnLayout& columns = definitions_->columns;
  extras_.joints.resize(columns.joints.size());
  extras_.coordinates.resize(columns.joints.size());
  extras_.contacts.resize(columns.contacts.size());
  extras_.elements.resize(columns.elements.size());
}

UserEventSystem::~UserEventSystem() = default;

void UserEventSystem::event_functions(double t, const VecX& y, VecX& g) const {
  if (own_count_ > 0) {
    formulation_->event_functions(t, y, own_g_);
    g.head(static_cast<Eigen::Index>(own_count_)) = own_g_;
  }
  // The row at (t, y), as the trajectory would have it there.
  formulation_->unpack_all(y, states_);
  if (row_->reads_extras()) formulation_->calc_row_extras(t, y, extras_);
  // The system's energies and momenta only where a condition reads them (this runs every step).
  SystemQuantities q;
  if (row_->reads_quantities()) q = row_quantities(formulation_->model(), states_, extras_);
  row_->take({t, states_, &q, &extras_});
  for (std::size_t k = 0; k < functions_.size(); ++k) {
    g(static_cast<Eigen::Index>(own_count_ + k)) = functions_[k]->evaluate();
  }
}

EventAction UserEventSystem::on_event(std::size_t event_index, double t, VecX& y) {
  if (event_index < own_count_) return formulation_->on_event(event_index, t, y);
  return definitions_->events[event_index - own_count_].stop ? EventAction::Stop
                                                             : EventAction::Record;
}

std::vector<UserEventRecord> UserEventSystem::occurrences(
    std::span<const EventRecord> located) const {
  std::vector<UserEventRecord> records;
  for (const EventRecord& e : located) {
    if (e.index < own_count_) continue;
    records.push_back(
        {e.t, definitions_->events[e.index - own_count_].name, e.action == EventAction::Stop});
  }
  return records;
}

}  // namespace tumble
