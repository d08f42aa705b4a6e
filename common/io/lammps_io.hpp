#pragma once
// LAMMPS in and out (docs/cli.md, "Files"): a dump of the custom style that OVITO 3.x draws as
// superballs with no mapping, and a data file of atom_style ellipsoid (with the superellipsoid
// blockiness of LAMMPS 30Mar2026 where p != 1). Both at full precision (17 digits).

#include "packing/packing.hpp"

#include <filesystem>

namespace sbpack {

/// One frame (timestep 0) of `dump custom`: the periodic box [0, L)^3 and per particle
///   id type x y z quatw quati quatj quatk shapex shapey shapez
///   SuperquadricRoundness.Phi SuperquadricRoundness.Theta
/// (LAMMPS's quaternion (w, i, j, k) body to lab and shape diameters 2a; OVITO maps the columns
/// by name to Orientation, Aspherical Shape and Superquadric Roundness = (1/p, 1/p)). Atomic.
void writeLammpsDump(const Packing& packing, const std::filesystem::path& file);

/// The first frame of a LAMMPS dump: a cubic periodic box (BOX BOUNDS pp pp pp, no tilt),
/// positions x y z (or unwrapped xu yu zu, or scaled xs ys zs), quatw..quatk (identity where
/// absent), equal shapex shapey shapez = 2a (or the key-free sbpack dump), p = 1 / roundness
/// (repaired from single precision as for XYZ) or 1 without the roundness columns; particles in
/// the order of their ids. Throws PackingFileError naming the file and line.
Packing readLammpsDump(const std::filesystem::path& file);

/// A data file for `atom_style ellipsoid` (p = 1) or `atom_style ellipsoid superellipsoid`
/// (LAMMPS 30Mar2026 and later, p != 1: blockiness n1 = n2 = 2p on each Ellipsoids line): the
/// header counts, the box 0 L, `Atoms # ellipsoid` (id type 1 density x y z, density 1) and
/// `Ellipsoids` (id 2a 2a 2a quatw quati quatj quatk [2p 2p]). Atomic.
void writeLammpsData(const Packing& packing, const std::filesystem::path& file);

/// Reads such a data file: the box (cubic, from 0 or any origin), the Atoms and Ellipsoids
/// sections joined by id (every atom an ellipsoid with equal shapes 2a), p from the blockiness
/// (n1 = n2 = 2p) or 1 without it. Throws PackingFileError naming the file and line.
Packing readLammpsData(const std::filesystem::path& file);

} // namespace sbpack
