#pragma once
// A plane run's rows carry each body's angle about z counted on through whole turns, not the
// rotation's angle in (-pi, pi]: a rolling disk's angle grows with the distance it rolled.
#include <span>

#include "tumble/body/rigid_body.hpp"
#include "tumble/dynamics/row_extras.hpp"

namespace tumble {

// Each body's angle about z at time t (into extras.planar_angles): the rotation's, on the branch
// nearest to where the rates say the body turned from the last time this was called with these
// extras (the trapezoid of the two rates), so that a body that turns on past a half turn between
// rows, as a rolling disk does, is counted on (provided the rates' error over the interval stays
// below half a turn). The first call takes the rotation's angle.
void continue_planar_angles(double t, std::span<const BodyState> states, RowExtras& extras);

}  // namespace tumble
