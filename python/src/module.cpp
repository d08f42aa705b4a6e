// The extension module sbpack._sbpack (docs/python.md): one binding file per area. C++ errors
// become Python exceptions: std::invalid_argument (pybind11's default), InvalidPacking and
// std::domain_error are ValueError; PackingFileError and OutputPathError are OSError; Interrupted
// is KeyboardInterrupt.
#include "bindings.hpp"
#include "cli/option_suggestion.hpp"
#include "io/atomic_file.hpp"
#include "io/packing_io.hpp"
#include "packing/validation.hpp"
#include "progress/progress.hpp"
#include "version.hpp"

#include <pybind11/stl.h>

namespace {

void translateErrors() {
    pybind11::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const sbpack::InvalidPacking& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const sbpack::PackingFileError& e) {
            PyErr_SetString(PyExc_OSError, e.what());
        } catch (const sbpack::OutputPathError& e) {
            PyErr_SetString(PyExc_OSError, e.what());
        } catch (const sbpack::Interrupted& e) {
            PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
        }
    });
}

} // namespace

PYBIND11_MODULE(_sbpack, m) {
    m.doc() = "sbpack C++ core: packings, analyses, generator (docs/python.md)";
    m.attr("__version__") = sbpack::kVersion;
    translateErrors();
    sbpack::python::registerPacking(m);
    sbpack::python::registerResults(m);
    sbpack::python::registerAnalyses(m);
    sbpack::python::registerGenerator(m);
    // The rule for mistyped options, for sbpack's Python keywords too (python/sbpack/_arguments.py)
    m.def("closest_options", &sbpack::closestOptions, pybind11::arg("given"),
          pybind11::arg("known"),
          "The known options nearest a mistyped one (sbgen's and sbanalyze's rule)");
}
