#include "voxels/vdb_image.hpp"

#include <openvdb/io/Stream.h>

#include <mutex>
#include <sstream>

namespace sbpack {

std::string vdbImage(const openvdb::GridBase::Ptr& grid, double boxLength, int voxels,
                     const std::string& units, double lengthUnit) {
    static std::once_flag initialized;
    std::call_once(initialized, [] { openvdb::initialize(); });
    grid->insertMeta("box_length", openvdb::DoubleMetadata(boxLength));
    grid->insertMeta("voxels", openvdb::Int64Metadata(voxels));
    grid->insertMeta("units", openvdb::StringMetadata(units));
    grid->insertMeta("length_unit", openvdb::DoubleMetadata(lengthUnit));
    std::ostringstream bytes(std::ios::binary);
    openvdb::io::Stream(bytes).write(openvdb::GridCPtrVec{grid});
    return std::move(bytes).str();
}

} // namespace sbpack
