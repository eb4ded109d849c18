#pragma once
// The animation page's plots beyond its own (omega, energy, |L|): the trajectory columns the
// scenario names (output.plots), or by default each body's speed and the joints' angles; and the
// run's events, which the page marks on every plot's time axis.
#include <string>
#include <vector>

#include "tumble/output/columns.hpp"
#include "tumble/scenario/scenario.hpp"

namespace tumble {

struct AnimationPlot {
  std::string title;
  std::vector<std::string> columns;  // the trajectory CSV's names
};

// output.plots, or the defaults where it is not given. Throws ScenarioError at the first column
// the run's trajectory does not have, naming its key and the kinds of column there are.
std::vector<AnimationPlot> animation_plots(const Scenario& scenario, const ColumnLayout& layout);

// A moment the page marks: a contact's event, a jump, or one of the scenario's events.
struct AnimationEvent {
  double t = 0.0;
  std::string what;  // "floor: slip stops", "jump: impulse ball", "event: flip"
};

}  // namespace tumble
