#pragma once
// `tumble modes` from a scenario: its model in joint coordinates, its initial state, the
// linearisation about it and the modes; and the modes' CSV. (The rows that show each mode shape
// moving, for the animation page, are mode_shape_rows.hpp's.)
#include <memory>
#include <string>

#include "tumble/modes/modal_analysis.hpp"
#include "tumble/scenario/scenario.hpp"

namespace tumble {

struct ScenarioModes {
  std::shared_ptr<const ModalEquations> equations;
  Linearisation linearisation;
  ModalAnalysis analysis;
};

// The scenario's equations in modal coordinates about its initial state, whatever that state is.
// Throws ScenarioError, as `tumble run` would for the same file.
std::shared_ptr<const ModalEquations> modal_equations_of(const Scenario& scenario);

// Throws ScenarioError or NotSteady.
ScenarioModes modes_of_scenario(const Scenario& scenario);

// One row per mode: its number, kind, eigenvalue, natural and damped frequency, period,
// damping ratio, growth rate, then each kept coordinate's amplitude and phase in its shape.
std::string modes_csv(const ScenarioModes& modes);

}  // namespace tumble
