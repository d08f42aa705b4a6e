#pragma once
// sbanalyze's options, each declared once (docs/architecture.md, "Options"): its name, its
// value's name, its help with the default printed from the analyses' parameter structs in
// RunSettings, and how its value fills them. The command line (cli/command_line.cpp), its --help,
// docs/cli.md (generated from --help), Python (the keywords of sbpack's analysis classes and their
// docstrings, _sbpack.analysis_options()) and the results' provenance (runOptions) read it.

#include "pipeline/run_settings.hpp"

#include <span>
#include <string>
#include <string_view>

namespace sbpack {

struct OptionRow {
    std::string_view name;      ///< "voxels": the command line's --voxels, Python's voxels=
    std::string_view valueName; ///< "M"; empty: a flag, which takes no value
    /// The help; "{}" where the default goes (shownValue of the defaults)
    std::string_view help;
    /// Fills `s` from `value` ("" for a flag); throws std::invalid_argument naming `option`
    void (*parse)(RunSettings& s, const std::string& option, const std::string& value);
    /// The value in `s` as the option would be given ("" where none is set, e.g. an unset
    /// --alpha-window); nullptr: a flag or a path, not printed
    std::string (*shownValue)(const RunSettings& s) = nullptr;
    /// Help text after the row's own, computed (--compute's list of analyses); nullptr: none
    std::string (*moreHelp)() = nullptr;
    /// A default that depends on another option, printed at the help's second "{}" (--pore-voxels
    /// under --pores voxel); nullptr: none
    std::string (*dependentDefault)() = nullptr;
};

/// Every option of the analysis command, in --help's order.
std::span<const OptionRow> analysisOptionTable();
/// The row named `name` (without dashes); throws std::logic_error if there is none.
const OptionRow& findOption(std::string_view name);
/// The settings before any option: every analysis, the hardware's threads, the default FFTW
/// wisdom file; the rest RunSettings' member defaults.
RunSettings defaultRunSettings();
/// "--name value ..." of the options of the run's analyses (AnalysisInfo::options) that have a
/// value in `settings`, in the table's order: the results' provenance (the run's "options").
std::string runOptions(const RunSettings& settings);
/// The row's help with its default printed from `defaults`.
std::string optionHelp(const OptionRow& row, const RunSettings& defaults);

} // namespace sbpack
