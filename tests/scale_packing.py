#!/usr/bin/env python3
"""Writes a packing with every length times a factor (docs/reliability.md, "Units").

    scale_packing.py IN.h5 OUT.h5 FACTOR

OUT is IN with positions, velocities, semi_axis and box_length times FACTOR (phi, p, the
orientations, the pressure and the provenance as they are): the same packing in other units,
e.g. grains of 1.5 mm in metres from one of D = 1.5 (FACTOR 1e-3).
"""
import shutil
import sys

import h5py


def main(argv):
    source, target, factor = argv[1], argv[2], float(argv[3])
    shutil.copyfile(source, target)
    with h5py.File(target, "r+") as f:
        for name in ("semi_axis", "box_length"):
            f.attrs[name] = f.attrs[name] * factor
        for name in ("positions", "velocities"):
            if name in f:
                f[name][...] = f[name][()] * factor
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
