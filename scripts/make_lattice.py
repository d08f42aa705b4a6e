#!/usr/bin/env python3
"""Writes a lattice packing of aligned superballs in sbpack's text format.

Simple-cubic (sc) lattices of aligned superballs touch face to face at lattice constant
2R for every p, so Z = 6 and no rattlers: a small scene with a known answer.
usage: make_lattice.py P CELLS OUT.txt [--fcc]   (fcc: spheres only, Z = 12)
"""
import math
import sys


def main():
    p, cells, out = float(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    fcc = "--fcc" in sys.argv
    r = 0.5
    basis = [(0, 0, 0)]
    a = 2 * r
    if fcc:
        basis = [(0, 0, 0), (0.5, 0.5, 0), (0.5, 0, 0.5), (0, 0.5, 0.5)]
        a = 2 * r * math.sqrt(2)
    box = a * cells
    sites = [((i + bx) * a, (j + by) * a, (k + bz) * a)
             for i in range(cells) for j in range(cells) for k in range(cells)
             for bx, by, bz in basis]
    with open(out, "w") as f:
        f.write("# sbpack text packing v1\n")
        f.write(f"# p {p!r}\n# semi_axis {r!r}\n# box_length {box!r}\n")
        f.write(f"# n_particles {len(sites)}\n")
        for x, y, z in sites:
            f.write(f"{x!r} {y!r} {z!r} 1 0 0 0\n")


if __name__ == "__main__":
    main()
