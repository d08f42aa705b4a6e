#pragma once
// Ensemble statistics over packings of equal p and N: mean and standard deviation of every
// scalar the schema marks Reduce::MeanStd, and of the shell-averaged curves (Reduce::Curve) on a
// common grid in Q w. Inputs that differ in p or N form separate ensembles.

#include "pipeline/file_analysis.hpp"
#include "schema/record.hpp"
#include "shells/shell_average.hpp"

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace sbpack {

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
    std::vector<std::int64_t> files; ///< files with a shell in the bin
};

/// Curves (Q w, value) of several files on the common grid.
EnsembleCurve ensembleCurve(std::span<const ShellAverage> curves,
                            std::span<const double> meanWidths, std::span<const double> boxLengths);

/// One ensemble (ensembles/<k>): its members (indices of the run's files) and its groups.
struct EnsembleResults {
    std::vector<std::size_t> members;
    schema::Record root{schema::ensembleRootGroup()};
    std::vector<schema::Record> groups;

    /// The statistics of analysis group `name`; nullptr if no member has that group.
    const schema::Record* group(std::string_view name) const;
    schema::Record* group(std::string_view name);
};

/// The files grouped by (p, N and a mixture's size ratio), each group in input order, groups in
/// order of first appearance.
std::vector<std::vector<std::size_t>> ensembleMembers(std::span<const FileResults> files);

/// Statistics over `members` of `files`. Throws std::invalid_argument, naming both inputs, if the
/// members differ in p or N (they are never averaged together), or if there are none.
EnsembleResults computeEnsemble(std::span<const FileResults> files,
                                std::vector<std::size_t> members);

/// One ensemble per (p, N) of ensembleMembers(files).
std::vector<EnsembleResults> computeEnsembles(std::span<const FileResults> files);

} // namespace sbpack
