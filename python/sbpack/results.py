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
import json
import os

import h5py
import numpy as np

from . import _sbpack

# The schema sbanalyze writes (docs/results-schema.md): its format_version and the fields that
# earlier versions named otherwise, read under today's names.
_SCHEMA = json.loads(_sbpack.schema_json())
FORMAT, FORMAT_VERSION = _SCHEMA["format"], _SCHEMA["format_version"]
OLDEST_VERSION = 2


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


def _rename_fields(out, version):
    """Today's names in a file of an earlier format_version (the schema's "renamed")."""
    for r in _SCHEMA["renamed"]:
        if version >= r["since"]:
            continue
        for entry in [*out.get("files", {}).values(), *out.get("ensembles", {}).values()]:
            group = entry.get(r["group"]) if isinstance(entry, dict) else None
            if group is None:
                continue
            for before, now in ((r["before"], r["now"]), (r["before"] + "_std", r["now"] + "_std")):
                for table in (group, group.get("units", {})):
                    if before in table:
                        table[now] = table.pop(before)


def _indexed(d):
    """files/<i> and ensembles/<k> as lists."""
    return [d[k] for k in sorted(d, key=int)] if d else []


def read_results(path):
    """The results file at ``path`` as nested dicts, in today's names (a file of an earlier
    format_version from 2 on is read under the names it has now, docs/results-schema.md "Names");
    ValueError if it is not an sbpack.results file of such a version. Only a regular file is opened: a FIFO or device raises OSError at
    once instead of blocking (docs/reliability.md), as Packing.read does."""
    if os.path.exists(path) and not os.path.isfile(path):
        raise OSError(errno.EINVAL, "not a regular file (a FIFO, device, socket or directory); "
                      "results are read from regular files only", str(path))
    with h5py.File(path, "r") as f:
        version = f.attrs.get("format_version")
        if (_value(f.attrs.get("format")) != FORMAT
                or version not in range(OLDEST_VERSION, FORMAT_VERSION + 1)):
            raise ValueError(f"'{path}': not an {FORMAT} file of format_version "
                             f"{OLDEST_VERSION} to {FORMAT_VERSION}")
        out = _group(f)
    _rename_fields(out, int(version))
    out["files"] = _indexed(out.get("files", {}))
    out["ensembles"] = _indexed(out.get("ensembles", {}))
    return out
