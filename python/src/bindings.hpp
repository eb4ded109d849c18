#pragma once
// The compiled half of the Python module, tumble._tumble: each bind_* adds one part of it. The
// public API, with its docstrings and type hints, is python/tumble/__init__.py, which calls these.
#include <pybind11/pybind11.h>

#include <string>
#include <utility>
#include <vector>

#include "tumble/scenario/scenario.hpp"

namespace tumble::python {

namespace py = pybind11;

// tumble.ScenarioError (with file, line, column, key, why) for a ScenarioError; the others as
// pybind11 translates them (std::invalid_argument: ValueError, std::runtime_error: RuntimeError).
void bind_errors(py::module_& m);
void bind_model(py::module_& m);     // load, Model, RunOutput, State
void bind_sweep(py::module_& m);     // sweep, find
void bind_inertia(py::module_& m);   // inertia
void bind_modes(py::module_& m);     // modes
void bind_commands(py::module_& m);  // run_cli: `python3 -m tumble`

// A scenario given as (source, is_text, name): a file's path, or YAML text that `name` names in
// messages (and whose mesh files are found relative to the current directory).
struct ScenarioSource {
  std::string source;
  bool is_text = false;
  std::string name;
  std::string text() const;  // reads the file; a ScenarioError at line 0 if it cannot
  std::string path() const { return is_text ? name : source; }
};

// Python's set={name: value} as the command line's --set: each value is an expression's text.
using Overrides = std::vector<std::pair<std::string, std::string>>;
std::vector<ParameterOverride> to_overrides(const Overrides& overrides);

}  // namespace tumble::python
