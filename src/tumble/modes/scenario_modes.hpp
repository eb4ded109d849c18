#pragma once
// `tumble modes` from a scenario: its model in joint coordinates, its initial state, the
// linearisation about it and the modes; the modes' CSV; and rows that show each mode shape
// moving, for the animation page.
#include <string>

#include "tumble/modes/modal_analysis.hpp"
#include "tumble/output/animation_html.hpp"
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

// Each mode that moves, one after the other, for three cycles (three periods; a real mode swings
// its shape over 2 s cycles), about the initial configuration; the largest turn in a shape is
// 0.2 rad, the largest displacement a tenth of `size` (m). A mode without positions (a free
// body's spin) moves its positions by speed / lambda, the motion its speeds make. Neutral modes
// and shapes that move nothing are not shown; `shown` gets, for each mode shown, its index in
// ModalAnalysis::modes and the time its cycles start.
struct ShownMode {
  std::size_t mode = 0;
  double start = 0.0;  // s
};
RecordedTrajectory mode_shape_rows(const ScenarioModes& modes, double size,
                                   std::vector<ShownMode>& shown);

}  // namespace tumble
