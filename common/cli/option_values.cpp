#include "cli/option_values.hpp"

#include <cctype>
#include <cerrno>
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
    const double value = parseNumber(option, text);
    if (value != std::floor(value))
        throw std::invalid_argument("option " + option + ": '" + text + "' is not an integer");
    if (value < static_cast<double>(minimum) || value > static_cast<double>(maximum))
        throw std::invalid_argument("option " + option + ": " + text + " is not in [" +
                                    std::to_string(minimum) + ", " + std::to_string(maximum) + "]");
    return static_cast<std::int64_t>(value);
}

} // namespace sbpack
