// The option table (analysis/cli/option_table.hpp): each option declared once, its printed
// default the default the run uses, every analysis's options in it, the command line built
// from it.

#include "cli/command_line.hpp"
#include "cli/option_table.hpp"
#include "pipeline/analysis_registry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace sbpack {
namespace {

/// Every default the table prints, from `s`.
std::vector<std::string> shownDefaults(const RunSettings& s) {
    std::vector<std::string> shown;
    for (const OptionRow& row : analysisOptionTable())
        shown.push_back(row.shownDefault != nullptr ? row.shownDefault(s) : "");
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
    const std::vector<std::string> before = shownDefaults(defaults);
    for (const OptionRow& row : analysisOptionTable()) {
        if (row.shownDefault == nullptr || row.name == "fft-wisdom") continue; // a description
        RunSettings s = defaults;
        const std::string shown = row.shownDefault(defaults);
        row.parse(s, "--" + std::string(row.name), shown);
        EXPECT_EQ(shownDefaults(s), before) << "--" << row.name << ' ' << shown;
    }
    const RunSettings parsed = parseAnalyzeArguments({"a.h5", "--out", "r.h5"});
    EXPECT_EQ(shownDefaults(parsed), before);
    EXPECT_EQ(parsed.voxels, 300);
    EXPECT_EQ(parsed.poreVoxels, 200);
    EXPECT_EQ(parsed.poreMethod, PoreMethod::Refined);
    EXPECT_DOUBLE_EQ(parsed.hyperuniformity.fitQmaxW, 1.4); // the paper's fit range
}

TEST(OptionTable, HelpPrintsTheDefaultFromTheSettings) {
    RunSettings s = defaultRunSettings();
    s.voxels = 123;
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
    EXPECT_EQ(s.voxels, 64);
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
