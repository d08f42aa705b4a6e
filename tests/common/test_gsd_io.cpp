// GSD in and out (io/gsd_io.hpp; docs/cli.md, "Files"): sbpack's file round-trips bit for bit;
// its schema chunks, read back through the reference library, are the packing in single
// precision inside [-L/2, L/2), with a shape whose vertices lie on the superball; a frame as HOOMD
// writes one (float32, a Sphere type_shape, no sbpack chunks) reads as spheres; what cannot be a
// packing is refused naming the file. The peers' view (gsd.hoomd, freud, OVITO):
// bench/formats_vs_peers.sh.

#include "io/gsd_io.hpp"
#include "io/packing_formats.hpp"
#include "io/packing_io.hpp"
#include "packing_file_fixtures.hpp"
#include "third_party/gsd/gsd.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace sbpack {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    return fixtures::scratch("sbpack_test_gsd_io", name);
}

Packing superballs(double p) {
    Packing packing = fixtures::randomSuperballs(p, 50, 7);
    packing.positions[0].x() = std::nextafter(packing.boxLength, 0.0); // rounds onto +L/2
    packing.reducedPressure = 1.0e12 / 3.0;
    packing.seed = 18446744073709551557ULL;
    return packing;
}

/// One chunk of frame 0 through the reference library.
template <class T> std::vector<T> chunk(const fs::path& file, const char* name, gsd_type type) {
    gsd_handle handle{};
    EXPECT_EQ(gsd_open(&handle, file.c_str(), GSD_OPEN_READONLY), GSD_SUCCESS);
    const gsd_index_entry* e = gsd_find_chunk(&handle, 0, name);
    std::vector<T> out;
    if (e && e->type == type) {
        out.resize(e->N * e->M);
        EXPECT_EQ(gsd_read_chunk(&handle, out.data(), e), GSD_SUCCESS);
    }
    gsd_close(&handle);
    return out;
}

TEST(GsdIo, SbpacksFileRoundTripsBitForBit) {
    const Packing original = superballs(1.5);
    const fs::path file = scratch("round.gsd");
    writeGsd(original, file);
    const Packing read = readPackingFile(file);
    EXPECT_EQ(read.shapeSpec, original.shapeSpec);
    EXPECT_EQ(read.semiAxis, original.semiAxis);
    EXPECT_EQ(read.boxLength, original.boxLength);
    EXPECT_EQ(read.reducedPressure, original.reducedPressure);
    EXPECT_EQ(read.seed, original.seed);
    ASSERT_EQ(read.size(), original.size());
    for (std::size_t i = 0; i < read.size(); ++i) {
        EXPECT_EQ(read.positions[i], original.positions[i]) << i;
        EXPECT_EQ(read.orientations[i].coeffs(), original.orientations[i].coeffs()) << i;
    }
}

TEST(GsdIo, TheFileHasThePermissionsOfEveryOtherOutput) {
    // The reference library creates its files 0660; an sbpack GSD is made as the text format
    // is (0666 less the umask), so that others may read it where they may read the rest.
    const Packing packing = superballs(1.5);
    writeGsd(packing, scratch("mode.gsd"));
    writePackingFile(packing, scratch("mode.txt"));
    EXPECT_EQ(fs::status(scratch("mode.gsd")).permissions(),
              fs::status(scratch("mode.txt")).permissions());
}

TEST(GsdIo, TheSchemasChunksAreThePackingInSinglePrecision) {
    const Packing packing = superballs(10.0);
    const fs::path file = scratch("schema.gsd");
    writeGsd(packing, file);
    const double L = packing.boxLength;
    const auto box = chunk<float>(file, "configuration/box", GSD_TYPE_FLOAT);
    EXPECT_EQ(box, (std::vector<float>{static_cast<float>(L), static_cast<float>(L),
                                       static_cast<float>(L), 0.0F, 0.0F, 0.0F}));
    const auto position = chunk<float>(file, "particles/position", GSD_TYPE_FLOAT);
    const auto orientation = chunk<float>(file, "particles/orientation", GSD_TYPE_FLOAT);
    ASSERT_EQ(position.size(), 3 * packing.size());
    ASSERT_EQ(orientation.size(), 4 * packing.size());
    const auto half = static_cast<float>(0.5 * L);
    for (std::size_t i = 0; i < packing.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const float x = position[3 * i + k];
            EXPECT_TRUE(x >= -half && x < half) << i << ' ' << x;
            const double gap = std::remainder(x + 0.5 * L - packing.positions[i][k], L);
            EXPECT_LE(std::abs(gap), 1e-6 * L) << i; // float32 rounding only
        }
    EXPECT_EQ(position[0], -half); // the value that rounded onto +L/2 wraps to -L/2
    const Quaterniond& q = packing.orientations[3];
    EXPECT_EQ(orientation[12], static_cast<float>(q.w())); // (w, x, y, z)
    EXPECT_EQ(orientation[15], static_cast<float>(q.z()));
    // The shape: every vertex on |x|^2p + |y|^2p + |z|^2p = a^2p.
    const auto shapes = chunk<char>(file, "particles/type_shapes", GSD_TYPE_INT8);
    const nlohmann::json shape = nlohmann::json::parse(std::string(shapes.data()));
    EXPECT_EQ(shape["type"], "ConvexPolyhedron");
    ASSERT_GE(shape["vertices"].size(), 200u);
    const double a = packing.semiAxis, p = packing.shapeSpec.superballExponent().value();
    for (const auto& v : shape["vertices"]) {
        double sum = 0.0;
        for (int k = 0; k < 3; ++k)
            sum += std::pow(std::abs(v[k].get<double>()) / a, 2.0 * p);
        EXPECT_NEAR(sum, 1.0, 1e-6);
    }
}

/// A frame as HOOMD writes one: float32, centred box, a Sphere type_shape, nothing of sbpack's.
void writeHoomdFrame(const fs::path& file, const std::vector<float>& box,
                     const std::string& shape) {
    gsd_handle h{};
    ASSERT_EQ(gsd_create_and_open(&h, file.c_str(), "test", "hoomd", gsd_make_version(1, 4),
                                  GSD_OPEN_APPEND, 0),
              GSD_SUCCESS);
    const std::uint32_t n = 2;
    const std::vector<float> position{-1.0F, 0.5F, 0.0F, 1.25F, -3.999F, 2.0F};
    std::vector<char> shapes(shape.begin(), shape.end());
    shapes.push_back('\0');
    gsd_write_chunk(&h, "configuration/box", GSD_TYPE_FLOAT, 6, 1, 0, box.data());
    gsd_write_chunk(&h, "particles/N", GSD_TYPE_UINT32, 1, 1, 0, &n);
    gsd_write_chunk(&h, "particles/position", GSD_TYPE_FLOAT, n, 3, 0, position.data());
    gsd_write_chunk(&h, "particles/type_shapes", GSD_TYPE_INT8, 1,
                    static_cast<std::uint32_t>(shapes.size()), 0, shapes.data());
    gsd_end_frame(&h);
    gsd_close(&h);
}

TEST(GsdIo, AHoomdHardSphereFrameReadsAsSpheres) {
    const fs::path file = scratch("hoomd.gsd");
    writeHoomdFrame(file, {8.0F, 8.0F, 8.0F, 0.0F, 0.0F, 0.0F},
                    R"({"type": "Sphere", "diameter": 1.5})");
    const Packing packing = readPackingFile(file);
    EXPECT_EQ(packing.shapeSpec.superballExponent().value(), 1.0);
    EXPECT_EQ(packing.semiAxis, 0.75);
    EXPECT_EQ(packing.boxLength, 8.0);
    ASSERT_EQ(packing.size(), 2u);
    EXPECT_EQ(packing.positions[0], Vector3d(3.0, 4.5, 4.0)); // shifted by L/2 into [0, L)
    EXPECT_NEAR(packing.positions[1].y(), 0.001, 1e-6);
    EXPECT_EQ(packing.orientations[1].coeffs(), Quaterniond::Identity().coeffs());
    EXPECT_FALSE(packing.reducedPressure.has_value());
}

using fixtures::expectRefused;

TEST(GsdIo, RefusesWhatIsNotACubicSuperballPackingNamingTheFile) {
    const fs::path tilted = scratch("tilted.gsd");
    writeHoomdFrame(tilted, {8.0F, 8.0F, 8.0F, 0.1F, 0.0F, 0.0F},
                    R"({"type": "Sphere", "diameter": 1})");
    expectRefused(tilted, "is not cubic");
    const fs::path cube = scratch("polyhedron.gsd");
    writeHoomdFrame(cube, {8.0F, 8.0F, 8.0F, 0.0F, 0.0F, 0.0F},
                    R"({"type": "ConvexPolyhedron", "vertices": [[1, 1, 1]]})");
    expectRefused(cube, "without a shape sbpack reads");
    const fs::path text = scratch("text.gsd");
    std::ofstream(text) << "not a gsd file\n";
    expectRefused(text, "GSD: opening the file");
    const fs::path whole = scratch("whole.gsd");
    writeGsd(superballs(1.5), whole);
    const fs::path cut = scratch("cut.gsd");
    fs::copy_file(whole, cut, fs::copy_options::overwrite_existing);
    fs::resize_file(cut, fs::file_size(whole) / 2);
    expectRefused(cut, "GSD");
    expectRefused(scratch("absent.gsd"), "no such file");
}

// A hostile file: particles/N and the position chunk's N set to 2^32 - 1 (48 GB of positions in a
// file of a few hundred bytes); refused, naming the file, before anything of that size is
// allocated.
TEST(GsdIo, RefusesAChunkClaimingMoreThanTheFileHolds) {
    const fs::path file = scratch("hostile.gsd");
    writeHoomdFrame(file, {8.0F, 8.0F, 8.0F, 0.0F, 0.0F, 0.0F},
                    R"({"type": "Sphere", "diameter": 1})");
    std::fstream bytes(file, std::ios::in | std::ios::out | std::ios::binary);
    std::uint64_t index = 0;
    bytes.seekg(8); // gsd_header: magic, then index_location
    bytes.read(reinterpret_cast<char*>(&index), sizeof index);
    const std::uint32_t huge = 0xFFFFFFFFU;
    int patched = 0;
    for (std::uint64_t at = index;; at += sizeof(gsd_index_entry)) {
        gsd_index_entry entry{};
        bytes.seekg(static_cast<std::streamoff>(at));
        if (!bytes.read(reinterpret_cast<char*>(&entry), sizeof entry) || entry.location == 0)
            break;
        if (entry.N == 1 && entry.M == 1 && entry.type == GSD_TYPE_UINT32) { // particles/N
            bytes.seekp(entry.location);
            bytes.write(reinterpret_cast<const char*>(&huge), sizeof huge);
            ++patched;
        } else if (entry.N == 2 && entry.M == 3) { // particles/position
            entry.N = huge;
            bytes.seekp(static_cast<std::streamoff>(at));
            bytes.write(reinterpret_cast<const char*>(&entry), sizeof entry);
            ++patched;
        }
    }
    bytes.close();
    ASSERT_EQ(patched, 2);
    expectRefused(file, "GSD");
}

} // namespace
} // namespace sbpack
