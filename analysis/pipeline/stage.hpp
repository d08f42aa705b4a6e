#pragma once
// What a stage (one analysis of one file, pipeline/stages/) works with: the packing, the run's
// settings, progress, where it exports, and the results of the stages it needs.

#include "io/atomic_file.hpp"
#include "packing/packing.hpp"
#include "pipeline/analysis_registry.hpp"
#include "pipeline/run_settings.hpp"
#include "progress/progress.hpp"
#include "schema/field_table.hpp"
#include "schema/record.hpp"

#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <typeindex>
#include <utility>
#include <vector>

namespace sbpack {

class DistributedGrids;

/// Where a grid is exported: written through `output` (committed with the results), reported
/// as `destination`.
struct VdbExport {
    AtomicOutput* output;
    std::filesystem::path destination;
};

class FileContext {
  public:
    /// `packing` as read; the stages see it in its analysis length unit (packing()).
    FileContext(const Packing& packing, const RunSettings& settings, const Progress& progress,
                std::map<Analysis, VdbExport> exports)
        : analysed_(packing), settings_(settings), progress_(progress),
          meanWidth_(analysed_.packing().shape().meanWidth()), exports_(std::move(exports)) {}

    /// The packing in units of lengthUnit() (D ~ 1: docs/reliability.md, "Units"), what every
    /// stage computes on; the results tables scale back to the packing's units (scales()).
    const Packing& packing() const { return analysed_.packing(); }
    /// Packing::analysisLengthUnit of the packing as read: 1 where 1 <= D < 2.
    double lengthUnit() const { return analysed_.lengthUnit(); }
    const RunSettings& settings() const { return settings_; }
    /// Whether the voxel grids go to the GPU (--device cuda): identical superballs only, what
    /// the GPU voxeliser reads (grid/voxel_rows.hpp): not a mixture's (docs/mixtures.md), nor
    /// another family's (docs/gpu.md); analyzeFile warns.
    bool gridsOnGpu() const {
        return settings_.device.device == ComputeDevice::Cuda && !packing().isMixture() &&
               packing().shapeSpec.superballExponent();
    }
    const Progress& progress() const { return progress_; }
    /// The mean width w in units of lengthUnit().
    double meanWidth() const { return meanWidth_; }
    /// What the results tables scale by (schema/field_table.hpp).
    schema::Scales scales() const { return {meanWidth_, lengthUnit()}; }
    /// Where `analysis` exports its grid (--vdb); nullptr when it does not.
    const VdbExport* vdbExport(Analysis analysis) const {
        const auto it = exports_.find(analysis);
        return it == exports_.end() ? nullptr : &it->second;
    }

    /// The distributed grid computations (--distribute grids, pipeline/distributed_grids.hpp);
    /// nullptr when each grid is whole on this process.
    const DistributedGrids* grids() const { return grids_; }
    void distributeGrids(const DistributedGrids* grids) { grids_ = grids; }

    /// Keeps a stage's result for the stages that need it (AnalysisInfo::needs); released once no
    /// later stage of the file needs it.
    template <class T> void keep(Analysis analysis, T value) {
        kept_.insert_or_assign(analysis,
                               Kept{typeid(T), std::make_shared<const T>(std::move(value))});
    }
    /// The result `analysis` kept; std::logic_error when there is none of type T (a stage that
    /// uses another's result must list it in its needs).
    template <class T> const T& kept(Analysis analysis) const {
        const auto it = kept_.find(analysis);
        if (it == kept_.end() || it->second.type != typeid(T))
            throw std::logic_error(std::string("stage result not kept: ") +
                                   std::string(analysisInfo(analysis).name));
        return *static_cast<const T*>(it->second.value.get());
    }
    void release(Analysis analysis) { kept_.erase(analysis); }

    /// A results group beyond the stage's own (an analysis that fills several, e.g. hyper).
    void addGroup(schema::Record record) { groups_.push_back(std::move(record)); }
    /// The groups added since the last call.
    std::vector<schema::Record> takeGroups() { return std::exchange(groups_, {}); }

  private:
    struct Kept {
        std::type_index type;
        std::shared_ptr<const void> value;
    };
    AnalysedPacking analysed_;
    const RunSettings& settings_;
    const Progress& progress_;
    double meanWidth_;
    std::map<Analysis, VdbExport> exports_;
    std::map<Analysis, Kept> kept_;
    std::vector<schema::Record> groups_;
    const DistributedGrids* grids_ = nullptr;
};

} // namespace sbpack
