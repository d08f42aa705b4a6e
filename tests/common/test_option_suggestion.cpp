// "Did you mean" for mistyped options (common/cli/option_suggestion; issue 66 item 6).
#include "cli/option_suggestion.hpp"

#include <gtest/gtest.h>

namespace sbpack {
namespace {

const std::vector<std::string> kKnown{"--gamma-slow",  "--gamma-fast", "--pores",
                                      "--pore-voxels", "--voxels",     "--seed",
                                      "--n",           "--p",          "--threads"};

TEST(OptionSuggestion, UnderscoresAreReadAsHyphens) {
    EXPECT_EQ(closestOptions("--gamma_slow", kKnown), std::vector<std::string>{"--gamma-slow"});
}

TEST(OptionSuggestion, OneOrTwoEditsAwayAreSuggestedTheNearestOnly) {
    EXPECT_EQ(closestOptions("--voxel", kKnown), std::vector<std::string>{"--voxels"});
    EXPECT_EQ(closestOptions("--threds", kKnown), std::vector<std::string>{"--threads"});
    EXPECT_EQ(closestOptions("--sede", kKnown), std::vector<std::string>{"--seed"}); // swap
    // --gamma-slwo: one transposition from --gamma-slow, more from --gamma-fast
    EXPECT_EQ(closestOptions("--gamma-slwo", kKnown), std::vector<std::string>{"--gamma-slow"});
}

TEST(OptionSuggestion, APrefixSuggestsEveryOptionItBegins) {
    EXPECT_EQ(closestOptions("--pore", kKnown),
              (std::vector<std::string>{"--pores", "--pore-voxels"}));
}

TEST(OptionSuggestion, ShortNamesAllowOneEditAndNothingFarIsSuggested) {
    EXPECT_EQ(closestOptions("--m", kKnown), (std::vector<std::string>{"--n", "--p"}));
    EXPECT_TRUE(
        closestOptions("--xy", kKnown).empty()); // two edits from --n: too far for 2 letters
    EXPECT_TRUE(closestOptions("--bogus", kKnown).empty());
    EXPECT_TRUE(closestOptions("--temperature", kKnown).empty());
}

TEST(OptionSuggestion, TheMessageNamesTheOptionAndTheSuggestions) {
    EXPECT_EQ(unknownOptionMessage("--bogus", kKnown), "unknown option --bogus");
    EXPECT_EQ(unknownOptionMessage("--gamma_slow", kKnown),
              "unknown option --gamma_slow; did you mean --gamma-slow?");
    EXPECT_EQ(unknownOptionMessage("--pore", kKnown),
              "unknown option --pore; did you mean --pores or --pore-voxels?");
}

} // namespace
} // namespace sbpack
