#pragma once
// What the binding files share; python/src/module.cpp registers each area (docs/python.md).
#include "packing/packing.hpp"
#include "schema/record.hpp"
#include "stop/stop_request.hpp"

#include <pybind11/pybind11.h>

#include <functional>

namespace sbpack::python {

namespace py = pybind11;

void registerPacking(py::module_& m);
void registerAnalyses(py::module_& m);
void registerGenerator(py::module_& m);
void registerResults(py::module_& m);

/// A results group as a dict: numbers as float or int, strings as str, datasets as numpy arrays
/// (the schema's names, docs/results-schema.md).
py::dict recordToDict(const schema::Record& record);

/// Runs `work` with the GIL released on a worker thread while this (the calling) thread polls
/// for Python signals every 50 ms; `work` gets this call's own stop request (common/stop), which
/// Ctrl-C makes: then it waits for `work` to stop and raises KeyboardInterrupt. Exceptions of
/// `work` propagate.
void runInterruptibly(const std::function<void(const StopRequest&)>& work);

} // namespace sbpack::python
