#pragma once
// A scenario's `events:` in a run: each a function of the output row at (t, y) (its `when:`
// compiled against the trajectory's columns and the parameters) whose zero crossings the driver
// locates as it locates the contacts' mode changes, to the integrator's precision. The events
// ride on the formulation's own: UserEventSystem hands the driver the formulation with the user
// events after its own, and records each or stops the run there.
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tumble/dynamics/formulation.hpp"
#include "tumble/integrators/driver.hpp"
#include "tumble/output/columns.hpp"
#include "tumble/output/row_variables.hpp"
#include "tumble/scenario/scenario.hpp"

namespace tumble {

// What a model keeps of its scenario's events: enough for each run to compile them.
struct UserEventDefinitions {
  std::vector<UserEventSpec> events;
  ColumnLayout columns;
  std::map<std::string, double> parameters;
};

class UserEventSystem final : public OdeSystem {
 public:
  // Throws ScenarioError at an event's `when:` for a name that is neither a column nor a
  // parameter, or an expression that does not compile.
  UserEventSystem(Formulation& formulation,
                  std::shared_ptr<const UserEventDefinitions> definitions);
  ~UserEventSystem() override;

  // The user events among a run's located events (their indices after the formulation's).
  std::vector<UserEventRecord> occurrences(std::span<const EventRecord> located) const;

  Eigen::Index dimension() const override { return formulation_->dimension(); }
  void begin(double t0, const VecX& y) override { formulation_->begin(t0, y); }
  void derivative(double t, const VecX& y, VecX& dydt) const override {
    formulation_->derivative(t, y, dydt);
  }
  std::span<const Eigen::Index> unit_quaternion_offsets() const override {
    return formulation_->unit_quaternion_offsets();
  }
  bool jacobian(double t, const VecX& y, MatX& dfdy) const override {
    return formulation_->jacobian(t, y, dfdy);
  }
  bool gives_jacobian() const override { return formulation_->gives_jacobian(); }
  void project(double t, VecX& y) const override { formulation_->project(t, y); }
  void tolerance_units(const VecX& y0, VecX& units) const override {
    formulation_->tolerance_units(y0, units);
  }
  std::span<const EventSpec> events() const override { return specs_; }
  void event_functions(double t, const VecX& y, VecX& g) const override;
  EventAction on_event(std::size_t event_index, double t, VecX& y) override;
  bool refresh_event_functions(double t, const VecX& y) override {
    return formulation_->refresh_event_functions(t, y);
  }
  bool events_rescreened() const override { return formulation_->events_rescreened(); }
  double step_limit(double t, const VecX& y) const override {
    return formulation_->step_limit(t, y);
  }
  double next_breakpoint(double t) const override { return formulation_->next_breakpoint(t); }
  void at_breakpoint(double t, VecX& y) override { formulation_->at_breakpoint(t, y); }
  const Formulation* rigid_body_formulation() const override { return formulation_; }

 private:
  Formulation* formulation_;
  std::shared_ptr<const UserEventDefinitions> definitions_;  // a run may outlive its model
  std::size_t own_count_;         // the formulation's events, first in specs_
  std::vector<EventSpec> specs_;  // the formulation's, then the user events
  std::unique_ptr<RowVariables> row_;
  std::vector<std::unique_ptr<BoundExpression>> functions_;  // g of each user event
  // The row at (t, y) the functions read, sized once.
  mutable VecX own_g_;
  mutable std::vector<BodyState> states_;
  mutable RowExtras extras_;
};

}  // namespace tumble
