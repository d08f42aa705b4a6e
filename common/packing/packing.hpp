#pragma once
// The packing model shared by sbgen and sbanalyze (docs/design.md §4).

#include "geometry/particle_shape.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace sbpack {

using Eigen::Quaterniond;

/// A provenance value: the generator's parameters and run log (group `provenance`).
using ProvenanceValue = std::variant<std::int64_t, double, std::string>;

/// Values per row of Packing::pairRecords.
inline constexpr std::size_t kPairRecordColumns = 13;

/// One contact's time-averaged force as sbgen measured it (group `contact_forces`;
/// docs/jamming.md, "Contact forces").
struct ContactForce {
    int i = 0; ///< particles, i < j
    int j = 0;
    Vector3d point = Vector3d::Zero();  ///< contact point x, lab frame, in [0, L)
    Vector3d normal = Vector3d::Zero(); ///< unit, from i to j
    double force = 0.0;                 ///< f >= 0 in kT / D: i pushes j with f n
};

/// sbgen's contact forces: the momentum each pair exchanged, averaged over the run's last
/// windows (docs/jamming.md, "Contact forces"; the per-particle residuals: forceBalance).
struct ContactForces {
    std::vector<ContactForce> contacts; ///< ascending (i, j)
    std::int64_t windows = 0;           ///< the windows averaged over
    double duration = 0.0;              ///< their summed duration (sbgen's time)
    /// sbgen's reduced pressure over those windows (their duration-weighted mean), which the
    /// forces' virial reproduces (virialPressure).
    double reducedPressure = 0.0;
};

/// Particles of one shape in a cubic periodic box of edge L: identical, or a mixture of sizes
/// (docs/mixtures.md).
struct Packing {
    /// The particles' shape family and parameters (superballs of exponent p).
    ShapeSpec shapeSpec;
    /// The semi-axis of every particle; of a mixture, the largest of semiAxes (what lengths that
    /// must hold for every particle, such as neighbour cut-offs, are sized by).
    double semiAxis = 0.5;
    /// A mixture's per-particle semi-axes (dataset `semi_axes`), N entries; empty where every
    /// particle has semiAxis, as every packing of identical particles is stored.
    std::vector<double> semiAxes;
    double boxLength = 1.0;
    std::vector<Vector3d> positions;         ///< in [0, L)
    std::vector<Quaterniond> orientations;   ///< unit (w, x, y, z), body to lab
    std::vector<Vector3d> velocities;        ///< optional: empty or N entries
    std::vector<Vector3d> angularVelocities; ///< optional: empty or N entries
    std::optional<double> reducedPressure;
    std::optional<std::uint64_t> seed;
    std::string generatorVersion;
    std::map<std::string, ProvenanceValue> provenance;
    /// What a generator needs to resume beyond the particles (group `resume_state`, sbgen's
    /// format, phase and growth clock: docs/design.md §4); not part of the provenance.
    std::map<std::string, ProvenanceValue> resumeState;
    /// sbgen's pair records, kPairRecordColumns values a row (dataset resume_state/pair_records,
    /// its row count resumeState["pair_records"]; the columns: generator/protocol/
    /// checkpoint_entries.cpp and docs/design.md §4).
    std::vector<double> pairRecords;
    /// sbgen's contact forces (group `contact_forces`), absent for packings from elsewhere.
    std::optional<ContactForces> contactForces;

    std::size_t size() const { return positions.size(); }
    /// The shape of every particle; of a mixture, the largest.
    ParticleShape shape() const { return {shapeSpec, semiAxis}; }
    /// shape()'s superball, for code that holds for superballs only.
    Superball superball() const { return shape().superball(); }
    bool isMixture() const { return !semiAxes.empty(); }
    /// Particle i's semi-axis.
    double semiAxisOf(std::size_t i) const { return semiAxes.empty() ? semiAxis : semiAxes[i]; }
    /// Particle i's size s_i = R_i / R, its semi-axis over the largest (1 for identical
    /// particles): the factor a mixture's per-particle lengths and volumes scale by
    /// (docs/mixtures.md).
    double relativeSize(std::size_t i) const {
        return semiAxes.empty() ? 1.0 : semiAxes[i] / semiAxis;
    }
    /// Every particle's relativeSize, empty for identical particles.
    std::vector<double> relativeSizes() const;
    /// The smallest particle's semi-axis (semiAxis for identical particles).
    double smallestSemiAxis() const;
    /// The pair's mean size over the largest, (R_i + R_j) / (2 R): the unit of a mixture's pair
    /// lengths (contact tolerance, reduced distance of g2: docs/mixtures.md); 1 for identical
    /// particles.
    double pairSize(std::size_t i, std::size_t j) const {
        return semiAxes.empty() ? 1.0 : 0.5 * (semiAxes[i] + semiAxes[j]) / semiAxis;
    }
    /// phi = sum_i v_i / L^3 (N v1 / L^3 for identical particles).
    double packingFraction() const;
    /// The length unit the analyses compute in (docs/reliability.md, "Units"): the power of two
    /// u with 1 <= D / u < 2 (D = 2 R), so that lengths divided by it are exact and a packing
    /// with 1 <= D < 2 is analysed as given.
    double analysisLengthUnit() const { return std::ldexp(1.0, std::ilogb(2.0 * semiAxis)); }
};

/// The mean of (s / unit)^3 over `sizes` (1 where empty: identical particles): a mixture's mean
/// particle volume over that of size `unit` (Packing::packingFraction, sbgen's growing engine).
double meanCubedSize(const std::vector<double>& sizes, double unit = 1.0);

/// The particles of `packing` with every length divided by `unit` (a power of two: exact), so
/// that a packing in any units is analysed at D ~ 1 and gives the same reduced results. The
/// exponent, pressure, seed and contact forces (their points scaled) are kept; velocities,
/// provenance and resume state are not.
Packing inLengthUnit(const Packing& packing, double unit);

/// A packing as the analyses see it: in its analysisLengthUnit, the packing itself where that is
/// 1 (no copy), else its copy by inLengthUnit. Holds a reference to `packing`.
class AnalysedPacking {
  public:
    explicit AnalysedPacking(const Packing& packing)
        : unit_(packing.analysisLengthUnit()), original_(&packing),
          scaled_(unit_ == 1.0 ? std::nullopt : std::optional(inLengthUnit(packing, unit_))) {}
    /// The packing in units of lengthUnit().
    const Packing& packing() const { return scaled_ ? *scaled_ : *original_; }
    /// Packing::analysisLengthUnit of the packing given, in its units.
    double lengthUnit() const { return unit_; }

  private:
    double unit_;
    const Packing* original_;
    std::optional<Packing> scaled_;
};

/// The lattice vector L m that the minimum image in a cubic periodic box of edge L adds to d.
inline Vector3d minimumImageShift(const Vector3d& d, double boxLength) {
    Vector3d shift;
    for (int k = 0; k < 3; ++k)
        shift[k] = -boxLength * std::nearbyint(d[k] / boxLength);
    return shift;
}

/// Minimum-image displacement in a cubic periodic box of edge L.
inline Vector3d minimumImage(const Vector3d& d, double boxLength) {
    return d + minimumImageShift(d, boxLength);
}

/// The lattice vector F L m that the minimum image in the cell F L (edges as columns, the
/// cube's images mapped by F; jamming/soft_relaxation) adds to d: F times the cube's shift of
/// F^-1 d. For F = I, bit for bit minimumImageShift.
inline Vector3d cellImageShift(const Vector3d& d, const Eigen::Matrix3d& cell,
                               const Eigen::Matrix3d& cellInverse, double boxLength) {
    return cell * minimumImageShift(cellInverse * d, boxLength);
}

/// Wraps a position into [0, L).
inline Vector3d wrapIntoBox(Vector3d r, double boxLength) {
    for (int k = 0; k < 3; ++k) {
        r[k] -= boxLength * std::floor(r[k] / boxLength);
        if (r[k] >= boxLength) r[k] = 0.0; // floor rounding at the upper edge
    }
    return r;
}

} // namespace sbpack
