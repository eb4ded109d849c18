// The broad phase's screening of a group's pairs (broad_phase.hpp), at the start of each step: each
// body's box, grown by how far it may move before the step's end, and the step's horizon.
#include <algorithm>
#include <cmath>
#include <limits>

#include "tumble/contact/contact_system.hpp"
#include "tumble/contact/landing_bound.hpp"

namespace tumble {

namespace {

// How far a body may move (its COM, and a point of its surface as it turns) within the horizon,
// in its bounding radii: the horizon is the time the fastest body takes to move this far. Half a
// ball's radius per step keeps a gas of balls' near pairs to its neighbours.
constexpr double kScreenReach = 0.5;
// As the step limit's kTurningMargin: the accelerations are taken at the step's start, and may
// grow within it.
constexpr double kScreenAccelerationMargin = 2.0;
// Every box grows by this much of its body's radius besides, so that two bodies that touch to
// round-off overlap.
constexpr double kScreenRoundOff = 1e-6;

}  // namespace

bool ContactSystem::any_touching() const {
  return std::any_of(watched().begin(), watched().end(),
                     [&](std::size_t c) { return s_.contacts[c].mode != ContactMode::Apart; });
}

double ContactSystem::screen_pairs() const {
  PairScreen& screen = d_.screen;
  if (!screen.active()) return std::numeric_limits<double>::infinity();
  // A point r from the COM moves at most |v_G| + |omega| |r|, its velocity turning at most
  // |a_G| + (|alpha| + |omega|^2) |r|: over a time t at most speed t + accel t^2 / 2.
  const std::span<const std::size_t> bodies = screen.bodies();
  double horizon = std::numeric_limits<double>::infinity();
  const auto reach = [&](std::size_t object, double& speed, double& accel) {
    const BodyMotion w = dynamics_.motion(bodies[object]);
    const double r = screen.bounds(object).radius;
    const double omega = w.velocity.head<3>().norm();
    speed = w.velocity.tail<3>().norm() + omega * r;
    accel = kScreenAccelerationMargin *
            (moving_point_acceleration_W(w, Vec3::Zero(), Vec3::Zero()).norm() +
             (w.acceleration.head<3>().norm() + omega * omega) * r);
  };
  for (std::size_t o = 0; o < bodies.size(); ++o) {
    double speed = 0.0, accel = 0.0;
    reach(o, speed, accel);
    horizon = std::min(horizon, first_root(kScreenReach * screen.bounds(o).radius, -speed, accel));
  }
  // A fixed-step method keeps its step whatever the horizon: the boxes grow by how far the bodies
  // move in that step where it is longer.
  const double span = std::max(horizon, fixed_step_);
  for (std::size_t o = 0; o < bodies.size(); ++o) {
    double speed = 0.0, accel = 0.0;
    reach(o, speed, accel);
    const BodyBounds& bounds = screen.bounds(o);
    const BodyMotion w = dynamics_.motion(bodies[o]);
    const double travel = std::isfinite(span) ? speed * span + 0.5 * accel * span * span : 0.0;
    const double grow = travel + kScreenRoundOff * bounds.radius;
    // The box about the surfaces turned into world axes, and the ball about the COM: the body is
    // in both.
    const Vec3 centre_W = w.r_G_W + w.R_WB * bounds.centre_B;
    const Vec3 half_W = w.R_WB.cwiseAbs() * bounds.half_B;
    const Vec3 lo = (centre_W - half_W).cwiseMax(w.r_G_W - Vec3::Constant(bounds.radius));
    const Vec3 hi = (centre_W + half_W).cwiseMin(w.r_G_W + Vec3::Constant(bounds.radius));
    d_.boxes[o] = {lo - Vec3::Constant(grow), hi + Vec3::Constant(grow)};
  }
  d_.rescreened = screen.screen(
      d_.boxes, [&](std::size_t c) { return s_.contacts[c].mode != ContactMode::Apart; },
      [&](std::size_t c) { calc_pair_point(c); });
  return horizon;
}

}  // namespace tumble
