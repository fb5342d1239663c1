// afford.DataError: a mistake in a user's file, raised with where it is
// (.file, .line, .column, 1-based as editors count) and what was expected
// and found (.message). A ValueError, so that `except ValueError` catches it.
#include <exception>

#include "bindings.h"
#include "errors.h"

namespace afford::python {

void bind_errors(py::module_& m) {
  // Kept for the whole process: the translator below raises it.
  static py::exception<DataError> data_error(m, "DataError", PyExc_ValueError);
  data_error.doc() =
      "A mistake in a file you wrote: str(e) is 'file:line:col: expected X, found Y'; "
      ".file (str), .line and .column (int, 1-based; 0 when the mistake is the whole file) and .message (str).";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const DataError& e) {
      py::object error = py::handle(data_error.ptr())(e.what());
      error.attr("file") = e.loc().file;
      error.attr("line") = e.loc().line;
      error.attr("column") = e.loc().column;
      error.attr("message") = e.message();
      PyErr_SetObject(data_error.ptr(), error.ptr());
    }
  });
}

}  // namespace afford::python
