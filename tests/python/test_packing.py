"""sbpack.Packing: files through the C++ readers and writers, arrays with the readers' checks and
the command line's messages (ValueError)."""
import os

import h5py
import numpy as np
import pytest

import sbpack
from conftest import DATA, run

P15 = os.path.join(DATA, "mrj-p1.5-1000.h5")


def test_properties_of_a_stored_packing():
    p = sbpack.Packing.read(P15)
    with h5py.File(P15) as f:
        assert np.array_equal(p.positions, f["positions"][:])
        assert np.array_equal(p.orientations, f["orientations"][:])
        assert p.box_length == f.attrs["box_length"] and p.p == f.attrs["p"]
        assert p.semi_axis == f.attrs["semi_axis"] and len(p) == f.attrs["n_particles"]
        assert abs(p.phi - f.attrs["phi"]) < 1e-12
        assert p.provenance["seed"] == f["provenance"].attrs["seed"]
    assert p.positions.shape == (1000, 3) and p.orientations.shape == (1000, 4)


@pytest.mark.parametrize("suffix", [".h5", ".txt"])
def test_round_trip_is_exact(tmp_path, suffix):
    p = sbpack.Packing.read(P15)
    path = tmp_path / f"copy{suffix}"
    p.write(path)
    q = sbpack.Packing.read(path)
    assert np.array_equal(p.positions, q.positions)
    assert np.array_equal(p.orientations, q.orientations)
    assert (p.box_length, p.p, p.semi_axis) == (q.box_length, q.p, q.semi_axis)


def test_arrays_make_the_same_packing_as_the_file():
    p = sbpack.Packing.read(P15)
    q = sbpack.Packing(p.positions, p.orientations, p.box_length, p=p.p, semi_axis=p.semi_axis)
    assert np.array_equal(p.positions, q.positions) and q.phi == p.phi


def text_packing(path, p, rows):
    lines = ["# sbpack text packing v1", f"# p {p}", "# semi_axis 0.5", "# box_length 5",
             f"# n_particles {len(rows)}"] + [" ".join(map(str, r)) for r in rows]
    path.write_text("\n".join(lines) + "\n")


def cli_error(sbanalyze, path, tmp_path):
    r = run([sbanalyze, "convert", str(path), str(tmp_path / "out.h5")])
    assert r.returncode == 1
    return r.stderr.strip().removeprefix("sbanalyze: error: ")


BAD = {
    "nan position": (1.5, [[0, 0, 0, 1, 0, 0, 0], [float("nan"), 1, 1, 1, 0, 0, 0]]),
    "unnormalised quaternion": (1.5, [[0, 0, 0, 1, 0, 0, 0], [1, 1, 1, 2, 0, 0, 0]]),
    "p out of range": (0.3, [[0, 0, 0, 1, 0, 0, 0], [1, 1, 1, 1, 0, 0, 0]]),
}


@pytest.mark.parametrize("case", BAD)
def test_bad_arrays_raise_the_clis_message(sbanalyze, tmp_path, case):
    p, rows = BAD[case]
    path = tmp_path / "bad.txt"
    text_packing(path, p, rows)
    rows = np.array(rows, dtype=float)
    with pytest.raises(ValueError) as error:
        sbpack.Packing(rows[:, :3], rows[:, 3:], 5.0, p=p, semi_axis=0.5, source=str(path))
    assert str(error.value) == cli_error(sbanalyze, path, tmp_path)


def test_wrong_shape_raises_the_clis_message(sbanalyze, tmp_path):
    path = tmp_path / "shape.h5"
    with h5py.File(path, "w") as f:
        f.attrs.update({"format": "sbpack.packing", "format_version": np.int64(1), "p": 1.0,
                        "box_length": 5.0, "semi_axis": 0.5, "n_particles": np.int64(2),
                        "phi": 2 * np.pi / 6 / 125})
        f["positions"] = np.zeros((2, 3))
        f["orientations"] = np.zeros((2, 3))
    with pytest.raises(ValueError) as error:
        sbpack.Packing(np.zeros((2, 3)), np.zeros((2, 3)), 5.0, p=1.0, semi_axis=0.5,
                       source=str(path))
    assert str(error.value) == cli_error(sbanalyze, path, tmp_path)


def test_bad_option_raises_the_clis_message(sbanalyze, tmp_path):
    r = run([sbanalyze, P15, "--compute", "sq", "--qmax", "-1", "--json", "-"])
    with pytest.raises(ValueError) as error:
        sbpack.StructureFactor(qmax=-1)
    assert r.returncode == 1 and str(error.value) in r.stderr


def test_a_missing_file_is_an_os_error(tmp_path):
    with pytest.raises(OSError, match="no such file"):
        sbpack.Packing.read(tmp_path / "missing.h5")


def test_misuses_are_named(tmp_path):
    """Issue 46, defect 15: transposed or 1-D positions, an unknown extension, a NUL in source,
    and write errors as OSError."""
    with pytest.raises(ValueError, match=r"has shape 3 x 100, expected N x 3 \(one row per "
                                         r"particle; transposed\?\)"):
        sbpack.Packing(np.zeros((3, 100)), np.zeros((100, 4)), 5.0, p=1.5, semi_axis=0.5)
    with pytest.raises(ValueError, match=r"has shape rank 1, expected N x 3"):
        sbpack.Packing(np.zeros(3), np.zeros((1, 4)), 5.0, p=1.5, semi_axis=0.5)
    with pytest.raises(ValueError, match="source contains a NUL"):
        sbpack.Packing(np.zeros((1, 3)), [[1.0, 0, 0, 0]], 5.0, p=1.5, semi_axis=0.5,
                       source="a\0b")
    packing = sbpack.Packing.read(P15)
    with pytest.raises(ValueError, match=r"unknown extension \(use .h5, .txt, .xyz, .gsd"):
        packing.write(tmp_path / "x.bad")
    assert not (tmp_path / "x.bad").exists()
    with pytest.raises(OSError, match="does not exist"):
        packing.write(tmp_path / "missing" / "x.h5")


def test_arrays_are_read_only_copies():
    """Issue 66 item 6: an edit of packing.positions was lost without a word (a copy)."""
    packing = sbpack.Packing.read(P15)
    for array in (packing.positions, packing.orientations):
        with pytest.raises(ValueError, match="read-only"):
            array[0, 0] = 1.0
    moved = packing.positions.copy()
    moved[0, 0] = (moved[0, 0] + 0.5) % packing.box_length
    edited = sbpack.Packing(moved, packing.orientations, packing.box_length, p=packing.p,
                            semi_axis=packing.semi_axis)
    assert edited.positions[0, 0] == moved[0, 0]


def test_arrays_of_other_than_real_numbers_are_refused():
    """Issue 65 item 8: boolean and complex arrays were cast (True as 1, the imaginary part
    dropped); integers are numbers."""
    q = [[1.0, 0, 0, 0]]
    with pytest.raises(TypeError, match="'arrays': positions must hold real numbers, not dtype bool"):
        sbpack.Packing(np.ones((1, 3), dtype=bool), q, 5.0, p=1.5, semi_axis=0.5)
    with pytest.raises(TypeError, match="orientations must hold real numbers, not dtype complex128"):
        sbpack.Packing(np.ones((1, 3)), np.array(q) + 1j, 5.0, p=1.5, semi_axis=0.5)
    with pytest.raises(TypeError, match="positions must hold real numbers, not dtype <U1"):
        sbpack.Packing([["a", "b", "c"]], q, 5.0, p=1.5, semi_axis=0.5)
    packing = sbpack.Packing(np.array([[1, 2, 3]]), [[1, 0, 0, 0]], 5.0, p=1.5, semi_axis=0.5)
    assert packing.positions.tolist() == [[1.0, 2.0, 3.0]]


def test_the_shape_is_never_a_silent_default():
    """Issue 43: rebuilding an MRJ packing from its arrays without semi_axis once gave phi = 0.2
    (a default of 0.5); p and semi_axis are now required keywords."""
    p = sbpack.Packing.read(P15)
    # issue 66 item 6: Python's message, naming the keyword, not pybind11's with the arrays
    with pytest.raises(TypeError, match=r"^Packing.__init__\(\) missing 1 required keyword-only "
                                        r"argument: 'semi_axis'$"):
        sbpack.Packing(p.positions, p.orientations, p.box_length, p=1.5)
    with pytest.raises(TypeError):
        sbpack.Packing(p.positions, p.orientations, p.box_length, semi_axis=p.semi_axis)
    q = sbpack.Packing(p.positions, p.orientations, p.box_length, p=p.p, semi_axis=p.semi_axis)
    assert q.phi == p.phi


def test_the_shape_is_its_family_and_parameters_by_name():
    """Issue 67: the constructor takes the shape's parameters by name (any family by shape=), and
    the packing names its shape as the file does."""
    p = sbpack.Packing.read(P15)
    assert p.shape == {"shape": "superball", "p": p.p} and p.p == 1.5
    assert "superball" in sbpack.shape_families() and sbpack.shape_families()["superball"] == ["p"]
    q = sbpack.Packing(p.positions, p.orientations, p.box_length, shape="superball", p=1.5,
                       semi_axis=p.semi_axis)
    assert q.shape == p.shape and q.phi == p.phi
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'pp'; did you mean p\?"):
        sbpack.Packing(p.positions, p.orientations, p.box_length, pp=1.5, semi_axis=p.semi_axis)
    with pytest.raises(TypeError, match="missing the superball's keyword argument 'p'"):
        sbpack.Packing(p.positions, p.orientations, p.box_length, semi_axis=p.semi_axis)
    with pytest.raises(ValueError, match=r"'arrays': unknown shape family 'cube' \(known: "
                                         r"superball\)"):
        sbpack.Packing(p.positions, p.orientations, p.box_length, shape="cube", a=1.0,
                       semi_axis=p.semi_axis)


def test_a_mixture_from_arrays_keeps_its_sizes_in_the_file_and_in_text(tmp_path):
    """docs/mixtures.md: semi_axes by keyword, phi the sum of the particles' own volumes, the
    sizes kept by the packing file and by the text format's eighth column."""
    positions = np.array([[0.5, 0.5, 0.5], [2.0, 2.0, 2.0], [3.5, 0.5, 2.0]])
    orientations = np.tile([1.0, 0.0, 0.0, 0.0], (3, 1))
    radii = np.array([0.5, 0.35, 0.35])
    p = sbpack.Packing(positions, orientations, 5.0, p=1.0, semi_axis=0.5, semi_axes=radii)
    assert p.is_mixture and np.array_equal(p.semi_axes, radii)
    assert abs(p.phi - 4 / 3 * np.pi * np.sum(radii**3) / 125) < 1e-15
    p.write(tmp_path / "mix.h5")
    with h5py.File(tmp_path / "mix.h5") as f:
        assert np.array_equal(f["semi_axes"][:, 0], radii) and f.attrs["semi_axis"] == 0.5
    assert np.array_equal(sbpack.Packing.read(tmp_path / "mix.h5").semi_axes, radii)
    p.write(tmp_path / "mix.txt")
    lines = (tmp_path / "mix.txt").read_text().splitlines()
    assert [len(line.split()) for line in lines[-3:]] == [8, 8, 8]
    assert np.array_equal(sbpack.Packing.read(tmp_path / "mix.txt").semi_axes, radii)
    with pytest.raises(ValueError, match="not the largest of semi_axes"):
        sbpack.Packing(positions, orientations, 5.0, p=1.0, semi_axis=0.4, semi_axes=radii)
    identical = sbpack.Packing.read(P15)
    assert not identical.is_mixture and np.all(identical.semi_axes == identical.semi_axis)
