// Distributed grids against the threaded single process (docs/scale-out.md), run by ctest under
// mpirun -np 2 and -np 3: for each packing of data/ named and M = 96 and 128, chi_V of the slabs
// (FFTW's MPI transform) equals SpectralDensity::compute's to 1e-12 relative, the distributed
// distance transform equals periodicDistanceTransform exactly, and the measured communication
// equals the plan's (pipeline/scale_plan.hpp), the measured memory per rank is within it.
#include "io/packing_io.hpp"
#include "mpi/distributed_distance_transform.hpp"
#include "mpi/mpi_communicator.hpp"
#include "parallel/parallel.hpp"
#include "pores/distance_transform.hpp"
#include "spectral/spectral_density.hpp"
#include "spectral/voxel_fourier_transform.hpp"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

namespace sbpack {
namespace {

int failures = 0;

void expect(bool ok, const std::string& what) {
    if (ok) return;
    std::cerr << "FAILED: " << what << '\n';
    ++failures;
}

void checkChi(const MpiCommunicator& comm, const Packing& packing, int m, const std::string& tag) {
    const Progress quiet;
    SpectralDensityParameters parameters;
    parameters.maxQw = 12.0;
    parameters.fft.planning = FftPlanning::Estimate;
    const Voxelization whole = Voxelizer({m}).compute(packing, quiet);
    const SpectralDensityResult serial = SpectralDensity(parameters).compute(packing, whole, quiet);
    const SlabVoxels slab = comm.grids()->voxelize(packing, m, quiet);
    DistributionFigures figures;
    const SpectralDensityResult distributed =
        comm.grids()->spectralDensity(packing, slab, parameters, quiet, figures);
    expect(slab.solidCount == whole.solidCount(), tag + ": solid voxels");
    expect(serial.shells.count == distributed.shells.count, tag + ": shell counts");
    double worst = 0.0;
    for (std::size_t i = 0; i < serial.shells.size(); ++i)
        worst = std::max(worst, std::abs(serial.shells.value[i] - distributed.shells.value[i]) /
                                    std::abs(serial.shells.value[i]));
    expect(worst <= 1e-12, tag + ": chi differs by " + std::to_string(worst) + " relative");
    const DistributionFigures plan = spectralGridPlan(packing, m, comm.size());
    expect(figures.communicationBytes == plan.communicationBytes, tag + ": chi communication");
    expect(figures.memoryPerRankBytes <= plan.memoryPerRankBytes, tag + ": chi memory per rank");
    if (comm.rank() == 0)
        std::cout << tag << ": chi max relative difference " << worst << ", communication "
                  << figures.communicationBytes << " bytes\n";
}

void checkDistances(const MpiCommunicator& comm, const Packing& packing, int m,
                    const std::string& tag) {
    const Progress quiet;
    const Voxelization whole = Voxelizer({m}).compute(packing, quiet);
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m);
    whole.copySolidMask(mask);
    const PoreSizeMap serial = periodicDistanceTransform(mask, m, whole.voxelSize());
    const Slab x = slabOf(m, comm.size(), comm.rank());
    const std::size_t plane = static_cast<std::size_t>(m) * m;
    const std::span<const std::uint8_t> mine(mask.data() + x.begin * plane, x.size() * plane);
    const DistanceSlab slab = distributedDistanceTransform(comm, mine, m, quiet);
    std::int64_t differing = 0;
    for (int y = slab.y.begin; y < slab.y.end; ++y)
        for (int i = 0; i < m; ++i)
            for (int k = 0; k < m; ++k)
                differing += slab.squared[((y - slab.y.begin) * plane) + i * m + k] !=
                             serial.squaredDistances()[(i * plane) + y * m + k];
    comm.sum(std::span<std::int64_t>(&differing, 1));
    expect(differing == 0, tag + ": " + std::to_string(differing) + " distances differ");
    expect(slab.largest == serial.maxSquaredDistance(), tag + ": largest distance");
    double sent = slab.sentBytes;
    comm.sum(std::span<double>(&sent, 1));
    const DistributionFigures plan = poreGridPlan(packing, m, comm.size());
    expect(sent == plan.communicationBytes, tag + ": transpose communication");
    expect(slab.peakBytes <= plan.memoryPerRankBytes, tag + ": distance memory per rank");
    if (comm.rank() == 0)
        std::cout << tag << ": distance map equal (" << plane * m << " voxels), sent " << sent
                  << " bytes\n";
}

} // namespace
} // namespace sbpack

int main(int argc, char** argv) {
    using namespace sbpack;
    const MpiSession session(argc, argv);
    const MpiCommunicator comm;
    const ThreadBudget budget(1);
    for (int i = 1; i < argc; ++i) {
        const Packing packing = readPacking(argv[i]);
        for (int m : {96, 128}) {
            std::ostringstream tag;
            tag << argv[i] << " M = " << m << " on " << comm.size() << " ranks";
            checkChi(comm, packing, m, tag.str());
            checkDistances(comm, packing, m, tag.str());
        }
    }
    int all = failures;
    MPI_Allreduce(MPI_IN_PLACE, &all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    if (comm.rank() == 0) std::cout << (all == 0 ? "mpi grids: ok\n" : "mpi grids: FAILED\n");
    return all == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
