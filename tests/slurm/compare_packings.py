"""Compares sbgen packings bit for bit: every dataset (values, dtype and shape) and every attribute
of the file and its groups, except the run's clocks (cpu_time_s, wall_time_s).

usage: compare_packings.py REFERENCE.h5 OTHER.h5 [REFERENCE.h5 OTHER.h5 ...]
Prints one line per pair; exits 1 if any pair differs.
"""
import sys

import h5py
import numpy as np

CLOCKS = {"cpu_time_s", "wall_time_s"}


def items(f):
    found = {"/": f}
    f.visititems(lambda name, obj: found.__setitem__(name, obj))
    return found


def same_value(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


def compare(reference, other):
    problems = []
    with h5py.File(reference, "r") as a, h5py.File(other, "r") as b:
        ia, ib = items(a), items(b)
        if set(ia) != set(ib):
            problems.append(f"objects differ: {sorted(set(ia) ^ set(ib))}")
        datasets = 0
        for name in sorted(set(ia) & set(ib)):
            x, y = ia[name], ib[name]
            if isinstance(x, h5py.Dataset) != isinstance(y, h5py.Dataset):
                problems.append(f"{name}: a dataset in one file only")
                continue
            if isinstance(x, h5py.Dataset):
                datasets += 1
                if not same_value(x[()], y[()]):
                    problems.append(f"dataset {name} differs")
            keys = (set(x.attrs) | set(y.attrs)) - CLOCKS
            for key in sorted(keys):
                if key not in x.attrs or key not in y.attrs:
                    problems.append(f"attribute {name}:{key} in one file only")
                elif not same_value(x.attrs[key], y.attrs[key]):
                    problems.append(f"attribute {name}:{key}: {x.attrs[key]} != {y.attrs[key]}")
    return datasets, problems


def main(args):
    if len(args) < 2 or len(args) % 2:
        sys.exit(__doc__)
    failed = False
    for reference, other in zip(args[::2], args[1::2]):
        datasets, problems = compare(reference, other)
        if problems:
            failed = True
            print(f"DIFFERENT: {other} against {reference}: " + "; ".join(problems))
        else:
            print(f"identical: {other} = {reference} ({datasets} datasets, all attributes but "
                  "the clocks)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
