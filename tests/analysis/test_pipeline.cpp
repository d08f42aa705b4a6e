#include "cli/command_line.hpp"
#include "hyperuniformity/hyperuniformity_fields.hpp"
#include "io/hdf5_handles.hpp"
#include "io/packing_io.hpp"
#include "numerics/sample_statistics.hpp"
#include "parallel/parallel.hpp"
#include "pipeline/analysis_registry.hpp"
#include "pipeline/ensemble.hpp"
#include "pipeline/resources.hpp"
#include "pipeline/run.hpp"
#include "pores/exact_pore_size.hpp"
#include "spectral/spectral_density.hpp"
#include "structure/structure_factor.hpp"
#include "temp_dir.hpp"
#include "voxels/voxelization.hpp"

#include "test_packings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

namespace sbpack {
namespace {

namespace fs = std::filesystem;

const Progress quiet;

RunSettings settingsFor(std::vector<fs::path> inputs, const fs::path& output) {
    RunSettings s;
    s.inputs = std::move(inputs);
    s.output = output;
    s.threads = 2;
    s.voxelization.voxels = 40;
    s.pores.voxels = 40;
    s.structureFactor.maxQw = 8.0;
    s.analyses = resolveAnalyses("all");
    s.fft = {FftPlanning::Estimate, {}};
    s.quiet = true;
    return s;
}

TEST(AnalysisRegistry, ResolvesNamesAndWhatTheyNeed) {
    EXPECT_EQ(resolveAnalyses("sq"), AnalysisSet{Analysis::StructureFactor});
    EXPECT_EQ(resolveAnalyses("chi"), (AnalysisSet{Analysis::SpectralDensity, Analysis::Voxels}));
    EXPECT_EQ(resolveAnalyses("all").size(), analysisRegistry().size() - 1); // but jamming
    EXPECT_EQ(analysisNames(resolveAnalyses("voxels,sq")), "sq,voxels");
    try {
        resolveAnalyses("sq,bogus");
        FAIL() << "accepted an unknown analysis";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'bogus'"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("known: contacts, sq, chi, voxels"),
                  std::string::npos);
    }
    EXPECT_THROW(resolveAnalyses("sq,"), std::invalid_argument);
}

TEST(CommandLine, ParsesTheAnalysisOptions) {
    const RunSettings s = parseAnalyzeArguments(
        {"a.h5",       "--compute", "sq",           "b.h5",  "--threads", "1",      "--voxels",
         "64",         "--qmax",    "12.5",         "--out", "r.h5",      "--json", "-",
         "--fft-plan", "estimate",  "--fft-wisdom", "none",  "--vdb",     "dir",    "--quiet"});
    EXPECT_EQ(s.inputs, (std::vector<fs::path>{"a.h5", "b.h5"}));
    EXPECT_EQ(s.analyses, (AnalysisSet{Analysis::StructureFactor, Analysis::Voxels})); // --vdb
    EXPECT_EQ(s.threads, 1);
    EXPECT_EQ(s.voxelization.voxels, 64);
    EXPECT_EQ(s.poreVoxels(), 200);
    EXPECT_DOUBLE_EQ(s.structureFactor.maxQw, 12.5);
    EXPECT_DOUBLE_EQ(s.spectralDensity().maxQw, 12.5);
    EXPECT_EQ(s.fft.planning, FftPlanning::Estimate);
    EXPECT_TRUE(s.fft.wisdomFile.empty());
    EXPECT_TRUE(s.quiet);
    const RunSettings pores =
        parseAnalyzeArguments({"a.h5", "--out", "r.h5", "--pores", "exact", "--pore-points", "1000",
                               "--fft-planning-budget", "0.5"});
    EXPECT_EQ(pores.poreMethod(), PoreMethod::Exact);
    EXPECT_EQ(pores.pores.points, 1000);
    EXPECT_DOUBLE_EQ(pores.fft.planningBudget, 0.5);
    EXPECT_EQ(pores.grids(), std::set<VoxelGrid>{VoxelGrid::Spectral}); // exact needs no grid
    EXPECT_EQ(parseAnalyzeArguments({"a.h5", "--out", "r.h5", "--pores", "refined"}).poreMethod(),
              PoreMethod::Refined);
    EXPECT_TRUE(
        std::isinf(parseAnalyzeArguments({"a.h5", "--out", "r.h5", "--fft-planning-budget", "none"})
                       .fft.planningBudget));
    const RunSettings defaults = parseAnalyzeArguments({"a.h5", "--out", "r.h5"});
    EXPECT_EQ(defaults.poreMethod(), PoreMethod::Refined);
    EXPECT_EQ(defaults.poreVoxels(), 200);
    // The paper's voxel method at the paper's M unless --pore-voxels says otherwise; the
    // distributed grid's pores are voxel pores.
    EXPECT_EQ(parseAnalyzeArguments({"a.h5", "--out", "r.h5", "--pores", "voxel"}).poreVoxels(),
              500);
    EXPECT_EQ(
        parseAnalyzeArguments({"a.h5", "--out", "r.h5", "--pores", "voxel", "--pore-voxels", "300"})
            .poreVoxels(),
        300);
    const RunSettings distributed =
        parseAnalyzeArguments({"a.h5", "--out", "r.h5", "--distribute", "grids"});
    EXPECT_EQ(distributed.poreMethod(), PoreMethod::Voxel);
    EXPECT_EQ(distributed.poreVoxels(), 500);
    EXPECT_DOUBLE_EQ(defaults.fft.planningBudget, kDefaultFftPlanningBudget);
    EXPECT_EQ(defaults.voxelization.voxels, 300);
    EXPECT_DOUBLE_EQ(defaults.structureFactor.maxQw, 30.0);
    EXPECT_EQ(defaults.analyses, resolveAnalyses("all"));
    for (const std::vector<std::string>& bad :
         {std::vector<std::string>{"a.h5", "--threads", "0"},
          {"a.h5", "--threads", std::to_string(ThreadBudget::maxThreads() + 1)},
          {"a.h5", "--threads", "two"},
          {"a.h5", "--voxels", "0"},
          {"a.h5", "--qmax", "-3"},
          {"a.h5", "--compute", "pores?"},
          {"a.h5", "--fft-plan", "quick"},
          {"a.h5", "--pores", "fast"},
          {"a.h5", "--pore-points", "-1"},
          {"a.h5", "--fft-planning-budget", "-1"},
          {"a.h5", "--bogus"},
          {"a.h5", "--out"},
          {"a.h5", "--tolerance", "-1"}})
        EXPECT_THROW(parseAnalyzeArguments(bad), std::invalid_argument) << bad[1];
}

TEST(Pipeline, OneAndTwoThreadsAgree) {
    // The whole chain, serial on one thread against parallel on two: the voxels exactly, the
    // curves to 1e-12 (FFTW's threaded plans may round differently).
    for (const Packing& packing : {testing::latticePacking(1.5, 3, 1.35, 0.03, 41),
                                   testing::latticePacking(1.0, 3, 1.2, 0.05, 43)}) {
        std::vector<std::uint8_t> masks[2];
        ShellAverage sq[2], chi[2], exact[2];
        for (const int threads : {1, 2}) {
            const ThreadBudget budget(threads);
            Progress run;
            run.setSerial(threads == 1);
            const Voxelization voxels = Voxelizer({48}).compute(packing, run);
            masks[threads - 1].resize(48 * 48 * 48);
            voxels.copySolidMask(masks[threads - 1], run);
            sq[threads - 1] = StructureFactor({20.0}).compute(packing, run).shells;
            SpectralDensityParameters parameters;
            parameters.maxQw = 20.0;
            parameters.fft = {FftPlanning::Estimate, {}};
            const SpectralDensityResult s =
                SpectralDensity(parameters).compute(packing, voxels, run);
            chi[threads - 1] = s.shells;
            if (s.exactSphere) exact[threads - 1] = s.exactSphere->exact;
        }
        EXPECT_EQ(masks[0], masks[1]);
        for (const auto* curves : {sq, chi, exact}) {
            ASSERT_EQ(curves[0].size(), curves[1].size());
            for (std::size_t s = 0; s < curves[0].size(); ++s)
                EXPECT_NEAR(curves[0].value[s], curves[1].value[s],
                            1e-12 * std::abs(curves[0].value[s]));
        }
        EXPECT_EQ(exact[0].size() > 0, packing.shapeSpec.superballExponent().value() == 1.0);
    }
}

TEST(Pipeline, WritesTheResultsFileOfOneInput) {
    const TempDir dir("sbpack-test-pipeline-one");
    writePacking(testing::latticePacking(1.5, 3, 1.35, 0.03, 5), dir / "a.h5");
    const RunSettings s = settingsFor({dir / "a.h5"}, dir / "r.h5");
    std::ostringstream log, out;
    const RunResults results = runAnalyses(s, log, out);
    ASSERT_EQ(results.files.size(), 1u);
    // Quiet: no stage lines; two warnings: hyper is skipped in a box of 3^3 cells, and the
    // lattice is called ordered (its particles are solid-like, docs/order-metrics.md §5).
    const std::string warnings = log.str();
    EXPECT_NE(warnings.find("hyperuniformity skipped: alpha window"), std::string::npos);
    EXPECT_NE(warnings.find("order: this packing has ordered: solid-like fraction = 1.000"),
              std::string::npos);
    EXPECT_EQ(std::count(warnings.begin(), warnings.end(), '\n'), 2) << warnings;
    EXPECT_EQ(results.files[0].group("spreadability"), nullptr);
    const Hdf5Handle h5 = openFileReadOnly(dir / "r.h5");
    const hid_t root = h5.get();
    EXPECT_EQ(readStringAttribute(root, "format"), "sbpack.results");
    EXPECT_EQ(readInt64Attribute(root, "format_version"), schema::kFormatVersion);
    EXPECT_EQ(readInt64Attribute(root, "n_files"), 1);
    EXPECT_EQ(readStringAttribute(root, "runtime_s_units"), "s");
    // One input has the layout of several: files/0 and ensembles/0.
    const Hdf5Handle file = openGroup(openGroup(root, "files").get(), "0");
    EXPECT_EQ(readInt64Attribute(file.get(), "n_particles"), 27);
    EXPECT_DOUBLE_EQ(readDoubleAttribute(file.get(), "p"), 1.5);
    EXPECT_GT(readDoubleAttribute(file.get(), "mean_width"), 1.0);
    EXPECT_EQ(readStringAttribute(file.get(), "mean_width_units"), "length");
    for (const char* group : {"structure_factor", "spectral_density", "voxelization", "contacts"}) {
        ASSERT_TRUE(hasLink(file.get(), group)) << group;
        EXPECT_TRUE(hasAttribute(openGroup(file.get(), group).get(), "runtime_s")) << group;
    }
    const Hdf5Handle chi = openGroup(file.get(), "spectral_density");
    EXPECT_EQ(readInt64Attribute(chi.get(), "voxels"), 40);
    EXPECT_DOUBLE_EQ(readDoubleAttribute(chi.get(), "phi_voxel"),
                     results.files[0].group("voxelization")->number("phi_voxel"));
    for (const char* name : {"Q", "chi", "count", "Q_w"})
        EXPECT_TRUE(hasLink(chi.get(), name)) << name;
    const Hdf5Handle chiData(H5Dopen2(chi.get(), "chi", H5P_DEFAULT), H5Dclose);
    EXPECT_EQ(readStringAttribute(chiData.get(), "units"), "length^3");
    const Hdf5Handle vox = openGroup(file.get(), "voxelization");
    EXPECT_DOUBLE_EQ(readDoubleAttribute(vox.get(), "phi_exact"),
                     results.files[0].root.number("phi"));
    const Hdf5Handle contacts = openGroup(file.get(), "contacts");
    EXPECT_TRUE(hasLink(contacts.get(), "counts"));
    EXPECT_DOUBLE_EQ(readDoubleAttribute(contacts.get(), "tolerance"), 1e-10);
    EXPECT_TRUE(hasLink(openGroup(root, "ensembles").get(), "0"));
    EXPECT_EQ(dir.entries(), 2u); // the input and the results: no temporaries left
}

TEST(Pipeline, SeveralInputsGetFilesAndAnEnsemble) {
    const TempDir dir("sbpack-test-pipeline-ensemble");
    const Packing packing = testing::latticePacking(1.0, 3, 1.2, 0.05, 7);
    writePacking(packing, dir / "a.h5");
    writePacking(packing, dir / "b.h5");
    RunSettings s = settingsFor({dir / "a.h5", dir / "b.h5"}, dir / "r.h5");
    s.analyses = resolveAnalyses("sq,contacts");
    s.json = "-";
    std::ostringstream log, out;
    const RunResults results = runAnalyses(s, log, out);
    EXPECT_NE(out.str().find("\"ensembles\""), std::string::npos);
    const Hdf5Handle h5 = openFileReadOnly(dir / "r.h5");
    EXPECT_EQ(readInt64Attribute(h5.get(), "n_files"), 2);
    EXPECT_EQ(readInt64Attribute(h5.get(), "n_ensembles"), 1);
    const Hdf5Handle files = openGroup(h5.get(), "files");
    EXPECT_EQ(readStringAttribute(openGroup(files.get(), "1").get(), "input"),
              (dir / "b.h5").string());
    EXPECT_TRUE(hasLink(openGroup(files.get(), "0").get(), "structure_factor"));
    EXPECT_FALSE(
        hasLink(openGroup(files.get(), "0").get(), "voxelization")); // sq voxelises nothing
    // Identical inputs: the ensemble mean is each file's curve, the spread zero.
    ASSERT_EQ(results.ensembles.size(), 1u);
    const schema::Record& curve = *results.ensembles[0].group("structure_factor");
    const schema::Record& one = *results.files[0].group("structure_factor");
    const std::vector<double>& mean = curve.floats("S");
    ASSERT_EQ(mean.size(), one.floats("S").size());
    for (std::size_t i = 0; i < mean.size(); ++i) {
        EXPECT_DOUBLE_EQ(mean[i], one.floats("S")[i]);
        EXPECT_EQ(curve.floats("S_std")[i], 0.0);
        EXPECT_EQ(curve.integers("files")[i], 2);
        EXPECT_EQ(curve.integers("count")[i], 2 * one.integers("count")[i]);
    }
    const Hdf5Handle ensemble = openGroup(openGroup(h5.get(), "ensembles").get(), "0");
    const Hdf5Handle sq = openGroup(ensemble.get(), "structure_factor");
    for (const char* name : {"Q_w", "Q", "S", "S_std", "count", "files"})
        EXPECT_TRUE(hasLink(sq.get(), name)) << name;
    EXPECT_DOUBLE_EQ(readDoubleAttribute(openGroup(ensemble.get(), "contacts").get(), "z_mean_std"),
                     0.0);
}

/// The lattice packing with stored forces of the given magnitudes on pairs (0, 1), (0, 2), ...
Packing withForces(Packing packing, const std::vector<double>& magnitudes) {
    ContactForces forces;
    forces.windows = 1;
    forces.duration = 1.0;
    forces.reducedPressure = 1e6;
    for (std::size_t k = 0; k < magnitudes.size(); ++k)
        forces.contacts.push_back({0, static_cast<int>(k) + 1, Vector3d(0.5, 0.5, 0.5),
                                   Vector3d::UnitX(), magnitudes[k]});
    packing.contactForces = forces;
    return packing;
}

// Issue 62: the stored forces' distribution is an optional field: an ensemble averages it over
// the members that have it (a packing from elsewhere has none), pointwise.
TEST(Pipeline, EnsembleForceDistributionIsOverTheMembersWithForces) {
    const TempDir dir("sbpack-test-pipeline-forces");
    const Packing packing = testing::latticePacking(1.0, 3, 1.2, 0.05, 7);
    writePacking(withForces(packing, {2.0, 2.0}), dir / "a.h5"); // x = 1, 1
    writePacking(withForces(packing, {1.0, 3.0}), dir / "b.h5"); // x = 0.5, 1.5
    writePacking(packing, dir / "c.h5");
    RunSettings s = settingsFor({dir / "a.h5", dir / "b.h5", dir / "c.h5"}, dir / "r.h5");
    s.analyses = resolveAnalyses("contacts");
    std::ostringstream log, out;
    const RunResults results = runAnalyses(s, log, out);
    EXPECT_FALSE(results.files[2].group("contacts")->has("force_density"));
    EXPECT_EQ(results.files[1].group("contacts")->number("force_second_moment"), 1.25);
    const schema::Record& e = *results.ensembles[0].group("contacts");
    EXPECT_EQ(e.number("force_count"), 2.0);
    EXPECT_EQ(e.number("force_mean"), 2.0);
    EXPECT_EQ(e.number("force_second_moment"), 1.125); // (1 + 1.25) / 2
    const std::vector<double>& edges = e.floats("force_edges");
    const std::vector<double>& density = e.floats("force_density");
    const double width = edges[1] - edges[0];
    for (std::size_t k = 0; k < density.size();
         ++k) { // bins of 0.1: x = 0.5, 1, 1.5 open 5, 10, 15
        const double each = k == 10 ? 2.0 : (k == 5 || k == 15) ? 1.0 : 0.0;
        EXPECT_DOUBLE_EQ(density[k], each / 2.0 / 2.0 / width) << k; // 2 forces, 2 members
    }
}

/// F(at) of one file's right-continuous steps, by a plain scan.
double stepsAt(const std::vector<double>& delta, const std::vector<double>& F, double at) {
    double value = F.front();
    for (std::size_t j = 0; j < delta.size() && delta[j] <= at; ++j)
        value = F[j];
    return value;
}

// The ensemble's F(delta) is the mean of its files' step functions on one delta / w grid.
TEST(Pipeline, EnsemblePoreSizesAreTheMeanOfTheFilesSteps) {
    const TempDir dir("sbpack-test-pipeline-steps");
    writePacking(testing::latticePacking(1.0, 3, 1.2, 0.05, 7), dir / "a.h5");
    writePacking(testing::latticePacking(1.0, 3, 1.2, 0.05, 8), dir / "b.h5");
    RunSettings s = settingsFor({dir / "a.h5", dir / "b.h5"}, dir / "r.h5");
    s.analyses = resolveAnalyses("pores");
    std::ostringstream log, out;
    const RunResults results = runAnalyses(s, log, out);
    ASSERT_EQ(results.ensembles.size(), 1u);
    const schema::Record& e = *results.ensembles[0].group("pore_size");
    const std::vector<double>& grid = e.floats("delta_w");
    ASSERT_EQ(grid.size(), static_cast<std::size_t>(schema::kStepsGrid + 1));
    EXPECT_EQ(grid.front(), 0.0);
    double reach = 0.0;
    for (const FileResults& f : results.files)
        reach = std::max(reach, f.group("pore_size")->floats("delta_w").back());
    EXPECT_EQ(grid.back(), reach);
    EXPECT_EQ(e.floats("F").front(), 1.0);
    EXPECT_EQ(e.floats("F_std").front(), 0.0);
    EXPECT_EQ(e.floats("F").back(), 0.0);
    for (std::size_t k = 0; k < grid.size(); ++k) {
        const schema::Record& a = *results.files[0].group("pore_size");
        const schema::Record& b = *results.files[1].group("pore_size");
        const double fa = stepsAt(a.floats("delta_w"), a.floats("F"), grid[k]);
        const double fb = stepsAt(b.floats("delta_w"), b.floats("F"), grid[k]);
        EXPECT_NEAR(e.floats("F")[k], 0.5 * (fa + fb), 1e-15) << k;
        EXPECT_NEAR(e.floats("F_std")[k], std::abs(fa - fb) / std::sqrt(2.0), 1e-15) << k;
        if (k > 0) {
            EXPECT_LE(e.floats("F")[k], e.floats("F")[k - 1]);
        }
    }
}

TEST(Pipeline, InputsOfOtherPOrNFormSeparateEnsembles) {
    const TempDir dir("sbpack-test-pipeline-mixed");
    writePacking(testing::latticePacking(1.0, 3, 1.2, 0.05, 7), dir / "a.h5");
    writePacking(testing::latticePacking(1.5, 3, 1.35, 0.03, 5), dir / "b.h5");
    writePacking(testing::latticePacking(1.0, 3, 1.2, 0.05, 8), dir / "c.h5");
    RunSettings s = settingsFor({dir / "a.h5", dir / "b.h5", dir / "c.h5"}, dir / "r.h5");
    s.analyses = resolveAnalyses("contacts");
    std::ostringstream log, out;
    const RunResults results = runAnalyses(s, log, out);
    ASSERT_EQ(results.ensembles.size(), 2u);
    EXPECT_EQ(results.ensembles[0].members, (std::vector<std::size_t>{0, 2}));
    EXPECT_EQ(results.ensembles[1].members, (std::vector<std::size_t>{1}));
    EXPECT_DOUBLE_EQ(results.ensembles[1].root.number("p"), 1.5);
    std::vector<FileResults> mixed{results.files[0], results.files[1]};
    EXPECT_THROW(computeEnsemble(mixed, {0, 1}), std::invalid_argument);
}

/// A member of p = 1.5 as hyper records it: E(t) = t^{-(3 + alpha) / 2} exactly (so the local
/// alpha is alpha at every t), the window [1, 10], and fitted wave vectors at `qw` whose chi_V
/// is a0 + a1 Q^alpha + `shift`.
FileResults hyperMember(double alpha, double a0, double a1, std::vector<double> qw, double shift) {
    FileResults f;
    f.root.set("p", 1.5).set("n_particles", 100);
    schema::Record s(kSpreadabilityGroup), h(kHyperuniformityGroup);
    std::vector<double> t, excess, chi;
    for (int k = 0; k <= 40; ++k) {
        t.push_back(std::pow(10.0, -1.0 + 0.1 * k));
        excess.push_back(std::pow(t.back(), -0.5 * (3.0 + alpha)));
    }
    for (std::size_t i = 0; i < qw.size(); ++i)
        chi.push_back(a0 + a1 * std::pow(qw[i], alpha) + shift);
    s.set("t", t).set("excess", excess).set("t_fit_min", 1.0).set("t_fit_max", 10.0);
    h.set("fit_Q_w", qw).set("fit_chi", chi).set("chi_peak", 0.02);
    f.groups = {std::move(s), std::move(h)};
    return f;
}

// The ensemble's small-Q fit is one fit through every member's wave vectors at the pooled alpha:
// members that scatter about one law a0 + a1 Q^alpha (here +- 1e-3 at the same wave vectors)
// give it back, with their scatter as its error.
TEST(Pipeline, EnsembleFitsEveryMembersWaveVectorsAtThePooledAlpha) {
    const double alpha = 0.4, a0 = 3e-4, a1 = 2e-3;
    const std::vector<FileResults> files{hyperMember(alpha, a0, a1, {0.6, 0.6, 1.2, 1.2}, 1e-3),
                                         hyperMember(alpha, a0, a1, {0.6, 0.6, 1.2, 1.2}, -1e-3),
                                         hyperMember(alpha, a0, a1, {0.85, 1.04, 1.04}, 0.0)};
    const EnsembleResults e = computeEnsemble(files, {0, 1, 2});
    EXPECT_NEAR(e.group("spreadability")->number("alpha_pooled"), alpha, 1e-12);
    const schema::Record& h = *e.group("hyperuniformity");
    EXPECT_NEAR(h.number("a0_pooled"), a0, 1e-15);
    EXPECT_NEAR(h.number("a1_pooled"), a1, 1e-15);
    EXPECT_NEAR(h.number("H_pooled"), a0 / 0.02, 1e-13);
    EXPECT_GT(h.number("a0_pooled_stderr"), 1e-4);
    EXPECT_LT(h.number("a0_pooled_stderr"), 1e-2);
    EXPECT_NEAR(h.number("chi_peak"), 0.02, 1e-17);
    // One member alone: its own shifted law, exactly.
    const EnsembleResults alone = computeEnsemble(files, {0});
    const schema::Record& first = *alone.group("hyperuniformity");
    EXPECT_NEAR(first.number("a0_pooled"), a0 + 1e-3, 1e-15);
    EXPECT_LT(first.number("a0_pooled_stderr"), 1e-15);
}

TEST(Pipeline, EnsembleCurvesShareAGridInQw) {
    // Two files whose boxes differ by 1 %: shell s of each lands in bin s.
    ShellAverage a{{1.0, 2.0}, {10.0, 20.0}, {6, 12}}, b{{1.01, 2.02}, {14.0, 30.0}, {6, 12}};
    const std::vector<ShellAverage> curves{a, b};
    const std::vector<double> widths{1.0, 1.0};
    const std::vector<double> lengths{2.0 * std::numbers::pi, 2.0 * std::numbers::pi / 1.01};
    const EnsembleCurve c = ensembleCurve(curves, widths, lengths);
    ASSERT_EQ(c.mean.size(), 2u);
    EXPECT_DOUBLE_EQ(c.mean[0], 12.0);
    EXPECT_DOUBLE_EQ(c.std[0], std::sqrt(8.0));
    EXPECT_DOUBLE_EQ(c.mean[1], 25.0);
    EXPECT_DOUBLE_EQ(c.qw[1], 2.01);
    EXPECT_EQ(c.files[1], 2);
    const SampleStatistics one = sampleStatistics(std::vector<double>{3.0});
    EXPECT_EQ(one.std, 0.0);
}

TEST(Pipeline, BadInputLeavesNoOutput) {
    const TempDir dir("sbpack-test-pipeline-bad");
    writePacking(testing::latticePacking(1.0, 3, 1.2, 0.05, 9), dir / "good.h5");
    {
        std::ofstream bad(dir / "bad.h5");
        bad << "not a packing\n";
    }
    std::ostringstream log, out;
    // An invalid second input, a grid too coarse, a grid too large for memory, no threads.
    RunSettings invalid = settingsFor({dir / "good.h5", dir / "bad.h5"}, dir / "r.h5");
    EXPECT_THROW(runAnalyses(invalid, log, out), std::exception);
    RunSettings coarse = settingsFor({dir / "good.h5"}, dir / "r.h5");
    coarse.voxelization.voxels = 8;
    try {
        runAnalyses(coarse, log, out);
        FAIL() << "accepted a coarse grid";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("--voxels 8"), std::string::npos) << e.what();
    }
    RunSettings huge = settingsFor({dir / "good.h5"}, dir / "r.h5");
    huge.voxelization.voxels = 50000;
    try {
        runAnalyses(huge, log, out);
        FAIL() << "accepted a grid larger than memory";
    } catch (const std::invalid_argument& e) {
        // The largest stage of all at M = 50000: voronoi's labels and features.
        EXPECT_NE(std::string(e.what()).find("set-Voronoi labels and features 50000^3"),
                  std::string::npos)
            << e.what();
    }
    RunSettings noThreads = settingsFor({dir / "good.h5"}, dir / "r.h5");
    noThreads.threads = 0;
    EXPECT_THROW(runAnalyses(noThreads, log, out), std::invalid_argument);
    // Outputs that would overwrite an input or each other.
    EXPECT_THROW(runAnalyses(settingsFor({dir / "good.h5"}, dir / "good.h5"), log, out),
                 std::invalid_argument);
    RunSettings clash = settingsFor({dir / "good.h5"}, dir / "r.h5");
    clash.json = dir / "r.h5";
    EXPECT_THROW(runAnalyses(clash, log, out), std::invalid_argument);
    EXPECT_EQ(dir.entries(), 2u); // the two inputs only
    EXPECT_TRUE(availableMemoryBytes().has_value());
}

TEST(Pipeline, OverlappingParticlesAreAnalysedWithAWarning) {
    const TempDir dir("sbpack-test-pipeline-overlap");
    Packing packing = testing::latticePacking(1.0, 3, 1.2, 0.0, 9);
    packing.positions[1] = packing.positions[0] + Vector3d(0.25, 0.0, 0.0);
    writePacking(packing, dir / "a.h5");
    RunSettings s = settingsFor({dir / "a.h5"}, dir / "r.h5");
    s.analyses = resolveAnalyses("sq");
    std::ostringstream log, out;
    runAnalyses(s, log, out);
    EXPECT_NE(log.str().find("overlapping pair(s), the worst (0, 1) by 0.75 D"), std::string::npos)
        << log.str();
}

// docs/mixtures.md: every analysis reads a mixture's sizes.
TEST(Pipeline, AMixtureGetsEveryAnalysis) {
    const TempDir dir("sbpack-test-pipeline-mixture");
    Packing packing = testing::latticePacking(1.0, 4, 1.2, 0.05, 11);
    for (std::size_t i = 0; i < packing.size(); ++i)
        packing.semiAxes.push_back(i % 2 == 0 ? 0.5 : 0.4);
    writePacking(packing, dir / "a.h5");
    Packing identical = packing;
    identical.semiAxes.clear();
    writePacking(identical, dir / "b.h5");
    const RunSettings s = settingsFor({dir / "a.h5", dir / "b.h5"}, dir / "r.h5");
    std::ostringstream log, out;
    const RunResults results = runAnalyses(s, log, out);
    ASSERT_EQ(results.files.size(), 2u);
    EXPECT_EQ(results.ensembles.size(), 2u); // the mixture is not pooled with identical particles
    const FileResults& file = results.files[0];
    ASSERT_NE(file.group("contacts"), nullptr);
    ASSERT_NE(file.group("structure_factor"), nullptr);
    const schema::Record& sq = *file.group("structure_factor");
    EXPECT_EQ(sq.floats("S_AB").size(), sq.floats("S").size());
    EXPECT_DOUBLE_EQ(sq.number("x_A"), 0.5);
    EXPECT_FALSE(results.files[1].group("structure_factor")->has("S_AB"));
    for (const char* computed : {"order", "voxelization", "spectral_density", "pore_size",
                                 "transport", "voronoi", "variance"})
        EXPECT_NE(file.group(computed), nullptr) << computed;
    EXPECT_EQ(log.str().find("not computed"), std::string::npos) << log.str();
    // The partials' ensemble statistics on S's grid (one member here: its own curve).
    const schema::Record* partials = results.ensembles[0].group("structure_factor");
    ASSERT_NE(partials, nullptr);
    ASSERT_TRUE(partials->has("S_AB"));
    EXPECT_EQ(partials->floats("S_AB").size(), partials->floats("S").size());
    EXPECT_DOUBLE_EQ(partials->number("x_A"), 0.5);
    EXPECT_FALSE(results.ensembles[1].group("structure_factor")->has("S_AB"));
    // phi sums the particles' own volumes.
    const double v = 4.0 / 3.0 * std::numbers::pi;
    EXPECT_NEAR(file.root.number("phi"), 32 * v * (0.125 + 0.064) / std::pow(4 * 1.2, 3), 1e-12);
}

TEST(Pipeline, InterruptStopsAStageAtItsNextChunk) {
    const Packing packing = testing::latticePacking(1.5, 3, 1.35, 0.03, 5);
    StopRequest stop;
    stop.request();
    const Progress stopped(nullptr, nullptr, stop);
    EXPECT_THROW(Voxelizer({40}).compute(packing, stopped), Interrupted);
    EXPECT_THROW(StructureFactor({10.0}).compute(packing, stopped), Interrupted);
    EXPECT_THROW(ExactPoreSizeDistribution({1000}).compute(packing, stopped), Interrupted);
    // Another call's request (Python gives each its own) and the process's are untouched.
    EXPECT_FALSE(processStopRequest().requested());
    EXPECT_NO_THROW(Voxelizer({40}).compute(packing, quiet));
}

TEST(Pipeline, AnInterruptNamesItsSignal) {
    StopRequest stop;
    stop.request(SIGTERM);
    try {
        Progress(nullptr, nullptr, stop).checkInterrupt();
        ADD_FAILURE() << "no Interrupted";
    } catch (const Interrupted& e) {
        EXPECT_EQ(e.signal(), SIGTERM);
        EXPECT_NE(std::string(e.what()).find("by SIGTERM: no output was written"),
                  std::string::npos)
            << e.what();
    }
}

// A whole run given a request stops before it writes anything.
TEST(Pipeline, ARequestedStopEndsARunWithoutOutput) {
    const TempDir dir("sbpack-test-pipeline-stop");
    writePacking(testing::latticePacking(1.5, 3, 1.35, 0.03, 5), dir / "a.h5");
    RunSettings s = settingsFor({dir / "a.h5"}, dir / "r.h5");
    s.analyses = resolveAnalyses("sq");
    StopRequest stop;
    stop.request(SIGINT);
    std::ostringstream log, out;
    EXPECT_THROW(runAnalyses(s, log, out, stop), Interrupted);
    EXPECT_FALSE(fs::exists(dir / "r.h5"));
    EXPECT_NO_THROW(runAnalyses(s, log, out)); // the process's request was not made
    EXPECT_TRUE(fs::exists(dir / "r.h5"));
}

} // namespace
} // namespace sbpack
