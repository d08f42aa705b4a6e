"""sbpack's GSD and LAMMPS files against the peers that read and write them
(bench/formats_vs_peers.sh; docs/cli.md, "Files"; bench/RESULTS.md, "GSD and LAMMPS against
gsd.hoomd, freud and OVITO").

usage: formats_vs_peers.py SBANALYZE PACKING.h5 WORKDIR

1. sbanalyze convert PACKING.h5 WORKDIR/out.gsd, read by gsd.hoomd (the reference reader): the
   schema's single-precision positions and orientations against the packing's (h5py), the
   double-precision log copies exactly, the box; freud's box from it; OVITO's importer where
   installed (positions, orientations, the type's shape).
2. A hard-sphere frame written by gsd.hoomd as HOOMD writes one (float32, a Sphere
   type_shape, no sbpack chunks) read by sbanalyze info: N, L, p = 1 and a.
3. sbanalyze convert PACKING.h5 to a LAMMPS dump and data file, read by OVITO's importers: the
   superquadric roundness (1/p), the shape (a) and the orientations against the packing's.
"""
import subprocess
import sys

import gsd.hoomd
import gsd.version
import h5py
import numpy as np


def written_by_sbpack(sbanalyze, packing, work):
    out = f"{work}/out.gsd"
    subprocess.run([sbanalyze, "convert", packing, out], check=True, capture_output=True)
    with h5py.File(packing) as f:
        r, q = f["positions"][:], f["orientations"][:]
        L = float(f.attrs["box_length"])
    frame = gsd.hoomd.open(out, "r")[-1]
    pos = frame.particles.position.astype(float)
    shifted = (pos + L / 2) % L
    err = np.abs((shifted - r + L / 2) % L - L / 2).max()
    print(f"gsd.hoomd {gsd.version.version}: N = {frame.particles.N}, box {list(frame.configuration.box)}")
    print(f"  position (float32) against the packing: largest |difference| {err:.3e} "
          f"(float32 spacing at L/2: {np.spacing(np.float32(L / 2)):.3e}); "
          f"in [-L/2, L/2): {bool((pos >= -L / 2).all() and (pos < L / 2).all())}")
    print(f"  orientation (float32, w x y z): largest |difference| "
          f"{np.abs(frame.particles.orientation - q).max():.3e}")
    exact = frame.log["particles/sbpack/position"]
    print(f"  log/particles/sbpack/position float64 equal bit for bit: {np.array_equal(exact, r)}; "
          f"orientation: {np.array_equal(frame.log['particles/sbpack/orientation'], q)}")
    print(f"  log/sbpack/p = {frame.log['sbpack/p']}, semi_axis = {frame.log['sbpack/semi_axis']}")
    print(f"  type_shapes: {frame.particles.type_shapes[0]['type']} of "
          f"{len(frame.particles.type_shapes[0]['vertices'])} vertices")
    try:
        import freud
        box = freud.box.Box.from_box(frame.configuration.box)
        print(f"freud {freud.__version__}: box L = {box.Lx}, cubic {box.Lx == box.Ly == box.Lz}")
    except ImportError:
        print("freud: not installed")
    try:
        from ovito.io import import_file
        data = import_file(out).compute()
        p = data.particles
        kind = p.particle_types.types[0]
        mesh = kind.mesh
        print(f"OVITO: {p.count} particles, properties {sorted(p.keys())}; largest |position - "
              f"gsd.hoomd's| {np.abs(np.asarray(p.positions) - pos).max():.3e}; the type's "
              f"shape {kind.shape.name} of {mesh.vertex_count if mesh else 0} vertices")
    except ImportError:
        print("OVITO: not installed")


def written_by_gsd(sbanalyze, work):
    rng = np.random.default_rng(1)
    n, L, d = 64, 8.0, 1.0
    grid = np.stack(np.meshgrid(*[np.arange(4)] * 3, indexing="ij"), -1).reshape(-1, 3)
    frame = gsd.hoomd.Frame()
    frame.particles.N = n
    frame.particles.position = ((grid + 0.5) * L / 4 - L / 2
                                + rng.uniform(-0.1, 0.1, (n, 3))).astype(np.float32)
    frame.particles.types = ["A"]
    frame.particles.typeid = np.zeros(n, dtype=np.uint32)
    frame.particles.type_shapes = [{"type": "Sphere", "diameter": d}]
    frame.configuration.box = [L, L, L, 0, 0, 0]
    path = f"{work}/hoomd.gsd"
    with gsd.hoomd.open(path, "w") as f:
        f.append(frame)
    info = subprocess.run([sbanalyze, "info", path], capture_output=True, text=True, check=True)
    print("a HOOMD hard-sphere frame (gsd.hoomd, float32, Sphere of diameter 1) by sbanalyze info:")
    for line in info.stdout.splitlines()[1:5]:
        print("  " + line.strip())


def lammps_by_ovito(sbanalyze, packing, work):
    try:
        from ovito.io import import_file
    except ImportError:
        print("OVITO: not installed (LAMMPS files not checked)")
        return
    with h5py.File(packing) as f:
        r, q = f["positions"][:], f["orientations"][:]
        p, a = float(f.attrs["p"]), float(f.attrs["semi_axis"])
    for name in ("out.dump", "out.data"):
        path = f"{work}/{name}"
        subprocess.run([sbanalyze, "convert", packing, path], check=True, capture_output=True)
        particles = import_file(path).compute().particles
        keys = sorted(particles.keys())
        line = f"OVITO reads {name}: properties {keys}"
        if "Superquadric Roundness" in keys:
            roundness = np.asarray(particles["Superquadric Roundness"])
            line += f"; roundness {roundness.min():.17g}..{roundness.max():.17g} (1/p {1 / p:.17g})"
        if "Aspherical Shape" in keys:
            shape = np.asarray(particles["Aspherical Shape"])
            line += f"; shape {shape.min():.17g}..{shape.max():.17g} (a {a:.17g})"
        xyzw = np.asarray(particles["Orientation"])
        wxyz = np.concatenate([xyzw[:, 3:], xyzw[:, :3]], axis=1)
        line += (f"; |orientation - packing's| {np.abs(wxyz - q).max():.2e}, "
                 f"|position - packing's| {np.abs(np.asarray(particles.positions) - r).max():.2e}")
        print(line)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    written_by_sbpack(*sys.argv[1:])
    written_by_gsd(sys.argv[1], sys.argv[3])
    lammps_by_ovito(*sys.argv[1:])
