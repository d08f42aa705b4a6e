// The analyses of sbanalyze for Python (docs/python.md, "Analyses"): options parsed by the command
// line's own parser (the same names, defaults and messages), then the registry's stages on one
// packing (pipeline/file_analysis), exactly as sbanalyze runs them; results as dicts by group.
#include "bindings.hpp"

#include "cli/command_line.hpp"
#include "contacts/contact_types.hpp"
#include "order/order_metrics.hpp"
#include "parallel/parallel.hpp"
#include "pipeline/analysis_registry.hpp"
#include "pipeline/file_analysis.hpp"
#include "pipeline/option_table.hpp"
#include "pipeline/run.hpp"
#include "pores/distance_transform.hpp"
#include "progress/progress.hpp"
#include "voxels/voxelization.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace sbpack::python {

namespace {

/// sbanalyze's report, split into its messages: a line that starts "sbanalyze: " starts one,
/// the lines after it (a warning's indented detail, e.g. the gaps of unresolved contacts)
/// continue it; blank lines are dropped.
std::vector<std::string> reportMessages(const std::string& report) {
    std::vector<std::string> messages;
    std::istringstream in(report);
    for (std::string line; std::getline(in, line);) {
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        if (line.starts_with("sbanalyze: ") || messages.empty())
            messages.push_back(line);
        else
            messages.back() += "\n" + line;
    }
    return messages;
}

/// The report in Python: each warning one RuntimeWarning, raised at the line that called the
/// sbpack wrapper (stack level 2); stage lines to sys.stderr, as on the command line.
void reportInPython(const std::string& report) {
    for (const std::string& message : reportMessages(report)) {
        if (message.starts_with("sbanalyze: ") && !message.starts_with("sbanalyze: warning: "))
            py::print(message, py::arg("file") = py::module_::import("sys").attr("stderr"));
        else if (PyErr_WarnEx(PyExc_RuntimeWarning, message.c_str(), 2) != 0)
            throw py::error_already_set();
    }
}

class Analyzer {
  public:
    /// `args`: sbanalyze's options without files, e.g. {"--compute", "sq", "--qmax", "20"}.
    explicit Analyzer(const std::vector<std::string>& args)
        : settings_(parseAnalyzeArguments(args)) {}

    /// {"file": files/<i> attributes, "<group>": the group, ...} for one packing.
    py::dict compute(const Packing& packing, const std::string& input) const {
        checkPackingForRun(packing, settings_, input);
        std::ostringstream warnings;
        FileResults results;
        runInterruptibly([&](const StopRequest& stop) {   // Ctrl-C: at the next chunk
            const ThreadBudget budget(settings_.threads); // on the thread that computes
            const Progress progress(nullptr, &warnings, stop);
            results = analyzeFile(packing, input, settings_, progress);
        });
        reportInPython(warnings.str());
        py::dict groups;
        groups["file"] = recordToDict(results.root);
        for (const schema::Record& g : results.groups)
            groups[py::str(std::string(g.group().name))] = recordToDict(g);
        return groups;
    }

    std::string analyses() const { return analysisNames(settings_.analyses); }
    int threads() const { return settings_.threads; }

  private:
    RunSettings settings_;
};

/// A whole sbanalyze run (pipeline/run: every input checked first, the ensembles, the results
/// file written atomically at the end); `args` as the command line's.
void analyzeFiles(const std::vector<std::string>& args) {
    const RunSettings settings = parseAnalyzeArguments(args);
    std::ostringstream log;
    std::ostringstream out;
    runInterruptibly([&](const StopRequest& stop) { runAnalyses(settings, log, out, stop); });
    reportInPython(log.str());
}

/// The plane x = (i + 1/2) a of the voxelization on an M^3 grid and of its pore-size map (the
/// stages' Voxelizer and periodicDistanceTransform): (solid[j, k], pore size in length units,
/// 0 in the solid), for the figure of a packing slice (sbpack.plot).
py::tuple voxelSlice(const Packing& packing, int voxels, int plane, int threads) {
    Voxelizer::checkResolution(packing, voxels);
    const AnalysedPacking analysed(packing); // in its length unit, as the stages see it
    if (plane < 0 || plane >= voxels)
        throw std::invalid_argument("plane " + std::to_string(plane) + " is not in [0, " +
                                    std::to_string(voxels) + ")");
    const auto m = static_cast<std::size_t>(voxels);
    std::vector<std::uint8_t> mask(m * m * m);
    std::vector<double> distance(m * m);
    runInterruptibly([&](const StopRequest& stop) {
        const ThreadBudget budget(threads);
        const Progress progress(nullptr, nullptr, stop);
        Voxelizer({voxels}).compute(analysed.packing(), progress).copySolidMask(mask, progress);
        const PoreSizeMap map = periodicDistanceTransform(
            mask, voxels, analysed.packing().boxLength / voxels, progress);
        const auto d2 = map.squaredDistances().subspan(plane * m * m, m * m);
        for (std::size_t i = 0; i < m * m; ++i) // in the packing's units
            distance[i] =
                std::sqrt(static_cast<double>(d2[i])) * map.voxelSize() * analysed.lengthUnit();
    });
    const auto n = static_cast<py::ssize_t>(m);
    py::array_t<std::uint8_t> solid({n, n});
    std::copy_n(mask.begin() + static_cast<std::ptrdiff_t>(plane * m * m), m * m,
                solid.mutable_data());
    py::array_t<double> pores({n, n});
    std::copy(distance.begin(), distance.end(), pores.mutable_data());
    return py::make_tuple(solid, pores);
}

/// The registry's rows (pipeline/analysis_registry.hpp), from which sbpack's analysis classes
/// are written out (python/generate_analysis_classes.py).
py::list registryRows() {
    py::list rows;
    for (const AnalysisInfo& info : analysisRegistry()) {
        if (info.pythonClass.empty()) continue;
        py::list groups, options;
        for (const schema::Group* g : info.groups)
            groups.append(std::string(g->name));
        for (std::string_view option : analysisOptions(info))
            options.append(std::string(option));
        py::list needGroups;
        for (Analysis need : runOrder(resolveAnalyses(info.name)))
            if (need != info.analysis)
                for (const schema::Group* g : analysisInfo(need).groups)
                    needGroups.append(std::string(g->name));
        py::dict row;
        row["name"] = std::string(info.name);
        row["python_class"] = std::string(info.pythonClass);
        row["description"] = std::string(info.description);
        row["groups"] = groups;
        row["options"] = options;
        row["need_groups"] = needGroups;
        rows.append(row);
    }
    return rows;
}

/// The option table (pipeline/option_table.hpp): each option's name, value name, default and help
/// as the command line prints them, for the analysis classes' docstrings.
py::dict optionRows() {
    const RunSettings defaults = defaultRunSettings();
    py::dict rows;
    for (const OptionRow& row : analysisOptionTable()) {
        py::dict entry;
        entry["value"] = std::string(row.valueName);
        entry["default"] = row.shownValue != nullptr ? row.shownValue(defaults) : "";
        entry["help"] = optionHelp(row, defaults);
        entry["dependent_default"] = row.dependentDefault != nullptr;
        rows[py::str(std::string(row.name))] = entry;
    }
    return rows;
}

} // namespace

void registerAnalyses(py::module_& m) {
    py::class_<Analyzer>(m, "Analyzer",
                         "sbanalyze's analyses on one packing at a time; options as the command "
                         "line's (docs/python.md)")
        .def(py::init<const std::vector<std::string>&>(), py::arg("args"))
        .def("compute", &Analyzer::compute, py::arg("packing"), py::arg("input") = "<python>")
        .def_property_readonly("analyses", &Analyzer::analyses)
        .def_property_readonly("threads", &Analyzer::threads);
    m.def("analysis_registry", &registryRows,
          "sbanalyze's analyses: name (--compute), python_class, description, groups (its own "
          "first), need_groups (those of the analyses it needs) and options (the command line's, "
          "without --, besides threads)");
    py::dict thresholds; // order/order_metrics.hpp; docs/order-metrics.md §5
    thresholds["q6_local_mean"] = kOrderedLocalQ6;
    thresholds["T"] = kOrderedT;
    thresholds["P4"] = kOrderedP4;
    thresholds["solid_like_fraction"] = kOrderedSolidFraction;
    thresholds["crystal_cluster_fraction"] = kOrderedCrystalCluster;
    m.attr("order_thresholds") = thresholds;
    m.attr("mrj_local_q6") = py::make_tuple(kMrjLocalQ6Low, kMrjLocalQ6High);
    py::dict regions; // contacts/contact_types.hpp; docs/contact-types.md Eq. 2.4
    for (std::size_t r = 0; r < kContactRegions; ++r)
        regions[py::str(std::string(regionName(ContactRegion(r))))] = kUniformRegionFractions[r];
    m.attr("uniform_region_fractions") = regions;
    m.def("analysis_options", &optionRows,
          "sbanalyze's options by name (without --): value (its name; empty for a flag), default "
          "(as --help prints it; empty where it prints none), dependent_default (the default "
          "depends on another option, as the help says) and help");
    m.def("analyze", &analyzeFiles, py::arg("args"),
          "sbanalyze FILE... [options] in-process (args without the program name)");
    m.def("voxel_slice", &voxelSlice, py::arg("packing"), py::arg("voxels"), py::arg("plane"),
          py::arg("threads") = 1,
          "(solid, pore_size): plane x = (plane + 1/2) L / voxels of the voxelization and of "
          "the pore-size map (length units; 0 in the solid), as the pores analysis computes them");
}

} // namespace sbpack::python
