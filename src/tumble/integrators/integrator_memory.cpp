// The memory every method shares, for a checkpoint file (Integrator::archive_memory).
#include "tumble/integrators/integrator.hpp"

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
  archive.number("t_previous", t_previous_);
  archive.number("h", h_);
  archive.number("step_bound", step_bound_);
  archive_sized(archive, "y", y_);
  archive_sized(archive, "y_previous", y_previous_);
  archive.integer("accepted_steps", stats_.accepted_steps);
  archive.integer("rejected_steps", stats_.rejected_steps);
  archive.integer("rhs_evaluations", stats_.rhs_evaluations);
}

}  // namespace tumble
