// libFuzzer target for the option-number parser (common/cli/option_values; issue 46): the bytes
// are an option's text. parseNumber gives the whole text's number or std::invalid_argument
// "option OPTION: ..."; parseInteger, with the ranges its callers in sbgen and sbanalyze pass,
// gives an integer inside its range that equals parseNumber's value, or std::invalid_argument
// naming the option; never undefined behaviour (a double outside int64_t cast to it).
#include "cli/option_values.hpp"
#include "fuzz_input.hpp"

#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace {

struct Range {
    std::int64_t minimum, maximum;
};

/// The ranges of parseInteger's callers (generator/cli/options.cpp, analysis/cli/command_line.cpp)
/// and the extremes of int64_t.
constexpr Range kRanges[] = {
    {2, 100'000'000},
    {0, std::int64_t(1) << 53},
    {INT32_MIN, INT32_MAX},
    {1, 1 << 24},
    {1, 65536},
    {0, std::int64_t(1) << 40},
    {0, std::numeric_limits<std::int64_t>::max()},
    {0, 100000},
    {std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max()},
};

constexpr const char* kOption = "--fuzzed-option";

void requireOptionNamed(const std::invalid_argument& e, const char* where) {
    if (std::string(e.what()).rfind(std::string("option ") + kOption + ": ", 0) != 0)
        sbpack::fuzz::finding(std::string(where) + ": the message does not start with the option",
                              e);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::optional<double> number;
    try {
        number = sbpack::parseNumber(kOption, text);
    } catch (const std::invalid_argument& e) {
        requireOptionNamed(e, "parseNumber");
    } catch (const std::exception& e) {
        sbpack::fuzz::finding("parseNumber: not std::invalid_argument", e);
    }
    for (const Range& range : kRanges) {
        try {
            const std::int64_t value =
                sbpack::parseInteger(kOption, text, range.minimum, range.maximum);
            if (value < range.minimum || value > range.maximum ||
                !(number && static_cast<double>(value) == *number))
                sbpack::fuzz::finding("parseInteger: " + std::to_string(value) +
                                          " is outside its range or not parseNumber's value",
                                      std::runtime_error(text));
        } catch (const std::invalid_argument& e) {
            requireOptionNamed(e, "parseInteger");
        } catch (const std::exception& e) {
            sbpack::fuzz::finding("parseInteger: not std::invalid_argument", e);
        }
    }
    return 0;
}
