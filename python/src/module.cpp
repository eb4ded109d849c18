// tumble._tumble: the engine for python/tumble/__init__.py.
#include "bindings.hpp"

#include "tumble/scenario/scenario_document.hpp"

namespace tumble::python {

std::string ScenarioSource::text() const {
  return is_text ? source : read_scenario_file(source);
}

std::vector<ParameterOverride> to_overrides(const Overrides& overrides) {
  std::vector<ParameterOverride> out;
  for (const auto& [name, value] : overrides) out.push_back({name, value});
  return out;
}

}  // namespace tumble::python

PYBIND11_MODULE(_tumble, m) {
  m.doc() = "tumble's engine, compiled; use the tumble package (import tumble), not this.";
  m.attr("__version__") = TUMBLE_VERSION;
  tumble::python::bind_errors(m);
  tumble::python::bind_model(m);
  tumble::python::bind_sweep(m);
  tumble::python::bind_inertia(m);
  tumble::python::bind_modes(m);
  tumble::python::bind_commands(m);
}
