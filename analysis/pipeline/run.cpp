#include "pipeline/run.hpp"

#include "io/atomic_file.hpp"
#include "io/packing_io.hpp"
#include "parallel/parallel.hpp"
#include "pipeline/resources.hpp"
#include "pipeline/summary_json.hpp"
#include "voxels/voxelization.hpp"

#include <fstream>
#include <memory>
#include <ostream>
#include <set>
#include <stdexcept>

namespace sbpack {

namespace fs = std::filesystem;

namespace {

// Strings are appended piecewise: GCC 12 misreports "literal" + string (-Wrestrict).
std::string quotedName(const fs::path& file) {
    std::string quoted = "'";
    quoted += file.string();
    quoted += '\'';
    return quoted;
}

/// "[2/5] packing.h5": the prefix of a file's progress lines.
std::string fileContext(std::size_t index, std::size_t count, const fs::path& file) {
    std::string context = "[";
    context += std::to_string(index + 1);
    context += '/';
    context += std::to_string(count);
    context += "] ";
    context += file.string();
    return context;
}

/// Where each input's grids are exported with `suffix` (".vdb" for the voxels,
/// "-pore-size.vdb" for the pore-size map): DIR/<stem><suffix>; stems must differ. Empty paths
/// when nothing is exported.
std::vector<fs::path> vdbTargets(const RunSettings& settings, Analysis analysis,
                                 const std::string& suffix) {
    std::vector<fs::path> targets(settings.inputs.size());
    if (settings.vdbDirectory.empty()) return targets;
    if (!settings.runs(Analysis::Voxels) && !settings.runs(Analysis::PoreSizes))
        throw std::invalid_argument(
            "option --vdb: exports the voxels or pores analyses, and neither is run");
    std::error_code ec;
    if (!fs::is_directory(settings.vdbDirectory, ec))
        throw std::invalid_argument("option --vdb: " + quotedName(settings.vdbDirectory) +
                                    " is not a directory");
    if (!settings.runs(analysis)) return targets;
    std::set<fs::path> seen;
    for (std::size_t i = 0; i < settings.inputs.size(); ++i) {
        targets[i] = settings.vdbDirectory / settings.inputs[i].stem();
        targets[i] += suffix;
        if (!seen.insert(targets[i]).second)
            throw std::invalid_argument("option --vdb: two inputs would both be exported to " +
                                        quotedName(targets[i]));
        checkWritable(targets[i]);
    }
    return targets;
}

/// The outputs can be written and overwrite neither each other nor an input.
void checkOutputs(const RunSettings& settings) {
    if (settings.output.empty() && settings.json.empty())
        throw std::invalid_argument("nothing to write: give --out RESULTS.h5 and/or --json FILE");
    std::vector<fs::path> outputs;
    if (!settings.output.empty()) outputs.push_back(settings.output);
    if (!settings.json.empty() && settings.json != "-") outputs.push_back(settings.json);
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        checkWritable(outputs[i]);
        const fs::path target = fs::weakly_canonical(outputs[i]);
        if (i == 1 && target == fs::weakly_canonical(outputs[0]))
            throw std::invalid_argument("--out and --json name the same file " +
                                        quotedName(outputs[i]));
        for (const fs::path& input : settings.inputs)
            if (target == fs::weakly_canonical(input))
                throw std::invalid_argument("output " + quotedName(outputs[i]) +
                                            " is also an input");
    }
}

/// Everything that can be checked before the first analysis, so that bad input costs nothing.
std::vector<Packing> readAndCheckInputs(const RunSettings& settings) {
    if (settings.inputs.empty()) throw std::invalid_argument("no packing file given");
    std::vector<Packing> packings;
    for (const fs::path& input : settings.inputs) {
        Packing packing = readPacking(input);
        for (VoxelGrid grid : settings.grids()) {
            try {
                Voxelizer::checkResolution(packing, settings.voxelsOf(grid));
            } catch (const VoxelResolutionError& e) {
                throw std::invalid_argument(
                    quotedName(input) + ": option " +
                    (grid == VoxelGrid::Pore ? "--pore-voxels " : "--voxels ") +
                    std::to_string(settings.voxelsOf(grid)) + ": " + e.what());
            }
        }
        checkMemory(packing, settings, quotedName(input));
        packings.push_back(std::move(packing));
    }
    return packings;
}

} // namespace

RunResults runAnalyses(const RunSettings& settings, std::ostream& log, std::ostream& out) {
    const Stopwatch clock;
    const ThreadBudget budget(settings.threads);
    checkOutputs(settings);
    const std::vector<fs::path> vdbFiles = vdbTargets(settings, Analysis::Voxels, ".vdb");
    const std::vector<fs::path> poreVdbFiles =
        vdbTargets(settings, Analysis::PoreSizes, "-pore-size.vdb");
    const std::vector<Packing> packings = readAndCheckInputs(settings);

    Progress progress(settings.quiet ? nullptr : &log, &log);
    RunResults results;
    // Exports go to temporaries, committed with the results file.
    std::vector<std::unique_ptr<AtomicOutput>> exports;
    for (std::size_t i = 0; i < packings.size(); ++i) {
        progress.setContext(fileContext(i, packings.size(), settings.inputs[i]));
        const auto exportTo = [&](const fs::path& file) -> std::optional<VdbExport> {
            if (file.empty()) return std::nullopt;
            exports.push_back(std::make_unique<AtomicOutput>(file));
            return VdbExport{exports.back()->temporaryPath(), file};
        };
        const std::optional<VdbExport> vdb = exportTo(vdbFiles[i]);
        const std::optional<VdbExport> poreVdb = exportTo(poreVdbFiles[i]);
        results.files.push_back(
            analyzeFile(packings[i], settings.inputs[i], settings, progress, vdb, poreVdb));
    }
    progress.setContext("");
    if (results.files.size() > 1) {
        const Stopwatch ensembleClock;
        results.ensemble = computeEnsemble(results.files);
        progress.stageDone("ensemble", ensembleClock.seconds(),
                           std::to_string(results.files.size()) + " files");
    }
    results.runtimeSeconds = clock.seconds();

    std::unique_ptr<AtomicOutput> resultsFile;
    if (!settings.output.empty()) {
        resultsFile = std::make_unique<AtomicOutput>(settings.output);
        writeResultsFile(resultsFile->temporaryPath(), results, settings);
    }
    std::unique_ptr<AtomicOutput> jsonFile;
    if (settings.json == "-") {
        writeJsonSummary(out, results, settings);
    } else if (!settings.json.empty()) {
        jsonFile = std::make_unique<AtomicOutput>(settings.json);
        std::ofstream json(jsonFile->temporaryPath());
        writeJsonSummary(json, results, settings);
        json.close();
        if (!json) throw OutputPathError("cannot write " + quotedName(settings.json));
    }
    for (const auto& e : exports)
        e->commit();
    if (jsonFile) jsonFile->commit();
    if (resultsFile) {
        resultsFile->commit();
        progress.stageDone("wrote " + settings.output.string(),
                           clock.seconds() - results.runtimeSeconds);
    }
    return results;
}

} // namespace sbpack
