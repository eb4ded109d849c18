#include "tumble/output/animation_plots.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <unordered_set>

#include "tumble/scenario/yaml_reader.hpp"

namespace tumble {

std::vector<AnimationPlot> animation_plots(const Scenario& scenario, const ColumnLayout& layout) {
  std::vector<AnimationPlot> plots;
  if (!scenario.output.plots_given) {
    AnimationPlot speeds{"speed of the COM (m/s)", {}};
    for (const std::string& body : layout.bodies) speeds.columns.push_back(body + ".speed");
    if (!speeds.columns.empty()) plots.push_back(std::move(speeds));
    AnimationPlot angles{"joint angles (rad)", {}};
    for (std::size_t j = 0; j < layout.joints.size(); ++j) {
      const auto& names = layout.joint_coordinates[j];
      if (std::find(names.begin(), names.end(), "angle") != names.end()) {
        angles.columns.push_back(layout.joints[j] + ".angle");
      }
    }
    if (!angles.columns.empty()) plots.push_back(std::move(angles));
    return plots;
  }
  const std::vector<std::string> names = column_names(layout);
  const std::unordered_set<std::string> known(names.begin(), names.end());
  for (const PlotSpec& spec : scenario.output.plots) {
    for (std::size_t i = 0; i < spec.columns.size(); ++i) {
      if (!known.contains(spec.columns[i])) {
        throw ScenarioError(
            spec.where[i], spec.keys[i],
            fmt::format("'{}' is not a column of this run's trajectory; its columns are the CSV "
                        "header's: t, BODY.x .. BODY.speed, JOINT.angle (its coordinates), "
                        "CONTACT.N .. CONTACT.slip, KE, PE, E, ... (docs/scenario.md)",
                        scenario_reading::printable(spec.columns[i])));
      }
    }
    AnimationPlot plot{fmt::format("{}", fmt::join(spec.columns, ", ")), spec.columns};
    plots.push_back(std::move(plot));
  }
  return plots;
}

}  // namespace tumble
