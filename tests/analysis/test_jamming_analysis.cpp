// The jamming analysis end to end (sbanalyze --compute jamming, info --jamming; docs/jamming.md):
// the known categories of small lattices through the stage and the results file, the motions'
// datasets in their documented n x 3 shape, the ensembles' counts, and the options' errors.

#include "cli/command_line.hpp"
#include "io/hdf5_handles.hpp"
#include "io/packing_io.hpp"
#include "io/text_io.hpp"
#include "jamming/jamming_categories.hpp"
#include "jamming/jamming_fields.hpp"
#include "pipeline/analysis_registry.hpp"
#include "pipeline/run.hpp"
#include "temp_dir.hpp"

#include "../common/order_lattices.hpp"
#include "test_packings.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace sbpack {
namespace {

namespace fs = std::filesystem;

const std::string kData = SBPACK_DATA_DIR;

/// Unit spheres on a simple-cubic lattice of 4^3 touching cells: locally jammed, but its rows
/// slide (docs/jamming.md, "Known answers").
Packing simpleCubicSpheres(const Vector3d& offset = Vector3d(0.13, 0.29, 0.41)) {
    return lattices::cubicCrystal(4, 1.0, lattices::kSimpleCubic, offset);
}

/// `sbanalyze INPUTS --compute jamming --out OUT [extra]`, quiet.
RunResults runJamming(const std::vector<fs::path>& inputs, const fs::path& out,
                      std::vector<std::string> extra = {}) {
    std::vector<std::string> args;
    for (const fs::path& in : inputs)
        args.push_back(in.string());
    for (const char* a : {"--compute", "jamming", "--quiet", "--threads", "1", "--out"})
        args.emplace_back(a);
    args.push_back(out.string());
    args.insert(args.end(), extra.begin(), extra.end());
    std::ostringstream log, json;
    return runAnalyses(parseAnalyzeArguments(args), log, json);
}

/// The dimensions of dataset `name` of the group at `path` in the results file `file`.
std::vector<hsize_t> datasetShape(const fs::path& file, const std::string& path,
                                  const std::string& name) {
    const Hdf5Handle h5 = openFileReadOnly(file);
    Hdf5Handle group = openGroup(h5.get(), path);
    const Hdf5Handle dataset(H5Dopen2(group.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
    const Hdf5Handle space(H5Dget_space(dataset.get()), H5Sclose);
    std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.get())));
    H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    return dims;
}

TEST(JammingAnalysis, SimpleCubicSpheresAreLocallyButNotCollectivelyJammed) {
    const TempDir dir("sbpack-test-jamming-sc");
    writePacking(simpleCubicSpheres(), dir / "sc.h5");
    const RunResults results = runJamming({dir / "sc.h5"}, dir / "r.h5");
    const FileResults& file = results.files.at(0);
    const schema::Record& jamming = *file.group("jamming");
    EXPECT_EQ(jamming.text("category"), "local");
    EXPECT_EQ(jamming.text("verdict"), "locally jammed, not collectively (first order)");
    EXPECT_EQ(jamming.text("undecided"), "");
    EXPECT_EQ(jamming.integer("backbone"), 64);
    EXPECT_EQ(jamming.integer("contacts"), 192);
    EXPECT_EQ(file.group("jamming_local")->text("verdict"), "jammed");
    const schema::Record& collective = *file.group("jamming_collective");
    EXPECT_EQ(collective.text("verdict"), "unjammed");
    EXPECT_EQ(collective.integer("order"), 1);
    EXPECT_EQ(collective.integer("isostatic_deficit"), 3 * 64 - 3 - 192);
    EXPECT_LT(collective.number("largest_opening"), 1e-9); // rows slide, nothing opens
    EXPECT_GE(collective.integer("n_flex_moving"), 4);     // at least one row of 4
    EXPECT_FALSE(collective.has("opening_displacement"));
    EXPECT_EQ(file.group("jamming_strict")->text("verdict"), "unjammed");
    // The flex as the file holds it: n x 3, in units of D; spheres have no rotation.
    EXPECT_EQ(datasetShape(dir / "r.h5", "files/0/jamming_collective", "flex_displacement"),
              (std::vector<hsize_t>{64, 3}));
    EXPECT_EQ(datasetShape(dir / "r.h5", "files/0/jamming_strict", "flex_strain"),
              (std::vector<hsize_t>{3, 3}));
    EXPECT_EQ(datasetShape(dir / "r.h5", "files/0/jamming_strict", "freed").size(), 1u);
    EXPECT_FALSE(collective.has("flex_rotation"));
}

// Donev et al.'s finite-gap test (docs/jamming.md §4.1) end to end: the simple cubic rows slide
// by more than 1 D within every pair's gap at 0.25 D (the 6 touching neighbours only); the
// network's source is named; superballs are refused with the reason.
TEST(JammingAnalysis, FiniteGapTestSlidesTheSimpleCubicRowsAndRefusesSuperballs) {
    const TempDir dir("sbpack-test-jamming-finite-gap");
    writePacking(simpleCubicSpheres(), dir / "sc.h5");
    const RunResults results = runJamming({dir / "sc.h5"}, dir / "r.h5",
                                          {"--jamming-contacts", "gaps", "--jamming-max-step", "10",
                                           "--jamming-unjam-distance", "1"});
    const FileResults& file = results.files.at(0);
    EXPECT_EQ(file.group("jamming")->text("category"), "local");
    EXPECT_EQ(file.group("jamming")->integer("contacts"), 192);
    EXPECT_NE(file.group("jamming")->text("tolerance_from").find("Donev"), std::string::npos);
    const schema::Record& collective = *file.group("jamming_collective");
    EXPECT_EQ(collective.text("verdict"), "unjammed");
    EXPECT_GT(collective.number("largest_displacement"), 1.0);
    JammingSettings settings;
    settings.test.useGaps = true;
    settings.test.maxStep = 10.0;
    settings.test.unjammingDistance = 1.0;
    try {
        testJammingCategories(readTextPacking(kData + "/sc-lattice-p1.5.txt"), settings, {}, {});
        ADD_FAILURE() << "superballs were not refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("finite-gap test of sphere packings"),
                  std::string::npos)
            << e.what();
    }
    settings.relax = true; // the nearest jammed packing has no gaps to test: refused at once
    try {
        testJammingCategories(simpleCubicSpheres(), settings, {}, {});
        ADD_FAILURE() << "--jamming-relax with the finite-gap test was not refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("give one"), std::string::npos) << e.what();
    }
}

TEST(JammingAnalysis, FaceCentredCubicSpheresAreStrictlyJammed) {
    const TempDir dir("sbpack-test-jamming-fcc");
    const RunResults results = runJamming({kData + "/fcc-spheres.txt"}, dir / "r.h5");
    const FileResults& file = results.files.at(0);
    EXPECT_EQ(file.group("jamming")->text("category"), "strict");
    EXPECT_EQ(file.group("jamming")->text("verdict"), "strictly jammed at first order");
    EXPECT_EQ(file.group("jamming")->text("tolerance_from"), "--tolerance (no reduced pressure)");
    for (const char* name : {"jamming_local", "jamming_collective", "jamming_strict"}) {
        const schema::Record& g = *file.group(name);
        EXPECT_EQ(g.text("verdict"), "jammed") << name;
        EXPECT_TRUE(g.integers("freed").empty()) << name;
        EXPECT_FALSE(g.has("flex_displacement") || g.has("opening_displacement")) << name;
    }
    EXPECT_EQ(file.group("jamming_collective")->integer("isostatic_deficit"), 3 * 108 - 3 - 648);
}

// --jamming-relax (docs/jamming.md §6.7): fcc spheres 1e-4 D apart are jammed only once a shell
// closes that gap; the categories are those of the relaxed packing at its shell, strict, and
// the relaxation's numbers and per-particle displacement are in the file. Without the option the
// same packing has no contact at all.
TEST(JammingAnalysis, RelaxedFaceCentredCubicWithGapsIsStrictlyJammedAtItsShell) {
    const TempDir dir("sbpack-test-jamming-relax");
    const double gap = 1e-4;
    writePacking(lattices::cubicCrystal(2, std::sqrt(2.0) * (1.0 + gap), lattices::kFaceCentred),
                 dir / "fcc.h5");
    const RunResults results =
        runJamming({dir / "fcc.h5"}, dir / "r.h5", {"--jamming-relax", "on"});
    const schema::Record& jamming = *results.files.at(0).group("jamming");
    EXPECT_EQ(jamming.integer("relaxed"), 1);
    EXPECT_EQ(jamming.text("category"), "strict");
    EXPECT_EQ(jamming.text("tolerance_from"), "the relaxation's jamming shell");
    EXPECT_LT(jamming.number("relaxation_shell_unjammed"), gap);
    EXPECT_GE(jamming.number("relaxation_shell_jammed"), gap);
    EXPECT_LE(jamming.number("relaxation_shell_jammed"), 1.05 * gap);
    EXPECT_LT(jamming.number("relaxation_displacement_max"), 1e-12);
    EXPECT_EQ(jamming.integer("contacts"), 6 * 32);
    EXPECT_EQ(datasetShape(dir / "r.h5", "files/0/jamming", "relaxation_displacement"),
              (std::vector<hsize_t>{32, 3}));
    const RunResults plain = runJamming({dir / "fcc.h5"}, dir / "plain.h5");
    EXPECT_EQ(plain.files.at(0).group("jamming"), nullptr); // every particle a rattler: skipped
}

// sbgen's 100 spheres (docs/jamming.md §6.8): relaxed in their cubic box they are collectively
// but not strictly jammed (their stress keeps a shear part, which a shear at the volume undoes);
// relaxed with the box free, at a larger shell and a strained cell, strictly.
TEST(JammingAnalysis, SbgensSpheresAreStrictlyJammedOnlyWhereTheRelaxationDeformsTheBox) {
    const TempDir dir("sbpack-test-jamming-relax-box");
    const std::string packing = kData + "/mrj-spheres-100.h5";
    const RunResults held = runJamming({packing}, dir / "held.h5", {"--jamming-relax", "on"});
    const schema::Record& fixed = *held.files.at(0).group("jamming");
    EXPECT_EQ(fixed.text("category"), "collective");
    EXPECT_EQ(fixed.number("relaxation_box_strain"), 0.0);
    const RunResults free = runJamming({packing}, dir / "free.h5", {"--jamming-relax", "box"});
    const schema::Record& box = *free.files.at(0).group("jamming");
    EXPECT_EQ(box.integer("relaxed"), 1);
    EXPECT_EQ(box.text("category"), "strict");
    EXPECT_GT(box.number("relaxation_box_strain"), 1e-4);
    EXPECT_GT(box.number("relaxation_shell_unjammed"), fixed.number("relaxation_shell_jammed"));
}

// p = 1.5: the rotations are degrees of freedom, every category is undecided at first order
// (docs/jamming.md, "Known answers": the aligned simple-cubic superballs rotate), and the flex's
// rotation is in the file as n x 3 radians.
TEST(JammingAnalysis, SuperballLatticeIsUndecidedAndItsFlexRotates) {
    const TempDir dir("sbpack-test-jamming-p15");
    const RunResults results = runJamming({kData + "/sc-lattice-p1.5.txt"}, dir / "r.h5",
                                          {"--jamming-categories", "local,collective"});
    const FileResults& file = results.files.at(0);
    const schema::Record& jamming = *file.group("jamming");
    EXPECT_EQ(jamming.text("category"), "none");
    EXPECT_EQ(jamming.text("undecided"), "local,collective");
    EXPECT_EQ(jamming.text("categories"), "local,collective");
    EXPECT_NE(jamming.text("verdict").find("undecided at first order: local, collective"),
              std::string::npos);
    // The second order ran on the collective test: face centres against face centres, both
    // flat (aligned p = 1.5 cubes), where the gap's Hessian diverges (docs/jamming.md §6).
    const schema::Record& collective = *file.group("jamming_collective");
    EXPECT_EQ(collective.text("second_order"), "singular curvature");
    EXPECT_EQ(collective.integer("order"), 1);
    EXPECT_FALSE(file.group("jamming_local")->has("second_order")); // local has none
    EXPECT_EQ(file.group("jamming_strict"), nullptr);               // not asked for
    EXPECT_EQ(datasetShape(dir / "r.h5", "files/0/jamming_collective", "flex_rotation"),
              (std::vector<hsize_t>{125, 3}));
    EXPECT_EQ(file.group("jamming_collective")->floats("flex_rotation").size(), 3u * 125u);
}

TEST(JammingAnalysis, EnsemblesCountThePackingsPerCategory) {
    const TempDir dir("sbpack-test-jamming-ensemble");
    writePacking(simpleCubicSpheres(), dir / "a.h5");
    writePacking(simpleCubicSpheres(Vector3d(0.31, 0.07, 0.22)), dir / "b.h5");
    const RunResults results =
        runJamming({dir / "a.h5", dir / "b.h5", kData + "/fcc-spheres.txt"}, dir / "r.h5");
    ASSERT_EQ(results.ensembles.size(), 2u);
    const schema::Record& sc = *results.ensembles[0].group("jamming");
    EXPECT_EQ(sc.integer("n_files"), 2);
    EXPECT_EQ(sc.integer("n_local"), 2);
    EXPECT_EQ(sc.integer("n_strict") + sc.integer("n_collective") + sc.integer("n_none"), 0);
    EXPECT_EQ(results.ensembles[0].group("jamming_collective")->integer("n_unjammed"), 2);
    EXPECT_EQ(results.ensembles[0].group("jamming_local")->integer("n_jammed"), 2);
    EXPECT_EQ(results.ensembles[1].group("jamming")->integer("n_strict"), 1);
}

TEST(JammingAnalysis, IsNotInAllAndSkipsAPackingWithoutBackbone) {
    EXPECT_EQ(resolveAnalyses("all").count(Analysis::Jamming), 0u);
    EXPECT_EQ(resolveAnalyses("all,jamming").count(Analysis::Jamming), 1u);
    const TempDir dir("sbpack-test-jamming-rsa");
    writePacking(testing::randomSequentialAddition(40, 0.2, 3), dir / "rsa.h5");
    const RunResults results = runJamming({dir / "rsa.h5"}, dir / "r.h5");
    EXPECT_EQ(results.files.at(0).group("jamming"), nullptr); // every particle a rattler
    EXPECT_EQ(results.files.at(0).group("jamming_local"), nullptr);
}

TEST(JammingAnalysis, OptionErrorsNameTheOption) {
    for (const auto& [option, value, message] :
         {std::tuple{"--jamming-categories", "local,bogus",
                     "option --jamming-categories: 'bogus' is not a jamming category"},
          std::tuple{"--jamming-max-step", "0", "option --jamming-max-step: must be positive"},
          std::tuple{"--jamming-tolerance", "-1", "option --jamming-tolerance: must be >= 0"},
          std::tuple{"--jamming-contacts", "soft",
                     "option --jamming-contacts: 'soft' is not ideal or gaps"}}) {
        try {
            parseAnalyzeArguments({"a.h5", "--json", "-", option, value});
            ADD_FAILURE() << option << ' ' << value << " accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
        }
    }
    const RunSettings s =
        parseAnalyzeArguments({"a.h5", "--json", "-", "--jamming-categories", "strict,local,strict",
                               "--jamming-tolerance", "1e-8", "--jamming-contacts", "gaps"});
    EXPECT_EQ(s.jamming.categories,
              (std::vector<JammingCategory>{JammingCategory::Local, JammingCategory::Strict}));
    EXPECT_EQ(s.jamming.tolerance, 1e-8);
    EXPECT_TRUE(s.jamming.test.useGaps);
}

/// `sbanalyze info ARGS...`: its standard output, error and status.
struct InfoRun {
    std::string out, err;
    int status;
};
InfoRun info(std::vector<std::string> args) {
    args.insert(args.begin(), {"sbanalyze", "info"});
    std::vector<const char*> argv;
    for (const std::string& a : args)
        argv.push_back(a.c_str());
    std::ostringstream out, err;
    const int status = runCommandLine(static_cast<int>(argv.size()), argv.data(), out, err);
    return {out.str(), err.str(), status};
}

TEST(JammingAnalysis, InfoNamesTheCategory) {
    const InfoRun fcc = info({"--jamming", kData + "/fcc-spheres.txt"});
    EXPECT_EQ(fcc.status, 0) << fcc.err;
    EXPECT_NE(fcc.out.find("jamming category     strict: strictly jammed at first order"),
              std::string::npos)
        << fcc.out;
    const InfoRun local =
        info({"--jamming", "--jamming-categories", "local", kData + "/fcc-spheres.txt"});
    EXPECT_NE(local.out.find("jamming category     local: locally jammed at first order"),
              std::string::npos)
        << local.out;
    EXPECT_EQ(info({kData + "/fcc-spheres.txt"}).out.find("jamming category"), std::string::npos);
    const InfoRun refused = info({"--jamming-categories", "local", kData + "/fcc-spheres.txt"});
    EXPECT_EQ(refused.status, 1);
    EXPECT_NE(refused.err.find("option --jamming-categories: info tests the jamming categories "
                               "only with --jamming"),
              std::string::npos)
        << refused.err;
}

TEST(JammingAnalysis, RecordRefusesMotionsThatAreNotRowsOfThree) {
    schema::Record record(kJammingLocalGroup);
    EXPECT_THROW(record.set("flex_displacement", std::vector<double>(4)), std::logic_error);
    EXPECT_NO_THROW(record.set("flex_displacement", std::vector<double>(6)));
}

} // namespace
} // namespace sbpack
