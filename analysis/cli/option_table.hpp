#pragma once
// sbanalyze's options, each declared once (docs/architecture.md, "Options"): its name, its
// value's name, its help with the default printed from RunSettings' defaults, and how its value
// fills RunSettings. The command line (command_line.cpp), its --help, docs/cli.md (generated from
// --help) and Python (the keywords of sbpack's analysis classes, their docstrings from
// _sbpack.analysis_options()) all read this table.

#include "pipeline/run_settings.hpp"

#include <span>
#include <string>
#include <string_view>

namespace sbpack {

struct OptionRow {
    std::string_view name;      ///< "voxels": the command line's --voxels, Python's voxels=
    std::string_view valueName; ///< "M"; empty: a flag, which takes no value
    /// The help; "{}" where the default goes (shownDefault)
    std::string_view help;
    /// Fills `s` from `value` ("" for a flag); throws std::invalid_argument naming `option`
    void (*parse)(RunSettings& s, const std::string& option, const std::string& value);
    /// The default as the help prints it, from the default settings; nullptr: none printed
    std::string (*shownDefault)(const RunSettings& defaults) = nullptr;
    /// Help text after the row's own, computed (--compute's list of analyses); nullptr: none
    std::string (*moreHelp)() = nullptr;
};

/// Every option of the analysis command, in --help's order.
std::span<const OptionRow> analysisOptionTable();
/// The row named `name` (without dashes); throws std::logic_error if there is none.
const OptionRow& findOption(std::string_view name);
/// The settings before any option: every analysis, the hardware's threads, the default FFTW
/// wisdom file; the rest RunSettings' member defaults.
RunSettings defaultRunSettings();
/// The row's help with its default printed from `defaults`.
std::string optionHelp(const OptionRow& row, const RunSettings& defaults);

} // namespace sbpack
