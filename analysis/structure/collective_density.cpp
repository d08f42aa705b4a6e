#include "structure/collective_density.hpp"

#include "parallel/parallel.hpp"
#include "parallel/vector_clones.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sbpack {

namespace {

/// Particles per block of the inner loop: their phase tables stay in the L2 cache while every
/// (n_y, n_z) of one plane n_x is accumulated.
constexpr std::int64_t kParticleBlock = 128;
/// Exact sin/cos every this many steps of the recurrence, which bounds its rounding drift.
constexpr int kRecurrenceRestart = 16;

} // namespace

int isqrt(std::int64_t m) {
    auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(m)));
    while (r * r > m)
        --r;
    while ((r + 1) * (r + 1) <= m)
        ++r;
    return static_cast<int>(r);
}

PhaseTable phaseTable(std::span<const Eigen::Vector3d> positions, int axis, double boxLength,
                      int kmax) {
    const std::size_t stride = static_cast<std::size_t>(kmax) + 1;
    PhaseTable t{std::vector<double>(positions.size() * stride),
                 std::vector<double>(positions.size() * stride)};
    for (std::size_t j = 0; j < positions.size(); ++j) {
        const double fraction = positions[j][axis] / boxLength;
        const double theta = 2.0 * std::numbers::pi * fraction;
        const double c1 = std::cos(theta), s1 = std::sin(theta);
        double* c = &t.c[j * stride];
        double* s = &t.s[j * stride];
        for (int k = 0; k <= kmax; ++k) {
            if (k % kRecurrenceRestart == 0) {
                // 2 pi (k x / L mod 1): exact argument reduction keeps the restart exact.
                const double turns = k * fraction - std::floor(k * fraction);
                c[k] = std::cos(2.0 * std::numbers::pi * turns);
                s[k] = std::sin(2.0 * std::numbers::pi * turns);
            } else {
                c[k] = c[k - 1] * c1 - s[k - 1] * s1;
                s[k] = s[k - 1] * c1 + c[k - 1] * s1;
            }
        }
    }
    return t;
}

namespace {

/// One row (n_x, n_y) of a plane over particles [begin, end): the sums over j of
/// u_j cos(θz_j n_z), u_j sin(θz_j n_z), v_j cos, v_j sin for n_z < zl (real and imaginary
/// parts, 8 arrays), where u = e^{-i(θx n_x + θy n_y)} and v = e^{-i(θx n_x - θy n_y)}.
SBPACK_VECTOR_CLONES
void accumulateRow(std::int64_t begin, std::int64_t end, int nx, int ny, int zl,
                   std::int64_t stride, const PhaseTable& x, const PhaseTable& y,
                   const PhaseTable& z, double* __restrict auR, double* __restrict auI,
                   double* __restrict buR, double* __restrict buI, double* __restrict avR,
                   double* __restrict avI, double* __restrict bvR, double* __restrict bvI) {
    for (std::int64_t j = begin; j < end; ++j) {
        const double xr = x.c[j * stride + nx], xi = -x.s[j * stride + nx];
        const double yc = y.c[j * stride + ny], ys = y.s[j * stride + ny];
        // u = X (yc - i ys), v = X (yc + i ys) with X = xr + i xi.
        const double uR = xr * yc + xi * ys, uI = xi * yc - xr * ys;
        const double vR = xr * yc - xi * ys, vI = xi * yc + xr * ys;
        const double* __restrict zc = &z.c[j * stride];
        const double* __restrict zs = &z.s[j * stride];
        for (int nz = 0; nz < zl; ++nz) {
            auR[nz] += uR * zc[nz];
            auI[nz] += uI * zc[nz];
            buR[nz] += uR * zs[nz];
            buI[nz] += uI * zs[nz];
            avR[nz] += vR * zc[nz];
            avI[nz] += vI * zc[nz];
            bvR[nz] += vR * zs[nz];
            bvI[nz] += vI * zs[nz];
        }
    }
}

/// The rows of plane n_x (|n|^2 <= maxN2 leaves n_y^2 + n_z^2 <= rest): row n_y holds 8 arrays
/// over n_z = 0..zmax(n_y), Re and Im of A_u, B_u, A_v, B_v with A = sum of (u or v) cos(θz n_z),
/// B = sum of (u or v) sin(θz n_z) (accumulateRow), from offset[n_y] on.
struct PlaneRows {
    std::vector<int> length;         ///< zmax(n_y) + 1
    std::vector<std::size_t> offset; ///< of row n_y in the plane's sums; offset.back(): their size
};

PlaneRows planeRows(std::int64_t rest) {
    const int ymax = isqrt(rest);
    PlaneRows rows{std::vector<int>(ymax + 1), std::vector<std::size_t>(ymax + 2, 0)};
    for (int ny = 0; ny <= ymax; ++ny) {
        rows.length[ny] = isqrt(rest - static_cast<std::int64_t>(ny) * ny) + 1;
        rows.offset[ny + 1] = rows.offset[ny] + 8 * static_cast<std::size_t>(rows.length[ny]);
    }
    return rows;
}

/// The modes of plane n_x from its rows' sums, in the order (n_y, n_z, sign combination):
/// rho(n_x, +-n_y, n_z) = A - i B, rho(n_x, +-n_y, -n_z) = A + i B.
DensityModes planeModes(int nx, const PlaneRows& rows, const std::vector<double>& acc,
                        bool amplitudes) {
    DensityModes out;
    auto emit = [&](int ny, int nz, double re, double im) {
        out.n.push_back({nx, ny, nz});
        out.intensity.push_back(re * re + im * im);
        if (amplitudes) out.amplitude.emplace_back(re, im);
    };
    for (int ny = 0; ny + 1 < static_cast<int>(rows.offset.size()); ++ny) {
        const int zl = rows.length[ny];
        const double* a = &acc[rows.offset[ny]];
        const bool xOrY = nx > 0 || ny > 0, xAndY = nx > 0 && ny > 0;
        for (int nz = 0; nz < zl; ++nz) {
            const double auR = a[nz], auI = a[zl + nz], buR = a[2 * zl + nz], buI = a[3 * zl + nz];
            const double avR = a[4 * zl + nz], avI = a[5 * zl + nz], bvR = a[6 * zl + nz],
                         bvI = a[7 * zl + nz];
            if (xOrY || nz > 0) emit(ny, nz, auR + buI, auI - buR);
            if (xOrY && nz > 0) emit(ny, -nz, auR - buI, auI + buR);
            if (xAndY) emit(-ny, nz, avR + bvI, avI - bvR);
            if (xAndY && nz > 0) emit(-ny, -nz, avR - bvI, avI + bvR);
        }
    }
    return out;
}

/// The modes of one plane n_x, in the order (n_y, n_z, sign combination).
DensityModes plane(int nx, std::int64_t maxN2, std::int64_t particles, int kmax,
                   const PhaseTable& x, const PhaseTable& y, const PhaseTable& z,
                   const Progress& progress, bool amplitudes) {
    const std::int64_t stride = kmax + 1;
    const PlaneRows rows = planeRows(maxN2 - static_cast<std::int64_t>(nx) * nx);
    std::vector<double> acc(rows.offset.back(), 0.0);
    for (std::int64_t begin = 0; begin < particles; begin += kParticleBlock) {
        progress.checkInterrupt();
        const std::int64_t end = std::min(particles, begin + kParticleBlock);
        for (std::size_t ny = 0; ny < rows.length.size(); ++ny) {
            const int zl = rows.length[ny];
            double* const a = &acc[rows.offset[ny]];
            accumulateRow(begin, end, nx, static_cast<int>(ny), zl, stride, x, y, z, a, a + zl,
                          a + 2 * zl, a + 3 * zl, a + 4 * zl, a + 5 * zl, a + 6 * zl, a + 7 * zl);
        }
    }
    return planeModes(nx, rows, acc, amplitudes);
}

} // namespace

DensityModes collectiveDensity(std::span<const Eigen::Vector3d> positions, double boxLength,
                               std::int64_t maxN2, const Progress& progress, bool amplitudes) {
    if (!(boxLength > 0.0) || !std::isfinite(boxLength))
        throw std::invalid_argument("collective density: box length must be positive and finite");
    if (maxN2 < 1) throw std::invalid_argument("collective density: no wave vector (maxN2 < 1)");
    const int kmax = isqrt(maxN2);
    const PhaseTable x = phaseTable(positions, 0, boxLength, kmax);
    const PhaseTable y = phaseTable(positions, 1, boxLength, kmax);
    const PhaseTable z = phaseTable(positions, 2, boxLength, kmax);
    const auto particles = static_cast<std::int64_t>(positions.size());
    return orderedReduce(
        kmax + 1, DensityModes{},
        [&](std::int64_t nx) {
            return plane(static_cast<int>(nx), maxN2, particles, kmax, x, y, z, progress,
                         amplitudes);
        },
        [](DensityModes& all, const DensityModes& p) {
            all.n.insert(all.n.end(), p.n.begin(), p.n.end());
            all.intensity.insert(all.intensity.end(), p.intensity.begin(), p.intensity.end());
            all.amplitude.insert(all.amplitude.end(), p.amplitude.begin(), p.amplitude.end());
        },
        progress);
}

} // namespace sbpack
