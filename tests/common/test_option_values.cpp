// Option values (common/cli/option_values): numbers parsed whole, out-of-range values named as
// such (issue 46, defect 14).
#include "cli/option_values.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace sbpack {
namespace {

std::string refusal(const std::string& text) {
    try {
        parseNumber("--x", text);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "accepted";
}

TEST(OptionValues, NumbersAreParsedWhole) {
    EXPECT_EQ(parseNumber("--x", "1.5e-3"), 1.5e-3);
    EXPECT_EQ(parseNumber("--x", "-2"), -2.0);
    EXPECT_EQ(refusal("ten"), "option --x: 'ten' is not a number");
    EXPECT_EQ(refusal("1.5x"), "option --x: '1.5x' is not a number");
    EXPECT_EQ(refusal(""), "option --x: '' is not a number");
    EXPECT_EQ(refusal(" 1"), "option --x: ' 1' is not a number");
}

TEST(OptionValues, OutOfRangeIsNamedNotCalledNotANumber) {
    EXPECT_EQ(refusal("1e-320"),
              "option --x: 1e-320 is below the range of double precision numbers");
    EXPECT_EQ(refusal("1e400"),
              "option --x: 1e400 is beyond the range of double precision numbers");
    EXPECT_EQ(refusal("-1e400"),
              "option --x: -1e400 is beyond the range of double precision numbers");
    EXPECT_EQ(parseNumber("--x", "2.3e-308"), 2.3e-308); // the smallest normal numbers stay
}

TEST(OptionValues, IntegersInTheirRange) {
    EXPECT_EQ(parseInteger("--n", "1000", 1, 1 << 20), 1000);
    EXPECT_THROW(parseInteger("--n", "1.5", 1, 10), std::invalid_argument);
    EXPECT_THROW(parseInteger("--n", "11", 1, 10), std::invalid_argument);
}

} // namespace
} // namespace sbpack
