"""sbpack.read_results: today's files, and files of format_version 2 read under today's names
(docs/results-schema.md, "Names")."""
import json

import h5py
import numpy as np
import pytest

import sbpack
from sbpack import _sbpack
from conftest import DATA, FAST, cli_args, run


@pytest.fixture(scope="module")
def transport_results(sbanalyze, tmp_path_factory):
    out = tmp_path_factory.mktemp("results") / "r.h5"
    options = dict(FAST, pore_voxels=64)
    done = run([sbanalyze, f"{DATA}/mrj-p1.5-1000.h5", "--compute", "transport", "--out",
                str(out), "--quiet"] + cli_args(options))
    assert done.returncode == 0, done.stderr
    return out


def as_version_2(path, copy):
    """The file as sbanalyze wrote it at format_version 2: the renamed fields under their names
    then (the schema's own list)."""
    renamed = json.loads(_sbpack.schema_json())["renamed"]
    copy.write_bytes(path.read_bytes())
    with h5py.File(copy, "r+") as f:
        f.attrs["format_version"] = np.int64(2)
        for top in ("files", "ensembles"):
            for entry in f[top].values():
                for r in renamed:
                    group = entry[r["group"]]
                    for suffix in ("", "_std"):
                        now, before = r["now"] + suffix, r["before"] + suffix
                        if now in group.attrs:
                            group.attrs[before] = group.attrs[now]
                            group.attrs[before + "_units"] = group.attrs[now + "_units"]
                            del group.attrs[now], group.attrs[now + "_units"]
    return copy


def test_a_file_of_today(transport_results):
    r = sbpack.read_results(transport_results)
    assert r["format_version"] == sbpack.results.FORMAT_VERSION == 3
    transport = r["files"][0]["transport"]
    assert transport["units"]["mean_survival_time_w2"] == "w^2/D"
    # tau D / w^2 from its own columns (Eq. 19 over the mean width squared)
    w = r["files"][0]["mean_width"]
    assert transport["mean_survival_time_w2"] == pytest.approx(
        transport["mean_survival_time"] * transport["diffusion_coefficient"] / w**2, rel=1e-14)


def test_a_file_of_version_2_reads_under_todays_names(transport_results, tmp_path):
    today = sbpack.read_results(transport_results)
    old = sbpack.read_results(as_version_2(transport_results, tmp_path / "v2.h5"))
    assert old["format_version"] == 2
    for level in ("files", "ensembles"):
        now, then = today[level][0]["transport"], old[level][0]["transport"]
        assert sorted(k for k in then if "scaled" in k) == []
        for name in ("mean_survival_time_w2", "principal_relaxation_time_w2"):
            assert then[name] == now[name]
    assert old["ensembles"][0]["transport"]["mean_survival_time_w2_std"] == 0.0


def test_other_versions_are_refused(transport_results, tmp_path):
    copy = tmp_path / "v1.h5"
    copy.write_bytes(transport_results.read_bytes())
    with h5py.File(copy, "r+") as f:
        f.attrs["format_version"] = np.int64(1)
    with pytest.raises(ValueError, match="format_version 2 to 3"):
        sbpack.read_results(copy)
