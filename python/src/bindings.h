// The pieces of the Python module afford._afford, one file each: errors,
// models and runs, stepping, exploring, reports and manifests. module.cpp
// calls each bind_* once.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <vector>

#include "session.h"

namespace afford::python {

namespace py = pybind11;

// A compiled session as Python holds it: shared by the Model object and
// every State made from it, so that a State outlives the Model it came from.
using SessionPtr = std::shared_ptr<CompiledSession>;  // never changed once compiled

// The inferred functions as `afford run --json` prints them (cli/run.cpp):
// [{name, t, explanation: [{t, text, detail?}]}], the times (s) exact.
py::list functions_of(const std::vector<Inference>& inferences);

void bind_errors(py::module_& m);    // afford.DataError and its translation
void bind_model(py::module_& m);     // load, compile, Model, Model.run
void bind_stepping(py::module_& m);  // Model.state(), State.step
void bind_explore(py::module_& m);   // explore
void bind_reports(py::module_& m);   // gap, check, effects, signals, export_mjcf

}  // namespace afford::python
