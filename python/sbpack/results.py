"""sbpack.read_results: an sbanalyze results file as plain nested dicts (docs/results-schema.md).

    r = read_results("results.h5")
    r["files"][0]["structure_factor"]["S"]      # numpy array
    r["ensembles"][0]["contacts"]["z_mean_std"]  # float
    r["files"][0]["units"]["box_length"]         # "length"

Each group is a dict of its attributes (numbers, strings) and datasets (numpy arrays), with its
analyses' groups as sub-dicts and the units under "units". ``files`` and ``ensembles`` are lists in
the order of their indices. Reading HDF5 is all it does (h5py); the numbers are sbanalyze's.
"""
import errno
import os

import h5py
import numpy as np

FORMAT, FORMAT_VERSION = "sbpack.results", 2


def _value(v):
    if isinstance(v, bytes):
        return v.decode()
    if isinstance(v, np.generic):
        return v.item()
    return v


def _group(g):
    out, units = {}, {}
    for name, value in g.attrs.items():
        if name.endswith("_units"):
            units[name[: -len("_units")]] = _value(value)
        else:
            out[name] = _value(value)
    for name, item in g.items():
        if isinstance(item, h5py.Group):
            out[name] = _group(item)
        else:
            out[name] = item[()]
            if "units" in item.attrs:
                units[name] = _value(item.attrs["units"])
    if units:
        out["units"] = units
    return out


def _indexed(d):
    """files/<i> and ensembles/<k> as lists."""
    return [d[k] for k in sorted(d, key=int)] if d else []


def read_results(path):
    """The results file at ``path`` as nested dicts; ValueError if it is not an sbpack.results
    file of format_version 2. Only a regular file is opened: a FIFO or device raises OSError at
    once instead of blocking (docs/reliability.md), as Packing.read does."""
    if os.path.exists(path) and not os.path.isfile(path):
        raise OSError(errno.EINVAL, "not a regular file (a FIFO, device, socket or directory); "
                      "results are read from regular files only", str(path))
    with h5py.File(path, "r") as f:
        if _value(f.attrs.get("format")) != FORMAT or f.attrs.get("format_version") != FORMAT_VERSION:
            raise ValueError(f"'{path}': not an {FORMAT} file of format_version {FORMAT_VERSION}")
        out = _group(f)
    out["files"] = _indexed(out.get("files", {}))
    out["ensembles"] = _indexed(out.get("ensembles", {}))
    return out
