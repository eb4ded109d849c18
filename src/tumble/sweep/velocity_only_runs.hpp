#pragma once
// The runs of a sweep whose varied parameters reach only the bodies' initial velocities (a spin,
// a throw, a disturbance: the chapter's flip time against the tilt, the backspin disk against
// v0): one model serves them all, and a run computes only its y0. What a run's parameters reach
// is read from a ParameterTrace of one full read; a run then evaluates the same expressions, each
// compiled once over the parameters as variables (BoundExpression::Compile::AsConstants: the
// operations a full read folds over them as constants), so its scenario, and its result, are the
// same bytes, without muParser parsing each text again at every run.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tumble/scenario/expression.hpp"
#include "tumble/scenario/parameter_trace.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {

class VelocityOnlyRuns {
 public:
  // Null unless every number the trace found depending on `varied` is a parameter or a component
  // of a body's velocity or angular_velocity. `scenario` and `model` are a full read's at some
  // values of `varied`, with `trace` following them.
  static std::unique_ptr<VelocityOnlyRuns> make(const std::vector<std::string>& varied,
                                                const ParameterTrace& trace,
                                                const Scenario& scenario,
                                                std::shared_ptr<const SimulationModel> model);

  // The scenario at these values of the varied parameters (valid until the next call). Throws
  // ExpressionError where an expression cannot be evaluated at them (the run then reads the
  // document, whose message says where).
  const Scenario& scenario_at(std::span<const double> values);
  const SimulationModel& model() const { return *model_; }

 private:
  struct ParameterStep {
    std::string name;
    std::size_t slot;  // in values_
    std::unique_ptr<BoundExpression> expression;
  };
  struct VelocityStep {
    std::size_t body;
    bool angular;
    int axis;
    std::unique_ptr<BoundExpression> expression;
  };
  VelocityOnlyRuns() = default;
  // The expression's value now; throws ExpressionError where it is not finite, as a read would.
  static double value_of(const BoundExpression& expression);

  std::vector<std::string> varied_;
  std::vector<std::size_t> varied_slots_;  // in values_
  std::vector<ParameterStep> parameters_;  // defined from varied ones, in the file's order
  std::vector<VelocityStep> velocities_;
  Scenario scenario_;
  std::shared_ptr<const SimulationModel> model_;
  // Every parameter, at the last run's values: the variables the expressions read (sized once,
  // before they are compiled over it).
  std::vector<double> values_;
};

}  // namespace tumble
