#!/usr/bin/env python3
"""Compares two sbanalyze results files entry by entry (docs/scale-out.md, the MPI tests).

    compare_results.py A.h5 B.h5 [--rtol R] [--scale S]

Every group, attribute and dataset must be present in both and equal: bit for bit by default,
or within the relative tolerance R (numbers only). --scale S: B is of the packings of A with
every length times S (tests/scale_packing.py, docs/reliability.md "Units"): B's values are
compared in A's units, divided by S^k for units length^k (1/length: k = -1, time: k = 2),
integers (voxel counts, contacts, shells) bit for bit, and `input` (the file name) is left out;
two values both below R w^k (w: the file's or ensemble's mean_width) are zero to that precision
and equal (pore_size/error_bound, a certificate of rounding, is about 1e-14 w either way). Left out: what differs between any two runs
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


# The power of the length in each dimensional unit of the results schema (schema::unitFactor).
LENGTH_POWER = {"length": 1, "length^2": 2, "length^3": 3, "1/length": -1, "time": 2}


def units_of(attrs, name):
    units = attrs.get(name + "_units", b"") if name else attrs.get("units", b"")
    return units.decode() if isinstance(units, bytes) else str(units)


def same(a, b, rtol, scaled=None):
    """scaled: (S^k, w^k) of the value's units under --scale."""
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype.kind != b.dtype.kind:
        return False
    zero = 0.0
    if scaled is not None and a.dtype.kind == "f":
        b, zero = b / scaled[0], rtol * scaled[1]
    elif a.dtype.kind not in "fiu" or rtol == 0.0 or scaled is not None:
        return a.tobytes() == b.tobytes()
    largest = np.maximum(np.abs(a), np.abs(b))
    close = (np.abs(a - b) <= rtol * largest) | (largest <= zero)
    return bool(np.all((a == b) | close | (np.isnan(a) & np.isnan(b))))


def walk(a, b, path, rtol, problems, scale=None, width=1.0):
    count = 0
    skip = LAYOUT | (RUN_ONLY if path == "/" else set()) | ({"input"} if scale else set())
    width = float(a.attrs.get("mean_width", width))

    def factor(units):
        k = LENGTH_POWER.get(units, 0)
        return (scale**k, width**k) if scale else None

    for name in sorted(set(a.attrs) | set(b.attrs)):
        if name.endswith("_units") or name in skip or seconds(a.attrs, name):
            continue
        count += 1
        if name not in a.attrs or name not in b.attrs:
            problems.append(f"{path}@{name}: only in one file")
        elif not same(a.attrs[name], b.attrs[name], rtol, factor(units_of(a.attrs, name))):
            problems.append(f"{path}@{name}: {a.attrs[name]} != {b.attrs[name]}")
    for name in sorted(set(a) | set(b)):
        if name not in a or name not in b:
            problems.append(f"{path}{name}: only in one file")
        elif isinstance(a[name], h5py.Group):
            count += walk(a[name], b[name], f"{path}{name}/", rtol, problems, scale, width)
        elif not seconds(a[name].attrs, "units"):
            count += 1
            units = units_of(a[name].attrs, None)
            if not same(a[name][()], b[name][()], rtol, factor(units)):
                problems.append(f"{path}{name}: datasets differ")
    return count


def main(argv):
    rtol = float(argv[argv.index("--rtol") + 1]) if "--rtol" in argv else 0.0
    scale = float(argv[argv.index("--scale") + 1]) if "--scale" in argv else None
    problems = []
    with h5py.File(argv[1]) as a, h5py.File(argv[2]) as b:
        count = walk(a, b, "/", rtol, problems, scale)
    for p in problems:
        print("DIFFERENT", p)
    if problems or count == 0:
        return 1
    print(f"results equal: {count} entries" + (f" (rtol {rtol})" if rtol else " (bit for bit)"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
