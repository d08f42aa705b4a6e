#include "contacts/contact_types.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace sbpack {
namespace {

constexpr std::array<std::string_view, kContactRegions> kRegionNames{"axis", "edge", "diagonal"};
constexpr std::array<std::string_view, kContactPairTypes> kPairTypeNames{
    "axis_axis", "axis_edge", "axis_diagonal", "edge_edge", "edge_diagonal", "diagonal_diagonal"};
constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The solid angle where the caps of angular radius t about two orthogonal axes overlap, by
/// Gauss-Bonnet over the lens they bound (docs/contact-types.md Eq. 2.3); for 45 deg < t <
/// theta_max, where no third cap reaches it.
double orthogonalCapsOverlap(double t) {
    const double cot = 1.0 / std::tan(t);
    return 2.0 * std::numbers::pi - 2.0 * std::acos(-cot * cot) -
           4.0 * std::cos(t) * std::acos(cot);
}

/// The contacts' bins of theta and the uniform normals' density in them; NaN elsewhere.
ContactTypeDistribution binsOfTheta() {
    ContactTypeDistribution d;
    const double width = kMaxAxisAngleDegrees / kAxisAngleBins;
    for (int b = 0; b <= kAxisAngleBins; ++b)
        d.axisAngleEdges.push_back(b * width);
    d.axisAngleEdges.back() = kMaxAxisAngleDegrees;
    for (int b = 0; b < kAxisAngleBins; ++b)
        d.uniformAngleDensity.push_back((uniformAxisAngleCdf(d.axisAngleEdges[b + 1] * kDegree) -
                                         uniformAxisAngleCdf(d.axisAngleEdges[b] * kDegree)) /
                                        width);
    d.regionFractions.fill(kNaN);
    d.pairTypeFractions.fill(kNaN);
    d.meanAxisAngleDegrees = kNaN;
    d.axisAngleDensity.assign(kAxisAngleBins, kNaN);
    return d;
}

} // namespace

std::string_view regionName(ContactRegion region) {
    return kRegionNames[static_cast<std::size_t>(region)];
}

std::string_view pairTypeName(std::size_t type) {
    return kPairTypeNames.at(type);
}

std::size_t contactPairType(ContactRegion a, ContactRegion b) {
    constexpr std::array<std::array<std::size_t, kContactRegions>, kContactRegions> kTypeOf{
        {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}}};
    return kTypeOf[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)];
}

ContactEnd classifyNormal(const Vector3d& n) {
    if (!(std::abs(n.norm() - 1.0) <= 1e-9))
        throw std::invalid_argument(fmt::format(
            "contact types: normal ({:g}, {:g}, {:g}) is not a unit vector", n[0], n[1], n[2]));
    std::array<double, 3> a{std::abs(n[0]), std::abs(n[1]), std::abs(n[2])};
    std::sort(a.begin(), a.end(), std::greater<>());
    // cosines of the angle to the nearest <100>, <110> and <111>
    const double axis = a[0];
    const double edge = (a[0] + a[1]) / std::numbers::sqrt2;
    const double diagonal = (a[0] + a[1] + a[2]) * std::numbers::inv_sqrt3;
    ContactEnd end;
    end.region = axis >= edge && axis >= diagonal
                     ? ContactRegion::Axis
                     : (edge >= diagonal ? ContactRegion::Edge : ContactRegion::Diagonal);
    end.axisAngle = std::acos(std::min(1.0, axis));
    return end;
}

double uniformAxisAngleCdf(double t) {
    if (t <= 0.0) return 0.0;
    if (t >= kMaxAxisAngleDegrees * kDegree) return 1.0;
    const double caps = 3.0 * (1.0 - std::cos(t)); // Eq. 2.1: six caps of 2 pi (1 - cos t)
    if (t <= std::numbers::pi / 4.0) return caps;
    return caps - 3.0 / std::numbers::pi * orthogonalCapsOverlap(t); // Eq. 2.2: 12 overlaps
}

std::vector<TypedContact> typedContacts(const Packing& packing, const ContactResult& network) {
    if (network.rattler.size() != packing.size() || packing.orientations.size() != packing.size() ||
        network.normals.size() != network.contacts.size())
        throw std::invalid_argument(fmt::format(
            "contact types: the network ({} particles, {} contacts, {} normals) is not of the "
            "packing ({} particles, {} orientations)",
            network.rattler.size(), network.contacts.size(), network.normals.size(), packing.size(),
            packing.orientations.size()));
    std::vector<TypedContact> typed;
    for (std::size_t k = 0; k < network.contacts.size(); ++k) {
        const auto [i, j] = network.contacts[k];
        if (network.rattler[i] || network.rattler[j]) continue;
        const Vector3d& n = network.normals[k]; // lab frame, from i toward j
        // body frame: R^T n, the quaternion body -> lab inverted
        typed.push_back({i, j, classifyNormal(packing.orientations[i].normalized().conjugate() * n),
                         classifyNormal(packing.orientations[j].normalized().conjugate() * -n)});
    }
    return typed;
}

ContactTypeDistribution contactTypeDistribution(std::span<const TypedContact> contacts) {
    ContactTypeDistribution d = binsOfTheta();
    d.contactCount = contacts.size();
    if (contacts.empty()) return d;
    std::array<long, kContactRegions> regions{};
    std::array<long, kContactPairTypes> pairTypes{};
    std::vector<long> bins(kAxisAngleBins, 0);
    const double width = kMaxAxisAngleDegrees / kAxisAngleBins;
    double angleSum = 0.0;
    for (const TypedContact& c : contacts) {
        ++pairTypes[contactPairType(c.atI.region, c.atJ.region)];
        for (const ContactEnd& end : {c.atI, c.atJ}) {
            const double theta = end.axisAngle / kDegree;
            ++regions[static_cast<std::size_t>(end.region)];
            ++bins[std::min(kAxisAngleBins - 1, static_cast<int>(theta / width))];
            angleSum += theta;
        }
    }
    const auto count = static_cast<double>(contacts.size());
    for (std::size_t r = 0; r < kContactRegions; ++r)
        d.regionFractions[r] = static_cast<double>(regions[r]) / (2.0 * count);
    for (std::size_t t = 0; t < kContactPairTypes; ++t)
        d.pairTypeFractions[t] = static_cast<double>(pairTypes[t]) / count;
    for (int b = 0; b < kAxisAngleBins; ++b)
        d.axisAngleDensity[b] = static_cast<double>(bins[b]) / (2.0 * count * width);
    d.meanAxisAngleDegrees = angleSum / (2.0 * count);
    return d;
}

} // namespace sbpack
