#include "tumble/sweep/velocity_only_runs.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <string_view>
#include <tuple>

namespace tumble {
namespace {

// The body, the velocity and the axis of a path "bodies.NAME.velocity[k]" or
// "bodies.NAME.angular_velocity[k]", or a planar scenario's "bodies.NAME.angular_velocity" (its
// rate about z); none for another path.
std::optional<std::tuple<std::size_t, bool, int>> velocity_component(
    std::string_view path, const std::vector<BodySpec>& bodies) {
  constexpr std::string_view kBodies = "bodies.";
  if (!path.starts_with(kBodies)) return std::nullopt;
  path.remove_prefix(kBodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const std::string& name = bodies[b].name;
    if (!path.starts_with(name) || path.size() <= name.size() || path[name.size()] != '.') {
      continue;
    }
    const std::string_view key = path.substr(name.size() + 1);
    if (key == "angular_velocity") return std::make_tuple(b, true, 2);  // planar: about z
    for (const bool angular : {false, true}) {
      for (int axis = 0; axis < 3; ++axis) {
        const std::string wanted =
            std::string(angular ? "angular_velocity[" : "velocity[") + char('0' + axis) + "]";
        if (key == wanted) return std::make_tuple(b, angular, axis);
      }
    }
  }
  return std::nullopt;
}

}  // namespace

std::unique_ptr<VelocityOnlyRuns> VelocityOnlyRuns::make(
    const std::vector<std::string>& varied, const ParameterTrace& trace, const Scenario& scenario,
    std::shared_ptr<const SimulationModel> model) {
  std::unique_ptr<VelocityOnlyRuns> runs(new VelocityOnlyRuns());
  // Every parameter a variable, as every one is defined where a full read's runs evaluate.
  std::map<std::string, std::size_t> slots;
  std::vector<BoundExpression::Variable> variables;
  runs->values_.reserve(scenario.parameters.size());
  for (const auto& [name, value] : scenario.parameters) {
    slots[name] = runs->values_.size();
    runs->values_.push_back(value);
  }
  for (const auto& [name, slot] : slots) variables.push_back({name, &runs->values_[slot]});
  const auto compiled = [&](const std::string& text) {
    return std::make_unique<BoundExpression>(text, variables,
                                             BoundExpression::Compile::AsConstants);
  };
  constexpr std::string_view kParameters = "parameters.";
  try {
    for (const ParameterTrace::Use& use : trace.uses) {
      if (std::string_view(use.path).starts_with(kParameters)) {
        std::string name = use.path.substr(kParameters.size());
        const auto slot = slots.find(name);
        if (slot == slots.end()) return nullptr;
        runs->parameters_.push_back({std::move(name), slot->second, compiled(use.expression)});
      } else if (const auto component = velocity_component(use.path, scenario.bodies)) {
        const auto [body, angular, axis] = *component;
        runs->velocities_.push_back({body, angular, axis, compiled(use.expression)});
      } else {
        return nullptr;  // it reaches the model
      }
    }
    for (const std::string& name : varied) {
      const auto slot = slots.find(name);
      if (slot == slots.end()) return nullptr;
      runs->varied_slots_.push_back(slot->second);
    }
  } catch (const ExpressionError&) {
    return nullptr;  // each run reads the document, which says what is wrong where
  }
  runs->varied_ = varied;
  runs->scenario_ = scenario;
  runs->model_ = std::move(model);
  return runs;
}

double VelocityOnlyRuns::value_of(const BoundExpression& expression) {
  const double value = expression.evaluate();
  if (!std::isfinite(value)) {
    throw ExpressionError("expression '" + expression.text() + "' is not finite here", "");
  }
  return value;
}

const Scenario& VelocityOnlyRuns::scenario_at(std::span<const double> values) {
  // A full read evaluates the varied values' 17-digit text, which reads back as these doubles.
  for (std::size_t i = 0; i < varied_.size(); ++i) {
    values_[varied_slots_[i]] = values[i];
    scenario_.parameters[varied_[i]] = values[i];
  }
  for (const ParameterStep& step : parameters_) {
    const double value = value_of(*step.expression);
    values_[step.slot] = value;
    scenario_.parameters[step.name] = value;
  }
  for (const VelocityStep& step : velocities_) {
    BodySpec& body = scenario_.bodies[step.body];
    Vec3& velocity = step.angular ? body.angular_velocity_W : body.velocity_W;
    velocity(step.axis) = value_of(*step.expression);
  }
  return scenario_;
}

}  // namespace tumble
