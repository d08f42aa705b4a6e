"""sbpack.read_results: today's files, and files of format_version 2 and 3 read under today's
names (docs/results-schema.md, "Names")."""
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


@pytest.fixture(scope="module")
def hyper_results(sbanalyze, tmp_path_factory):
    out = tmp_path_factory.mktemp("results") / "h.h5"
    done = run([sbanalyze, f"{DATA}/mrj-p1.5-1000.h5", "--compute", "hyper", "--voxels", "100",
                "--out", str(out), "--quiet"] + cli_args(FAST))
    assert done.returncode == 0, done.stderr
    return out


def as_version(path, copy, version):
    """The file as sbanalyze wrote it at `version`: the fields renamed since under their names
    then (the schema's own list)."""
    renamed = json.loads(_sbpack.schema_json())["renamed"]
    copy.write_bytes(path.read_bytes())
    with h5py.File(copy, "r+") as f:
        f.attrs["format_version"] = np.int64(version)
        for top in ("files", "ensembles"):
            for entry in f[top].values():
                for r in (r for r in renamed if r["since"] > version and r["group"] in entry):
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
    assert r["format_version"] == sbpack.results.FORMAT_VERSION == 4
    transport = r["files"][0]["transport"]
    assert transport["units"]["mean_survival_time_w2"] == "w^2/D_diff"
    # tau D_diff / w^2 from its own columns (Eq. 19 over the mean width squared)
    w = r["files"][0]["mean_width"]
    assert transport["mean_survival_time_w2"] == pytest.approx(
        transport["mean_survival_time"] * transport["diffusion_coefficient"] / w**2, rel=1e-14)


def test_a_file_of_version_2_reads_under_todays_names(transport_results, tmp_path):
    today = sbpack.read_results(transport_results)
    old = sbpack.read_results(as_version(transport_results, tmp_path / "v2.h5", 2))
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
    with pytest.raises(ValueError, match="format_version 2 to 4"):
        sbpack.read_results(copy)


def test_a_file_of_version_3_holds_the_window_mean_as_alpha(hyper_results, tmp_path):
    # Until format_version 4, alpha was the window's mean local alpha: read as alpha_window_mean.
    today = sbpack.read_results(hyper_results)
    old = sbpack.read_results(as_version(hyper_results, tmp_path / "v3.h5", 3))
    for level in ("files", "ensembles"):
        now, then = today[level][0]["spreadability"], old[level][0]["spreadability"]
        assert then["alpha_window_mean"] == now["alpha_window_mean"]
        assert then["alpha_window_mean_stderr" if level == "files" else "alpha_window_mean_std"] \
            == now["alpha_window_mean_stderr" if level == "files" else "alpha_window_mean_std"]
    assert now["alpha"] != now["alpha_window_mean"]
