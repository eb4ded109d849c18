#pragma once
// Turns a checked Scenario into the engine's Model and the bodies' states at t = 0.
#include <vector>

#include "tumble/dynamics/model.hpp"
#include "tumble/scenario/scenario.hpp"

namespace tumble {

Model build_model(const Scenario& scenario);
// COM positions follow from each body frame's position and the COM offset in the body frame.
std::vector<BodyState> initial_states(const Scenario& scenario);

}  // namespace tumble
