#!/usr/bin/python3
"""Copies sbgen packings for keeping: the root attributes, positions, orientations and the
provenance group, without velocities and the resume state (a tenth of the size; sbanalyze reads
the copy as it reads the original: those two are optional, docs/packing-schema.md).

usage: /usr/bin/python3 scripts/store_packing.py OUTDIR PACKING.h5 [PACKING.h5 ...]
"""
import os
import sys

import h5py


def store(source, target):
    with h5py.File(source, "r") as inp, h5py.File(target + ".tmp", "w") as out:
        for key, value in inp.attrs.items():
            out.attrs[key] = value
        for name in ("positions", "orientations"):
            out.create_dataset(name, data=inp[name][:])
        inp.copy("provenance", out)
    os.replace(target + ".tmp", target)


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__.strip())
    os.makedirs(argv[1], exist_ok=True)
    for source in argv[2:]:
        store(source, os.path.join(argv[1], os.path.basename(source)))


if __name__ == "__main__":
    main(sys.argv)
