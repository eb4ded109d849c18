#pragma once
// How a contact holds its body in a run's current mode, for the Jacobian of the run's equations
// (modes/state_jacobian.hpp), which writes the same forces over dual numbers: the run's modes
// say which constraints hold (contact_forces.cpp), and this is what the Jacobian needs of them.
#include "tumble/math/types.hpp"

namespace tumble {

struct ContactHold {
  enum class Kind {
    Apart,     // no force
    Point,     // rolling or sticking at one point: its velocity held (three rows)
    Normal,    // sliding at one point: its normal velocity held, Coulomb's friction on the push
    Features,  // on an edge, a face or a side's line, or with a spin's friction: no Jacobian yet
  } kind = Kind::Apart;
  double friction = 0.0;  // Normal: mu (0: frictionless)
  // Normal: the friction is against the slip itself, so the state turns it (the slip has grown
  // past its zero). Otherwise it is along slide_W (unit, in the plane), which the state does not
  // move: the way a slip starting from none is pushed.
  bool follows_slip = false;
  Vec3 slide_W = Vec3::Zero();
};

}  // namespace tumble
