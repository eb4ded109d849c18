#pragma once
// Runs an Integrator on an OdeSystem from t0 to t_end and builds on its three calls (step,
// dense_output, restart) everything a simulation needs:
//  - output rows at t0 + k * output_every from the continuous extension, projected as a step's
//    end is (or at every step);
//  - located events: sign changes of the system's g_k between two steps are bracketed and then
//    pinned down by the Illinois variant of regula falsi on the dense output, to a bracket of a
//    few ulps of t; the system then records, jumps (the method restarts) or stops;
//  - breakpoints: a step lands exactly on each, the system may change the state there, and the
//    method restarts, so no step straddles a discontinuity of f.
#include <functional>
#include <string>
#include <vector>

#include "tumble/integrators/integrator.hpp"

namespace tumble {

struct DriverOptions {
  double output_every = 0.0;    // s; 0: one row per accepted step
  long max_steps = 10'000'000;  // accepted steps before the run is declared failed
};

struct EventRecord {
  double t = 0.0;
  std::size_t index = 0;  // into OdeSystem::events()
  EventAction action = EventAction::Record;
};

struct IntegrationReport {
  bool completed = false;
  double t_reached = 0.0;
  std::string failure;  // why it stopped early, with the time; empty if completed
  std::vector<EventRecord> events;
  IntegratorStats stats;
};

// Called with each output row; y is only valid during the call.
using Observer = std::function<void(double t, const VecX& y)>;

IntegrationReport integrate(Integrator& integrator, OdeSystem& system, double t0, const VecX& y0,
                            double t_end, const DriverOptions& options, const Observer& observe);

}  // namespace tumble
