#pragma once
// The signed wave index n of a DFT index (the wave vectors Q = 2 pi n / L of chi_V, paper Eq. 12):
// one rule for the CPU's shell sums and spectra (spectral/, hyperuniformity/), the GPU's gather and
// sums (gpu/cuda_kernels.cu) and the compact cube (gpu/compact_cube.hpp). Host and device alike.

#include "geometry/norm_parts.hpp"

namespace sbpack::grid {

/// Signed wave index of DFT index k of an M-periodic transform: k for k <= M/2, else k - M (the
/// CPU's shell sums and spectra, the GPU's gather and sums, the compact cube of period 2s + 1).
SBPACK_HD inline int signedIndex(int k, int m) {
    return 2 * k <= m ? k : k - m;
}

} // namespace sbpack::grid
