"""The module's analyses give sbanalyze's results bit for bit (the same stages on the same
packing): every dataset and number of every group, for every data/*.h5, but the timings."""
import glob
import inspect
import os
import warnings

import numpy as np
import pytest

import sbpack
from conftest import DATA, FAST, cli_args, run

PACKINGS = sorted(glob.glob(os.path.join(DATA, "*.h5")))
OPTIONS = dict(FAST, voxels=100, pore_voxels=100, bootstrap=20)
ANALYSES = [
    (sbpack.Contacts, "contacts", {"tolerance": 1e-6}),
    (sbpack.StructureFactor, "sq", {"qmax": 20}),
    (sbpack.SpectralDensity, "chi", {}),
    (sbpack.PoreSizes, "pores", {}),
    (sbpack.PoreSizes, "pores", {"pores": "refined"}),
    (sbpack.Transport, "transport", {}),
    (sbpack.Hyperuniformity, "hyper", {}),
    # local only: the coupled programs take minutes at N = 5000 (docs/jamming.md §7)
    (sbpack.Jamming, "jamming", {"jamming_categories": "local"}),
]
def is_timing(name):
    """Wall-clock times (units "s" in docs/results-schema.md: runtime_s, fft_s, ...)."""
    return name.endswith("_s")


def assert_same_group(cli, module, where):
    names = {k for k in cli if k != "units" and not is_timing(k)}
    assert names == {k for k in module if not is_timing(k)}, where
    for name in names:
        a, b = cli[name], module[name]
        if isinstance(a, np.ndarray):  # NaN where a value is undefined (e.g. no contacts)
            assert a.dtype == b.dtype and np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), \
                f"{where}/{name}"
        else:
            assert a == b or (a != a and b != b), f"{where}/{name}: {a} != {b}"


@pytest.mark.parametrize("cls,compute,extra", ANALYSES, ids=[a[1] for a in ANALYSES])
def test_module_equals_cli(sbanalyze, tmp_path, cls, compute, extra):
    keywords = inspect.signature(cls).parameters
    options = {k: v for k, v in {**OPTIONS, **extra}.items() if k in keywords}
    out = tmp_path / "cli.h5"
    r = run([sbanalyze, *PACKINGS, "--compute", compute, "--quiet", "--out", str(out),
             *cli_args(options)])
    assert r.returncode == 0, r.stderr
    files = sbpack.read_results(out)["files"]
    analysis = cls(**options)
    for path, cli in zip(PACKINGS, files):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # skipped groups, as the CLI warns
            groups = analysis.compute(sbpack.Packing.read(path), input=path).groups
        assert set(groups) - {"file"} == {g for g in cli if isinstance(cli[g], dict)} - {"units"}
        assert_same_group({k: v for k, v in cli.items() if not isinstance(v, dict)},
                          groups["file"], path)
        for group in set(groups) - {"file"}:
            assert_same_group(cli[group], groups[group], f"{path}/{group}")


def test_attributes_are_the_groups_values():
    s = sbpack.StructureFactor(qmax=10, threads=2).compute(
        sbpack.Packing.read(os.path.join(DATA, "mrj-p1.5-1000.h5")))
    assert isinstance(s, sbpack.StructureFactorResult)
    assert np.array_equal(s.S, s.groups["structure_factor"]["S"])
    assert s.qmax == 10 and len(s.Q) == s.max_shell
    with pytest.raises(AttributeError):
        s.chi


def test_dir_lists_the_results():
    """dir() and help() list a result's fields before any run (they are properties of its class,
    issue 61): its own groups' names, then its needs' and the file's; each is the group's value."""
    assert {"z_mean", "rattler_fraction", "counts", "phi", "mean_width"} <= set(
        dir(sbpack.ContactsResult))
    assert "mean contact number Z" in sbpack.ContactsResult.z_mean.__doc__
    c = sbpack.Contacts(threads=2).compute(
        sbpack.Packing.read(os.path.join(DATA, "sc-lattice-p1.5.txt")))
    names = set(dir(c))
    for group in c.groups.values():
        assert set(group) - {"units"} <= names | {"input"}
    assert c.z_mean == c.groups["contacts"]["z_mean"] == 6
    assert c.phi == c.groups["file"]["phi"]


def as_printed(value):
    """A default as numbers where it is numbers (30 and "30", (1e-3, 1e4) and "1e-3,1e4")."""
    words = value if isinstance(value, tuple) else str(value).split(",")
    try:
        return tuple(float(w) for w in words)
    except ValueError:
        return tuple(str(w) for w in words)


def test_signatures_are_the_option_tables():
    """Each class takes its registry row's options as keyword-only parameters, with the defaults
    the command line prints (None where the default is the machine's or hangs on another
    option), and documents each (issue 61: one declaration)."""
    table = sbpack._sbpack.analysis_options()
    rows = {row["python_class"]: row for row in sbpack._sbpack.analysis_registry()}
    assert [cls.__name__ for cls in sbpack.ANALYSES] == list(rows)
    for cls in sbpack.ANALYSES:
        parameters = inspect.signature(cls).parameters
        names = ["threads", *rows[cls.__name__]["options"]]
        assert list(parameters) == [n.replace("-", "_") for n in names], cls.__name__
        for name in names[1:]:
            row, default = table[name], parameters[name.replace("-", "_")].default
            assert parameters[name.replace("-", "_")].kind is inspect.Parameter.KEYWORD_ONLY
            if default is None:
                assert row["dependent_default"] or row["default"] == "", name
            else:
                assert as_printed(default) == as_printed(row["default"]), (name, default, row)
            assert f"{name.replace('-', '_')} : " in cls.__doc__, (cls.__name__, name)
    assert "qmax=30" in str(inspect.signature(sbpack.StructureFactor))


def test_a_warning_of_several_lines_is_one_runtime_warning():
    """Unresolved contacts: the verdict and its gap distribution, one RuntimeWarning (issue 43:
    it was one per line, a blank one included)."""
    packing = sbpack.Packing.read(os.path.join(DATA, "stalled-column-p10-200.h5"))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sbpack.Contacts(threads=2).compute(packing)
    messages = [str(w.message) for w in caught]
    assert len(messages) == 1 and all(w.category is RuntimeWarning for w in caught), messages
    lines = messages[0].splitlines()
    assert "NOT resolved" in lines[0] and len(lines) > 3
    assert all(line.startswith("    ") and line.endswith("pairs") for line in lines[1:])
    assert caught[0].filename == __file__  # raised at the caller's line


def test_analyze_warns_once_per_message_and_prints_its_stage_lines(tmp_path, capsys):
    """sbpack.analyze: the warning is one RuntimeWarning; without quiet, the stage lines go to
    standard error as sbanalyze's do, not as warnings."""
    path = os.path.join(DATA, "stalled-column-p10-200.h5")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sbpack.analyze([path], tmp_path / "r.h5", compute="contacts", quiet=False, threads=2)
    assert [str(w.message).count("NOT resolved") for w in caught] == [1]
    stages = capsys.readouterr().err.splitlines()
    assert stages and all(line.startswith("sbanalyze: ") for line in stages)
    assert not any("warning" in line for line in stages)


def test_hyperuniformity_skipped_on_a_small_box_warns():
    packing = sbpack.Packing.read(os.path.join(DATA, "dense-p10-200.h5"))
    with pytest.warns(RuntimeWarning, match="alpha window"):
        h = sbpack.Hyperuniformity(voxels=100, **FAST).compute(packing)
    assert "spreadability" not in h.groups and "spectral_density" in h.groups


def test_a_sequence_is_a_pair_only():
    """Issue 65 item 8: tolerance=[1] was read as --tolerance 1; pairs and lists keep theirs."""
    with pytest.raises(ValueError, match="tolerance: a sequence of 1 values; it takes one value"):
        sbpack.Contacts(tolerance=[1])
    with pytest.raises(ValueError, match="alpha_window: a sequence of 3 values; it takes a pair"):
        sbpack.Hyperuniformity(alpha_window=(1, 2, 5.8))
    with pytest.raises(ValueError, match="a sequence of 0 values; it takes a non-empty list"):
        sbpack.Jamming(jamming_categories=[])
    assert sbpack.Hyperuniformity(alpha_window=(1, 5.8)) is not None
    assert sbpack.Jamming(jamming_categories=("local", "collective", "strict")) is not None


def test_analyze_names_its_misuses_in_python(tmp_path):
    """Issue 66 item 6: analyze(q_max=20) answered in the command line's spelling, and a Packing
    given for the files failed with "'Packing' object is not iterable"."""
    path = os.path.join(DATA, "fcc-spheres.txt")
    with pytest.raises(TypeError, match=r"^analyze\(\) got an unexpected keyword argument "
                                        r"'q_max'; did you mean qmax\?$"):
        sbpack.analyze(path, tmp_path / "r.h5", q_max=20)
    with pytest.raises(TypeError, match=r"a Packing goes to an analysis's compute\(packing\)"):
        sbpack.analyze(sbpack.Packing.read(path), tmp_path / "r.h5")
    assert not (tmp_path / "r.h5").exists()


def test_unknown_option_is_a_type_error():
    with pytest.raises(TypeError, match="unexpected keyword argument 'voxels'"):
        sbpack.StructureFactor(voxels=10)
