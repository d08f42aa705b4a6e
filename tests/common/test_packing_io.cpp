// Packing file I/O (docs/design.md §4): HDF5 and text round trips, the OVITO export, every rejected
// input, and the atomic output helper.

#include "io/atomic_file.hpp"
#include "io/hdf5_handles.hpp"
#include "io/packing_formats.hpp"
#include "io/packing_io.hpp"
#include "io/packing_schema.hpp"
#include "io/text_io.hpp"
#include "packing/contact_forces.hpp"
#include "packing/validation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace sbpack {
namespace {

namespace fs = std::filesystem;

/// A packing with every optional field set; fixed seed.
Packing makePacking(std::size_t n = 6) {
    std::mt19937_64 rng(20240611);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(1.7);
    packing.semiAxis = 0.5;
    packing.boxLength = 10.0;
    for (std::size_t i = 0; i < n; ++i) {
        packing.positions.emplace_back(10.0 * uniform(rng), 10.0 * uniform(rng),
                                       10.0 * uniform(rng));
        packing.orientations.push_back(
            Quaterniond(gauss(rng), gauss(rng), gauss(rng), gauss(rng)).normalized());
        packing.velocities.emplace_back(gauss(rng), gauss(rng), gauss(rng));
        packing.angularVelocities.emplace_back(gauss(rng), gauss(rng), gauss(rng));
    }
    packing.reducedPressure = 1.0e14 / 3.0;
    packing.seed = std::numeric_limits<std::uint64_t>::max() - 12345; // beyond int64
    packing.generatorVersion = "0.1.0";
    packing.provenance["gamma"] = 0.001;
    packing.provenance["n_collisions"] = std::int64_t{-123456789012345};
    packing.provenance["command"] = std::string("sbgen --p 1.7 --n 6");
    packing.provenance["log"] = std::string(200000, 'x'); // beyond the 64 KiB compact limit
    packing.resumeState["format"] = std::string("sbgen.state/1");
    packing.resumeState["growth_rate"] = 1e-2;
    return packing;
}

/// Contact forces between makePacking()'s particles (the points inside the box).
ContactForces makeForces() {
    ContactForces forces;
    forces.windows = 50;
    forces.duration = 1.25e-7;
    forces.reducedPressure = 1e8 / 3.0;
    forces.contacts = {{0, 1, Vector3d(1.5, 2.25, 9.75), Vector3d(1, 2, 2) / 3.0, 3.5e7},
                       {1, 4, Vector3d(0.125, 5.0, 5.5), Vector3d(0, 0.6, -0.8), 0.0},
                       {2, 5, Vector3d(7.0, 3.0, 1.0), Vector3d(-1, 0, 0), 1.0 / 3.0}};
    return forces;
}

/// Runs `action`, expects an E whose message contains every word.
template <typename E, typename F>
void expectError(F&& action, std::initializer_list<std::string> words) {
    try {
        action();
        ADD_FAILURE() << "no exception thrown";
    } catch (const E& e) {
        const std::string message = e.what();
        for (const std::string& word : words)
            EXPECT_NE(message.find(word), std::string::npos)
                << "message \"" << message << "\" lacks \"" << word << "\"";
    }
}

class TemporaryDirectoryTest : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("sbpack_io_" + std::to_string(::getpid()) + "_" +
                                            info->test_suite_name() + "_" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path file(const std::string& name) const { return dir_ / name; }
    std::size_t entries() const {
        return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {}));
    }

  private:
    fs::path dir_;
};

/// Opens a packing file for editing, to build malformed inputs.
Hdf5Handle openForEditing(const fs::path& file) {
    return Hdf5Handle(H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
}

class PackingIo : public TemporaryDirectoryTest {
  protected:
    /// Writes a good file and returns its path.
    fs::path goodFile(const std::string& name = "packing.h5") {
        const fs::path path = file(name);
        writePacking(makePacking(), path);
        return path;
    }
    /// Overwrites the positions with `edit` applied to the good ones.
    template <typename Edit> fs::path withPositions(Edit edit) {
        const fs::path path = goodFile();
        std::vector<double> values =
            readMatrixDataset(openFileReadOnly(path).get(), "positions", makePacking().size(), 3);
        edit(values);
        writeMatrixDataset(openForEditing(path).get(), "positions", values, 3);
        return path;
    }
};

TEST_F(PackingIo, RoundTripIsBitExact) {
    const Packing original = makePacking();
    const fs::path path = file("round_trip.h5");
    writePacking(original, path);
    const Packing read = readPacking(path);

    EXPECT_EQ(read.shapeSpec, original.shapeSpec);
    EXPECT_EQ(read.semiAxis, original.semiAxis);
    EXPECT_EQ(read.boxLength, original.boxLength);
    ASSERT_EQ(read.size(), original.size());
    for (std::size_t i = 0; i < original.size(); ++i) {
        EXPECT_EQ(read.positions[i], original.positions[i]) << i;
        EXPECT_EQ(read.orientations[i].coeffs(), original.orientations[i].coeffs()) << i;
        EXPECT_EQ(read.velocities[i], original.velocities[i]) << i;
        EXPECT_EQ(read.angularVelocities[i], original.angularVelocities[i]) << i;
    }
    EXPECT_EQ(read.reducedPressure, original.reducedPressure);
    EXPECT_EQ(read.seed, original.seed);
    EXPECT_EQ(read.generatorVersion, original.generatorVersion);
    EXPECT_EQ(read.provenance, original.provenance);
    EXPECT_EQ(read.resumeState, original.resumeState);
}

TEST_F(PackingIo, AnEarlierFilesResumeStateInTheProvenanceIsMovedToItsGroup) {
    Packing original = makePacking();
    original.resumeState.clear();
    original.provenance["state_phase"] = std::int64_t{2};
    original.provenance["state_growth_rate"] = 1e-4;
    const fs::path path = file("earlier.h5");
    writePacking(original, path);
    const Packing read = readPacking(path);
    EXPECT_EQ(read.resumeState.at("phase"), ProvenanceValue(std::int64_t{2}));
    EXPECT_EQ(read.resumeState.at("growth_rate"), ProvenanceValue(1e-4));
    EXPECT_EQ(read.provenance.count("state_phase"), 0U);
    EXPECT_EQ(read.provenance.at("gamma"), ProvenanceValue(0.001));
}

/// makePacking() without any of the file's optional entries.
Packing minimalPacking() {
    Packing packing = makePacking();
    packing.velocities.clear();
    packing.angularVelocities.clear();
    packing.reducedPressure.reset();
    packing.seed.reset();
    packing.generatorVersion.clear();
    packing.provenance.clear();
    packing.resumeState.clear();
    return packing;
}

TEST_F(PackingIo, OptionalFieldsStayAbsent) {
    const Packing original = minimalPacking();
    const fs::path path = file("minimal.h5");
    writePacking(original, path);
    const Packing read = readPacking(path);
    EXPECT_TRUE(read.velocities.empty());
    EXPECT_TRUE(read.angularVelocities.empty());
    EXPECT_FALSE(read.reducedPressure);
    EXPECT_FALSE(read.seed);
    EXPECT_TRUE(read.provenance.empty());
    EXPECT_TRUE(read.resumeState.empty());
    EXPECT_FALSE(read.contactForces);
    EXPECT_FALSE(hasLink(openFileReadOnly(path).get(), "contact_forces"));
    EXPECT_FALSE(hasLink(openFileReadOnly(path).get(), "velocities"));
    EXPECT_FALSE(hasLink(openFileReadOnly(path).get(), "resume_state"));
}

/// Whether the file `root` holds `e` (io/packing_schema.hpp).
bool holds(hid_t root, const PackingEntry& e) {
    const std::string name(e.name), group(e.group);
    const auto in = [&](hid_t where) {
        return e.kind == PackingKind::Attribute ? hasAttribute(where, name) : hasLink(where, name);
    };
    if (group.empty()) return in(root);
    return hasLink(root, group) && in(openGroup(root, group).get());
}

/// The file at `path` holds the table's entries (every one, or the required ones only) and, at
/// its root, nothing else. Its particles are superballs, whose file names no family.
void expectTheTableEntries(const fs::path& path, bool optionalToo) {
    const Hdf5Handle h5 = openFileReadOnly(path);
    std::size_t attributes = 0, links = 0;
    for (const PackingEntry& e : packingEntries()) {
        const bool expected = (optionalToo && e.name != packing_file::kShape) || !e.optional;
        EXPECT_EQ(holds(h5.get(), e), expected) << e.group << "/" << e.name;
        if (expected && e.group.empty()) ++(e.kind == PackingKind::Attribute ? attributes : links);
    }
    EXPECT_EQ(attributeNames(h5.get()).size(), attributes);
    H5G_info_t info;
    ASSERT_GE(H5Gget_info(h5.get(), &info), 0);
    EXPECT_EQ(info.nlinks, links);
}

TEST_F(PackingIo, TheWriterWritesTheDeclaredEntriesAndNoOthers) { // issue 45
    Packing full = makePacking();
    full.resumeState[packing_file::kPairRecords] = std::int64_t{1};
    full.pairRecords.assign(kPairRecordColumns, 0.5);
    full.contactForces = makeForces();
    full.semiAxes.assign(full.size(), full.semiAxis); // a mixture's (docs/mixtures.md)
    full.semiAxes.back() = 0.5 * full.semiAxis;
    writePacking(full, file("full.h5"));
    expectTheTableEntries(file("full.h5"), true);
    EXPECT_EQ(readPacking(file("full.h5")).pairRecords, full.pairRecords);
    writePacking(minimalPacking(), file("minimal.h5"));
    expectTheTableEntries(file("minimal.h5"), false);
}

TEST_F(PackingIo, ContactForcesRoundTripWithTheirUnitsAndResiduals) { // issue 62
    Packing original = makePacking();
    original.contactForces = makeForces();
    const fs::path path = file("forces.h5");
    writePacking(original, path);
    const std::optional<ContactForces> read = readPacking(path).contactForces;
    ASSERT_TRUE(read);
    const ContactForces& expected = *original.contactForces;
    EXPECT_EQ(read->windows, expected.windows);
    EXPECT_EQ(read->duration, expected.duration);
    EXPECT_EQ(read->reducedPressure, expected.reducedPressure);
    ASSERT_EQ(read->contacts.size(), expected.contacts.size());
    for (std::size_t c = 0; c < expected.contacts.size(); ++c) {
        const ContactForce &a = read->contacts[c], &b = expected.contacts[c];
        EXPECT_EQ(std::pair(a.i, a.j), std::pair(b.i, b.j)) << c;
        EXPECT_EQ(a.point, b.point) << c;
        EXPECT_EQ(a.normal, b.normal) << c;
        EXPECT_EQ(a.force, b.force) << c;
    }
    // The residuals are written for h5py readers, as forceBalance computes them, with units.
    const Hdf5Handle h5 = openFileReadOnly(path);
    const Hdf5Handle group = openGroup(h5.get(), "contact_forces");
    const ForceBalance balance = forceBalance(original, expected);
    const std::vector<double> net = readMatrixDataset(group.get(), "net_torques", 6, 3);
    for (std::size_t i = 0; i < 6; ++i)
        EXPECT_EQ(Vector3d(net[3 * i], net[3 * i + 1], net[3 * i + 2]), balance.netTorques[i]);
    const auto units = [&](const char* name) {
        return readStringAttribute(openDataset(group.get(), name).get(), "units");
    };
    EXPECT_EQ(units("forces"), "kT/D");
    EXPECT_EQ(units("net_forces"), "kT/D");
    EXPECT_EQ(units("net_torques"), "kT");
    EXPECT_EQ(units("points"), "length");
    EXPECT_EQ(units("pairs"), "1");
}

TEST_F(PackingIo, TamperedContactForcesAreRefusedNamingTheRow) { // issue 62
    const auto tampered = [&](const char* dataset, std::size_t columns, std::size_t index,
                              double value) {
        Packing packing = makePacking();
        packing.contactForces = makeForces();
        const fs::path path = file("tampered.h5");
        writePacking(packing, path);
        const Hdf5Handle h5 = openForEditing(path);
        const Hdf5Handle group = openGroup(h5.get(), "contact_forces");
        std::vector<double> values = readMatrixDataset(group.get(), dataset, 3, columns);
        values[index] = value;
        writeMatrixDataset(group.get(), dataset, values, columns);
        return path;
    };
    const auto refused = [&](const fs::path& path, const char* problem) {
        expectError<PackingFileError>([&] { readPacking(path); },
                                      {"contact_forces row 1", problem});
    };
    refused(tampered("pairs", 2, 2, 4.0), "i < j < n_particles"); // (4, 4)
    refused(tampered("pairs", 2, 3, 6.0), "i < j < n_particles"); // j = N
    refused(tampered("normals", 3, 3, 0.5), "unit vector");
    refused(tampered("forces", 1, 1, -1.0), "non-negative");
    refused(tampered("points", 3, 4, NAN), "finite");
}

TEST_F(PackingIo, WritesTheSchemaAttributes) {
    const Packing packing = makePacking();
    const fs::path path = goodFile();
    const Hdf5Handle h5 = openFileReadOnly(path);
    EXPECT_EQ(readStringAttribute(h5.get(), "format"), "sbpack.packing");
    EXPECT_EQ(readInt64Attribute(h5.get(), "format_version"), 1);
    EXPECT_EQ(readInt64Attribute(h5.get(), "n_particles"), 6);
    EXPECT_EQ(readDoubleAttribute(h5.get(), "phi"), packing.packingFraction());
    EXPECT_EQ(attributeKind(h5.get(), "seed"), AttributeKind::Integer);
}

TEST_F(PackingIo, ReaderWrapsPositionsAndNormalisesQuaternions) {
    const fs::path path = withPositions([](std::vector<double>& v) {
        v[0] = -0.25; // particle 0, x
        v[4] = 10.5;  // particle 1, y
    });
    std::vector<double> q = readMatrixDataset(openFileReadOnly(path).get(), "orientations", 6, 4);
    for (int k = 0; k < 4; ++k)
        q[4 + k] *= 1.0 + 5e-7; // particle 1, within the tolerance
    writeMatrixDataset(openForEditing(path).get(), "orientations", q, 4);

    const Packing read = readPacking(path);
    EXPECT_DOUBLE_EQ(read.positions[0].x(), 9.75);
    EXPECT_DOUBLE_EQ(read.positions[1].y(), 0.5);
    EXPECT_NEAR(read.orientations[1].norm(), 1.0, 1e-15);
}

TEST_F(PackingIo, AHugeClaimWithNothingStoredIsRefusedBeforeAllocating) {
    // n_particles = 1e9 and a chunked positions dataset of that extent, never written: reading it
    // would allocate 24 GB of fill values.
    const fs::path path = goodFile();
    {
        const Hdf5Handle h5 = openForEditing(path);
        H5Adelete(h5.get(), "n_particles");
        writeInt64Attribute(h5.get(), "n_particles", 1000000000);
        H5Ldelete(h5.get(), "positions", H5P_DEFAULT);
        const hsize_t dims[2] = {1000000000, 3}, chunk[2] = {1024, 3};
        const Hdf5Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose);
        const Hdf5Handle layout(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
        H5Pset_chunk(layout.get(), 2, chunk);
        const Hdf5Handle positions(H5Dcreate2(h5.get(), "positions", H5T_IEEE_F64LE, space.get(),
                                              H5P_DEFAULT, layout.get(), H5P_DEFAULT),
                                   H5Dclose);
        ASSERT_GE(positions.get(), 0);
    }
    EXPECT_LT(fs::file_size(path), 1000000u); // a small file
    expectError<PackingFileError>([&] { readPacking(path); },
                                  {"positions", "claims 1000000000 x 3 values but stores only"});
}

TEST_F(PackingIo, AFixedLengthStringWithAnEmbeddedNulIsRefused) {
    // "sbpack.packing\0junk" as a C string is the right format name: it must not pass.
    const fs::path path = goodFile();
    {
        const Hdf5Handle h5 = openForEditing(path);
        H5Adelete(h5.get(), "format");
        const std::string text("sbpack.packing\0junk", 19);
        const Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
        H5Tset_size(type.get(), text.size());
        H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
        const Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
        const Hdf5Handle attribute(
            H5Acreate2(h5.get(), "format", type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
            H5Aclose);
        ASSERT_GE(H5Awrite(attribute.get(), type.get(), text.data()), 0);
    }
    expectError<std::exception>([&] { readPacking(path); },
                                {"packing.h5", "format", "embedded NUL"});
}

TEST_F(PackingIo, AParticleWiderThanTheBoxIsRefused) {
    Packing packing = makePacking();
    packing.semiAxis = 1e300; // what convert once wrote and could not read back
    expectError<std::exception>([&] { writePacking(packing, file("wide.h5")); },
                                {"semi_axis = 1e+300", "wider than the box"});
    EXPECT_FALSE(fs::exists(file("wide.h5")));
}

TEST_F(PackingIo, LengthsOutsideTheRangeOfResultsAreRefusedWithTheLimit) {
    // Scaled by 1e-300 or 1e100 (sbgen --phi-init 1e-300 wrote L = 2.2e100): results up to
    // length^3 would not be normal doubles (docs/design.md §5, "Units"; issue 65).
    Packing tiny = makePacking();
    tiny.semiAxis *= 1e-300;
    tiny.boxLength *= 1e-300;
    for (Vector3d& r : tiny.positions)
        r *= 1e-300;
    expectError<std::exception>([&] { writePacking(tiny, file("tiny.h5")); },
                                {"semi_axis = ", "below 1e-100", "[1e-100, 1e+100]"});
    Packing huge = makePacking();
    huge.boxLength = 2.2e100;
    expectError<std::exception>([&] { writePacking(huge, file("huge.h5")); },
                                {"box_length = 2.2e+100 above 1e+100", "rescale"});
    Packing small = makePacking(); // 1e-90 is in range
    small.semiAxis *= 1e-90;
    small.boxLength *= 1e-90;
    for (Vector3d& r : small.positions)
        r *= 1e-90;
    EXPECT_NO_THROW(writePacking(small, file("small.h5")));
}

TEST_F(PackingIo, MissingFile) {
    const fs::path path = file("absent.h5");
    expectError<PackingFileError>([&] { readPacking(path); }, {"absent.h5", "no such file"});
}

TEST_F(PackingIo, NotHdf5) {
    const fs::path path = file("text.h5");
    std::ofstream(path) << "this is not HDF5\n";
    expectError<PackingFileError>([&] { readPacking(path); }, {"text.h5", "not an HDF5 file"});
}

TEST_F(PackingIo, TruncatedFile) {
    const fs::path path = goodFile("cut.h5");
    fs::resize_file(path, fs::file_size(path) / 2);
    expectError<PackingFileError>([&] { readPacking(path); }, {"cut.h5", "truncated"});
}

TEST_F(PackingIo, WrongFormatString) {
    const fs::path path = goodFile();
    writeStringAttribute(openForEditing(path).get(), "format", "sbpack.results");
    expectError<PackingFileError>([&] { readPacking(path); },
                                  {"packing.h5", "format", "sbpack.results"});
}

TEST_F(PackingIo, WrongFormatVersion) {
    const fs::path path = goodFile();
    writeInt64Attribute(openForEditing(path).get(), "format_version", 2);
    expectError<PackingFileError>([&] { readPacking(path); }, {"packing.h5", "format_version 2"});
}

TEST_F(PackingIo, MissingDataset) {
    const fs::path path = goodFile();
    H5Ldelete(openForEditing(path).get(), "orientations", H5P_DEFAULT);
    expectError<PackingFileError>([&] { readPacking(path); },
                                  {"packing.h5", "orientations", "missing"});
}

TEST_F(PackingIo, MissingAttribute) {
    const fs::path path = goodFile();
    H5Adelete(openForEditing(path).get(), "semi_axis");
    expectError<PackingFileError>([&] { readPacking(path); },
                                  {"packing.h5", "semi_axis", "missing"});
}

TEST_F(PackingIo, ShapeNotMatchingParticleCount) {
    const fs::path path = goodFile();
    writeInt64Attribute(openForEditing(path).get(), "n_particles", 7);
    expectError<PackingFileError>([&] { readPacking(path); },
                                  {"packing.h5", "positions", "shape 6 x 3", "7 x 3"});
}

TEST_F(PackingIo, WrongSecondDimension) {
    const fs::path path = goodFile();
    const std::vector<double> wide(6 * 4, 0.5);
    writeMatrixDataset(openForEditing(path).get(), "positions", wide, 4);
    expectError<PackingFileError>([&] { readPacking(path); },
                                  {"packing.h5", "positions", "shape 6 x 4"});
}

TEST_F(PackingIo, NanCoordinate) {
    const fs::path path =
        withPositions([](std::vector<double>& v) { v[3 * 3 + 1] = std::nan(""); });
    expectError<InvalidPacking>([&] { readPacking(path); },
                                {"packing.h5", "particle 3", "non-finite", "position"});
}

TEST_F(PackingIo, QuaternionFarFromUnit) {
    const fs::path path = goodFile();
    std::vector<double> q = readMatrixDataset(openFileReadOnly(path).get(), "orientations", 6, 4);
    for (int k = 0; k < 4; ++k)
        q[4 * 2 + k] *= 1.5;
    writeMatrixDataset(openForEditing(path).get(), "orientations", q, 4);
    expectError<InvalidPacking>([&] { readPacking(path); },
                                {"packing.h5", "particle 2", "quaternion", "norm 1.5"});
}

TEST_F(PackingIo, PBelowOneHalf) {
    const fs::path path = goodFile();
    writeDoubleAttribute(openForEditing(path).get(), "p", 0.4);
    expectError<InvalidPacking>([&] { readPacking(path); }, {"packing.h5", "p = 0.4"});
}

TEST_F(PackingIo, PNotANumber) {
    const fs::path path = goodFile();
    writeDoubleAttribute(openForEditing(path).get(), "p", std::nan(""));
    expectError<InvalidPacking>([&] { readPacking(path); }, {"packing.h5", "p = nan"});
}

// The family's name is written only for a family other than the superball, so a superball file
// is as before; a file that names the superball reads the same, one that names a family this
// build does not know is refused naming it and the file.
TEST_F(PackingIo, TheShapeFamilyIsReadByName) {
    const fs::path path = goodFile();
    EXPECT_FALSE(hasAttribute(openForEditing(path).get(), "shape"));
    const Packing before = readPacking(path);
    writeStringAttribute(openForEditing(path).get(), "shape", "superball");
    EXPECT_EQ(readPacking(path).shapeSpec, before.shapeSpec);
    writeStringAttribute(openForEditing(path).get(), "shape", "ellipsoid");
    expectError<PackingFileError>([&] { readPacking(path); },
                                  {"packing.h5", "shape 'ellipsoid'", "superball"});
}

TEST_F(PackingIo, BoxLengthNotPositive) {
    const fs::path path = goodFile();
    writeDoubleAttribute(openForEditing(path).get(), "box_length", 0.0);
    expectError<InvalidPacking>([&] { readPacking(path); }, {"packing.h5", "box_length = 0"});
}

TEST_F(PackingIo, SemiAxisNotPositive) {
    const fs::path path = goodFile();
    writeDoubleAttribute(openForEditing(path).get(), "semi_axis", -0.5);
    expectError<InvalidPacking>([&] { readPacking(path); }, {"packing.h5", "semi_axis = -0.5"});
}

TEST_F(PackingIo, ReducedPressureNotPositive) { // issue 46, defect 11
    const fs::path path = goodFile();
    for (double pressure : {-1.0, 0.0}) {
        writeDoubleAttribute(openForEditing(path).get(), "reduced_pressure", pressure);
        expectError<InvalidPacking>([&] { readPacking(path); },
                                    {"packing.h5", "reduced_pressure = ", "positive"});
    }
}

TEST_F(PackingIo, AnExternalLinkIsRefusedNotFollowed) { // issue 46, defect 5
    const fs::path path = goodFile();
    ASSERT_EQ(::mkfifo(file("fifo.h5").c_str(), 0600), 0);
    for (const char* target : {"fifo.h5", "packing.h5"}) { // a FIFO would block the open
        {
            const Hdf5Handle h5 = openForEditing(path);
            if (H5Lexists(h5.get(), "velocities", H5P_DEFAULT) > 0)
                H5Ldelete(h5.get(), "velocities", H5P_DEFAULT);
            ASSERT_GE(H5Lcreate_external(target, "/velocities", h5.get(), "velocities", H5P_DEFAULT,
                                         H5P_DEFAULT),
                      0);
        }
        expectError<PackingFileError>([&] { readPacking(path); },
                                      {"packing.h5", "velocities", "external link"});
    }
}

TEST_F(PackingIo, WritesThroughASymbolicLink) { // issue 46, defect 3
    const Packing packing = makePacking();
    fs::create_directory(file("target"));
    fs::create_symlink("target/real.h5", file("link.h5")); // dangling until written
    writePacking(packing, file("link.h5"));
    EXPECT_TRUE(fs::is_symlink(file("link.h5")));
    EXPECT_EQ(readPacking(file("target") / "real.h5").positions, packing.positions);
    fs::create_symlink("link.h5", file("chain.h5")); // a chain, to an existing file
    writePacking(packing, file("chain.h5"));
    EXPECT_TRUE(fs::is_symlink(file("chain.h5")) && fs::is_symlink(file("link.h5")));
    fs::create_symlink("loop.h5", file("loop.h5"));
    expectError<OutputPathError>([&] { writePacking(packing, file("loop.h5")); },
                                 {"loop.h5", "symbolic links"});
}

TEST_F(PackingIo, PhiDisagreeingWithContents) {
    const fs::path path = goodFile();
    writeDoubleAttribute(openForEditing(path).get(), "phi", 0.6);
    expectError<InvalidPacking>([&] { readPacking(path); }, {"packing.h5", "phi = 0.6"});
}

TEST_F(PackingIo, WriteIntoMissingDirectory) {
    const fs::path path = file("no_such_dir") / "out.h5";
    expectError<OutputPathError>([&] { writePacking(makePacking(), path); },
                                 {"no_such_dir", "does not exist"});
}

TEST_F(PackingIo, WriteRejectsInvalidPackingAndLeavesNothing) {
    Packing packing = makePacking();
    packing.orientations.pop_back();
    expectError<InvalidPacking>([&] { writePacking(packing, file("bad.h5")); },
                                {"bad.h5", "count mismatch"});
    EXPECT_EQ(entries(), 0u);
}

class PackingValidation : public ::testing::Test {};

TEST_F(PackingValidation, AcceptsAGoodPackingWithPositionsOutsideTheBox) {
    Packing packing = makePacking();
    packing.positions[0] = Vector3d(-1.0, 11.0, 25.0);
    EXPECT_NO_THROW(validatePacking(packing, "src"));
}

// Issue 65 item 8: far outside the box, wrapping rounds a position by more than 1e-12 L (1e6 L
// out: 5e-10 D; 1e300: to 0), so such a position is refused with the particle named; 1e3 L
// (eps 1e3 L = 2e-12 L) still passes.
TEST_F(PackingValidation, RefusesPositionsSoFarOutThatWrappingWouldRoundThem) {
    Packing packing = makePacking();
    packing.positions[2] = Vector3d(0.5, 1e3 * packing.boxLength, -1e3 * packing.boxLength);
    EXPECT_NO_THROW(validatePacking(packing, "src"));
    for (const double far : {1e6 * packing.boxLength, -1e300}) {
        packing.positions[2] = Vector3d(0.5, far, 0.5);
        expectError<InvalidPacking>([&] { validatePacking(packing, "src.h5"); },
                                    {"src.h5", "particle 2", "box lengths from the box"});
    }
}

TEST_F(PackingValidation, RejectsNoParticles) {
    Packing packing = makePacking();
    packing.positions.clear();
    packing.orientations.clear();
    packing.velocities.clear();
    packing.angularVelocities.clear();
    expectError<InvalidPacking>([&] { validatePacking(packing, "src.h5"); },
                                {"src.h5", "no particles"});
}

TEST_F(PackingValidation, RejectsVelocityArraysOfTheWrongLength) {
    Packing packing = makePacking();
    packing.angularVelocities.pop_back();
    expectError<InvalidPacking>([&] { validatePacking(packing, "src.h5"); },
                                {"src.h5", "angular velocity", "count mismatch"});
}

TEST_F(PackingValidation, RejectsInfiniteVelocityAndInfiniteP) {
    Packing packing = makePacking();
    packing.velocities[4].z() = std::numeric_limits<double>::infinity();
    expectError<InvalidPacking>([&] { validatePacking(packing, "src.h5"); },
                                {"src.h5", "particle 4", "velocity", "non-finite"});
    packing = makePacking();
    packing.shapeSpec = sbpack::ShapeSpec::superball(std::numeric_limits<double>::infinity());
    expectError<InvalidPacking>([&] { validatePacking(packing, "src.h5"); }, {"p = inf"});
}

TEST_F(PackingValidation, RejectsNanQuaternion) {
    Packing packing = makePacking();
    packing.orientations[5].x() = std::nan("");
    expectError<InvalidPacking>([&] { validatePacking(packing, "src.h5"); },
                                {"particle 5", "non-finite", "quaternion"});
}

class TextIo : public TemporaryDirectoryTest {
  protected:
    fs::path textFile(const std::string& body, const std::string& name = "packing.txt") {
        const fs::path path = file(name);
        std::ofstream(path) << body;
        return path;
    }
    static constexpr const char* kHeader = "# sbpack text packing v1\n# p 1.5\n# semi_axis 0.5\n"
                                           "# box_length 10\n";
};

TEST_F(TextIo, RoundTripIsBitExact) {
    const Packing original = makePacking();
    const fs::path path = file("round_trip.txt");
    writeTextPacking(original, path);
    const Packing read = readTextPacking(path);
    EXPECT_EQ(read.shapeSpec, original.shapeSpec);
    EXPECT_EQ(read.semiAxis, original.semiAxis);
    EXPECT_EQ(read.boxLength, original.boxLength);
    ASSERT_EQ(read.size(), original.size());
    for (std::size_t i = 0; i < original.size(); ++i) {
        EXPECT_EQ(read.positions[i], original.positions[i]) << i;
        EXPECT_EQ(read.orientations[i].coeffs(), original.orientations[i].coeffs()) << i;
    }
}

// Issue 65 item 4: the reduced pressure (it sets the jam check's tolerance, so Z and phi_R) and
// the seed survive the text format; what it cannot carry is named for convert's warning.
TEST_F(TextIo, CarriesThePressureAndSeedAndNamesWhatItLeavesOut) {
    Packing original = makePacking();
    original.reducedPressure = 1.0761381753160638e8;
    original.seed = 9007199254740992;
    const fs::path path = file("pressure.txt");
    writeTextPacking(original, path);
    const Packing read = readTextPacking(path);
    EXPECT_EQ(read.reducedPressure, original.reducedPressure);
    EXPECT_EQ(read.seed, original.seed);
    const std::vector<std::string> left{"velocities", "angular velocities", "provenance",
                                        "resume state (a checkpoint's)"};
    EXPECT_EQ(notCarriedBy(original, PackingFormat::Text), left); // makePacking has them all
    EXPECT_EQ(notCarriedBy(original, PackingFormat::Gsd), left);
    EXPECT_TRUE(notCarriedBy(original, PackingFormat::Hdf5).empty());
    std::vector<std::string> leftByXyz{"reduced_pressure", "seed"};
    leftByXyz.insert(leftByXyz.end(), left.begin(), left.end());
    EXPECT_EQ(notCarriedBy(original, PackingFormat::ExtendedXyz), leftByXyz);
    EXPECT_TRUE(notCarriedBy(read, PackingFormat::Text).empty());
    const fs::path bare = textFile(std::string(kHeader) + "# n_particles 1\n1 2 3 1 0 0 0\n");
    EXPECT_FALSE(readTextPacking(bare).reducedPressure.has_value());
    expectError<PackingFileError>(
        [&] {
            readTextPacking(textFile(std::string(kHeader) +
                                         "# reduced_pressure 1e6\n# reduced_pressure 1e7\n# "
                                         "n_particles 1\n1 2 3 1 0 0 0\n",
                                     "twice.txt"));
        },
        {"twice.txt", "'reduced_pressure' is repeated"});
}

TEST_F(TextIo, ReadsCommentsBlankLinesAndCarriageReturns) {
    const fs::path path =
        textFile(std::string(kHeader) + "# n_particles 2\n# a free comment\n\r\n"
                                        "1 2 3 1 0 0 0\r\n-1 +2 3e0 0 1 0 0\n# trailing\n");
    const Packing read = readTextPacking(path);
    ASSERT_EQ(read.size(), 2u);
    EXPECT_EQ(read.shapeSpec.superballExponent().value(), 1.5);
    EXPECT_EQ(read.positions[1], Vector3d(9.0, 2.0, 3.0)); // wrapped
    EXPECT_EQ(read.orientations[1].x(), 1.0);
}

// issue 65 item 8: a byte-order mark or trailing blanks on the header refused the file, while CRLF
// was read.
TEST_F(TextIo, ReadsAByteOrderMarkAndTrailingBlanks) {
    const fs::path path = textFile("\xEF\xBB\xBF# sbpack text packing v1 \t\r\n# p 1.5  \n"
                                   "# semi_axis 0.5\t\n# box_length 10 \r\n# n_particles 1 \n"
                                   "1 2 3 1 0 0 0  \n");
    const Packing read = readTextPacking(path);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(read.boxLength, 10.0);
    EXPECT_EQ(read.positions[0], Vector3d(1.0, 2.0, 3.0));
    // A mark anywhere but the file's start is no blank.
    const fs::path inner = textFile(
        std::string(kHeader) + "\xEF\xBB\xBF# n_particles 1\n1 2 3 1 0 0 0\n", "inner.txt");
    expectError<PackingFileError>([&] { readTextPacking(inner); }, {"inner.txt", "line 5"});
}

TEST_F(TextIo, MalformedLineNamesTheLine) {
    const fs::path path =
        textFile(std::string(kHeader) + "# n_particles 2\n1 2 3 1 0 0 0\n1 2 3 1 0 0\n");
    expectError<PackingFileError>([&] { readTextPacking(path); },
                                  {"packing.txt", "line 7", "expected 7 numbers", "found 6"});
}

TEST_F(TextIo, NonNumberNamesTheLine) {
    const fs::path path = textFile(std::string(kHeader) + "# n_particles 1\n1 2 x 1 0 0 0\n");
    expectError<PackingFileError>([&] { readTextPacking(path); },
                                  {"packing.txt", "line 6", "'x' is not a number"});
}

TEST_F(TextIo, MissingHeaderKey) {
    const fs::path path = textFile("# sbpack text packing v1\n# p 1.5\n# box_length 10\n"
                                   "# n_particles 1\n1 2 3 1 0 0 0\n");
    expectError<PackingFileError>([&] { readTextPacking(path); },
                                  {"packing.txt", "missing header key 'semi_axis'"});
}

// docs/architecture.md, "a new shape": the header names the shape as the packing file does, the
// family under `shape` (none: the superball) and its parameters by name, in any order.
TEST_F(TextIo, TheHeaderNamesTheShapeFamilyAndItsParametersInAnyOrder) {
    const std::string particles = "# semi_axis 0.5\n# box_length 10\n# n_particles 1\n"
                                  "1 2 3 1 0 0 0\n";
    const Packing plain = readTextPacking(textFile(kHeader + std::string("# n_particles 1\n1 2 3 "
                                                                         "1 0 0 0\n")));
    for (const char* shape : {"# shape superball\n# p 1.5\n", "# p 1.5\n# shape superball\n"}) {
        const Packing named = readTextPacking(
            textFile("# sbpack text packing v1\n" + std::string(shape) + particles, "named.txt"));
        EXPECT_EQ(named.shapeSpec, plain.shapeSpec) << shape;
        EXPECT_EQ(named.shapeSpec, ShapeSpec::superball(1.5));
    }
    const fs::path unknown = textFile(
        "# sbpack text packing v1\n# shape ellipsoid\n# p 1.5\n" + particles, "unknown.txt");
    expectError<PackingFileError>(
        [&] { readTextPacking(unknown); },
        {"unknown.txt", "line 2", "unknown shape family 'ellipsoid'", "known: superball"});
    const fs::path twice = textFile(
        "# sbpack text packing v1\n# shape superball\n# shape superball\n# p 1.5\n" + particles,
        "twice.txt");
    expectError<PackingFileError>([&] { readTextPacking(twice); },
                                  {"twice.txt", "line 3", "header key 'shape' is repeated"});
}

TEST_F(TextIo, WrongParticleCount) {
    const fs::path path = textFile(std::string(kHeader) + "# n_particles 3\n1 2 3 1 0 0 0\n");
    expectError<PackingFileError>([&] { readTextPacking(path); },
                                  {"packing.txt", "n_particles 3", "1 particle lines"});
}

TEST_F(TextIo, NotATextPacking) {
    const fs::path path = textFile("3\nLattice=\"1 0 0 0 1 0 0 0 1\"\n");
    expectError<PackingFileError>([&] { readTextPacking(path); },
                                  {"packing.txt", "line 1", "not an sbpack text packing"});
}

TEST_F(TextIo, NanCoordinateNamesTheParticle) {
    const fs::path path =
        textFile(std::string(kHeader) + "# n_particles 2\n1 2 3 1 0 0 0\n1 nan 3 1 0 0 0\n");
    expectError<InvalidPacking>([&] { readTextPacking(path); },
                                {"packing.txt", "particle 1", "non-finite"});
}

TEST_F(TextIo, MissingFile) {
    expectError<PackingFileError>([&] { readTextPacking(file("absent.txt")); },
                                  {"absent.txt", "no such file"});
}

TEST_F(TextIo, ExtendedXyzForOvito) {
    const Packing packing = makePacking();
    const fs::path path = file("packing.xyz");
    writeExtendedXyz(packing, path);

    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "6");
    std::getline(in, line);
    EXPECT_NE(line.find("Lattice=\"10 0 0 0 10 0 0 0 10\""), std::string::npos) << line;
    EXPECT_NE(line.find("Origin=\"0 0 0\""), std::string::npos) << line;
    EXPECT_NE(line.find("pbc=\"T T T\""), std::string::npos) << line;
    EXPECT_NE(line.find("Properties=species:S:1:pos:R:3:orientation:R:4:aspherical_shape:R:3:"
                        "superquadric_roundness:R:2"),
              std::string::npos)
        << line;
    for (std::size_t i = 0; i < packing.size(); ++i) {
        ASSERT_TRUE(std::getline(in, line)) << i;
        std::istringstream fields(line);
        std::string species;
        double v[12];
        fields >> species;
        for (double& x : v)
            fields >> x;
        ASSERT_TRUE(fields) << line;
        EXPECT_EQ(species, "Superball");
        const Quaterniond& q = packing.orientations[i];
        const double expected[12] = {packing.positions[i].x(),
                                     packing.positions[i].y(),
                                     packing.positions[i].z(),
                                     q.x(),
                                     q.y(),
                                     q.z(),
                                     q.w(),
                                     0.5,
                                     0.5,
                                     0.5,
                                     1.0 / 1.7,
                                     1.0 / 1.7};
        for (int k = 0; k < 12; ++k)
            EXPECT_EQ(v[k], expected[k]) << "particle " << i << " " << k;
    }
    EXPECT_FALSE(std::getline(in, line) && !line.empty());
}

// Issue 66 item 1: the XYZ export reads back bit for bit (17 digits); OVITO's spelling (keys
// in any case, only the shape keys or only the shape columns) reads alike; what is not a
// packing of identical superballs in a cube is refused with the file and line.
TEST_F(TextIo, ExtendedXyzReadsBackBitForBit) {
    const Packing packing = makePacking();
    const fs::path path = file("round.xyz");
    writeExtendedXyz(packing, path);
    const Packing read = readPackingFile(path);
    EXPECT_EQ(read.shapeSpec, packing.shapeSpec);
    // A p of many digits is the header's as written, not 1 / (1 / p) (which may miss it by an
    // ulp) nor rounded to 6 digits.
    Packing manyDigits = packing;
    manyDigits.shapeSpec =
        sbpack::ShapeSpec::superball(7.390019499834); // 1 / (1 / p) is 7.3900194998340005
    writeExtendedXyz(manyDigits, path);
    EXPECT_EQ(readPackingFile(path).shapeSpec.superballExponent().value(),
              manyDigits.shapeSpec.superballExponent().value());
    EXPECT_EQ(read.semiAxis, packing.semiAxis);
    EXPECT_EQ(read.boxLength, packing.boxLength);
    ASSERT_EQ(read.size(), packing.size());
    for (std::size_t i = 0; i < packing.size(); ++i) {
        EXPECT_EQ(read.positions[i], wrapIntoBox(packing.positions[i], packing.boxLength)) << i;
        EXPECT_EQ(read.orientations[i].coeffs(), packing.orientations[i].normalized().coeffs())
            << i;
    }
}

TEST_F(TextIo, ExtendedXyzInOvitosSpellingAndItsRefusals) {
    const std::string ovito = "2\nlattice=\"4 0 0 0 4 0 0 0 4\" PBC=\"T T T\" "
                              "properties=Species:S:1:Pos:R:3:Orientation:R:4:"
                              "Aspherical_Shape:R:3:Superquadric_Roundness:R:2\n";
    const std::string a = "A 1 1 1 0 0 0 1 0.5 0.5 0.5 0.8 0.8\n";
    const std::string b = "A 3 3 3 0 0 0.6 0.8 0.5 0.5 0.5 0.8 0.8\n";
    const Packing read = readExtendedXyz(textFile(ovito + a + b, "ovito.xyz"));
    EXPECT_DOUBLE_EQ(read.shapeSpec.superballExponent().value(), 1.25);
    EXPECT_EQ(read.semiAxis, 0.5);
    EXPECT_NEAR(read.orientations[1].w(), 0.8, 1e-15);
    EXPECT_NEAR(read.orientations[1].z(), 0.6, 1e-15);
    const std::string spheres = "1\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=pos:R:3 p=1 "
                                "semi_axis=0.5\n1 2 3\n";
    EXPECT_EQ(
        readExtendedXyz(textFile(spheres, "spheres.xyz")).shapeSpec.superballExponent().value(),
        1.0);
    // OVITO 3.17's own export: SuperquadricRoundness in single precision, 10 digits.
    const std::string written = "1\nLattice=\"4.0 0.0 0.0 0.0 4.0 0.0 0.0 0.0 4.0\" pbc=\"T T T\" "
                                "Properties=species:S:1:pos:R:3:orientation:R:4:"
                                "aspherical_shape:R:3:SuperquadricRoundness:R:2\n"
                                "Superball 1 2 3 0 0 0 1 0.7653366272 0.7653366272 0.7653366272 "
                                "0.6666667008 0.6666667008\n";
    EXPECT_EQ(readExtendedXyz(textFile(written, "ovito-written.xyz"))
                  .shapeSpec.superballExponent()
                  .value(),
              1.5);
    const auto refused = [&](const std::string& body, const std::string& words) {
        expectError<PackingFileError>([&] { readExtendedXyz(textFile(body, "bad.xyz")); },
                                      {"bad.xyz", words});
    };
    refused("2\nLattice=\"4 0 0 0 5 0 0 0 4\" Properties=pos:R:3 p=1 semi_axis=0.5\n",
            "not a cube");
    refused("1\nProperties=pos:R:3 p=1 semi_axis=0.5\n1 2 3\n", "no Lattice");
    refused("1\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=pos:R:3 semi_axis=0.5\n1 2 3\n",
            "no shape");
    refused("1\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=pos:R:3 p=1.5 semi_axis=0.5\n1 2 3\n",
            "no orientation column");
    refused(ovito + a + "A 3 3 3 0 0 0.6 0.8 0.5 0.5 0.5 0.7 0.7\n",
            "differ in superquadric_roundness");
    refused(ovito + a, "the header says 2 particles but the file has 1");
    // The header names the shape; axes in other proportions are another shape, not read as it.
    refused("1\nLattice=\"4 0 0 0 4 0 0 0 4\" Properties=pos:R:3:orientation:R:4:"
            "aspherical_shape:R:3 p=1.5\n1 2 3 0 0 0 1 0.5 0.5 0.25\n",
            "aspherical_shape's proportions 1:1:0.5 are not those of the header's shape, p = 1.5 "
            "(1:1:1)");
    refused(ovito + "A 1 1 1 0 0 0 1\n", "8 columns, Properties gives 13");
}

class AtomicOutputTest : public TemporaryDirectoryTest {};

TEST_F(AtomicOutputTest, LeavesNothingWhenNotCommitted) {
    {
        AtomicOutput output(file("result.h5"));
        std::ofstream(output.temporaryPath()) << "partial";
        EXPECT_EQ(output.temporaryPath().parent_path(), file("result.h5").parent_path());
        EXPECT_TRUE(fs::exists(output.temporaryPath()));
    }
    EXPECT_EQ(entries(), 0u);
}

TEST_F(AtomicOutputTest, LeavesNoTemporaryWhenCommitted) {
    std::ofstream(file("result.txt")) << "old";
    {
        AtomicOutput output(file("result.txt"));
        std::ofstream(output.temporaryPath()) << "new";
        output.commit();
    }
    EXPECT_EQ(entries(), 1u);
    std::string content;
    std::ifstream(file("result.txt")) >> content;
    EXPECT_EQ(content, "new");
}

TEST_F(AtomicOutputTest, RemovesTheStaleTemporariesOfDeadProcessesOnly) {
    const pid_t child = ::fork(); // a process that is gone: its pid is free
    if (child == 0) ::_exit(0);
    ASSERT_GT(child, 0);
    ASSERT_EQ(::waitpid(child, nullptr, 0), child);
    const fs::path dead = file(".result.h5.tmp-" + std::to_string(child));
    const fs::path live = file(".result.h5.tmp-" + std::to_string(::getppid()));
    const fs::path other = file(".other.h5.tmp-" + std::to_string(child));
    for (const fs::path& p : {dead, live, other})
        std::ofstream(p) << "partial";
    {
        AtomicOutput output(file("result.h5"));
        output.write("new");
        output.commit();
    }
    EXPECT_FALSE(fs::exists(dead));
    EXPECT_TRUE(fs::exists(live));  // its process may still be writing
    EXPECT_TRUE(fs::exists(other)); // another output's
}

TEST_F(AtomicOutputTest, WriteReplacesTheTemporaryAndCommitsIt) {
    std::ofstream(file("result.txt")) << "old";
    AtomicOutput output(file("result.txt"));
    output.write("longer content");
    output.write("new");
    output.commit();
    std::string content;
    std::ifstream(file("result.txt")) >> content;
    EXPECT_EQ(content, "new");
}

TEST_F(AtomicOutputTest, RefusesSpecialFilesAndItsOwnInput) {
    ASSERT_EQ(::mkfifo(file("pipe.h5").c_str(), 0600), 0);
    expectError<OutputPathError>([&] { checkWritable(file("pipe.h5")); },
                                 {"pipe.h5", "not a regular file"});
    expectError<PackingFileError>([&] { readPacking(file("pipe.h5")); },
                                  {"pipe.h5", "not a regular file"});
    std::ofstream(file("in.h5")) << "x";
    fs::create_hard_link(file("in.h5"), file("link.h5"));
    expectError<OutputPathError>([&] { checkNotInput(file("link.h5"), file("in.h5"), "convert"); },
                                 {"link.h5", "is also the input"});
    EXPECT_NO_THROW(checkNotInput(file("new.h5"), file("in.h5"), "convert"));
}

TEST_F(AtomicOutputTest, StreamDevicesAreWrittenInPlace) { // issue 66 item 6: --json /dev/null
    EXPECT_TRUE(isStreamDevice("/dev/null"));
    std::ofstream(file("plain.json")) << "{}";
    EXPECT_FALSE(isStreamDevice(file("plain.json")));
    EXPECT_FALSE(isStreamDevice(file("absent.json")));
    EXPECT_NO_THROW(writeToStreamDevice("/dev/null", "{\"phi\": 0.64}"));
    ASSERT_EQ(::mkfifo(file("pipe.json").c_str(), 0600), 0);
    EXPECT_TRUE(isStreamDevice(file("pipe.json")));
    // No process reads it: refused at once, not a wait for a reader.
    expectError<OutputPathError>([&] { writeToStreamDevice(file("pipe.json"), "{}"); },
                                 {"pipe.json", "a FIFO that no process is reading"});
    const int reader = ::open(file("pipe.json").c_str(), O_RDONLY | O_NONBLOCK);
    ASSERT_GE(reader, 0);
    writeToStreamDevice(file("pipe.json"), "{\"phi\": 0.64}\n");
    std::string received(64, '\0');
    const ssize_t n = ::read(reader, received.data(), received.size());
    ::close(reader);
    ASSERT_GT(n, 0);
    received.resize(static_cast<std::size_t>(n));
    EXPECT_EQ(received, "{\"phi\": 0.64}\n");
    expectError<OutputPathError>([&] { writeToStreamDevice(file("missing") / "pipe.json", "{}"); },
                                 {"pipe.json"});
}

TEST_F(AtomicOutputTest, CheckWritableRejectsMissingDirectoryAndDirectoryTarget) {
    expectError<OutputPathError>([&] { checkWritable(file("missing") / "x.h5"); },
                                 {"missing", "does not exist"});
    fs::create_directory(file("sub"));
    expectError<OutputPathError>([&] { checkWritable(file("sub")); }, {"sub", "is a directory"});
    EXPECT_NO_THROW(checkWritable(file("fine.h5")));
}

} // namespace
} // namespace sbpack
