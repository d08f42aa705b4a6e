// The option table (analysis/pipeline/option_table.hpp): each option declared once, its printed
// default the default the run uses, every analysis's options in it, the command line built
// from it.

#include "cli/command_line.hpp"
#include "pipeline/analysis_registry.hpp"
#include "pipeline/option_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace sbpack {
namespace {

/// Every default the table prints, from `s`.
std::vector<std::string> shownValues(const RunSettings& s) {
    std::vector<std::string> shown;
    for (const OptionRow& row : analysisOptionTable())
        shown.push_back(row.shownValue != nullptr ? row.shownValue(s) : "");
    return shown;
}

TEST(OptionTable, NamesAreUniqueAndEachHasHelp) {
    std::set<std::string_view> names;
    for (const OptionRow& row : analysisOptionTable()) {
        EXPECT_TRUE(names.insert(row.name).second) << row.name;
        EXPECT_FALSE(row.help.empty()) << row.name;
        EXPECT_NE(row.parse, nullptr) << row.name;
    }
}

// The default the help prints is the one the run uses: given back as the option's value it
// changes no printed default, and the settings equal those of no option at all.
TEST(OptionTable, PrintedDefaultsAreTheDefaultsUsed) {
    const RunSettings defaults = defaultRunSettings();
    const std::vector<std::string> before = shownValues(defaults);
    for (const OptionRow& row : analysisOptionTable()) {
        if (row.shownValue == nullptr || row.shownValue(defaults).empty()) continue; // unset
        RunSettings s = defaults;
        const std::string shown = row.shownValue(defaults);
        row.parse(s, "--" + std::string(row.name), shown);
        EXPECT_EQ(shownValues(s), before) << "--" << row.name << ' ' << shown;
    }
    const RunSettings parsed = parseAnalyzeArguments({"a.h5", "--out", "r.h5"});
    EXPECT_EQ(shownValues(parsed), before);
    EXPECT_EQ(parsed.voxelization.voxels, 300);
    EXPECT_EQ(parsed.poreVoxels(), 200);
    EXPECT_EQ(parsed.poreMethod(), PoreMethod::Refined);
    EXPECT_DOUBLE_EQ(parsed.hyperuniformity.fitQmaxW, 1.4); // the paper's fit range
}

/// The shown value of option `name` in `s`.
std::string shown(const RunSettings& s, std::string_view name) {
    return findOption(name).shownValue(s);
}

// Each default is written once, in the analysis's own parameter struct: the table's printed
// defaults are those the compute objects take when nobody sets them, also where two compute
// objects share an option (--qmax, --pore-seed) or a default hangs on another option.
TEST(OptionTable, DefaultsAreTheComputeObjectsOwn) {
    const RunSettings d = defaultRunSettings();
    RunSettings s;
    s.structureFactor.maxQw = SpectralDensityParameters{}.maxQw;
    EXPECT_EQ(shown(s, "qmax"), shown(d, "qmax"));
    s.hyperuniformity.chiExactQw = ExactSpectralDensityParameters{}.maxQw;
    EXPECT_EQ(shown(s, "chi-exact-qmax"), shown(d, "chi-exact-qmax"));
    s.pores.seed = ExactPoreSizeParameters{}.seed;
    EXPECT_EQ(shown(s, "pore-seed"), shown(d, "pore-seed"));
    EXPECT_EQ(d.voxelization.voxels, VoxelizationParameters{}.voxels);
    EXPECT_EQ(d.pores.gridParameters().randomPoints, PoreSizeParameters{}.randomPoints);
    EXPECT_EQ(d.pores.exactParameters().randomPoints, ExactPoreSizeParameters{}.randomPoints);
    EXPECT_NE(optionHelp(findOption("pore-points"), d).find("(0: 1e6, as the paper)"),
              std::string::npos);
    EXPECT_EQ(d.poreVoxels(), PoreSizeSettings::defaultVoxels(PoreSizeSettings::kDefaultMethod));
    EXPECT_NE(usage().find("(default 200; with --pores voxel\n"), std::string::npos) << usage();
}

// The results' provenance names the options of the analyses run, with the values used, and
// given back to the command line they set the same values.
TEST(OptionTable, RunOptionsRepeatTheRun) {
    const RunSettings sq = parseAnalyzeArguments(
        {"a.h5", "--json", "-", "--compute", "sq", "--qmax", "12.5", "--voxels", "64"});
    EXPECT_EQ(runOptions(sq), "--qmax 12.5"); // --voxels is not sq's
    const RunSettings all = parseAnalyzeArguments(
        {"a.h5", "--json", "-", "--pores", "voxel", "--alpha-window", "1,5.8", "--qmax", "20"});
    const std::string options = runOptions(all);
    for (const char* expected :
         {"--tolerance 1e-10", "--qmax 20", "--voxels 300", "--pore-voxels 500", "--pores voxel",
          "--alpha-window 1,5.8", "--fit-qmax 1.4", "--fft-plan measure"})
        EXPECT_NE(options.find(expected), std::string::npos) << expected << " in " << options;
    EXPECT_EQ(options.find("--threads"), std::string::npos) << options;
    std::vector<std::string> args{"a.h5", "--json", "-"};
    std::istringstream words(options);
    for (std::string word; words >> word;)
        args.push_back(word);
    EXPECT_EQ(shownValues(parseAnalyzeArguments(args)), shownValues(all)) << options;
}

TEST(OptionTable, HelpPrintsTheDefaultFromTheSettings) {
    RunSettings s = defaultRunSettings();
    s.voxelization.voxels = 123;
    EXPECT_NE(optionHelp(findOption("voxels"), s).find("(default 123)"), std::string::npos);
    EXPECT_NE(optionHelp(findOption("spread-times"), s).find("(default 1e-3,1e4)"),
              std::string::npos);
    EXPECT_NE(usage().find("(default 200; with --pores voxel"), std::string::npos);
    EXPECT_THROW(findOption("no-such-option"), std::logic_error);
}

TEST(OptionTable, EveryAnalysisOptionIsARow) {
    for (const AnalysisInfo& info : analysisRegistry())
        for (std::string_view option : analysisOptions(info))
            EXPECT_NO_THROW(findOption(option)) << info.name << ": --" << option;
}

TEST(OptionTable, EveryRowIsOnTheCommandLine) {
    const std::string help = usage();
    for (const OptionRow& row : analysisOptionTable())
        EXPECT_NE(help.find("--" + std::string(row.name) + ' '), std::string::npos) << row.name;
}

TEST(OptionTable, ParsesAndRefusesNamingTheOption) {
    const RunSettings s = parseAnalyzeArguments(
        {"a.h5", "--json", "-", "--voxels", "64", "--spread-times", "0.01,100", "--quiet",
         "--plan-ranks", "3", "--fft-planning-budget", "none", "--device", "cpu"});
    EXPECT_EQ(s.voxelization.voxels, 64);
    EXPECT_DOUBLE_EQ(s.hyperuniformity.tMin, 0.01);
    EXPECT_DOUBLE_EQ(s.hyperuniformity.tMax, 100.0);
    EXPECT_TRUE(s.quiet);
    EXPECT_TRUE(s.plan);
    EXPECT_EQ(s.planRanks, 3);
    EXPECT_TRUE(std::isinf(s.fft.planningBudget));
    EXPECT_EQ(s.requestedDevice, ComputeDevice::Cpu);
    for (const auto& [option, value, message] :
         {std::tuple{"--spread-times", "3,1", "option --spread-times: needs 0 < T1 < T2"},
          std::tuple{"--distribute", "all", "option --distribute: 'all' is not files or grids"},
          std::tuple{"--fft-planning-budget", "-1",
                     "option --fft-planning-budget: must be >= 0 and finite, or none"},
          std::tuple{"--qmax", "inf", "option --qmax: must be positive and finite"}}) {
        try {
            parseAnalyzeArguments({"a.h5", "--json", "-", option, value});
            ADD_FAILURE() << option << ' ' << value << " accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
        }
    }
}

} // namespace
} // namespace sbpack
