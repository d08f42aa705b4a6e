#!/usr/bin/env python3
"""Reprocesses the stored packings with a new contact tolerance: Z and the rattler fraction at the
paper's gap < 1e-10 D and at a looser one (sbanalyze --compute contacts --tolerance T).

By default the jammed MRJ packings of data/ (mrj-*.h5, compressed to reduced pressure 1e12, where
the load-bearing gaps are below 1e-10 D). Where a tolerance cuts through the load-bearing gaps of
a packing (one compressed less far, or not jammed), Z and phi_R are undetermined: the row says so
and gives the tolerance T the packing needs (tolerance_needed), instead of nan, and the
engine's RuntimeWarning gives the distribution of its gaps.

usage: PYTHONPATH=build/python python3 examples/reprocess_contacts.py [--tolerance T] [FILE.h5...]
"""
import argparse
import glob
import os

import sbpack

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")


def columns(c):
    """Z and phi_R of a computed Contacts, or why they are undetermined."""
    if c.resolved == 0:
        return f"{'undetermined (needs T >= ' + format(c.tolerance_needed, '.1e') + ')':>22}"
    return f"{c.z_mean:8.4f}  {c.rattler_fraction:12.4f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*",
                        default=sorted(glob.glob(os.path.join(DATA, "mrj-*.h5"))))
    parser.add_argument("--tolerance", type=float, default=1e-6)
    args = parser.parse_args()
    paper, loose = sbpack.Contacts(), sbpack.Contacts(tolerance=args.tolerance)
    print(f"{'packing':24} {'p':>5} {'N':>5}   Z(1e-10)  phi_R(1e-10)   "
          f"Z({args.tolerance:g})  phi_R({args.tolerance:g})")
    for path in args.files:
        packing = sbpack.Packing.read(path)
        a, b = paper.compute(packing), loose.compute(packing)  # unresolved: the engine warns
        print(f"{os.path.basename(path):24} {packing.p:5g} {len(packing):5d}   {columns(a)}   "
              f"{columns(b)}")


if __name__ == "__main__":
    main()
