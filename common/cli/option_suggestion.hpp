#pragma once
// "Did you mean ...?" for a mistyped option of sbgen or sbanalyze (issue 66 item 6): the known
// options nearest to what was typed, by edit distance, with '_' read as '-'.

#include <string>
#include <vector>

namespace sbpack {

/// The options of `known` (e.g. "--gamma-slow") nearest to `given` (e.g. "--gamma_slow",
/// "--voxel"): those at the smallest Damerau-Levenshtein distance between the names with
/// underscores read as hyphens, if that distance is at most 2 (at most 1 for names of 4
/// characters or fewer), plus every known option that `given` is a prefix of (--pore for
/// --pores, --pore-voxels); empty if none.
std::vector<std::string> closestOptions(const std::string& given,
                                        const std::vector<std::string>& known);

/// The long options ("--name") of a CLI11 App (a template: common does not link CLI11).
template <class App> std::vector<std::string> longOptionNames(const App& app) {
    std::vector<std::string> names;
    for (const auto* option : app.get_options())
        for (const std::string& name : option->get_lnames())
            names.push_back("--" + name);
    return names;
}

/// "unknown option GIVEN" with "; did you mean A?" (or "A or B?", ...) when closestOptions finds
/// any.
std::string unknownOptionMessage(const std::string& given, const std::vector<std::string>& known);

} // namespace sbpack
