#include "tumble/integrators/ode_system.hpp"

namespace tumble {

void normalize_unit_quaternions(std::span<const Eigen::Index> offsets, VecX& y) {
  for (const Eigen::Index k : offsets) y.segment<4>(k).normalize();
}

void OdeSystem::begin(double /*t0*/, const VecX& /*y*/) {}

void OdeSystem::project(double /*t*/, VecX& y) const {
  normalize_unit_quaternions(unit_quaternion_offsets(), y);
}

void OdeSystem::event_functions(double /*t*/, const VecX& /*y*/, VecX& /*g*/) const {}

EventAction OdeSystem::on_event(std::size_t /*event_index*/, double /*t*/, VecX& /*y*/) {
  return EventAction::Record;
}

double OdeSystem::next_breakpoint(double /*t*/) const {
  return std::numeric_limits<double>::infinity();
}

void OdeSystem::at_breakpoint(double /*t*/, VecX& /*y*/) {}

}  // namespace tumble
