#pragma once
// Rows that show each mode shape of `tumble modes` moving, for the animation page (`--animate`).
#include <vector>

#include "tumble/modes/scenario_modes.hpp"
#include "tumble/output/animation_html.hpp"

namespace tumble {

// Each mode that moves, one after the other, for three cycles (three periods; a real mode swings
// its shape over 2 s cycles), about the initial configuration; the largest turn in a shape is
// 0.2 rad, the largest displacement a tenth of `size` (m). A mode without positions (a free
// body's spin) moves its positions by speed / lambda, the motion its speeds make. The speeds
// move with the shape's speeds on the same scale: for a mode that oscillates without damping,
// the motion it makes (the rates are the positions' derivatives); for a real mode, swung back and
// forth, the speeds it has at each displacement (lambda times it). Neutral modes
// and shapes that move nothing are not shown; `shown` gets, for each mode shown, its index in
// ModalAnalysis::modes and the time its cycles start.
struct ShownMode {
  std::size_t mode = 0;
  double start = 0.0;  // s
};
RecordedTrajectory mode_shape_rows(const ScenarioModes& modes, double size,
                                   std::vector<ShownMode>& shown);

}  // namespace tumble
