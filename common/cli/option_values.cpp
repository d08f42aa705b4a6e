#include "cli/option_values.hpp"

#include <cmath>
#include <stdexcept>

namespace sbpack {

double parseNumber(const std::string& option, const std::string& text) {
    try {
        std::size_t used = 0;
        const double value = std::stod(text, &used);
        if (used == text.size()) return value;
    } catch (const std::exception&) {
    }
    throw std::invalid_argument("option " + option + ": '" + text + "' is not a number");
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
