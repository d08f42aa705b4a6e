"""Cross-check of sbanalyze --compute order against the peer freud, and their speed (issue 44).

    bash bench/order_vs_freud.sh [SBANALYZE] [PACKING]        (sets up freud's venv, runs this)
    VENV/bin/python bench/order_vs_freud.py SBANALYZE PACKING [--repeats 5] [--work DIR]

On one packing, over the same pairs (minimum image in the periodic box), it compares sbanalyze's
results group `order` (docs/results-schema.md; definitions in docs/order-metrics.md) with

- freud.order.Steinhardt(l = 4, 6, average=False) over the bonds shorter than sbanalyze's
  cutoff_w * w (neighbours {'mode': 'ball', 'r_max': cutoff}): the per-particle q6 against the
  dataset q6_local, the means against q4_local_mean and q6_local_mean, the system-wide `order`
  against Q4 and Q6;
- freud.density.RDF (normalization_mode 'exact') with sbanalyze's bins against g2.

freud works in single precision (positions, distances and Y_lm are float32), so it agrees to
about 1e-5, not 1e-12. A float64 reference computed here without Y_lm (by the addition theorem,
steinhardt_reference) checks sbanalyze's q_l(i) and Q_l to 1e-12. Timing: sbanalyze's wall time
(process, file reading and the contact network included) and its own runtime_s of the group,
against freud's neighbour query, Steinhardt and RDF, all on one thread, median of the repetitions,
run alternately.

The run fails (exit status 1) when a check misses its tolerance (TOLERANCES).
"""
import argparse
import math
import statistics
import subprocess
import sys
import time

import freud
import h5py
import numpy as np
from numpy.polynomial import legendre

LS = (4, 6)

# What "equal" means. freud computes in float32: q_l(i) to a few 1e-6, g2 to float32 rounding.
TOLERANCES = {
    "q_freud": 5e-5,       # |q_l(i) freud - q_l(i) sbanalyze or reference|, absolute
    "q_double": 1e-12,     # |q_l(i) and mean q_l sbanalyze - reference|, absolute
    "Q_double": 1e-9,      # |Q_l sbanalyze - reference| / Q_l
    "Q_freud": 1e-4,       # |Q_l from freud's q_lm(i), bond-weighted - Q_l sbanalyze| / Q_l
    "g2_freud": 1e-4,      # |g2 / pairs, freud - sbanalyze| / (g2 / pairs): the normalisation
    #                        (freud's V_b from float32 edges: 2^-24 r / dr is 1e-5 at 3 w)
    "g2_count": 1e-6,      # |g2 N rho V_b - integer|: sbanalyze's g2 is Eq. 1.1 of a count
}
# Pairs closer than this (in w) to a bin edge or to the cutoff may fall on either side in float32:
# coordinates up to L / 2 = 12 carry 1e-6 of rounding.
EDGE_BAND_W = 1e-5
# freud finds the candidate pairs up to r_max (1 + margin); their distances are taken in float64.
QUERY_MARGIN = 1e-4


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("sbanalyze")
    parser.add_argument("packing")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--work", default="/tmp", help="where sbanalyze writes its results file")
    return parser.parse_args()


def run_sbanalyze(exe, packing, out):
    """One run of `sbanalyze PACKING --compute order --threads 1`: wall time and the results."""
    command = [exe, packing, "--compute", "order", "--threads", "1", "--quiet", "--out", out]
    start = time.perf_counter()
    subprocess.run(command, check=True)
    wall = time.perf_counter() - start
    with h5py.File(out, "r") as results:
        group = results["files/0/order"]
        result = {name: group.attrs[name] for name in group.attrs}
        result.update({name: group[name][()] for name in group})
        result["mean_width"] = results["files/0"].attrs["mean_width"]
        result["threads"] = results.attrs["threads"]
        result["version"] = results.attrs["sbanalyze_version"]
        result["contacts_runtime_s"] = results["files/0/contacts"].attrs["runtime_s"]
        result["run_runtime_s"] = results.attrs["runtime_s"]
    result["wall_s"] = wall
    return result


def exact_pairs(query, positions, box_length, r_max):
    """Ordered pairs (i, j), i != j, with |r_j - r_i| < r_max by minimum image, in double.

    freud finds the candidates (float32, a margin beyond r_max); vectors and distances are then
    taken from the float64 positions.
    """
    args = {"mode": "ball", "r_max": r_max * (1 + QUERY_MARGIN), "exclude_ii": True}
    candidates = query.query(query.points, args).toNeighborList()
    i, j = candidates.query_point_indices, candidates.point_indices
    vectors = positions[j] - positions[i]
    vectors -= box_length * np.rint(vectors / box_length)
    distances = np.sqrt(np.einsum("ij,ij->i", vectors, vectors))
    keep = distances < r_max
    return i[keep], j[keep], vectors[keep], distances[keep]


def steinhardt_reference(i, vectors, distances, n):
    """Local q_l(i) (Eq. 2.2) and global Q_l (Eq. 2.1) in float64, without Y_lm.

    By the addition theorem (docs/order-metrics.md §2),
    sum_m |sum_a Y_lm(u_a)|^2 = (2l + 1) / (4 pi) sum_ab P_l(u_a . u_b), so
    q_l(i)^2 = sum_ab P_l(u_a . u_b) / N_b(i)^2 over the bonds a, b of i. With
    P_l(x) = sum_k c_k x^k and (u . v)^k = sum_{|alpha| = k} k! / alpha! u^alpha v^alpha, the double
    sum is sum_k c_k sum_alpha k! / alpha! (sum_a u_a^alpha)^2: monomial sums per particle.
    Q_l is the same over all ordered bonds of the system together.
    """
    units = vectors / distances[:, None]
    bonds = np.bincount(i, minlength=n).astype(float)
    local, total = {}, {}
    for ell in LS:
        per_particle, system = np.zeros(n), 0.0
        for k, coefficient in enumerate(legendre.leg2poly([0] * ell + [1])):
            if coefficient == 0:
                continue
            for a in range(k + 1):
                for b in range(k + 1 - a):
                    c = k - a - b
                    weight = coefficient * math.factorial(k) / (
                        math.factorial(a) * math.factorial(b) * math.factorial(c))
                    monomial = units[:, 0] ** a * units[:, 1] ** b * units[:, 2] ** c
                    sums = np.bincount(i, weights=monomial, minlength=n)
                    per_particle += weight * sums * sums
                    system += weight * sums.sum() ** 2
        with np.errstate(invalid="ignore", divide="ignore"):
            local[ell] = np.sqrt(np.maximum(per_particle, 0)) / bonds
        total[ell] = math.sqrt(max(system, 0)) / bonds.sum()
    return local, total, bonds


def freud_order(box, points, cutoff, nbins, r_max):
    """freud's neighbour query, Steinhardt (l = 4, 6) and RDF, each timed."""
    start = time.perf_counter()
    query = freud.locality.AABBQuery(box, points)
    bonds = query.query(points, {"mode": "ball", "r_max": cutoff, "exclude_ii": True})
    neighbours = bonds.toNeighborList()
    after_query = time.perf_counter()
    steinhardt = freud.order.Steinhardt(list(LS))
    steinhardt.compute(query, neighbors=neighbours)
    after_steinhardt = time.perf_counter()
    rdf = freud.density.RDF(nbins, r_max)
    rdf.compute(query)
    end = time.perf_counter()
    seconds = {"neighbours": after_query - start, "steinhardt": after_steinhardt - after_query,
               "rdf": end - after_steinhardt, "total": end - start}
    return query, neighbours, steinhardt, rdf, seconds


def near_edges(distances_w, edges_w):
    """Pairs within EDGE_BAND_W of each edge (uniformly spaced edges starting at 0)."""
    spacing = edges_w[1] - edges_w[0]
    nearest = np.rint(distances_w / spacing).astype(int)
    near = (np.abs(distances_w - nearest * spacing) < EDGE_BAND_W) & (nearest < len(edges_w))
    return np.bincount(nearest[near], minlength=len(edges_w))


def first_minimum(r_w, g2, half_width=2):
    """docs/order-metrics.md §1 (firstMinimum): the first local minimum below 1 of the moving
    average after its global maximum; the middle of a run of equal values. None if there is none."""
    n = len(g2)
    smooth = np.array([np.mean(g2[max(0, b - half_width):b + half_width + 1]) for b in range(n)])
    b = int(np.argmax(smooth)) + 1
    while b < n:
        if smooth[b] < 1 and smooth[b] <= smooth[b - 1]:
            end = b
            while end + 1 < n and smooth[end + 1] == smooth[b]:
                end += 1
            if end + 1 < n and smooth[end + 1] > smooth[b]:
                return 0.5 * (r_w[b] + r_w[end])
            b = end
        b += 1
    return None


class Checks:
    """Prints one pass/fail line per check and keeps the names of those that failed."""

    def __init__(self):
        self.failures = []

    def check(self, name, value, tolerance):
        ok = bool(value <= tolerance)
        print(f"  {'ok  ' if ok else 'FAIL'} {name}: {value:.3g} (tolerance {tolerance:g})")
        if not ok:
            self.failures.append(name)


def median_line(values):
    return (f"{statistics.median(values):.4f} s (min {min(values):.4f}, max {max(values):.4f}, "
            f"{len(values)} runs)")


def main():
    args = parse_args()
    freud.parallel.set_num_threads(1)
    out = f"{args.work}/order.h5"
    checks = Checks()

    with h5py.File(args.packing, "r") as packing:
        positions = packing["positions"][()].astype(np.float64)
        box_length = float(packing.attrs["box_length"])
        semi_axis = float(packing.attrs["semi_axis"])
        p = float(packing.attrs["p"])
    n = len(positions)
    box = freud.box.Box.cube(box_length)
    points = box.wrap(positions - box_length / 2).astype(np.float32)

    # Untimed first runs (page cache, imports), then the timed ones, alternately.
    ours = run_sbanalyze(args.sbanalyze, args.packing, out)
    width = float(ours["mean_width"])
    if "cutoff_w" not in ours:
        sys.exit("sbanalyze found no first minimum of g2 (no cutoff_w): nothing to compare")
    cutoff = float(ours["cutoff_w"]) * width
    dr_w = float(ours["g2_bin_width_w"])
    nbins = len(ours["g2"])
    r_max = nbins * dr_w * width
    freud_order(box, points, cutoff, nbins, r_max)
    walls, runtimes, runs, freud_seconds = [], [], [], []
    for _ in range(args.repeats):
        ours = run_sbanalyze(args.sbanalyze, args.packing, out)
        walls.append(ours["wall_s"])
        runtimes.append(float(ours["runtime_s"]))
        runs.append(float(ours["run_runtime_s"]))
        query, neighbours, steinhardt, rdf, seconds = freud_order(box, points, cutoff, nbins,
                                                                  r_max)
        freud_seconds.append(seconds)

    print(f"# sbanalyze --compute order against freud: {args.packing}")
    print(f"sbanalyze {ours['version']} ({args.sbanalyze}, threads {ours['threads']}); "
          f"freud {freud.__version__}, numpy {np.__version__}, h5py {h5py.__version__}, "
          f"python {sys.version.split()[0]}; freud on 1 thread")
    print(f"N = {n}, p = {p:g}, L = {box_length:.6f}, w = {width:.6f} (2 semi_axis = "
          f"{2 * semi_axis:.6f}), cutoff_w = {ours['cutoff_w']:g}, g2: {nbins} bins of "
          f"{dr_w:g} w up to {nbins * dr_w:g} w")

    # --- g2 -------------------------------------------------------------------------------------
    i, j, vectors, distances = exact_pairs(query, positions, box_length, r_max)
    edges_w = np.arange(nbins + 1) * dr_w
    shell = 4 * math.pi / 3 * (edges_w[1:] ** 3 - edges_w[:-1] ** 3) * width ** 3
    per_g2 = n * (n / box_length ** 3) * shell      # Eq. 1.1: ordered pairs 2 n_b = g2 N rho V_b
    ours_exact = ours["g2"] * per_g2
    ours_counts = np.rint(ours_exact).astype(np.int64)
    reference_counts = np.bincount(np.floor(distances / (dr_w * width)).astype(np.int64),
                                   minlength=nbins)[:nbins]
    freud_counts = rdf.bin_counts.astype(np.int64)
    # A pair within EDGE_BAND_W of an edge may land on either side of it in float32: below each
    # edge, freud's cumulative count may differ from sbanalyze's by at most those pairs.
    band = near_edges(distances / width, edges_w)
    crossed = np.cumsum(freud_counts) - np.cumsum(ours_counts)
    counted = freud_counts > 0
    normalisation = np.abs(rdf.rdf[counted] / freud_counts[counted]
                           / (ours["g2"][counted] / ours_counts[counted]) - 1)
    difference = np.abs(rdf.rdf - ours["g2"])
    worst = int(np.argmax(difference))
    equal = freud_counts == ours_counts
    print("\n## g2 (freud.density.RDF, normalization_mode 'exact': ordered pairs / (N rho V_b))")
    print(f"  pairs below {nbins * dr_w:g} w: {len(distances) // 2} (float64), "
          f"{freud_counts.sum() // 2} (freud), {ours_counts.sum() // 2} (sbanalyze); bin centres: "
          f"max |freud / w - r_w| = {np.abs(rdf.bin_centers / width - ours['r_w']).max():.2g}")
    print(f"  max |g2 freud - g2 sbanalyze| = {difference[worst]:.6g} at r = "
          f"{ours['r_w'][worst]:g} w (freud {rdf.rdf[worst]:.6g}, sbanalyze "
          f"{ours['g2'][worst]:.6g}); in the {equal.sum()} of {nbins} bins with equal counts: "
          f"{difference[equal].max():.3g}; g2 per pair, all bins: relative "
          f"{np.max(normalisation):.3g}")
    for edge in np.nonzero(crossed)[0] + 1:
        below = np.sum((distances / width < edges_w[edge])
                       & (distances / width > edges_w[edge] - EDGE_BAND_W)) // 2
        print(f"  edge {edges_w[edge]:g} w: freud has {crossed[edge - 1] // 2:+d} pairs below it "
              f"(of {band[edge] // 2} within {EDGE_BAND_W:g} w of it, {below} below it in "
              f"float64)")
    checks.check("g2 sbanalyze, |2 n_b - integer| (Eq. 1.1)",
                 np.abs(ours_exact - ours_counts).max(), TOLERANCES["g2_count"])
    checks.check("g2 sbanalyze - float64 reference, pairs per bin",
                 np.abs(ours_counts - reference_counts).max(), 0)
    checks.check("g2 freud - sbanalyze, pairs across an edge beyond those near it",
                 np.max(np.abs(crossed) - band[1:]), 0)
    checks.check("g2 freud - sbanalyze, relative, per pair (the normalisation)",
                 np.max(normalisation), TOLERANCES["g2_freud"])
    ours_minimum = first_minimum(ours["r_w"], ours["g2"])
    freud_minimum = first_minimum(ours["r_w"], rdf.rdf.astype(np.float64))
    print(f"  first minimum by §1's rule (re-implemented here): {ours_minimum} w on sbanalyze's "
          f"g2, {freud_minimum} w on freud's")
    checks.check("first minimum of sbanalyze's g2 - cutoff_w",
                 math.inf if ours_minimum is None
                 else abs(ours_minimum - float(ours["cutoff_w"])), 1e-12)

    # --- the bonds ------------------------------------------------------------------------------
    bonded = distances < cutoff
    i, j, vectors, distances = i[bonded], j[bonded], vectors[bonded], distances[bonded]
    near_cutoff = int(np.sum(np.abs(distances / width - ours["cutoff_w"]) < EDGE_BAND_W)) // 2
    same = np.array_equal(np.sort(i * n + j),
                          np.sort(neighbours.query_point_indices * n + neighbours.point_indices))
    print(f"\n## Bonds shorter than cutoff_w w = {cutoff:.6f}: {len(i)} ordered (both ends), "
          f"{near_cutoff} pairs within {EDGE_BAND_W:g} w of the cutoff; freud's ball query "
          f"{'gives the same' if same else 'DIFFERS from the float64'} list")
    if not same:
        order = np.lexsort((j, i))
        neighbours = freud.locality.NeighborList.from_arrays(
            n, n, i[order], j[order], vectors[order].astype(np.float32))
        steinhardt = freud.order.Steinhardt(list(LS))
        steinhardt.compute((box, points), neighbors=neighbours)
        print("  (Steinhardt recomputed by freud over the float64 list, freud.locality."
              "NeighborList.from_arrays)")

    # --- local q_l ------------------------------------------------------------------------------
    local, total, bonds = steinhardt_reference(i, vectors, distances, n)
    freud_q = {ell: steinhardt.particle_order[:, k].astype(np.float64)
               for k, ell in enumerate(LS)}
    unbonded = int(np.sum(bonds == 0))
    has = bonds > 0
    print(f"\n## Local q_l(i) (Eq. 2.2; freud Steinhardt average=False), {has.sum()} particles "
          f"with bonds, {unbonded} without (NaN), {bonds.min():.0f}-{bonds.max():.0f} bonds each")
    ours_q6 = ours["q6_local"]
    print(f"  q6: max |freud - sbanalyze| = {np.abs(freud_q[6] - ours_q6)[has].max():.3g} "
          f"(relative {np.max(np.abs(freud_q[6] - ours_q6)[has] / ours_q6[has]):.3g}); "
          f"max |sbanalyze - float64 reference| = {np.abs(ours_q6 - local[6])[has].max():.3g}")
    checks.check("q6(i) freud - sbanalyze", np.abs(freud_q[6] - ours_q6)[has].max(),
                 TOLERANCES["q_freud"])
    checks.check("q4(i) freud - float64 reference (sbanalyze writes no q4(i))",
                 np.abs(freud_q[4] - local[4])[has].max(), TOLERANCES["q_freud"])
    checks.check("q6(i) sbanalyze - float64 reference", np.abs(ours_q6 - local[6])[has].max(),
                 TOLERANCES["q_double"])
    checks.check("q6(i) NaN exactly where there is no bond",
                 float(np.any(np.isnan(ours_q6) != ~has)), 0)
    for ell in LS:
        ours_mean = float(ours[f"q{ell}_local_mean"])
        freud_mean = float(np.mean(freud_q[ell][has]))
        print(f"  mean q{ell}: sbanalyze {ours_mean:.12f}, freud {freud_mean:.12f} "
              f"(difference {freud_mean - ours_mean:+.2g}), float64 reference "
              f"{np.mean(local[ell][has]):.12f}")
        checks.check(f"mean q{ell} freud - sbanalyze", abs(freud_mean - ours_mean),
                     TOLERANCES["q_freud"])
        checks.check(f"mean q{ell} sbanalyze - float64 reference",
                     abs(ours_mean - np.mean(local[ell][has])), TOLERANCES["q_double"])

    # --- global Q_l -----------------------------------------------------------------------------
    # freud's `order` is |(1/N) sum_i q_lm(i)| (each q_lm(i) already divided by the particle's
    # own bond weight, so no choice of bond weights changes the particle average); Eq. 2.1 weighs
    # particle i by N_b(i). freud's q_lm(i) weighted by N_b(i) is Eq. 2.1.
    weighted = freud.order.Steinhardt(list(LS), weighted=True)
    weighted.compute((box, points), neighbors=neighbours)
    print("\n## Global Q_l (Eq. 2.1: Y_lm averaged over all bonds, each from both ends)")
    for k, ell in enumerate(LS):
        ours_global = float(ours[f"Q{ell}"])
        harmonics = np.asarray(steinhardt.particle_harmonics[k], dtype=np.complex128)
        qlm = (harmonics * bonds[:, None])[has].sum(axis=0) / bonds.sum()
        by_bonds = math.sqrt(4 * math.pi / (2 * ell + 1) * np.sum(np.abs(qlm) ** 2))
        particle_mean = float(steinhardt.order[k])
        print(f"  Q{ell}: sbanalyze {ours_global:.10f}, float64 reference {total[ell]:.10f}; "
              f"freud's q_lm(i) weighted by N_b(i) {by_bonds:.10f}; freud `order` "
              f"(particle average) {particle_mean:.10f} (weighted=True, unit weights: "
              f"{float(weighted.order[k]):.10f}), {particle_mean - ours_global:+.3g} "
              f"({(particle_mean - ours_global) / ours_global:+.2%}) from sbanalyze")
        checks.check(f"Q{ell} sbanalyze - float64 reference, relative",
                     abs(ours_global - total[ell]) / total[ell], TOLERANCES["Q_double"])
        checks.check(f"Q{ell} freud q_lm(i) weighted by N_b(i) - sbanalyze, relative",
                     abs(by_bonds - ours_global) / ours_global, TOLERANCES["Q_freud"])
    print(f"  bonds per particle: mean {bonds[has].mean():.3f}, standard deviation "
          f"{bonds[has].std():.3f}")
    if freud_minimum is not None and abs(freud_minimum - float(ours["cutoff_w"])) > 1e-12:
        other = freud.order.Steinhardt(list(LS))
        other.compute(query, neighbors={"mode": "ball", "r_max": freud_minimum * width,
                                        "exclude_ii": True})
        print(f"  with the cutoff {freud_minimum} w of freud's g2 instead: mean q4 "
              f"{np.mean(other.particle_order[:, 0]):.4f}, mean q6 "
              f"{np.mean(other.particle_order[:, 1]):.4f}, Q4 {other.order[0]:.4f}, "
              f"Q6 {other.order[1]:.4f} (freud's particle average)")

    # --- timing ---------------------------------------------------------------------------------
    def part(name):
        return [seconds[name] for seconds in freud_seconds]
    sbanalyze_wall = statistics.median(walls)
    sbanalyze_runtime = statistics.median(runtimes)
    freud_total = statistics.median(part("total"))
    print("\n## Time on one thread (median; sbanalyze and freud run alternately)")
    print(f"  sbanalyze wall (process, reading, contacts, order): {median_line(walls)}")
    print(f"  sbanalyze runtime_s of the run (no process start):  {median_line(runs)}")
    print(f"  sbanalyze runtime_s of the group order:            {median_line(runtimes)} "
          f"(contacts before it: {float(ours['contacts_runtime_s']):.4f} s)")
    for name in ("neighbours", "steinhardt", "rdf"):
        print(f"  freud {name:<44} {median_line(part(name))}")
    print(f"  freud total (neighbour query, Steinhardt, RDF):    {median_line(part('total'))}")
    print(f"  ratio: sbanalyze wall / freud {sbanalyze_wall / freud_total:.2f}, "
          f"sbanalyze runtime_s / freud {sbanalyze_runtime / freud_total:.2f}")

    print(f"\n{'FAILED: ' + ', '.join(checks.failures) if checks.failures else 'all checks pass'}")
    return 1 if checks.failures else 0


if __name__ == "__main__":
    sys.exit(main())
