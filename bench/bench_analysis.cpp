// bench_analysis: wall-clock timings of sbanalyze's stages on one packing (results in
// RESULTS.md). Each stage runs --repeats times; the best and the median are printed, since the
// machine may be shared, and for the three analyses also the best process CPU time (all
// threads), which a busy machine inflates less. FFTW plans come from the wisdom file (planned
// once before timing).
//
// usage: bench_analysis PACKING.h5 [--threads T] [--voxels M] [--sq-shell S] [--repeats R]
//                       [--memory-voxels M2] [--fft-wisdom FILE]

#include "io/packing_io.hpp"
#include "parallel/parallel.hpp"
#include "spectral/spectral_density.hpp"
#include "structure/structure_factor.hpp"
#include "voxels/voxelization.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace sbpack;

struct Options {
    std::string packing;
    int threads = 2;
    int voxels = 300;
    int sqShell = 40;
    int repeats = 5;
    int memoryVoxels = 0;
    std::string wisdom;
};

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 == argc) throw std::invalid_argument(a + " needs a value");
            return argv[++i];
        };
        if (a == "--threads")
            o.threads = std::stoi(value());
        else if (a == "--voxels")
            o.voxels = std::stoi(value());
        else if (a == "--sq-shell")
            o.sqShell = std::stoi(value());
        else if (a == "--repeats")
            o.repeats = std::stoi(value());
        else if (a == "--memory-voxels")
            o.memoryVoxels = std::stoi(value());
        else if (a == "--fft-wisdom")
            o.wisdom = value();
        else if (o.packing.empty())
            o.packing = a;
        else
            throw std::invalid_argument("unexpected argument " + a);
    }
    if (o.packing.empty()) throw std::invalid_argument("no packing file");
    return o;
}

/// CPU seconds of this process, all threads.
double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Best and median of the recorded times of each stage.
class Timings {
  public:
    void add(const std::string& stage, double seconds) {
        if (!times_.count(stage)) order_.push_back(stage);
        times_[stage].push_back(seconds);
    }
    void print() const {
        std::printf("%-40s %10s %10s\n", "stage", "best [s]", "median [s]");
        for (const std::string& stage : order_) {
            std::vector<double> t = times_.at(stage);
            std::sort(t.begin(), t.end());
            std::printf("%-40s %10.4f %10.4f\n", stage.c_str(), t.front(), t[t.size() / 2]);
        }
    }

  private:
    std::vector<std::string> order_;
    std::map<std::string, std::vector<double>> times_;
};

} // namespace

int main(int argc, char** argv) {
    try {
        const Options o = parse(argc, argv);
        const ThreadBudget budget(o.threads);
        const Packing packing = readPacking(o.packing);
        const Progress progress(nullptr, nullptr);
        const double w = packing.shape().meanWidth();
        std::printf("packing %s: N = %zu, %s, phi = %.4f, L = %.4f, w = %.4f; threads %d\n",
                    o.packing.c_str(), packing.size(), packing.shapeSpec.describe().c_str(),
                    packing.packingFraction(), packing.boxLength, w, o.threads);

        SpectralDensityParameters chiParameters;
        chiParameters.fft.wisdomFile = o.wisdom;
        const SpectralDensity chi(chiParameters);
        const Voxelizer voxelizer({o.voxels});
        {
            const Voxelization warm = voxelizer.compute(packing, progress); // plans, fills wisdom
            chi.compute(packing, warm, progress);
        }
        // S(Q) on shells 1..sqShell, i.e. |n| < sqShell + 1/2.
        const double maxQw = (o.sqShell + 0.5) * 2.0 * std::numbers::pi * w / packing.boxLength;
        const StructureFactor structureFactor({maxQw});

        Timings t;
        const std::string m = std::to_string(o.voxels) + "^3";
        for (int r = 0; r < o.repeats; ++r) {
            double cpu = cpuSeconds();
            const Voxelization voxels = voxelizer.compute(packing, progress);
            const double voxelizeCpu = cpuSeconds() - cpu;
            cpu = cpuSeconds();
            const SpectralDensityResult s = chi.compute(packing, voxels, progress);
            const double chiCpu = cpuSeconds() - cpu;
            cpu = cpuSeconds();
            const StructureFactorResult sq = structureFactor.compute(packing, progress);
            const double sqCpu = cpuSeconds() - cpu;
            t.add("voxelize " + m, voxels.runtimeSeconds());
            t.add("FFT plan (wisdom)", s.planSeconds);
            t.add("fill FFT grid", s.fillSeconds);
            t.add("FFT r2c", s.transformSeconds);
            t.add("shell average (" + std::to_string(s.maxShell) + " shells)", s.shellSeconds);
            t.add("voxelize + FFT + shells", voxels.runtimeSeconds() + s.planSeconds +
                                                 s.fillSeconds + s.transformSeconds +
                                                 s.shellSeconds);
            if (s.exactSphere) t.add("exact sphere chi (same shells)", s.exactSeconds);
            t.add("S(Q), |n| < " + std::to_string(o.sqShell) + ".5", sq.runtimeSeconds);
            t.add("CPU time, all threads: voxelize", voxelizeCpu);
            t.add(s.exactSphere ? "CPU time: chi (FFT, shells, exact)"
                                : "CPU time: chi (FFT, shells)",
                  chiCpu);
            t.add("CPU time: S(Q)", sqCpu);
        }
        t.print();
        if (o.memoryVoxels > 0) {
            const Voxelization big = Voxelizer({o.memoryVoxels}).compute(packing, progress);
            const double dense = std::pow(static_cast<double>(o.memoryVoxels), 3);
            std::printf("voxelization %d^3: %.1f s, phi_voxel %.6f, OpenVDB tree %.1f MB, "
                        "dense byte grid %.1f MB (ratio %.3f)\n",
                        o.memoryVoxels, big.runtimeSeconds(), big.phiVoxel(),
                        big.memoryBytes() / 1e6, dense / 1e6, big.memoryBytes() / dense);
        }
        return EXIT_SUCCESS;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_analysis: %s\n", e.what());
        return EXIT_FAILURE;
    }
}
