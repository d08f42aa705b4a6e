#pragma once
#include <string>

namespace sbpack {
/// One line per library sbanalyze links (HDF5, FFTW, TBB, OpenMP, OpenVDB), for --version.
std::string libraryVersions();
} // namespace sbpack
