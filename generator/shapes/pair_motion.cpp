#include "shapes/pair_motion.hpp"

#include <algorithm>

namespace sbpack {

void PairMemory::appendColumns(std::vector<double>& row) const {
    for (const Vector3d* v : {&normal, &witness.pointI, &witness.pointJ})
        row.insert(row.end(), v->data(), v->data() + 3);
    row.insert(row.end(), {witness.turnedI, witness.turnedJ});
}

std::optional<PairMemory> PairMemory::fromColumns(const double* columns, std::string& problem) {
    if (!std::all_of(columns, columns + 9, [](double x) { return std::isfinite(x); }) ||
        std::any_of(columns + 9, columns + 11, [](double x) { return std::isinf(x); })) {
        problem = "normal and points must be finite, the angles finite or NaN";
        return std::nullopt;
    }
    PairMemory m;
    m.normal = Vector3d(columns[0], columns[1], columns[2]);
    if (m.normal != Vector3d::Zero() && std::abs(m.normal.norm() - 1.0) > 1e-9) {
        problem = "the normal must be a unit vector or zero";
        return std::nullopt;
    }
    m.witness = {Vector3d(columns[3], columns[4], columns[5]),
                 Vector3d(columns[6], columns[7], columns[8]), columns[9], columns[10]};
    return m;
}

} // namespace sbpack
