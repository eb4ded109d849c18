#pragma once
// How a contact holds its body in a run's current mode, for the Jacobian of the run's equations
// (modes/state_jacobian.hpp), which writes the same forces over dual numbers: the run's modes
// say which constraints hold (contact_forces.cpp), and this is what the Jacobian needs of them.
#include <array>

#include "tumble/math/types.hpp"

namespace tumble {

struct ContactHold {
  enum class Kind {
    Apart,   // no force
    Point,   // rolling or sticking at one point: its velocity held (three rows)
    Normal,  // sliding at one point: its normal velocity held, Coulomb's friction on the push
    // On two or three points (an edge's or a side's ends, a face's corners, a pivot), each held
    // as a point of the body in `points`: the part's points move over a round body as it rolls,
    // and a face's friction acts at its centre with a spin's moment where the run slides it, so
    // this Jacobian is the run's to first order in that motion and that spread, not exactly: it
    // costs Newton a little, not the answer.
    Points,
  } kind = Kind::Apart;
  double friction = 0.0;  // Normal: mu (0: frictionless)
  // Normal: the friction is against the slip itself, so the state turns it (the slip has grown
  // past its zero). Otherwise it is along slide_W (unit, in the plane), which the state does not
  // move: the way a slip starting from none is pushed.
  bool follows_slip = false;
  Vec3 slide_W = Vec3::Zero();

  // Points: each point (body axes, from the COM) held as a one-point hold of kind Point or
  // Normal holds its point, with its own friction, follows_slip and slide_W.
  struct BodyPoint {
    Vec3 p_B = Vec3::Zero();
    Kind kind = Kind::Point;
    double friction = 0.0;
    bool follows_slip = false;
    Vec3 slide_W = Vec3::Zero();
  };
  std::array<BodyPoint, 3> points{};
  int point_count = 0;
};

}  // namespace tumble
