// LAMMPS in and out (io/lammps_io.hpp; docs/cli.md, "Files"): sbpack's dump and data file
// round-trip (positions bit for bit, p exactly); a dump as LAMMPS writes one (another column
// order, scaled positions, a box off the origin, ids out of order, extra columns) reads as the
// same particles; what cannot be a cubic packing is refused naming the file and line. OVITO's
// reading of the dump: bench/formats_vs_peers.sh.

#include "io/lammps_io.hpp"
#include "io/packing_formats.hpp"
#include "io/packing_io.hpp"
#include "packing_file_fixtures.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace sbpack {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    return fixtures::scratch("sbpack_test_lammps_io", name);
}

fs::path written(const std::string& name, const std::string& text) {
    const fs::path file = scratch(name);
    std::ofstream(file) << text;
    return file;
}

Packing superballs(double p, std::size_t n = 40) {
    return fixtures::randomSuperballs(p, n, 11);
}

void expectSame(const Packing& read, const Packing& original) {
    EXPECT_EQ(read.shapeSpec, original.shapeSpec);
    EXPECT_EQ(read.semiAxis, original.semiAxis);
    EXPECT_EQ(read.boxLength, original.boxLength);
    ASSERT_EQ(read.size(), original.size());
    for (std::size_t i = 0; i < read.size(); ++i) {
        EXPECT_EQ(read.positions[i], original.positions[i]) << i;
        EXPECT_LT((read.orientations[i].coeffs() - original.orientations[i].coeffs()).norm(), 1e-15)
            << i;
    }
}

TEST(LammpsIo, DumpAndDataFileRoundTrip) {
    for (const double p : {0.85, 1.0, 1.5, 10.0}) {
        const Packing original = superballs(p);
        for (const char* name : {"round.dump", "round.data"}) {
            const fs::path file = scratch(name);
            writePackingFile(original, file);
            SCOPED_TRACE(std::string(name) + " p " + std::to_string(p));
            expectSame(readPackingFile(file), original);
        }
    }
    // Spheres keep LAMMPS's 8 columns (every version reads them); superballs add the blockiness.
    writeLammpsData(superballs(1.0, 1), scratch("sphere.data"));
    writeLammpsData(superballs(1.5, 1), scratch("superball.data"));
    std::string line;
    for (const auto& [name, columns] : {std::pair{"sphere.data", 8}, {"superball.data", 10}}) {
        std::ifstream in(scratch(name));
        while (std::getline(in, line) && line != "Ellipsoids") {
        }
        std::getline(in, line);
        std::getline(in, line);
        std::istringstream tokens(line);
        int count = 0;
        for (std::string t; tokens >> t;)
            ++count;
        EXPECT_EQ(count, columns) << name << ": " << line;
    }
}

TEST(LammpsIo, ADumpAsLammpsWritesOneReadsAsTheSameParticles) {
    // Box [-5, 5)^3; ids 2, 1; scaled positions; the quaternion after extra columns.
    const fs::path file = written(
        "lammps.dump", "ITEM: TIMESTEP\n1000\nITEM: NUMBER OF ATOMS\n2\n"
                       "ITEM: BOX BOUNDS pp pp pp\n-5 5\n-5 5\n-5 5\n"
                       "ITEM: ATOMS type id xs ys zs vx shapex shapey shapez quatw quati quatj "
                       "quatk\n"
                       "1 2 0.75 0.5 0.1 9.9 1.2 1.2 1.2 0 0 0 1\n"
                       "1 1 0.25 0.5 0.5 9.9 1.2 1.2 1.2 1 0 0 0\n"
                       "ITEM: TIMESTEP\n2000\n");
    const Packing packing = readPackingFile(file);
    EXPECT_EQ(packing.shapeSpec.superballExponent().value(),
              1.0); // no roundness columns: LAMMPS's ellipsoids, here spheres
    EXPECT_EQ(packing.semiAxis, 0.6);
    EXPECT_EQ(packing.boxLength, 10.0);
    ASSERT_EQ(packing.size(), 2u);
    EXPECT_EQ(packing.positions[0], Vector3d(2.5, 5.0, 5.0)); // id 1 first, scaled by the box
    EXPECT_EQ(packing.positions[1], Vector3d(7.5, 5.0, 1.0));
    EXPECT_EQ(packing.orientations[1].coeffs(), Quaterniond(0, 0, 0, 1).coeffs());
}

/// Refused naming the file, the line and `words`.
void expectRefused(const fs::path& file, const std::string& words) {
    fixtures::expectRefused(file, words);
    fixtures::expectRefused(file, "line");
}

TEST(LammpsIo, RefusesWhatIsNotACubicPackingNamingTheFileAndLine) {
    const std::string head = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\n";
    const std::string atoms = "ITEM: ATOMS id x y z shapex shapey shapez\n";
    expectRefused(written("box.dump", head + "ITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n0 9\n" +
                                          atoms + "1 1 1 1 1 1 1\n2 3 3 3 1 1 1\n"),
                  "not cubic");
    expectRefused(written("tilt.dump", head + "ITEM: BOX BOUNDS xy xz yz pp pp pp\n"),
                  "orthogonal");
    const std::string box = "ITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n0 10\n";
    expectRefused(written("noshape.dump", head + box + "ITEM: ATOMS id x y z\n"), "shapex");
    expectRefused(written("twice.dump", head + box + atoms + "1 1 1 1 1 1 1\n1 3 3 3 1 1 1\n"),
                  "appears twice");
    expectRefused(written("short.dump", head + box + atoms + "1 1 1 1 1 1 1\n"), "1 of 2 atoms");
    // Two sizes are a mixture (docs/mixtures.md); two proportions are two shapes; ellipsoids are
    // no shape sbpack knows.
    expectRefused(written("two.dump", head + box + atoms + "1 1 1 1 1 1 1\n2 3 3 3 2 2 3\n"),
                  "differ in proportion");
    expectRefused(written("ellipsoid.dump", head + box + atoms + "1 1 1 1 2 2 3\n2 3 3 3 2 2 3\n"),
                  "no shape sbpack knows");
    const std::string data = "title\n\n2 atoms\n1 ellipsoids\n0 10 xlo xhi\n0 10 ylo yhi\n"
                             "0 10 zlo zhi\n\nAtoms\n\n1 1 1 1 1 1 1\n2 1 1 1 3 3 3\n";
    expectRefused(written("some.data", data), "every atom must be an ellipsoid");
    expectRefused(written("tri.data", "title\n\n1 atoms\n0 0 0 xy xz yz\n"), "triclinic");
}

} // namespace
} // namespace sbpack
