"""The jamming analysis in Python (sbpack.Jamming; docs/jamming.md §7): the category reached on
known lattices, each category's group one property, and the motions as (N, 3) arrays, in the
results file as in the module."""
import os

import numpy as np

import sbpack
from conftest import DATA, run


def test_fcc_spheres_are_strictly_jammed():
    j = sbpack.Jamming(threads=1).compute(
        sbpack.Packing.read(os.path.join(DATA, "fcc-spheres.txt")))
    assert isinstance(j, sbpack.JammingResult)
    assert j.category == "strict" and j.verdict == "strictly jammed at first order"
    assert j.undecided == "" and j.backbone == 108 and j.contacts == 648
    for group in (j.jamming_local, j.jamming_collective, j.jamming_strict):
        assert group["verdict"] == "jammed" and group["freed"].size == 0
        assert "flex_displacement" not in group


def test_superball_lattice_flexes_as_n_by_3_arrays(sbanalyze, tmp_path):
    path = os.path.join(DATA, "sc-lattice-p1.5.txt")
    j = sbpack.Jamming(jamming_categories="collective", threads=1).compute(
        sbpack.Packing.read(path), input=path)
    assert j.category == "none" and j.undecided == "collective"
    assert j.jamming_local is None and j.jamming_strict is None  # not asked for
    flex = j.jamming_collective["flex_displacement"]
    assert flex.shape == (125, 3) and j.jamming_collective["flex_rotation"].shape == (125, 3)
    out = tmp_path / "r.h5"
    r = run([sbanalyze, path, "--compute", "jamming", "--jamming-categories", "collective",
             "--threads", "1", "--quiet", "--out", str(out)])
    assert r.returncode == 0, r.stderr
    group = sbpack.read_results(out)["files"][0]["jamming_collective"]
    assert np.array_equal(group["flex_displacement"], flex)
    assert group["units"]["flex_displacement"] == "D" and group["units"]["flex_rotation"] == "rad"


def test_groups_sharing_a_table_are_one_property_each():
    names = dir(sbpack.JammingResult)
    assert {"category", "verdict", "jamming_local", "jamming_collective", "jamming_strict"} <= \
        set(names)
    assert "flex_displacement" not in names  # a name of each category's group, not one field
    assert "local jamming" in sbpack.JammingResult.jamming_local.__doc__
