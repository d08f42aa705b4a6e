#pragma once
// Translational order metric T of Truskett, Torquato & Debenedetti, PRE 62, 993 (2000)
// (docs/order-metrics.md §3): the excess occupation of the fcc neighbour shells at the packing's
// number density, 0 for an ideal gas and 1 for the fcc crystal.

#include "packing/packing.hpp"

#include <vector>

namespace sbpack {

/// One neighbour shell of the fcc lattice: its distance in units of the nearest-neighbour
/// distance d (sqrt of s / 2, s = h^2 + k^2 + l^2 over the lattice vectors (h, k, l) a / 2 with
/// h + k + l even) and the number of lattice points on it.
struct FccShell {
    double distance = 0.0;
    int coordination = 0;
};

/// The first `count` shells of the fcc lattice, nearest first: 12 at 1, 6 at sqrt 2, 24 at
/// sqrt 3, ... (there is none at sqrt 14). Throws std::invalid_argument unless count >= 1.
std::vector<FccShell> fccShells(int count);

struct TranslationalOrderParameters {
    /// N_C: the first N_C fcc shells.
    int shellCount = 12;
    /// Shell width a in units of the fcc nearest-neighbour distance d at the packing's density;
    /// shell i is [r_i - a / 2, r_i + a / 2) (docs/order-metrics.md §3: the choice).
    double shellWidth = 0.1;
};

struct TranslationalOrderResult {
    TranslationalOrderParameters parameters;
    double numberDensity = 0.0;            ///< rho w^3, rho = N / L^3
    double nearestNeighbourDistance = 0.0; ///< d / w = (sqrt 2 / rho)^{1/3} / w
    std::vector<double> shellRadius;       ///< r_i / w
    std::vector<double> occupation;        ///< n_i: mean number of centres in shell i of a centre
    std::vector<double> idealOccupation;   ///< n_i^ideal = rho V_i
    std::vector<int> fccOccupation;        ///< n_i^fcc
    /// T = |sum (n_i - n_i^ideal)| / sum (n_i^fcc - n_i^ideal) (Eq. 3.1).
    double order = 0.0;
    /// Standard deviation of the signed ratio for an ideal gas of the same N and rho (Eq. 3.3):
    /// a T within a few of these is indistinguishable from no translational order.
    double idealGasError = 0.0;
};

/// d, the nearest-neighbour distance of the fcc lattice at the packing's number density (length
/// units).
double fccNeighbourDistance(const Packing& packing);
/// How many of the first parameters.shellCount fcc shells (with their width) lie within L / 2.
int fccShellsThatFit(const Packing& packing, const TranslationalOrderParameters& parameters);

/// Compute object (docs/design.md §7): parameters validated at construction.
class TranslationalOrder {
  public:
    /// Throws std::invalid_argument unless shellCount >= 1 and 0 < shellWidth < the smallest
    /// distance between consecutive shells of the first shellCount (the shells do not overlap).
    explicit TranslationalOrder(TranslationalOrderParameters parameters);

    /// Throws std::invalid_argument for fewer than 2 particles or when the outermost shell
    /// reaches beyond L / 2 (the message gives how many shells fit).
    TranslationalOrderResult compute(const Packing& packing) const;

    const TranslationalOrderParameters& parameters() const { return parameters_; }

  private:
    TranslationalOrderParameters parameters_;
    std::vector<FccShell> shells_;
};

} // namespace sbpack
