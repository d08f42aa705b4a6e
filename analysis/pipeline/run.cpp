#include "pipeline/run.hpp"

#include "io/atomic_file.hpp"
#include "io/naming_file.hpp"
#include "io/packing_formats.hpp"
#include "io/packing_io.hpp"
#include "parallel/parallel.hpp"
#include "pipeline/record_bytes.hpp"
#include "pipeline/resources.hpp"
#include "pipeline/scale_plan.hpp"
#include "pipeline/stages/stages.hpp"
#include "pipeline/summary_json.hpp"
#include "voxels/voxelization.hpp"

#include <fmt/format.h>
#include <sys/stat.h>

#include <fstream>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace sbpack {

namespace fs = std::filesystem;

namespace {

std::string quotedName(const fs::path& file) {
    return fmt::format("'{}'", file.string());
}

/// Rethrows `e` with its message prefixed by the file's quoted name, unless it names the file
/// already (readers do); invalid input stays std::invalid_argument (issue 65 item 5: an
/// analysis's own message, e.g. the order metrics', named no file).
[[noreturn]] void rethrowNamingFile(const fs::path& file, const std::exception& e) {
    const std::string what = e.what(), named = messageNamingFile(what, file.string());
    if (named == what) throw;
    if (dynamic_cast<const std::invalid_argument*>(&e) != nullptr)
        throw std::invalid_argument(named);
    throw std::runtime_error(named);
}

/// "[2/5] packing.h5": the prefix of a file's progress lines.
std::string fileContext(std::size_t index, std::size_t count, const fs::path& file) {
    return fmt::format("[{}/{}] {}", index + 1, count, file.string());
}

/// The analyses of the run that export a grid with --vdb (AnalysisInfo::vdbSuffix).
std::vector<const AnalysisInfo*> exporters(const RunSettings& settings, std::string& names) {
    std::vector<const AnalysisInfo*> run;
    for (const AnalysisInfo& info : analysisRegistry()) {
        if (info.vdbSuffix.empty()) continue;
        names += (names.empty() ? "" : " or ") + std::string(info.name);
        const bool noMap = info.analysis == Analysis::PoreSizes &&
                           settings.poreMethod() == PoreMethod::Exact; // no voxels, no map
        if (settings.runs(info.analysis) && !noMap) run.push_back(&info);
    }
    return run;
}

/// Where each input's grids are exported: DIR/<stem><suffix> per analysis with a vdbSuffix
/// (".vdb" for the voxels, "-pore-size.vdb" for the pore-size map); stems must differ. Nothing
/// without --vdb.
std::vector<std::map<Analysis, fs::path>> vdbTargets(const RunSettings& settings) {
    std::vector<std::map<Analysis, fs::path>> targets(settings.inputs.size());
    if (settings.vdbDirectory.empty()) return targets;
    std::string names;
    const std::vector<const AnalysisInfo*> run = exporters(settings, names);
    if (run.empty())
        throw std::invalid_argument("option --vdb: exports the " + names +
                                    " analyses, and none is run");
    std::error_code ec;
    if (!fs::is_directory(settings.vdbDirectory, ec))
        throw std::invalid_argument("option --vdb: " + quotedName(settings.vdbDirectory) +
                                    " is not a directory");
    std::set<fs::path> seen;
    for (std::size_t i = 0; i < settings.inputs.size(); ++i)
        for (const AnalysisInfo* info : run) {
            fs::path target = settings.vdbDirectory / settings.inputs[i].stem();
            target += std::string(info->vdbSuffix);
            if (!seen.insert(target).second)
                throw std::invalid_argument("option --vdb: two inputs would both be exported to " +
                                            quotedName(target));
            checkWritable(target);
            targets[i][info->analysis] = std::move(target);
        }
    return targets;
}

/// The results and JSON files are none of the .vdb exports (each would replace the other).
void checkNotExported(const RunSettings& settings, const std::vector<fs::path>& outputs) {
    for (const std::map<Analysis, fs::path>& exports : vdbTargets(settings))
        for (const auto& [analysis, target] : exports)
            for (const fs::path& output : outputs)
                if (sameDestination(output, target))
                    throw std::invalid_argument("output " + quotedName(output) +
                                                " is also where --vdb exports " +
                                                std::string(analysisInfo(analysis).name) +
                                                ": name another file or --vdb directory");
}

/// The outputs can be written and overwrite neither each other, an export nor an input.
void checkOutputs(const RunSettings& settings) {
    if (settings.output.empty() && settings.json.empty())
        throw std::invalid_argument("nothing to write: give --out RESULTS.h5 and/or --json FILE");
    std::vector<fs::path> outputs;
    if (!settings.output.empty()) outputs.push_back(settings.output);
    if (!settings.json.empty() && settings.json != "-" && !isStreamDevice(settings.json))
        outputs.push_back(settings.json);
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        checkWritable(outputs[i]);
        if (i == 1 && sameDestination(outputs[1], outputs[0]))
            throw std::invalid_argument("--out and --json name the same file " +
                                        quotedName(outputs[i]));
        for (const fs::path& input : settings.inputs) {
            if (fs::weakly_canonical(outputs[i]) == fs::weakly_canonical(input))
                throw std::invalid_argument("output " + quotedName(outputs[i]) +
                                            " is also an input");
            checkNotInput(outputs[i], input, "input");
        }
    }
    checkNotExported(settings, outputs);
}

/// No input is given twice (through links and other spellings): it would count twice in its
/// ensemble, with a standard deviation that says nothing.
void checkDistinctInputs(const RunSettings& settings) {
    std::map<std::pair<dev_t, ino_t>, fs::path> seen;
    for (const fs::path& input : settings.inputs) {
        struct stat status {};
        if (::stat(input.c_str(), &status) != 0) continue; // the reader names a missing file
        const auto [at, fresh] = seen.emplace(std::pair{status.st_dev, status.st_ino}, input);
        if (!fresh)
            throw std::invalid_argument("input " + quotedName(input) + " is the file " +
                                        quotedName(at->second) +
                                        " again: each packing counts once in its ensemble");
    }
}

/// The inputs a rank analyses: all with one rank, --distribute grids or --plan, else every size-th
/// from its rank on (round robin: neighbouring inputs, often alike in cost, go to different
/// ranks).
std::vector<std::size_t> filesOfRank(const RunSettings& settings, const Communicator& comm) {
    std::vector<std::size_t> mine;
    const bool all = settings.distribute == Distribution::Grids || settings.plan;
    for (std::size_t i = all ? 0 : comm.rank(); i < settings.inputs.size();
         i += all ? 1 : comm.size())
        mine.push_back(i);
    return mine;
}

/// Everything that can be checked before the first analysis, so that bad input costs nothing:
/// the inputs of `mine` are read and validated.
std::vector<Packing> readAndCheckInputs(const RunSettings& settings,
                                        const std::vector<std::size_t>& mine) {
    if (settings.inputs.empty()) throw std::invalid_argument("no packing file given");
    std::vector<Packing> packings;
    for (std::size_t i : mine) {
        Packing packing = readPackingFile(settings.inputs[i]);
        checkPackingForRun(packing, settings, settings.inputs[i]);
        packings.push_back(std::move(packing));
    }
    return packings;
}

} // namespace

void checkPackingForRun(const Packing& packing, const RunSettings& settings,
                        const std::filesystem::path& input) {
    for (VoxelGrid grid : settings.grids()) {
        try {
            Voxelizer::checkResolution(packing, settings.voxelsOf(grid));
        } catch (const VoxelResolutionError& e) {
            throw std::invalid_argument(quotedName(input) + ": option " +
                                        (grid == VoxelGrid::Pore ? "--pore-voxels " : "--voxels ") +
                                        std::to_string(settings.voxelsOf(grid)) + ": " + e.what());
        }
    }
    // Distributed grids are checked per rank by the plan (pipeline/scale_plan.hpp).
    if (settings.distribute == Distribution::Files)
        checkMemory(packing, settings, quotedName(input));
}

namespace {

/// "[rank 1] [2/5] packing.h5" with several ranks.
std::string rankContext(const Communicator& comm, std::string context) {
    if (comm.size() == 1) return context;
    return context.empty() ? fmt::format("[rank {}]", comm.rank())
                           : fmt::format("[rank {}] {}", comm.rank(), context);
}

/// Analyses the files `mine` (the packings read for them); grids exported go to temporaries,
/// added to `exports` for the commit. With several inputs or ranks an error names its file.
IndexedFiles analyzeAll(const RunSettings& settings, const std::vector<std::size_t>& mine,
                        const std::vector<Packing>& packings, Progress& progress,
                        std::vector<std::unique_ptr<AtomicOutput>>& exports,
                        const Communicator& comm) {
    const std::vector<std::map<Analysis, fs::path>> vdbFiles = vdbTargets(settings);
    IndexedFiles files;
    for (std::size_t k = 0; k < mine.size(); ++k) {
        const std::size_t i = mine[k];
        progress.setContext(
            rankContext(comm, fileContext(i, settings.inputs.size(), settings.inputs[i])));
        std::map<Analysis, VdbExport> targets;
        for (const auto& [analysis, file] : vdbFiles[i]) {
            exports.push_back(std::make_unique<AtomicOutput>(file));
            targets[analysis] = VdbExport{exports.back().get(), file};
        }
        try {
            files.emplace_back(i, analyzeFile(packings[k], settings.inputs[i], settings, progress,
                                              targets, comm.grids()));
        } catch (const Interrupted&) {
            throw; // not the file's fault: the run's exit status says which signal
        } catch (const std::exception& e) {
            rethrowNamingFile(settings.inputs[i], e);
        }
    }
    progress.setContext(rankContext(comm, ""));
    return files;
}

/// Collective: every rank's files on rank 0, in input order (empty elsewhere). With
/// --distribute grids every rank holds every file and rank 0 keeps its own.
std::vector<FileResults> gatherFiles(IndexedFiles mine, const RunSettings& settings,
                                     const Communicator& comm) {
    std::vector<IndexedFiles> parts;
    if (comm.size() == 1 || settings.distribute == Distribution::Grids) {
        parts.push_back(std::move(mine));
    } else {
        // allGather: every rank takes part in the same collective; only rank 0 decodes. A record
        // refused as incomplete (schema/record.hpp) stops every rank, so that none waits here.
        std::string encoded;
        collectively(comm, [&] { encoded = encodeFiles(mine); });
        const std::vector<std::string> bytes = comm.allGather(encoded);
        if (comm.rank() == 0)
            for (const std::string& b : bytes)
                parts.push_back(decodeFiles(b));
    }
    if (comm.rank() != 0) return {};
    std::vector<FileResults> files(settings.inputs.size());
    for (IndexedFiles& part : parts)
        for (auto& [index, file] : part)
            files.at(index) = std::move(file);
    return files;
}

/// One ensemble per (p, N); a warning when the inputs make more than one.
std::vector<EnsembleResults> ensemblesOf(const std::vector<FileResults>& files,
                                         const Progress& progress) {
    const Stopwatch clock;
    std::vector<EnsembleResults> ensembles = computeEnsembles(files);
    std::string detail;
    for (const EnsembleResults& e : ensembles)
        detail += fmt::format("{}{}, N = {}: {} file(s)", detail.empty() ? "" : "; ",
                              schema::shapeOf(e.root).describe(), e.root.integer("n_particles"),
                              e.members.size());
    if (ensembles.size() > 1)
        progress.warn(fmt::format("the inputs differ in shape or N: {} ensembles, not averaged "
                                  "together ({})",
                                  ensembles.size(), detail));
    progress.stageDone("ensembles", clock.seconds(), detail);
    return ensembles;
}

/// The JSON summary to standard output or a stream device (/dev/null, a FIFO) now, or to a
/// temporary of `settings.json`, returned.
std::unique_ptr<AtomicOutput> writeJson(const RunSettings& settings, const RunResults& results,
                                        std::ostream& out) {
    if (settings.json == "-") writeJsonSummary(out, results, settings);
    if (settings.json.empty() || settings.json == "-") return nullptr;
    std::ostringstream json;
    writeJsonSummary(json, results, settings);
    if (isStreamDevice(settings.json)) {
        writeToStreamDevice(settings.json, json.str());
        return nullptr;
    }
    auto file = std::make_unique<AtomicOutput>(settings.json);
    file->write(json.str());
    return file;
}

} // namespace

RunResults runAnalyses(const RunSettings& settings, std::ostream& log, std::ostream& out,
                       const StopRequest& stop) {
    return runAnalyses(settings, log, out, SerialCommunicator(), stop);
}

namespace {

/// Rank 0: the ensembles, the results file and the JSON summary of the gathered files, committed
/// with the exports.
void writeOutputs(const RunSettings& settings, RunResults& results, const Progress& progress,
                  const Stopwatch& clock, std::ostream& out,
                  std::vector<std::unique_ptr<AtomicOutput>>& exports) {
    results.ensembles = ensemblesOf(results.files, progress);
    results.runtimeSeconds = clock.seconds();
    std::unique_ptr<AtomicOutput> resultsFile;
    if (!settings.output.empty()) {
        resultsFile = std::make_unique<AtomicOutput>(settings.output);
        resultsFile->write(resultsFileImage(settings.output.string(), results, settings));
    }
    const std::unique_ptr<AtomicOutput> jsonFile = writeJson(settings, results, out);
    for (const auto& e : exports)
        e->commit();
    if (jsonFile) jsonFile->commit();
    if (resultsFile) {
        resultsFile->commit();
        progress.stageDone("wrote " + settings.output.string(),
                           clock.seconds() - results.runtimeSeconds);
    }
}

} // namespace

RunResults runAnalyses(const RunSettings& settings, std::ostream& log, std::ostream& out,
                       const Communicator& comm, const StopRequest& stop) {
    const Stopwatch clock;
    const ThreadBudget budget(settings.threads);
    const std::vector<std::size_t> mine = filesOfRank(settings, comm);
    std::vector<Packing> packings;
    collectively(comm, [&] {
        checkDistribution(settings, comm);
        if (!settings.plan) checkOutputs(settings);
        checkDistinctInputs(settings);
        vdbTargets(settings); // option errors before any reading
        packings = readAndCheckInputs(settings, mine);
#ifdef SBPACK_WITH_CUDA
        // The device's memory plan depends on the grids alone: once per run.
        if (settings.device.device == ComputeDevice::Cuda && !settings.plan)
            stages::checkCudaRun(settings);
#endif
        if (settings.distribute == Distribution::Grids && !settings.plan)
            checkPlanMemory(settings, packings, comm.size());
    });
    if (settings.plan) {
        if (comm.rank() == 0) out << planText(settings, packings, mine, comm.size());
        return {};
    }

    Progress progress(settings.quiet ? nullptr : &log, &log, stop);
    RunResults results;
    results.ranks = comm.size();
    std::vector<std::unique_ptr<AtomicOutput>> exports; // committed with the results file
    IndexedFiles analysed;
    collectively(comm,
                 [&] { analysed = analyzeAll(settings, mine, packings, progress, exports, comm); });
    results.files = gatherFiles(std::move(analysed), settings, comm);
    if (comm.rank() == 0) {
        writeOutputs(settings, results, progress, clock, out, exports);
    } else {
        for (const auto& e : exports)
            e->commit();
    }
    return results;
}

} // namespace sbpack
