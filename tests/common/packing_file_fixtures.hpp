#pragma once
// What the format readers' tests share (test_gsd_io.cpp, test_lammps_io.cpp): a scratch folder,
// random superballs of one shape in a box, and the refusal every reader must give.

#include "io/packing_formats.hpp"
#include "io/packing_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

namespace sbpack::fixtures {

/// `name` in a folder of the test's own under the system's temporary directory.
inline std::filesystem::path scratch(const std::string& folder, const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / folder;
    std::filesystem::create_directories(dir);
    return dir / name;
}

/// n superballs of exponent p at random positions and orientations (overlaps allowed: the
/// formats carry numbers, not physics), with lengths that no short decimal rounds exactly.
inline Packing randomSuperballs(double p, std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(p);
    packing.semiAxis = 0.6180339887498949;
    packing.boxLength = 9.876543210987654;
    for (std::size_t i = 0; i < n; ++i) {
        packing.positions.emplace_back(packing.boxLength * uniform(rng),
                                       packing.boxLength * uniform(rng),
                                       packing.boxLength * uniform(rng));
        packing.orientations.push_back(
            Quaterniond(gauss(rng), gauss(rng), gauss(rng), gauss(rng)).normalized());
    }
    return packing;
}

/// Reading `file` throws PackingFileError whose message names the file and holds `words`.
inline void expectRefused(const std::filesystem::path& file, const std::string& words) {
    try {
        readPackingFile(file);
        ADD_FAILURE() << "read " << file;
    } catch (const PackingFileError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(file.string()), std::string::npos) << what;
        EXPECT_NE(what.find(words), std::string::npos) << what;
    }
}

} // namespace sbpack::fixtures
