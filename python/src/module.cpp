// The compiled half of the Python package `afford` (python/afford/__init__.py
// re-exports it with documentation and type stubs).
#include "bindings.h"

PYBIND11_MODULE(_afford, m) {
  m.doc() = "afford's C++ engine: sessions, stepping, explore, gap, checks (use the package `afford`)";
  afford::python::bind_errors(m);
  afford::python::bind_model(m);
  afford::python::bind_stepping(m);
  afford::python::bind_explore(m);
  afford::python::bind_reports(m);
}
