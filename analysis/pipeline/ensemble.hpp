#pragma once
// Ensemble statistics over several packings: mean and standard deviation of every scalar and
// of the shell-averaged curves on a common grid in Q w.

#include "pipeline/file_analysis.hpp"
#include "shells/shell_average.hpp"

#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace sbpack {

/// Mean and sample standard deviation (n - 1; 0 for one file) over the files that have it.
struct EnsembleScalar {
    double mean = 0.0;
    double std = 0.0;
    int files = 0;
};

/// A curve on the common grid: bin b holds the shells with round(Q w / dQw) = b, where dQw is
/// the mean over the files of 2 pi w / L (so files with equal L / w keep their own shells).
/// A file with several shells in one bin contributes their count-weighted mean.
struct EnsembleCurve {
    double binWidthQw = 0.0;
    std::vector<double> qw;          ///< mean Q w of the files' shells in the bin
    std::vector<double> q;           ///< mean Q
    std::vector<double> mean;        ///< mean over files of the value
    std::vector<double> std;         ///< sample standard deviation over files
    std::vector<std::int64_t> count; ///< wave vectors, all files together
    std::vector<int> files;          ///< files with a shell in the bin
};

/// One results group ("" for the per-file root attributes): scalars and at most one curve.
struct EnsembleGroup {
    std::map<std::string, EnsembleScalar> scalars;
    std::optional<EnsembleCurve> curve;
    std::string curveName; ///< "S", "chi"
};

struct EnsembleResults {
    int files = 0;
    std::map<std::string, EnsembleGroup> groups; ///< by results-file group name
};

/// Statistics of scalars given per file.
EnsembleScalar ensembleScalar(std::span<const double> values);
/// Curves (Q w, value) of several files on the common grid.
EnsembleCurve ensembleCurve(std::span<const ShellAverage> curves,
                            std::span<const double> meanWidths, std::span<const double> boxLengths);

EnsembleResults computeEnsemble(std::span<const FileResults> files);

} // namespace sbpack
