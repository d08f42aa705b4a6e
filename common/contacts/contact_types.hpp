#pragma once
// Where on a superball its contacts sit (docs/contact-types.md): each end of a contact among the
// non-rattlers is classified by its body-frame outward normal, the nearest of the shape's cubic
// symmetry directions by angle (<100> axis, <110> edge, <111> diagonal), and by its angle theta
// to the nearest body axis; the paper's closing "distribution of contact angles" against p.

#include "contacts/contact_network.hpp"
#include "packing/packing.hpp"

#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace sbpack {

/// The nearest symmetry direction of a body-frame normal (docs/contact-types.md §1). The rule is
/// on the normal only, so the names hold for every p: `Axis` <100> is the cube's face (p > 1)
/// and the octahedron's vertex (p < 1), `Edge` <110> an edge of either, `Diagonal` <111> the
/// cube's vertex and the octahedron's face.
enum class ContactRegion { Axis, Edge, Diagonal };
inline constexpr std::size_t kContactRegions = 3;
/// Unordered pairs of regions: axis-axis, axis-edge, axis-diagonal, edge-edge, edge-diagonal,
/// diagonal-diagonal (contactPairType's order).
inline constexpr std::size_t kContactPairTypes = 6;

/// "axis", "edge", "diagonal".
std::string_view regionName(ContactRegion region);
/// "axis_axis", "axis_edge", ..., "diagonal_diagonal" for contactPairType's index.
std::string_view pairTypeName(std::size_t type);
/// The index of the unordered pair {a, b} in 0 .. kContactPairTypes - 1 (symmetric in a, b).
std::size_t contactPairType(ContactRegion a, ContactRegion b);

/// Fractions of the sphere nearest <100>, <110>, <111>: the solid angles of the spherical
/// polygons that split the symmetry triangle, by Girard's theorem (docs/contact-types.md Eq.
/// 2.4); the region fractions of normals uniform on the sphere, e.g. of spheres.
inline constexpr std::array<double, kContactRegions> kUniformRegionFractions{
    0.27466734722856545, 0.44376753451290213, 0.28156511825853253};

/// theta_max = arccos(1 / sqrt 3): the largest angle from the nearest body axis, at <111>.
inline constexpr double kMaxAxisAngleDegrees = 54.735610317245346;
/// Equal bins of theta over [0, theta_max]: a constant, not an option (docs/contact-types.md §5).
inline constexpr int kAxisAngleBins = 30;

/// One end of a contact: the region of its body-frame normal and theta = arccos(max_k |n_k|),
/// the angle to the nearest body axis, in [0, theta_max] (radians).
struct ContactEnd {
    ContactRegion region = ContactRegion::Axis;
    double axisAngle = 0.0;
};

/// The end of the body-frame unit normal `n`: its region the nearest of +-<100>, +-<110>,
/// +-<111> by angle (ties go to the lower symmetry direction: axis before edge before
/// diagonal). Throws std::invalid_argument unless |n| is 1 within 1e-9.
ContactEnd classifyNormal(const Vector3d& n);

/// P(theta <= t) for normals uniform on the sphere (docs/contact-types.md Eq. 2.1 and 2.2): the
/// six caps of angular radius t about +-e_k, 3 (1 - cos t) up to 45 degrees, less their overlaps
/// beyond; 1 from theta_max on. `t` in radians.
double uniformAxisAngleCdf(double t);

/// A contact among the non-rattlers, its ends at i and j.
struct TypedContact {
    int i = 0;
    int j = 0;
    ContactEnd atI; ///< normal R_i^T n
    ContactEnd atJ; ///< normal R_j^T (-n)
};

/// The contacts of `network` (computed on `packing`) between two non-rattlers, in its order,
/// each end classified in its particle's body frame (R of the stored quaternion body -> lab,
/// normalised). Throws std::invalid_argument where the network is not the packing's (sizes).
std::vector<TypedContact> typedContacts(const Packing& packing, const ContactResult& network);

/// The distribution of the contact types (docs/contact-types.md §2); fractions and densities are
/// NaN where there is no contact.
struct ContactTypeDistribution {
    std::size_t contactCount = 0; ///< contacts among the non-rattlers
    /// Fractions of the 2 contactCount ends in each region (ContactRegion's order).
    std::array<double, kContactRegions> regionFractions{};
    /// Fractions of the contacts of each pair type (contactPairType's order).
    std::array<double, kContactPairTypes> pairTypeFractions{};
    double meanAxisAngleDegrees = 0.0;       ///< mean theta over the ends
    std::vector<double> axisAngleEdges;      ///< kAxisAngleBins + 1 edges, degrees, 0 .. theta_max
    std::vector<double> axisAngleDensity;    ///< probability density of theta per degree
    std::vector<double> uniformAngleDensity; ///< the same for normals uniform on the sphere
};

/// The distribution of `contacts`: the bins of theta in degrees, and the uniform normals'
/// density in them from uniformAxisAngleCdf.
ContactTypeDistribution contactTypeDistribution(std::span<const TypedContact> contacts);

} // namespace sbpack
