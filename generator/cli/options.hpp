#pragma once
// sbgen's command line (CLI11): parsing and validation before any work starts.

#include "protocol/jamming_protocol.hpp"

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {

struct GeneratorOptions {
    ProtocolParameters protocol;
    std::filesystem::path out;
    std::optional<std::filesystem::path> checkpoint;
    double checkpointInterval = 600.0; ///< seconds of wall time between checkpoints
    std::optional<std::filesystem::path> resume;
    std::optional<double> pressureFinal; ///< given explicitly (may change on resume)
    std::optional<double> costLimit;     ///< given explicitly (may change on resume)
    /// --pressure-finish and --finish-speed, given explicitly (may change on resume).
    std::optional<double> pressureFinish, finishSpeed;
    bool quiet = false;
    bool help = false;
    bool version = false;
};

/// The --help text.
std::string generatorUsage();

/// A protocol parameter's refusal as its option's: "option --pressure-final: must be ..." (the
/// parameter's own name where no option sets it).
std::invalid_argument optionError(const ProtocolParameterError& e);

/// Throws std::invalid_argument naming the option and the problem.
GeneratorOptions parseGeneratorOptions(const std::vector<std::string>& args);

} // namespace sbpack
