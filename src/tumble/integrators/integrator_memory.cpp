// The memory every method shares, for a checkpoint file (Integrator::archive_memory).
#include "tumble/integrators/integrator.hpp"

#include <cmath>
#include <string>

namespace tumble {

void Integrator::archive_sized(StateArchive& archive, std::string_view key, VecX& values) {
  const Eigen::Index size = values.size();
  archive.numbers(key, values);
  if (values.size() != size) {
    archive.fail(key, std::to_string(values.size()) + " numbers where the method has " +
                          std::to_string(size));
  }
}

void Integrator::archive_common(StateArchive& archive) {
  archive.number("t", t_);
  archive.require("t", std::isfinite(t_), "a finite time");
  archive.number("t_previous", t_previous_);
  archive.require("t_previous", std::isfinite(t_previous_), "a finite time");
  archive.number("h", h_);
  archive.require("h", std::isfinite(h_) && h_ >= 0.0, "a step size, finite and not negative");
  archive.number("step_bound", step_bound_);
  archive.require("step_bound", step_bound_ > 0.0, "a bound on the step, > 0 (inf: none)");
  archive_sized(archive, "y", y_);
  archive_sized(archive, "y_previous", y_previous_);
  archive.integer("accepted_steps", stats_.accepted_steps);
  archive.require("accepted_steps", stats_.accepted_steps >= 0, "a count, not negative");
  archive.integer("rejected_steps", stats_.rejected_steps);
  archive.require("rejected_steps", stats_.rejected_steps >= 0, "a count, not negative");
  archive.integer("rhs_evaluations", stats_.rhs_evaluations);
  archive.require("rhs_evaluations", stats_.rhs_evaluations >= 0, "a count, not negative");
}

void Integrator::archive_direction(StateArchive& archive, double& direction) {
  archive.number("direction", direction);
  archive.require("direction", direction == 1.0 || direction == -1.0,
                  "1 (forward in time) or -1 (backward)");
}

}  // namespace tumble
