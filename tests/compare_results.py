#!/usr/bin/env python3
"""Compares two sbanalyze results files entry by entry (docs/scale-out.md, the MPI tests).

    compare_results.py A.h5 B.h5 [--rtol R]

Every group, attribute and dataset must be present in both and equal: bit for bit by default,
or within the relative tolerance R (numbers only). Left out: what differs between any two runs
or between process layouts by design: wall-clock times (units "s"), the run's `threads`, `ranks`
and `distribute`, and the figures of a distributed grid (`ranks`, `slab`,
`memory_per_rank_bytes`, `communication_bytes`) and `memory_bytes` of a voxel slab.
Prints "results equal: N entries" or each difference, and exits 1 on any.
"""
import sys

import h5py
import numpy as np

RUN_ONLY = {"threads", "ranks", "distribute"}
LAYOUT = {"ranks", "slab", "memory_per_rank_bytes", "communication_bytes", "memory_bytes"}


def seconds(attrs, name):
    units = attrs.get(name + "_units", attrs.get("units", b""))
    return (units.decode() if isinstance(units, bytes) else units) == "s"


def same(a, b, rtol):
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype.kind != b.dtype.kind:
        return False
    if a.dtype.kind not in "fiu" or rtol == 0.0:
        return a.tobytes() == b.tobytes()
    return bool(np.all((a == b) | (np.abs(a - b) <= rtol * np.maximum(np.abs(a), np.abs(b)))))


def walk(a, b, path, rtol, problems):
    count = 0
    skip = LAYOUT | (RUN_ONLY if path == "/" else set())
    for name in sorted(set(a.attrs) | set(b.attrs)):
        if name.endswith("_units") or name in skip or seconds(a.attrs, name):
            continue
        count += 1
        if name not in a.attrs or name not in b.attrs:
            problems.append(f"{path}@{name}: only in one file")
        elif not same(a.attrs[name], b.attrs[name], rtol):
            problems.append(f"{path}@{name}: {a.attrs[name]} != {b.attrs[name]}")
    for name in sorted(set(a) | set(b)):
        if name not in a or name not in b:
            problems.append(f"{path}{name}: only in one file")
        elif isinstance(a[name], h5py.Group):
            count += walk(a[name], b[name], f"{path}{name}/", rtol, problems)
        elif not seconds(a[name].attrs, "units"):
            count += 1
            if not same(a[name][()], b[name][()], rtol):
                problems.append(f"{path}{name}: datasets differ")
    return count


def main(argv):
    rtol = float(argv[argv.index("--rtol") + 1]) if "--rtol" in argv else 0.0
    problems = []
    with h5py.File(argv[1]) as a, h5py.File(argv[2]) as b:
        count = walk(a, b, "/", rtol, problems)
    for p in problems:
        print("DIFFERENT", p)
    if problems or count == 0:
        return 1
    print(f"results equal: {count} entries" + (f" (rtol {rtol})" if rtol else " (bit for bit)"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
