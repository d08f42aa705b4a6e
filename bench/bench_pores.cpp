// bench_pores: cost and accuracy of the pore-size path (issue 6), results in bench/RESULTS.md.
//
// Common options: --packing FILE.h5 reads the test packing from FILE if it exists, else generates
// it (about 20 s) and writes it there; --p P replaces the spheres by superballs of exponent P
// inscribed in them (same circumradius 0.5, random orientations).
//
//   bench_pores edt [--voxels M] [--threads T] [--repeat R] [--write-mask F] [--write-distances F]
//                   [--write-vdb F.vdb]
//       times periodicDistanceTransform on the M^3 mask of the test packing (default 500, one
//       thread, 3 repeats); optionally writes the mask (M^3 uint8, index (i*M + j)*M + k) for
//       bench/peer_scipy_edt.py, the squared distances (M^3 uint32) for its --check, and the
//       pore-size map as OpenVDB (timed).
//   bench_pores errors [--points K] [--threads T] [--voxels M1,M2,...]
//       error of the voxel path against the voxel-free reference (K random void points, default
//       10^6) for M = 100, 200, 300, 500, with the run time of each.
//
// Test packing: N = 5000 spheres of diameter 1 at phi = 0.60, from uniformly random centres
// compressed slowly with pairwise overlap removal (seed 20240611). Dense and disordered but
// neither jammed nor MRJ; the generator's MRJ packings will replace it.

#include "contacts/cell_list.hpp"
#include "io/packing_io.hpp"
#include "packing/packing.hpp"
#include "parallel/parallel.hpp"
#include "pores/distance_transform.hpp"
#include "pores/exact_pore_size.hpp"
#include "pores/pore_size_distribution.hpp"
#include "transport/transport.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using sbpack::Packing;
using sbpack::Vector3d;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// CPU time of the process (all threads), to tell work from waiting on a shared machine.
double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// N spheres of diameter 1 at packing fraction phi: uniform random centres, then a slow
/// compression: the diameter grows from that of phi = 0.4 by 0.2 % per stage, and at each stage
/// Gauss-Seidel sweeps push every overlapping pair apart until none overlaps.
Packing disorderedSpheres(int count, double phi, std::uint64_t seed) {
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(1.0);
    packing.semiAxis = 0.5;
    packing.boxLength = std::cbrt(count * std::numbers::pi / 6.0 / phi);
    const double length = packing.boxLength;
    std::mt19937_64 generator(seed);
    std::uniform_real_distribution<double> uniform(0.0, length);
    std::vector<Vector3d>& r = packing.positions;
    for (int n = 0; n < count; ++n)
        r.emplace_back(uniform(generator), uniform(generator), uniform(generator));
    packing.orientations.assign(count, sbpack::Quaterniond::Identity());
    double diameter = std::cbrt(0.4 / phi);
    int sweeps = 0;
    for (bool last = false; !last;) {
        diameter = std::min(1.0, diameter * 1.002);
        last = diameter == 1.0;
        // Overlapping pairs (closer than the diameter) are pushed to 1.001 diameters apart: a
        // target at exact contact would leave pairs touching to within rounding forever.
        const double target = 1.001 * diameter;
        for (bool overlapping = true; overlapping; ++sweeps) {
            if (sweeps > 1000000) throw std::runtime_error("overlap removal did not converge");
            std::vector<std::pair<int, int>> pairs;
            sbpack::forEachNeighbourPair(
                r, length, 1.1 * diameter,
                [&](int i, int j, const Vector3d&) { pairs.emplace_back(i, j); });
            overlapping = false;
            for (const auto& [i, j] : pairs) {
                const Vector3d d = sbpack::minimumImage(r[j] - r[i], length);
                const double distance = d.norm();
                if (distance >= diameter) continue;
                overlapping = true;
                const Vector3d push = 0.5 * (target - distance) * d / distance;
                r[i] -= push;
                r[j] += push;
            }
            for (Vector3d& x : r)
                x = sbpack::wrapIntoBox(x, length);
        }
    }
    std::cerr << "packing: N = " << count << ", phi = " << phi << ", L = " << length << ", "
              << sweeps << " overlap-removal sweeps\n";
    return packing;
}

/// The same centres carrying superballs of exponent p inscribed in the spheres (circumradius
/// 0.5, so still no overlap) with uniformly random orientations: a superball test case.
Packing inscribedSuperballs(Packing packing, double p, std::uint64_t seed) {
    packing.shapeSpec = sbpack::ShapeSpec::superball(p);
    packing.semiAxis = 0.5 / sbpack::Superball(p, 1.0).circumradius();
    std::mt19937_64 generator(seed);
    std::normal_distribution<double> gauss;
    for (auto& q : packing.orientations)
        q = sbpack::Quaterniond(gauss(generator), gauss(generator), gauss(generator),
                                gauss(generator))
                .normalized();
    return packing;
}

/// Solid mask (voxel centre inside a particle, periodic), the layout of
/// Voxelization::copySolidMask; a plain loop over each particle's bounding box, for the bench.
std::vector<std::uint8_t> solidMask(const Packing& packing, int m) {
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m, 0);
    const double a = packing.boxLength / m;
    const sbpack::Superball shape = packing.superball();
    const double r = shape.circumradius();
    for (std::size_t n = 0; n < packing.size(); ++n) {
        const Vector3d& c = packing.positions[n];
        const sbpack::Matrix3d toBody = packing.orientations[n].toRotationMatrix().transpose();
        int lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            lo[k] = static_cast<int>(std::floor((c[k] - r) / a - 0.5));
            hi[k] = static_cast<int>(std::ceil((c[k] + r) / a - 0.5));
        }
        for (int i = lo[0]; i <= hi[0]; ++i)
            for (int j = lo[1]; j <= hi[1]; ++j)
                for (int k = lo[2]; k <= hi[2]; ++k) {
                    const Vector3d x((i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a);
                    const bool inside = shape.isSphere() ? (x - c).squaredNorm() < r * r
                                                         : shape.contains(toBody * (x - c));
                    if (!inside) continue;
                    const int wi = (i % m + m) % m, wj = (j % m + m) % m, wk = (k % m + m) % m;
                    mask[(static_cast<std::size_t>(wi) * m + wj) * m + wk] = 1;
                }
    }
    return mask;
}

template <class T> void writeRaw(const std::string& file, const T* data, std::size_t count) {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(count * sizeof(T)));
    if (!out) throw std::runtime_error("cannot write " + file);
}

struct Options {
    std::string mode;
    std::vector<int> voxels;
    int threads = 1;
    int repeat = 3;
    std::int64_t points = 1'000'000;
    double p = 1.0;
    std::string maskFile, distancesFile, packingFile, vdbFile;
};

Options parse(int argc, char** argv) {
    Options o;
    if (argc < 2) throw std::invalid_argument("usage: bench_pores edt|errors [options]");
    o.mode = argv[1];
    for (int n = 2; n < argc; ++n) {
        const std::string a = argv[n];
        if (n + 1 >= argc) throw std::invalid_argument("option " + a + " needs a value");
        const std::string v = argv[++n];
        if (a == "--voxels") {
            std::stringstream list(v);
            for (std::string item; std::getline(list, item, ',');)
                o.voxels.push_back(std::stoi(item));
        } else if (a == "--threads") {
            o.threads = std::stoi(v);
        } else if (a == "--repeat") {
            o.repeat = std::stoi(v);
        } else if (a == "--points") {
            o.points = std::stoll(v);
        } else if (a == "--write-mask") {
            o.maskFile = v;
        } else if (a == "--p") {
            o.p = std::stod(v);
        } else if (a == "--write-vdb") {
            o.vdbFile = v;
        } else if (a == "--packing") {
            o.packingFile = v;
        } else if (a == "--write-distances") {
            o.distancesFile = v;
        } else {
            throw std::invalid_argument("unknown option " + a);
        }
    }
    return o;
}

int edt(const Options& o, const Packing& packing) {
    const int m = o.voxels.empty() ? 500 : o.voxels.front();
    sbpack::checkPoreSizeMemory(m);
    auto start = std::chrono::steady_clock::now();
    std::vector<std::uint8_t> mask = solidMask(packing, m);
    const double voxelize = secondsSince(start);
    const auto solid = std::count(mask.begin(), mask.end(), 1);
    std::printf("M = %d: voxelised in %.2f s (bench voxeliser), phi_voxel = %.5f, phi = %.5f\n", m,
                voxelize, static_cast<double>(solid) / mask.size(), packing.packingFraction());
    if (!o.maskFile.empty()) writeRaw(o.maskFile, mask.data(), mask.size());
    double best = 1e300, bestCpu = 1e300;
    for (int r = 0; r < o.repeat; ++r) {
        start = std::chrono::steady_clock::now();
        const double cpuStart = cpuSeconds();
        const sbpack::PoreSizeMap map =
            sbpack::periodicDistanceTransform(mask, m, packing.boxLength / m);
        const double seconds = secondsSince(start), cpu = cpuSeconds() - cpuStart;
        best = std::min(best, seconds);
        bestCpu = std::min(bestCpu, cpu);
        std::printf("  EDT %d: %.3f s wall, %.3f s CPU (%d threads), void %lld, max delta = %.5f\n",
                    r, seconds, cpu, o.threads, static_cast<long long>(map.voidCount()),
                    map.voxelSize() * std::sqrt(static_cast<double>(map.maxSquaredDistance())));
        if (r + 1 == o.repeat && !o.distancesFile.empty())
            writeRaw(o.distancesFile, map.squaredDistances().data(), map.squaredDistances().size());
        if (r + 1 == o.repeat && !o.vdbFile.empty()) {
            start = std::chrono::steady_clock::now();
            map.writeVdb(o.vdbFile);
            std::printf("  writeVdb: %.2f s, %.1f MB\n", secondsSince(start),
                        static_cast<double>(std::filesystem::file_size(o.vdbFile)) / 1e6);
        }
    }
    std::printf("EDT M = %d, threads = %d: best of %d = %.3f s wall, %.3f s CPU\n", m, o.threads,
                o.repeat, best, bestCpu);
    return 0;
}

int errors(const Options& o, const Packing& packing) {
    const double w = packing.shape().meanWidth();
    sbpack::ExactPoreSizeParameters exactParameters;
    exactParameters.randomPoints = o.points;
    const auto exact =
        sbpack::ExactPoreSizeDistribution(exactParameters).compute(packing, sbpack::Progress());
    std::printf("exact (K = %lld random void points): %.2f s, <delta>/w = %.5f, <delta^2>/w^2 = "
                "%.6f, max/w = %.4f\n",
                static_cast<long long>(exact.samples), exact.runtimeSeconds, exact.meanOverWidth(),
                exact.secondMomentOverWidth2(), exact.maxOverWidth());
    std::printf("| M | a/w | EDT s | F s | <delta>/w | err <delta> | err <delta^2> | max gap F | "
                "shifted -a/2: err <delta> | err <delta^2> | max gap F |\n");
    const std::vector<int> list =
        o.voxels.empty() ? std::vector<int>{100, 200, 300, 500} : o.voxels;
    for (const int m : list) {
        sbpack::checkPoreSizeMemory(m);
        const std::vector<std::uint8_t> mask = solidMask(packing, m);
        const double a = packing.boxLength / m;
        auto start = std::chrono::steady_clock::now();
        const sbpack::PoreSizeMap map = sbpack::periodicDistanceTransform(mask, m, a);
        const double edtSeconds = secondsSince(start);
        const auto voxel = sbpack::PoreSizeDistribution({}).compute(map, w, sbpack::Progress());
        // The same curve moved down by half a voxel (centre-to-centre distances overshoot the
        // distance to the surface by about a / 2): informative only, not part of the library.
        std::vector<double> shiftedSizes;
        std::vector<std::int64_t> counts;
        double previous = 1.0;
        for (std::size_t j = 1; j < voxel.delta.size(); ++j) {
            shiftedSizes.push_back(voxel.delta[j] - 0.5 * a);
            counts.push_back(std::llround((previous - voxel.F[j]) * voxel.samples));
            previous = voxel.F[j];
        }
        const auto shifted = sbpack::poreSizeStatistics(shiftedSizes, counts, w, 64);
        auto relative = [](double x, double y) { return (x - y) / y; };
        std::printf(
            "| %d | %.4f | %.3f | %.3f | %.5f | %+.4f | %+.4f | %.4f | %+.4f | %+.4f | "
            "%.4f |\n",
            m, a / w, edtSeconds, voxel.runtimeSeconds, voxel.meanOverWidth(),
            relative(voxel.mean, exact.mean), relative(voxel.secondMoment, exact.secondMoment),
            sbpack::largestGap(voxel, exact), relative(shifted.mean, exact.mean),
            relative(shifted.secondMoment, exact.secondMoment), sbpack::largestGap(shifted, exact));
        if (m == list.back()) {
            const auto t = sbpack::Transport({}).compute(
                voxel, packing.shapeSpec.superballExponent(), packing.packingFraction());
            const auto te = sbpack::Transport({}).compute(
                exact, packing.shapeSpec.superballExponent(), packing.packingFraction());
            std::printf("transport at M = %d (exact in brackets): zeta2 = %.5f, F = %.4f, k/w^2 = "
                        "%.3e (%.3e), tau D/w^2 = %.3e (%.3e), T1 D/w^2 = %.3e (%.3e)\n",
                        m, t.zeta2.value_or(NAN), t.formationFactor.value_or(NAN),
                        t.permeabilityOverWidth2().value_or(NAN),
                        te.permeabilityOverWidth2().value_or(NAN), t.meanSurvivalTimeOverWidth2(),
                        te.meanSurvivalTimeOverWidth2(), t.principalRelaxationTimeOverWidth2(),
                        te.principalRelaxationTimeOverWidth2());
        }
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        const Options o = parse(argc, argv);
        const sbpack::ThreadBudget budget(o.threads);
        Packing packing;
        if (!o.packingFile.empty() && std::filesystem::exists(o.packingFile)) {
            packing = sbpack::readPacking(o.packingFile);
        } else {
            packing = disorderedSpheres(5000, 0.60, 20240611);
            if (!o.packingFile.empty()) sbpack::writePacking(packing, o.packingFile);
        }
        if (o.p != 1.0) packing = inscribedSuperballs(packing, o.p, 7);
        if (o.mode == "edt") return edt(o, packing);
        if (o.mode == "errors") return errors(o, packing);
        throw std::invalid_argument("unknown mode " + o.mode + " (edt or errors)");
    } catch (const std::exception& e) {
        std::cerr << "bench_pores: " << e.what() << '\n';
        return 1;
    }
}
