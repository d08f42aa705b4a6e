#include "cli/option_suggestion.hpp"

#include <algorithm>
#include <cstddef>
#include <numeric>

namespace sbpack {

namespace {

/// The optimal-string-alignment distance (Damerau-Levenshtein without repeated edits of a
/// substring): insertions, deletions, substitutions and transpositions of neighbours cost 1.
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i)
        d[i][0] = i;
    std::iota(d[0].begin(), d[0].end(), std::size_t{0});
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

std::string hyphenated(std::string name) {
    std::replace(name.begin(), name.end(), '_', '-');
    return name;
}

} // namespace

std::vector<std::string> closestOptions(const std::string& given,
                                        const std::vector<std::string>& known) {
    const std::string typed = hyphenated(given);
    const std::size_t limit = typed.size() <= 6 ? 1 : 2; // "--" and up to 4 characters: 1
    std::size_t best = limit;
    std::vector<std::string> nearest;
    const auto add = [&nearest](const std::string& option) {
        if (std::find(nearest.begin(), nearest.end(), option) == nearest.end())
            nearest.push_back(option);
    };
    for (const std::string& option : known) {
        const std::size_t distance = editDistance(typed, option);
        if (distance < best) nearest.clear(), best = distance;
        if (distance == best) add(option);
    }
    for (const std::string& option : known)
        if (typed.size() > 2 && option.rfind(typed, 0) == 0) add(option);
    return nearest;
}

std::string unknownOptionMessage(const std::string& given, const std::vector<std::string>& known) {
    std::string message = "unknown option " + given;
    const std::vector<std::string> nearest = closestOptions(given, known);
    for (std::size_t k = 0; k < nearest.size(); ++k)
        message += (k == 0                    ? "; did you mean "
                    : k + 1 == nearest.size() ? " or "
                                              : ", ") +
                   nearest[k];
    return nearest.empty() ? message : message + "?";
}

} // namespace sbpack
