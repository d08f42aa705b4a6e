#pragma once
// Command-line values shared by sbgen and sbanalyze: errors name the option and the text.

#include <cstdint>
#include <string>

namespace sbpack {

/// The whole of `text` as a number (inf and nan included; callers range-check); throws
/// std::invalid_argument "option OPTION: 'TEXT' is not a number".
double parseNumber(const std::string& option, const std::string& text);

/// An integer in [minimum, maximum], also written as 1e4; throws std::invalid_argument naming
/// the option.
std::int64_t parseInteger(const std::string& option, const std::string& text, std::int64_t minimum,
                          std::int64_t maximum);

} // namespace sbpack
