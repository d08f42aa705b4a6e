"""Cross-check of sbanalyze's solid-like particles against the peer freud (issue 63).

    bash bench/order_vs_freud.sh [SBANALYZE] [PACKING]        (sets up freud's venv, runs this)
    VENV/bin/python bench/solid_like_vs_freud.py SBANALYZE [PACKING...] [--lattices] [--work DIR]

sbanalyze's results group `order` (docs/results-schema.md) records the ten Wolde criterion over
the SANN bonds (docs/order-metrics.md §5): crystal_bonds (the crystal-like bonds xi(i) of each
particle), solid_like_fraction, crystal_cluster and sann_neighbours_mean. Here the SANN bonds are
found independently (freud's nearest-neighbour query for the candidates, float64 distances, the
shell rule of van Meel et al. 2012, Eq. 3, a pair a bond when either particle has the other in its
shell) and handed to freud.order.SolidLiquid(l = 6, q_threshold = 0.7, solid_threshold = 7,
normalize_q = True), the thresholds of common/order/solid_like.hpp. Compared per packing:

- the SANN bonds per particle (sann_neighbours_mean, exactly);
- xi(i) against freud's num_connections, particle by particle: equal but where a bond's d_6 lies
  within FLOAT32_BAND of 0.7 (freud computes q_lm in float32);
- the solid-like particles (xi >= 7) and the largest cluster of them joined by crystal-like bonds
  (freud's cluster_idx over the solid-like particles; freud counts every other particle as a
  cluster of one).

--lattices adds sc (125), bcc (128), fcc (256) and hcp (448, c / a = 1.75) of touching spheres
and the same displaced uniformly in [-h, h]^3 (h = 0.03 D, rms 3 % of D) at nearest-neighbour
distance 1.105 D, written as text packings into --work. The run fails (exit status 1) when a
check fails.
"""
import argparse
import itertools
import math
import subprocess
import sys

import freud
import h5py
import numpy as np

L_DEGREE, BOND_THRESHOLD, SOLID_BONDS = 6, 0.7, 7
FLOAT32_BAND = 1e-4  # |d_6 - 0.7| below which float32 may put a bond on either side
CANDIDATES = 40      # nearest neighbours queried for the SANN shell (sc needs 19)


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("sbanalyze")
    parser.add_argument("packings", nargs="*")
    parser.add_argument("--lattices", action="store_true")
    parser.add_argument("--work", default="/tmp")
    return parser.parse_args()


def write_text_packing(path, positions, box_length):
    """sbpack's text packing (common/io/text_io.hpp): spheres of diameter 1, aligned."""
    with open(path, "w") as out:
        out.write(f"# sbpack text packing v1\n# p 1.0\n# semi_axis 0.5\n"
                  f"# box_length {box_length:.17g}\n# n_particles {len(positions)}\n")
        for x, y, z in np.mod(positions, box_length):
            out.write(f"{x:.17g} {y:.17g} {z:.17g} 1 0 0 0\n")


def lattice(kind, d):
    """(positions, box edge) of a lattice with nearest-neighbour distance d."""
    bases = {"sc": (5, 1.0, [(0, 0, 0)]),
             "bcc": (4, 2 / math.sqrt(3), [(0, 0, 0), (.5, .5, .5)]),
             "fcc": (4, math.sqrt(2), [(0, 0, 0), (.5, .5, 0), (.5, 0, .5), (0, .5, .5)])}
    if kind == "hcp":  # 7 x 4 x 4 orthohexagonal cells (a, 1.75 a, c = 1.75 a)
        cell = d * np.array([1.0, 1.75, 1.75])
        basis = [(0, 0, 0), (.5, .5, 0), (.5, 1 / 6, .5), (0, 2 / 3, .5)]
        counts, edge = (7, 4, 4), 7 * d
    else:
        cells, a, basis = bases[kind]
        cell, counts, edge = d * a * np.ones(3), (cells,) * 3, cells * d * a
    sites = [(np.array(ijk) + b + np.array([0.13, 0.29, 0.41])) * cell
             for ijk in itertools.product(*map(range, counts)) for b in basis]
    return np.array(sites), edge


def lattice_files(work):
    rng = np.random.default_rng(63)
    h = 0.03
    files = []
    for kind in ("sc", "bcc", "fcc", "hcp"):
        for displaced in (False, True):
            positions, edge = lattice(kind, 1 + 2 * math.sqrt(3) * h + 1e-3 if displaced else 1.0)
            if displaced:
                positions = positions + rng.uniform(-h, h, positions.shape)
            path = f"{work}/{kind}{'-displaced' if displaced else ''}.txt"
            write_text_packing(path, positions, edge)
            files.append(path)
    return files


def sann_bonds(box, points, positions, box_length):
    """Each bond (i < j) once: SANN shells from float64 distances, union of both ends."""
    n = len(points)
    k = min(CANDIDATES, n - 1)
    query = freud.locality.AABBQuery(box, points)
    nlist = query.query(points, {"num_neighbors": k, "exclude_ii": True}).toNeighborList()
    i, j = nlist.query_point_indices.reshape(n, k), nlist.point_indices.reshape(n, k)
    vectors = positions[j] - positions[i]
    vectors -= box_length * np.rint(vectors / box_length)
    distances = np.linalg.norm(vectors, axis=2)
    order = np.argsort(distances, axis=1, kind="stable")
    distances, j = np.take_along_axis(distances, order, 1), np.take_along_axis(j, order, 1)
    m = np.arange(1, k + 1)
    with np.errstate(divide="ignore", invalid="ignore"):
        radius = np.cumsum(distances, axis=1) / (m - 2)
    closes = (m[None, :-1] >= 3) & (radius[:, :-1] < distances[:, 1:])
    if not closes.any(axis=1).all():
        sys.exit(f"a SANN shell does not close within {k} neighbours")
    shell = closes.argmax(axis=1) + 1
    pairs = {(min(a, b), max(a, b)) for a in range(n) for b in j[a, :shell[a]]}
    return np.array(sorted(pairs))


def freud_solid_liquid(box, points, positions, box_length, pairs):
    both = np.concatenate([pairs, pairs[:, ::-1]])
    both = both[np.lexsort((both[:, 1], both[:, 0]))]
    vectors = positions[both[:, 1]] - positions[both[:, 0]]
    vectors -= box_length * np.rint(vectors / box_length)
    nlist = freud.locality.NeighborList.from_arrays(
        len(points), len(points), both[:, 0], both[:, 1], vectors.astype(np.float32))
    solid_liquid = freud.order.SolidLiquid(L_DEGREE, BOND_THRESHOLD, SOLID_BONDS, normalize_q=True)
    solid_liquid.compute((box, points), neighbors=nlist)
    return solid_liquid, both


def sbanalyze_order(exe, packings, out):
    run = subprocess.run([exe, *packings, "--compute", "order", "--threads", "1", "--quiet",
                          "--out", out], capture_output=True, text=True)
    if run.returncode != 0:  # its warnings (the lattices have ordered) are expected otherwise
        sys.exit(f"sbanalyze failed ({run.returncode}):\n{run.stderr}")
    with h5py.File(out, "r") as results:
        return [{**dict(results[f"files/{k}/order"].attrs),
                 "crystal_bonds": results[f"files/{k}/order/crystal_bonds"][()]}
                for k in range(len(packings))]


def compare(name, ours, packing):
    positions, box_length = read_positions(packing)
    n = len(positions)
    box = freud.box.Box.cube(box_length)
    points = box.wrap(positions - box_length / 2).astype(np.float32)
    pairs = sann_bonds(box, points, positions, box_length)
    solid_liquid, both = freud_solid_liquid(box, points, positions, box_length, pairs)
    theirs = solid_liquid.num_connections.astype(int)
    xi = ours["crystal_bonds"].astype(int)
    near = np.abs(solid_liquid.ql_ij - BOND_THRESHOLD) < FLOAT32_BAND
    allowed = np.bincount(both[near, 0], minlength=n)
    solid, freud_solid = xi >= SOLID_BONDS, theirs >= SOLID_BONDS
    clusters = solid_liquid.cluster_idx[freud_solid]
    freud_largest = np.bincount(clusters).max() if len(clusters) else 0
    checks = {
        "SANN bonds per particle": abs(2 * len(pairs) / n - ours["sann_neighbours_mean"]) < 1e-12,
        "xi(i) = num_connections": bool(np.all(np.abs(xi - theirs) <= allowed)),
        "solid-like particles": bool(np.all(allowed[solid != freud_solid] > 0)),
        "largest cluster": int(ours["crystal_cluster"]) == freud_largest or bool(allowed.any()),
    }
    print(f"{name}: N {n}, SANN {2 * len(pairs) / n:.3f} per particle; solid-like "
          f"{solid.sum()} (freud {freud_solid.sum()}), same particles "
          f"{'yes' if np.all(solid == freud_solid) else 'NO'}; xi differs at "
          f"{int(np.sum(xi != theirs))} ({int(near.sum()) // 2} bonds within {FLOAT32_BAND:g} "
          f"of {BOND_THRESHOLD}); largest cluster {int(ours['crystal_cluster'])} (freud "
          f"{freud_largest}); solid_like_fraction {float(ours['solid_like_fraction']):.4f}")
    failed = [check for check, ok in checks.items() if not ok]
    for check in failed:
        print(f"  FAIL {check}")
    return failed


def read_positions(path):
    """Positions (float64) and box edge of an HDF5 or text packing."""
    if path.endswith(".h5"):
        with h5py.File(path, "r") as packing:
            return packing["positions"][()].astype(np.float64), float(packing.attrs["box_length"])
    with open(path) as text:
        header = dict(line.split()[1:] for line in text
                      if line.startswith("# ") and len(line.split()) == 3)
    return np.loadtxt(path, comments="#")[:, :3], float(header["box_length"])


def main():
    args = parse_args()
    freud.parallel.set_num_threads(1)
    packings = list(args.packings) + (lattice_files(args.work) if args.lattices else [])
    results = sbanalyze_order(args.sbanalyze, packings, f"{args.work}/solid_like.h5")
    print(f"# solid-like particles: sbanalyze against freud {freud.__version__}.order.SolidLiquid"
          f"(l = {L_DEGREE}, q_threshold = {BOND_THRESHOLD}, solid_threshold = {SOLID_BONDS}, "
          f"normalize_q = True) over the same SANN bonds")
    failures = []
    for packing, ours in zip(packings, results):
        failures += compare(packing.split("/")[-1], ours, packing)
    print("all checks pass" if not failures else f"FAILED: {len(failures)} checks")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
