// sbpack.generate: sbgen's jamming protocol in-process (generator/protocol, docs/python.md,
// "Generator"); a progress callback and Ctrl-C between windows, where the state is synchronised.
#include "bindings.hpp"

#include "protocol/final_packing.hpp"
#include "protocol/jamming_protocol.hpp"
#include "protocol/protocol_advice.hpp"

#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <map>
#include <optional>
#include <string>

namespace sbpack::python {

namespace {

const char* phaseName(Phase phase) {
    return phase == Phase::Fast ? "fast" : phase == Phase::Slow ? "slow" : "done";
}

py::dict statusDict(const ProtocolStatus& s) {
    py::dict d;
    d["phase"] = phaseName(s.phase);
    d["phi"] = s.packingFraction;
    d["reduced_pressure"] = s.reducedPressure;
    d["collisions"] = s.collisions;
    d["windows"] = s.windows;
    d["wall_s"] = s.wallSeconds;
    return d;
}

/// The protocol's validation, its parameters named by generate's keywords.
void validateAsKeywords(const ProtocolParameters& parameters) {
    static const std::map<std::string, std::string> kKeyword = {
        {"n_particles", "n"}, {"collisions_per_window", "window"}};
    try {
        parameters.validate();
    } catch (const ProtocolParameterError& e) {
        const auto it = kKeyword.find(e.parameter());
        throw py::value_error((it == kKeyword.end() ? e.parameter() : it->second) + ": " +
                              e.problem());
    }
}

/// Runs the protocol with the GIL released; after each window, with the GIL: Python's signals
/// (Ctrl-C stops the run at the end of the window) and `progress` every `interval` seconds.
bool runProtocol(JammingProtocol& protocol, const py::object& progress, double interval) {
    StopRequest stop; // this call's (common/stop/stop_request.hpp)
    auto last = std::chrono::steady_clock::now();
    py::gil_scoped_release release;
    return protocol.run(
        [&](const ProtocolStatus& s) {
            py::gil_scoped_acquire acquire;
            try {
                if (PyErr_CheckSignals() != 0) throw py::error_already_set();
                const auto now = std::chrono::steady_clock::now();
                if (!progress.is_none() &&
                    (s.phase == Phase::Done ||
                     std::chrono::duration<double>(now - last).count() >= interval)) {
                    progress(statusDict(s));
                    last = now;
                }
            } catch (py::error_already_set& e) {
                e.restore(); // raised once the run has stopped
                stop.request();
            }
        },
        stop);
}

Packing generate(const ProtocolParameters& parameters, const py::object& progress,
                 double interval) {
    validateAsKeywords(parameters);
    for (const std::string& warning : protocolWarnings(parameters)) // as sbgen's, before the run
        if (PyErr_WarnEx(PyExc_RuntimeWarning, warning.c_str(), 1) != 0)
            throw py::error_already_set();
    std::optional<JammingProtocol> started;
    try { // the random start polls Ctrl-C too (about 30 s at N = 1e6, p = 1.5; issue 65 item 3)
        py::gil_scoped_release release;
        started.emplace(parameters, [](int) {
            py::gil_scoped_acquire acquire;
            return PyErr_CheckSignals() == 0;
        });
    } catch (const PlacementStopped&) {
        throw py::error_already_set(); // the KeyboardInterrupt that PyErr_CheckSignals raised
    }
    JammingProtocol& protocol = *started;
    const bool done = runProtocol(protocol, progress, interval);
    if (PyErr_Occurred() != nullptr) throw py::error_already_set();
    if (!done) throw std::logic_error("sbpack.generate: the protocol stopped without a reason");
    if (!protocol.status().jam->jammed &&
        PyErr_WarnEx(PyExc_RuntimeWarning,
                     (protocol.status().jam->verdict + " (provenance jammed = 0)").c_str(), 1) != 0)
        throw py::error_already_set();
    return finalPacking(protocol);
}

using Option = std::optional<double>;

/// N from a Python int: ValueError naming n beyond sbgen --n's largest (pybind11 would raise
/// TypeError with its signature for an int beyond C's); small ones are the protocol's to refuse.
int particleCount(const py::int_& n) {
    int overflow = 0;
    const long long value = PyLong_AsLongLongAndOverflow(n.ptr(), &overflow);
    if (overflow != 0 || value > ProtocolParameters::kMostParticles ||
        value < -ProtocolParameters::kMostParticles)
        throw std::invalid_argument("n = " + py::repr(n).cast<std::string>() + " is not in [" +
                                    std::to_string(ProtocolParameters::kFewestParticles) + ", " +
                                    std::to_string(ProtocolParameters::kMostParticles) + "]");
    return static_cast<int>(value);
}

/// A progress callback must be callable (or None) and its interval a time, checked before the run,
/// not after it.
void checkProgress(const py::object& progress, double interval) {
    if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
        throw py::type_error("progress must be a callable taking the status dict, or None, not " +
                             py::repr(progress).cast<std::string>());
    // issue 65 item 8: -1 and NaN called it after every window (22,700 calls).
    if (!(std::isfinite(interval) && interval >= 0.0))
        throw py::value_error(
            "progress_interval = " + py::repr(py::float_(interval)).cast<std::string>() +
            ": must be a finite number of seconds >= 0 (0: after every window)");
}

/// The shape of family `family` (None: the superball), each of its parameters as given in
/// `given` (python/sbpack/_arguments.py passes the family's keywords there: p=1.5) or its
/// fallback, as sbgen's options (--p).
ShapeSpec generatedShape(const py::object& family, const py::dict& given) {
    const auto written =
        family.is_none() ? std::nullopt : std::optional(family.cast<std::string>());
    if (writtenShapeFamily(written) == nullptr)
        throw py::value_error("shape = '" + *written +
                              "': unknown shape family (the families: " + shapeFamilyNames() + ")");
    return ShapeSpec::readOrFallback(written, [&](std::string_view name) -> std::optional<double> {
        const py::str key(std::string(name).c_str());
        if (!given.contains(key)) return std::nullopt;
        if (!py::isinstance<py::float_>(given[key]) && !py::isinstance<py::int_>(given[key]))
            throw py::type_error(
                std::string(name) + " must be a number, not " +
                py::str(py::type::of(given[key]).attr("__name__")).cast<std::string>());
        return given[key].cast<double>();
    });
}

/// The parameters that set the expected cost (expected_collisions's keywords). Options left None
/// keep ProtocolParameters' defaults, which are sbgen's.
ProtocolParameters costParameters(const py::int_& n, const py::object& shape,
                                  const py::dict& shapeParameters, Option gammaSlow, Option speed,
                                  Option pressureSwitch, Option pressureFinal) {
    ProtocolParameters parameters;
    parameters.particles = particleCount(n);
    parameters.shape = generatedShape(shape, shapeParameters);
    if (gammaSlow) parameters.gammaSlow = gammaSlow;
    parameters.speed = speed.value_or(parameters.speed);
    parameters.pressureSwitch = pressureSwitch.value_or(parameters.pressureSwitch);
    parameters.pressureFinal = pressureFinal.value_or(parameters.pressureFinal);
    return parameters;
}

} // namespace

void registerGenerator(py::module_& m) {
    m.def(
        "generate",
        [](const py::int_& n, const py::object& shape, const py::dict& shapeParameters,
           std::uint64_t seed, Option phiInit, Option gammaFast, Option gammaSlow, Option speed,
           Option pressureSwitch, Option pressureFinal, Option window, Option costLimit,
           Option sizeRatio, Option largeFraction, Option polydispersity,
           const py::object& progress, double progressInterval) {
            checkProgress(progress, progressInterval);
            // Options left None keep ProtocolParameters' defaults, which are sbgen's.
            ProtocolParameters parameters = costParameters(n, shape, shapeParameters, gammaSlow,
                                                           speed, pressureSwitch, pressureFinal);
            parameters.seed = seed;
            parameters.sizeRatio = sizeRatio.value_or(parameters.sizeRatio); // docs/mixtures.md
            parameters.largeFraction = largeFraction.value_or(parameters.largeFraction);
            parameters.polydispersity = polydispersity.value_or(parameters.polydispersity);
            parameters.phiInit = phiInit.value_or(parameters.phiInit);
            if (gammaFast) parameters.gammaFast = gammaFast;
            parameters.collisionsPerWindow = window.value_or(parameters.collisionsPerWindow);
            parameters.costLimit = costLimit.value_or(parameters.costLimit);
            return generate(parameters, progress, progressInterval);
        },
        py::kw_only(), py::arg("n") = 1000, py::arg("shape") = py::none(),
        py::arg("parameters") = py::dict(), py::arg("seed") = 1, py::arg("phi_init") = py::none(),
        py::arg("gamma_fast") = py::none(), py::arg("gamma_slow") = py::none(),
        py::arg("speed") = py::none(), py::arg("pressure_switch") = py::none(),
        py::arg("pressure_final") = py::none(), py::arg("window") = py::none(),
        py::arg("cost_limit") = py::none(), py::arg("size_ratio") = py::none(),
        py::arg("large_fraction") = py::none(), py::arg("polydispersity") = py::none(),
        py::arg("progress") = py::none(), py::arg("progress_interval") = 2.0,
        "Jams a packing as sbgen does with the same options and defaults (docs/python.md); "
        "the shape by its family (shape=None: the superball) and its parameters by name (p=1.5, "
        "as sbgen's --p; default 1: spheres); "
        "size_ratio, large_fraction and polydispersity make a mixture as sbgen's --size-ratio, "
        "--large-fraction and --polydispersity (docs/mixtures.md); progress(status) every "
        "progress_interval seconds; Ctrl-C stops at the end of the running window");
    m.def(
        "expected_collisions",
        [](const py::int_& n, const py::object& shape, const py::dict& shapeParameters,
           Option gammaSlow, Option speed, Option pressureSwitch, Option pressureFinal) {
            const ProtocolParameters parameters = costParameters(
                n, shape, shapeParameters, gammaSlow, speed, pressureSwitch, pressureFinal);
            validateAsKeywords(parameters);
            return expectedCost(parameters).collisions;
        },
        py::kw_only(), py::arg("n") = 1000, py::arg("shape") = py::none(),
        py::arg("parameters") = py::dict(), py::arg("gamma_slow") = py::none(),
        py::arg("speed") = py::none(), py::arg("pressure_switch") = py::none(),
        py::arg("pressure_final") = py::none(),
        "The collisions sbgen expects of this protocol (docs/design.md §3, \"Expected cost\"; "
        "provenance expected_collisions); cost_limit is a multiple of it");
}

} // namespace sbpack::python
