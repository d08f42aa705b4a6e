#include "packing/packing.hpp"

namespace sbpack {

double Packing::packingFraction() const {
    return static_cast<double>(size()) * shape().volume() / (boxLength * boxLength * boxLength);
}

} // namespace sbpack
