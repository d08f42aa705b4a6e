#!/usr/bin/env python3
"""Writes a dense disordered test packing in sbpack's text format (for benchmarks and tests).

An fcc lattice of 4 CELLS^3 sites with random vacancies down to N particles, each moved by a
random displacement and given a uniformly random orientation, in a box sized for packing
fraction PHI. Displacements stay below half the gap between the circumscribed spheres, so no
two particles overlap; PHI must therefore be at most 0.7405 v1 / (4/3 pi rc^3) (0.74 for
spheres, 0.58 for p = 1.5). Not a jammed packing: a stand-in until sbgen produces MRJ ones.
usage: make_test_packing.py P N PHI SEED OUT.txt
"""
import math
import random
import sys


def superball_volume(p, r):
    g = math.gamma
    return 8 * r**3 * g(1 + 1 / (2 * p)) ** 3 / g(1 + 3 / (2 * p))


def circumradius(p, r):
    return r * max(1.0, 3 ** (0.5 - 1 / (2 * p)))


def random_quaternion(rng):
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(c * c for c in q))
    return [c / n for c in q]


def main():
    p, n, phi, seed, out = float(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), int(
        sys.argv[4]), sys.argv[5]
    rng = random.Random(seed)
    r = 0.5
    cells = math.ceil((n / 4) ** (1 / 3))
    box = (n * superball_volume(p, r) / phi) ** (1 / 3)
    a = box / cells
    nearest = a / math.sqrt(2)
    gap = nearest - 2 * circumradius(p, r)
    if gap <= 0:
        sys.exit(f"phi = {phi} is too dense for non-overlapping circumscribed spheres at p = {p}")
    basis = [(0, 0, 0), (0.5, 0.5, 0), (0.5, 0, 0.5), (0, 0.5, 0.5)]
    sites = [((i + bx) * a, (j + by) * a, (k + bz) * a) for i in range(cells)
             for j in range(cells) for k in range(cells) for bx, by, bz in basis]
    sites = rng.sample(sites, n)
    jitter = 0.499 * gap
    with open(out, "w") as f:
        f.write("# sbpack text packing v1\n")
        f.write(f"# p {p!r}\n# semi_axis {r!r}\n# box_length {box!r}\n# n_particles {n}\n")
        f.write(f"# make_test_packing.py {p} {n} {phi} {seed}\n")
        for x, y, z in sites:
            while True:  # uniform in the ball of radius `jitter`
                d = [rng.uniform(-1, 1) for _ in range(3)]
                if sum(c * c for c in d) <= 1:
                    break
            pos = [(c + jitter * dc) % box for c, dc in zip((x, y, z), d)]
            q = random_quaternion(rng)
            f.write(" ".join(repr(v) for v in pos + q) + "\n")


if __name__ == "__main__":
    main()
