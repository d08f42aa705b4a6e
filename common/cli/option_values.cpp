#include "cli/option_values.hpp"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace sbpack {

double parseNumber(const std::string& option, const std::string& text) {
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())) ||
        end != text.c_str() + text.size())
        throw std::invalid_argument("option " + option + ": '" + text + "' is not a number");
    // Out of range: overflow to infinity, or underflow (a subnormal or 0), is named as such.
    if (errno == ERANGE)
        throw std::invalid_argument("option " + option + ": " + text + " is " +
                                    (std::abs(value) > 1.0 ? "beyond" : "below") +
                                    " the range of double precision numbers");
    return value;
}

std::int64_t parseInteger(const std::string& option, const std::string& text, std::int64_t minimum,
                          std::int64_t maximum) {
    const auto outside = [&] {
        return std::invalid_argument("option " + option + ": " + text + " is not in [" +
                                     std::to_string(minimum) + ", " + std::to_string(maximum) +
                                     "]");
    };
    // Digits are read exactly: as a double, 2^63 - 1 is 2^63, which passed a check against
    // maximum 2^63 - 1 (itself 2^63 as a double) and was then cast to int64_t, undefined
    // behaviour (found by tests/fuzz/fuzz_option_number).
    std::int64_t exact = 0;
    const char* end = text.data() + text.size();
    if (const auto [last, ec] = std::from_chars(text.data(), end, exact);
        ec == std::errc() && last == end) {
        if (exact < minimum || exact > maximum) throw outside();
        return exact;
    }
    // Otherwise a number such as 1e4: whole, and inside int64_t before it is cast to it.
    const double value = parseNumber(option, text);
    if (value != std::floor(value))
        throw std::invalid_argument("option " + option + ": '" + text + "' is not an integer");
    if (!(value >= -0x1p63 && value < 0x1p63)) throw outside();
    const auto integer = static_cast<std::int64_t>(value);
    if (integer < minimum || integer > maximum) throw outside();
    return integer;
}

} // namespace sbpack
