#!/usr/bin/env python3
"""Reprocesses the stored packings with a new contact tolerance: Z and the rattler fraction at the
paper's gap < 1e-10 D and at a looser one (sbanalyze --compute contacts --tolerance T).

usage: PYTHONPATH=build/python python3 examples/reprocess_contacts.py [--tolerance T] [FILE.h5...]
"""
import argparse
import glob
import os

import sbpack

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", default=sorted(glob.glob(os.path.join(DATA, "*.h5"))))
    parser.add_argument("--tolerance", type=float, default=1e-6)
    args = parser.parse_args()
    paper, loose = sbpack.Contacts(), sbpack.Contacts(tolerance=args.tolerance)
    print(f"{'packing':24} {'p':>5} {'N':>5}   Z(1e-10)  phi_R(1e-10)   "
          f"Z({args.tolerance:g})  phi_R({args.tolerance:g})")
    for path in args.files:
        packing = sbpack.Packing.read(path)
        a, b = paper.compute(packing), loose.compute(packing)
        print(f"{os.path.basename(path):24} {packing.p:5g} {len(packing):5d}   {a.z_mean:8.4f}  "
              f"{a.rattler_fraction:12.4f}   {b.z_mean:8.4f}  {b.rattler_fraction:12.4f}")


if __name__ == "__main__":
    main()
