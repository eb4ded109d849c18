// ScenarioError crosses into Python as tumble.ScenarioError (python/tumble/_errors.py), with its
// location as attributes, so that a notebook can point at the line as the command line does.
#include "bindings.hpp"

namespace tumble::python {

void bind_errors(py::module_&) {
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const ScenarioError& e) {
      const py::object error_class = py::module_::import("tumble._errors").attr("ScenarioError");
      const py::object error =
          error_class(e.what(), e.where().file, e.where().line, e.where().column, e.key(), e.why());
      PyErr_SetObject(error_class.ptr(), error.ptr());
    }
  });
}

}  // namespace tumble::python
