#include "cli/option_values.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace sbpack {

namespace {

/// `text` as a message shows it: control characters (a NUL would end the message) as \xNN.
std::string shown(const std::string& text) {
    std::string out;
    for (const unsigned char c : text)
        out += std::iscntrl(c) ? fmt::format("\\x{:02x}", c) : std::string(1, static_cast<char>(c));
    return out;
}

/// strtod reads hexadecimal (0x10 is 16): a number of the command line is decimal.
bool isHexadecimal(const std::string& text) {
    const std::size_t digits = !text.empty() && (text[0] == '+' || text[0] == '-') ? 1 : 0;
    return text.size() > digits + 1 && text[digits] == '0' &&
           (text[digits + 1] == 'x' || text[digits + 1] == 'X');
}

} // namespace

double parseNumber(const std::string& option, const std::string& text) {
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())) ||
        end != text.c_str() + text.size() || isHexadecimal(text))
        throw std::invalid_argument("option " + option + ": '" + shown(text) + "' is not a number" +
                                    (isHexadecimal(text) ? " (write it in decimal)" : ""));
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
    // Otherwise a number such as 1e4: whole, and inside int64_t before it is cast to it; a
    // decimal point (10.0) is a real number's, not a count's (issue 65 item 8).
    const double value = parseNumber(option, text);
    if (value != std::floor(value) || text.find('.') != std::string::npos)
        throw std::invalid_argument("option " + option + ": '" + text + "' is not an integer");
    if (!(value >= -0x1p63 && value < 0x1p63)) throw outside();
    const auto integer = static_cast<std::int64_t>(value);
    if (integer < minimum || integer > maximum) throw outside();
    return integer;
}

} // namespace sbpack
