// C++ errors as Python exceptions: a refused scenario is
// breakshot.ScenarioError (a ValueError with .path and .reason);
// std::invalid_argument is ValueError (pybind11's own translation).
#include "bind.hpp"

namespace breakshot::python {

void bind_errors(py::module_& m) {
  (void)m;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ScenarioRefused& e) {
      py::object cls = py::module_::import("breakshot.errors").attr("ScenarioError");
      py::object err = cls(e.error.path, e.error.reason, e.error.unsupported);
      PyErr_SetObject(cls.ptr(), err.ptr());
    }
  });
}

}  // namespace breakshot::python
