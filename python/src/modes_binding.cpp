// tumble.modes: what `tumble modes` prints, as numbers: the linearisation's coordinates, the
// steady motion's rates, each mode's eigenvalue, frequencies, damping, growth and shape, the
// verdict, and the CSV's text.
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.hpp"
#include "tumble/modes/scenario_modes.hpp"

namespace tumble::python {
namespace {

py::dict modes_dict(const ScenarioModes& modes) {
  const Linearisation& lin = modes.linearisation;
  const ModalAnalysis& analysis = modes.analysis;
  py::dict out;
  std::vector<std::string> coordinates, units, symmetries, neutral;
  for (const ModalCoordinate& c : lin.coordinates) {
    coordinates.push_back(c.name);
    units.push_back(c.unit);
  }
  for (const Symmetry& s : lin.symmetries) symmetries.push_back(s.description);
  for (const Symmetry& s : lin.neutral_symmetries) neutral.push_back(s.description);
  out["coordinates"] = coordinates;
  out["units"] = units;
  out["ignorable"] = lin.ignorable;
  out["equilibrium"] = lin.equilibrium();
  py::dict drifting;
  for (const DriftingCoordinate& c : lin.drifting) drifting[py::str(c.name)] = c.rate;
  out["drifting"] = drifting;
  out["symmetries"] = symmetries;
  out["symmetry_rates"] = VecX(lin.symmetry_rates);
  out["neutral_symmetries"] = neutral;
  const auto count = static_cast<Eigen::Index>(analysis.modes.size());
  Eigen::VectorXcd eigenvalues(count);
  VecX natural(count), damped(count), damping(count), growth(count);
  Eigen::MatrixXcd shapes(count, static_cast<Eigen::Index>(coordinates.size()));
  std::vector<std::string> kinds;
  std::vector<std::optional<std::size_t>> twin_of;  // 1-based, as the summary numbers modes
  for (Eigen::Index i = 0; i < count; ++i) {
    const Mode& mode = analysis.modes[static_cast<std::size_t>(i)];
    eigenvalues(i) = mode.eigenvalue;
    natural(i) = mode.natural_frequency;
    damped(i) = mode.damped_frequency;
    damping(i) = mode.damping_ratio;
    growth(i) = mode.growth_rate;
    shapes.row(i) = mode.shape.transpose();
    kinds.push_back(kind_name(mode.kind));
    twin_of.push_back(mode.kind == Mode::Kind::DecayingTwin
                          ? std::optional<std::size_t>(mode.twin_of + 1)
                          : std::nullopt);
  }
  out["eigenvalues"] = eigenvalues;
  out["natural_frequency"] = natural;
  out["damped_frequency"] = damped;
  out["damping_ratio"] = damping;
  out["growth_rate"] = growth;
  out["shapes"] = shapes;
  out["kinds"] = kinds;
  out["twin_of"] = twin_of;
  out["verdict"] = verdict_name(analysis.verdict);
  out["verdict_text"] = analysis.verdict_text;
  out["csv"] = modes_csv(modes);
  return out;
}

}  // namespace

void bind_modes(py::module_& m) {
  m.def(
      "modes",
      [](const std::string& source, bool is_text, const std::string& name,
         const Overrides& overrides) {
        const std::vector<ParameterOverride> sets = to_overrides(overrides);
        const Scenario scenario =
            is_text ? load_scenario_text(source, name, sets) : load_scenario(source, sets);
        return modes_dict(modes_of_scenario(scenario));
      },
      py::arg("source"), py::arg("is_text"), py::arg("name"), py::arg("overrides"));
}

}  // namespace tumble::python
