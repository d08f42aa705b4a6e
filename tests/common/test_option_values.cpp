// Option values (common/cli/option_values): numbers parsed whole, out-of-range values named as
// such (issue 46, defect 14).
#include "cli/option_values.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
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
    // Issue 65 item 8: strtod's hexadecimal is not the command line's, and a NUL or another
    // control character is shown, not an end of the message.
    EXPECT_EQ(refusal("0x10"), "option --x: '0x10' is not a number (write it in decimal)");
    EXPECT_EQ(refusal("-0X1p3"), "option --x: '-0X1p3' is not a number (write it in decimal)");
    EXPECT_EQ(refusal(std::string("1\0"
                                  "2",
                                  3)),
              "option --x: '1\\x002' is not a number");
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
    // Issue 65 item 8: a count is not written 10.0 nor 0x10 (strtod read both as whole numbers)
    EXPECT_THROW(parseInteger("--n", "10.0", 1, 100), std::invalid_argument);
    EXPECT_THROW(parseInteger("--n", "1.0e1", 1, 100), std::invalid_argument);
    EXPECT_THROW(parseInteger("--n", "0x10", 1, 100), std::invalid_argument);
    EXPECT_EQ(parseInteger("--n", "1e1", 1, 100), 10);
    EXPECT_THROW(parseInteger("--n", "11", 1, 10), std::invalid_argument);
}

// Digits are read exactly: 2^63 - 1 is the largest int64_t and 2^63 beyond it (its double is
// 2^63, which was cast), 2^53 + 1 stays itself (its double is 2^53); found by the fuzz target
// tests/fuzz/fuzz_option_number (issue 46).
TEST(OptionValues, IntegersBeyondDoublePrecisionAreExact) {
    constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
    EXPECT_EQ(parseInteger("--seed", "9223372036854775807", 0, kMax), kMax);
    EXPECT_THROW(parseInteger("--seed", "9223372036854775808", 0, kMax), std::invalid_argument);
    EXPECT_EQ(parseInteger("--seed", "9007199254740993", 0, kMax), 9007199254740993LL);
    EXPECT_THROW(parseInteger("--seed", "9007199254740993", 0, 9007199254740992LL),
                 std::invalid_argument);
    EXPECT_EQ(parseInteger("--n", "1e4", 1, kMax), 10000); // exponent form stays
}

} // namespace
} // namespace sbpack
