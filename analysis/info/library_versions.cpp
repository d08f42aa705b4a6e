#include "info/library_versions.hpp"

#include <fftw3.h>
#include <hdf5.h>
#include <oneapi/tbb/version.h>
#include <openvdb/version.h>

#include <sstream>

namespace sbpack {

std::string libraryVersions() {
    unsigned major = 0, minor = 0, release = 0;
    H5get_libversion(&major, &minor, &release);
    std::ostringstream out;
    out << "  HDF5 " << major << '.' << minor << '.' << release << '\n'
        << "  " << fftw_version << '\n'
        << "  oneTBB " << TBB_runtime_version() << '\n'
        << "  OpenMP " << _OPENMP << '\n'
        << "  OpenVDB " << openvdb::getLibraryAbiVersionString() << '\n';
    return out.str();
}

} // namespace sbpack
