// ScenarioError crosses into Python as tumble.ScenarioError (python/tumble/_errors.py), with its
// location as attributes, so that a notebook can point at the line as the command line does;
// NotSteady (tumble modes' exit status 6) as tumble.NotSteadyError.
#include "bindings.hpp"
#include "tumble/modes/not_steady.hpp"

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
    } catch (const NotSteady& e) {
      const py::object error_class = py::module_::import("tumble._errors").attr("NotSteadyError");
      PyErr_SetObject(error_class.ptr(), error_class(e.what()).ptr());
    }
  });
}

}  // namespace tumble::python
