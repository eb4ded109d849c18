#include "tumble/integrators/ode_system.hpp"

namespace tumble {

void normalize_unit_quaternions(std::span<const Eigen::Index> offsets, VecX& y) {
  for (const Eigen::Index k : offsets) y.segment<4>(k).normalize();
}

void OdeSystem::begin(double /*t0*/, const VecX& /*y*/) {}

bool rescale_quaternion_derivatives(std::span<const Eigen::Index> offsets, const VecX& y_before,
                                    const VecX& y_after, VecX& dydt) {
  // Everything outside the quaternion slots must be bit-identical.
  Eigen::Index next = 0;
  const auto same = [&](Eigen::Index from, Eigen::Index to) {
    return (y_before.segment(from, to - from).array() == y_after.segment(from, to - from).array())
        .all();
  };
  for (const Eigen::Index k : offsets) {
    if (!same(next, k)) return false;
    next = k + 4;
  }
  if (!same(next, y_before.size())) return false;
  for (const Eigen::Index k : offsets) {
    const double norm_before = y_before.segment<4>(k).norm();
    if (norm_before == 0.0) return false;
    dydt.segment<4>(k) *= y_after.segment<4>(k).norm() / norm_before;
  }
  return true;
}

void OdeSystem::tolerance_units(const VecX& /*y0*/, VecX& units) const {
  units.setOnes();
}

void OdeSystem::project(double /*t*/, VecX& y) const {
  normalize_unit_quaternions(unit_quaternion_offsets(), y);
}

void OdeSystem::event_functions(double /*t*/, const VecX& /*y*/, VecX& /*g*/) const {}

bool OdeSystem::refresh_event_functions(double /*t*/, const VecX& /*y*/) {
  return false;
}

EventAction OdeSystem::on_event(std::size_t /*event_index*/, double /*t*/, VecX& /*y*/) {
  return EventAction::Record;
}

bool OdeSystem::jacobian(double /*t*/, const VecX& /*y*/, MatX& /*dfdy*/) const {
  return false;
}

double OdeSystem::step_limit(double /*t*/, const VecX& /*y*/) const {
  return std::numeric_limits<double>::infinity();
}

double OdeSystem::next_breakpoint(double /*t*/) const {
  return std::numeric_limits<double>::infinity();
}

void OdeSystem::at_breakpoint(double /*t*/, VecX& /*y*/) {}

}  // namespace tumble
