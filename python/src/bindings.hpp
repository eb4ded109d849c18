#pragma once
// The compiled half of the Python module, tumble._tumble: each bind_* adds one part of it. The
// public API, with its docstrings and type hints, is python/tumble/__init__.py, which calls these.
#include <pybind11/pybind11.h>

#include <chrono>
#include <optional>

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

// Python's signals while a run or a sweep holds no GIL: called often (after each step, or ten
// times a second), at most every 50 ms of wall time it takes the GIL and lets Python run its
// handlers (Ctrl-C's raises KeyboardInterrupt). True when a handler raised: the caller stops,
// and raises the exception kept here once it holds the GIL again.
class SignalWatch {
 public:
  bool operator()() {
    const auto now = std::chrono::steady_clock::now();
    if (now < next_check_) return false;
    next_check_ = now + std::chrono::milliseconds(50);
    const py::gil_scoped_acquire held;
    if (PyErr_CheckSignals() == 0) return false;
    raised_.emplace();  // takes the pending exception
    return true;
  }
  std::optional<py::error_already_set>& raised() { return raised_; }

 private:
  std::chrono::steady_clock::time_point next_check_ = std::chrono::steady_clock::now();
  std::optional<py::error_already_set> raised_;
};

}  // namespace tumble::python
