// sbpack.Packing: the packing model of common/packing, read and written by common/io, built from
// numpy arrays with the file readers' checks (docs/python.md, "Packing").
#include "bindings.hpp"

#include "io/packing_formats.hpp"
#include "io/packing_io.hpp"
#include "packing/validation.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace sbpack::python {

namespace {

namespace fs = std::filesystem;
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The HDF5 reader's message for a misshapen dataset (common/io/hdf5_handles.cpp):
/// "'<source>': dataset '/positions': has shape 5 x 2, expected 5 x 3"; `rows` < 0: any N.
void checkShape(const Array& a, const char* name, py::ssize_t rows, py::ssize_t cols,
                const std::string& source) {
    if (a.ndim() == 2 && (rows < 0 || a.shape(0) == rows) && a.shape(1) == cols) return;
    std::string shape = "rank " + std::to_string(a.ndim());
    if (a.ndim() == 2) shape = std::to_string(a.shape(0)) + " x " + std::to_string(a.shape(1));
    std::string expected = std::to_string(rows) + " x " + std::to_string(cols);
    if (rows < 0) {
        const bool transposed = a.ndim() == 2 && a.shape(0) == cols;
        expected = "N x " + std::to_string(cols) + " (one row per particle" +
                   (transposed ? "; transposed?)" : ")");
    }
    throw InvalidPacking("'" + source + "': dataset '/" + name + "': has shape " + shape +
                         ", expected " + expected);
}

/// Refuses a string that C++ messages would cut short at an embedded NUL.
void checkNoNul(const std::string& text, const char* what) {
    if (text.find('\0') != std::string::npos)
        throw std::invalid_argument(std::string(what) + " contains a NUL character");
}

/// `object` as an array of doubles if it holds real numbers (a float or integer dtype): a cast
/// would read booleans as 0 and 1 and drop the imaginary part of complex numbers (issue 65 item 8).
Array realArray(const py::object& object, const char* name, const std::string& source) {
    const py::array array = py::array::ensure(object);
    const char kind = array ? array.dtype().kind() : 'O';
    if (kind != 'f' && kind != 'i' && kind != 'u')
        throw py::type_error("'" + source + "': " + name + " must hold real numbers, not " +
                             (array ? "dtype " + py::str(array.dtype()).cast<std::string>()
                                    : py::repr(object.get_type()).cast<std::string>()));
    return Array::ensure(array);
}

/// The shape of family `family` (None: the superball), each parameter read by name from
/// `parameters` (ShapeSpec::read): TypeError for a missing one, ValueError naming `source` for
/// an unknown family.
ShapeSpec shapeFrom(const py::object& family, const py::dict& parameters,
                    const std::string& source) {
    const auto written =
        family.is_none() ? std::nullopt : std::optional(family.cast<std::string>());
    try {
        return ShapeSpec::read(written, [&](std::string_view name) {
            const py::str key(std::string(name).c_str());
            if (!parameters.contains(key))
                throw py::type_error("Packing.__init__() missing the " +
                                     written.value_or("superball") + "'s keyword argument '" +
                                     std::string(name) + "'");
            return parameters[key].cast<double>();
        });
    } catch (const std::invalid_argument& e) {
        throw py::value_error("'" + source + "': " + e.what());
    }
}

/// A packing from arrays, validated and canonicalised as the readers do (common/io).
Packing fromArrays(const py::object& positionsObject, const py::object& orientationsObject,
                   double boxLength, double semiAxis, const py::object& semiAxesObject,
                   const std::string& source, const py::object& family,
                   const py::dict& parameters) {
    checkNoNul(source, "source");
    const Array positions = realArray(positionsObject, "positions", source);
    const Array orientations = realArray(orientationsObject, "orientations", source);
    checkShape(positions, "positions", -1, 3, source);
    const py::ssize_t n = positions.shape(0);
    checkShape(orientations, "orientations", n, 4, source);
    Packing packing;
    packing.shapeSpec = shapeFrom(family, parameters, source);
    packing.boxLength = boxLength;
    packing.semiAxis = semiAxis;
    const auto r = positions.unchecked<2>();
    const auto q = orientations.unchecked<2>();
    for (py::ssize_t i = 0; i < n; ++i) {
        packing.positions.emplace_back(r(i, 0), r(i, 1), r(i, 2));
        packing.orientations.emplace_back(q(i, 0), q(i, 1), q(i, 2), q(i, 3));
    }
    if (!semiAxesObject.is_none()) { // a mixture's (docs/mixtures.md)
        const Array semiAxes = realArray(semiAxesObject, "semi_axes", source);
        if (semiAxes.ndim() != 1 || semiAxes.shape(0) != n)
            throw py::value_error("'" + source + "': semi_axes must have shape (" +
                                  std::to_string(n) + ",), one per particle");
        const auto a = semiAxes.unchecked<1>();
        for (py::ssize_t i = 0; i < n; ++i)
            packing.semiAxes.push_back(a(i));
    }
    validatePacking(packing, source);
    canonicalizePacking(packing);
    return packing;
}

Packing read(const fs::path& file) {
    py::gil_scoped_release release;
    return readPackingFile(file);
}

void write(const Packing& packing, const fs::path& file) {
    py::gil_scoped_release release; // an unknown extension is refused as convert refuses it
    writePackingFile(packing, file);
}

/// `a` made read-only: the arrays are copies, so an edit would be lost without a word (issue 66
/// item 6); a new packing is made from edited copies.
py::array_t<double> readOnly(py::array_t<double> a) {
    a.attr("setflags")(py::arg("write") = false);
    return a;
}

py::array_t<double> positionsOf(const Packing& packing) {
    py::array_t<double> a({static_cast<py::ssize_t>(packing.size()), py::ssize_t(3)});
    auto v = a.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < v.shape(0); ++i)
        for (py::ssize_t k = 0; k < 3; ++k)
            v(i, k) = packing.positions[i][k];
    return readOnly(std::move(a));
}

/// (w, x, y, z) per row, as the packing file.
py::array_t<double> orientationsOf(const Packing& packing) {
    py::array_t<double> a({static_cast<py::ssize_t>(packing.size()), py::ssize_t(4)});
    auto v = a.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < v.shape(0); ++i) {
        const Quaterniond& q = packing.orientations[i];
        v(i, 0) = q.w();
        v(i, 1) = q.x();
        v(i, 2) = q.y();
        v(i, 3) = q.z();
    }
    return readOnly(std::move(a));
}

/// Each particle's semi-axis R_i (a mixture's, docs/mixtures.md; semi_axis for every one of
/// identical particles).
py::array_t<double> semiAxesOf(const Packing& packing) {
    py::array_t<double> a(static_cast<py::ssize_t>(packing.size()));
    auto v = a.mutable_unchecked<1>();
    for (py::ssize_t i = 0; i < v.shape(0); ++i)
        v(i) = packing.semiAxisOf(static_cast<std::size_t>(i));
    return readOnly(std::move(a));
}

/// The shape's family under "shape" and each of its parameters by name.
py::dict shapeOf(const Packing& packing) {
    py::dict d;
    d["shape"] = std::string(packing.shapeSpec.info().name);
    for (const auto& [name, value] : packing.shapeSpec.namedValues())
        d[py::str(std::string(name))] = value;
    return d;
}

/// Every shape family's name with its parameters' names, the superball first.
py::dict shapeFamiliesOf() {
    py::dict d;
    for (const ShapeFamily& family : shapeFamilies()) {
        py::list names;
        for (const ShapeParameter& parameter : family.parameters)
            names.append(std::string(parameter.name));
        d[py::str(std::string(family.name))] = names;
    }
    return d;
}

py::dict provenanceOf(const Packing& packing) {
    py::dict d;
    for (const auto& entry : packing.provenance) // (clang 14 captures no structured bindings)
        std::visit([&d, &entry](const auto& v) { d[py::str(entry.first)] = v; }, entry.second);
    return d;
}

} // namespace

void registerPacking(py::module_& m) {
    m.def("shape_families", &shapeFamiliesOf,
          "Every shape family's name with its parameters' names, the superball first");
    py::class_<Packing>(m, "Packing",
                        "Particles of one shape (superballs of one p) in a cubic periodic box: "
                        "identical, or a mixture of sizes")
        .def(py::init(&fromArrays), py::arg("positions"), py::arg("orientations"),
             py::arg("box_length"), py::kw_only(), py::arg("semi_axis"),
             py::arg("semi_axes") = py::none(), py::arg("source") = "arrays",
             py::arg("shape") = py::none(), py::arg("parameters") = py::dict(),
             "From N x 3 positions and N x 4 unit quaternions (w, x, y, z), the shape's "
             "parameters (p) and semi_axis given by keyword (no default: a packing's grown size "
             "is its own, docs/python.md), shape= naming a family other than the superball; a "
             "mixture's N semi_axes by keyword too, semi_axis their largest "
             "(docs/mixtures.md); checked as the file readers check (ValueError with their "
             "message, naming `source`)")
        .def_static("read", &read, py::arg("path"), "Reads a .h5 (or .txt) packing file")
        .def("write", &write, py::arg("path"),
             "Writes .h5, .txt, .xyz (OVITO), .gsd (HOOMD, freud, OVITO), .dump or .data (LAMMPS), "
             "atomically")
        .def_property_readonly("positions", &positionsOf,
                               "N x 3 centroids in [0, L), a read-only copy")
        .def_property_readonly("orientations", &orientationsOf,
                               "N x 4 quaternions (w, x, y, z), a read-only copy")
        .def_readonly("box_length", &Packing::boxLength)
        .def_property_readonly(
            "p",
            [](const Packing& p) {
                for (const auto& [name, value] : p.shapeSpec.namedValues())
                    if (name == "p") return value;
                throw py::attribute_error("a " + std::string(p.shapeSpec.info().name) +
                                          " has no p: see shape");
            },
            "the superball exponent (paper Eq. 1)")
        .def_property_readonly("shape", &shapeOf,
                               "the shape's family under 'shape' and its parameters by name")
        .def_readonly("semi_axis", &Packing::semiAxis)
        .def_property_readonly("semi_axes", &semiAxesOf,
                               "N semi-axes R_i, a read-only copy: a mixture's sizes "
                               "(docs/mixtures.md), semi_axis (their largest) repeated where the "
                               "particles are identical")
        .def_property_readonly("is_mixture", &Packing::isMixture,
                               "whether it has per-particle sizes")
        .def_readonly("reduced_pressure", &Packing::reducedPressure)
        .def_readonly("seed", &Packing::seed)
        .def_property_readonly("phi", &Packing::packingFraction, "sum_i v_i / L^3 (N v1 / L^3)")
        .def_property_readonly(
            "mean_width", [](const Packing& p) { return p.shape().meanWidth(); },
            "mean width w of one particle (the largest of a mixture)")
        .def_property_readonly("provenance", &provenanceOf, "sbgen's parameters and run log")
        .def("__len__", &Packing::size)
        .def("__repr__", [](const Packing& p) {
            std::string text = "<sbpack.Packing N=" + std::to_string(p.size());
            if (const auto family = p.shapeSpec.writtenFamily())
                text += " shape=" + std::string(*family);
            for (const auto& [name, value] : p.shapeSpec.namedValues())
                text.append(" ").append(name).append("=").append(
                    py::repr(py::float_(value)).cast<std::string>());
            return text + " phi=" + py::repr(py::float_(p.packingFraction())).cast<std::string>() +
                   ">";
        });
}

} // namespace sbpack::python
