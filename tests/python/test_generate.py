"""sbpack.generate runs sbgen's protocol in-process: the same packing as sbgen with the same seed
and options, bit for bit (every dataset and provenance entry but the timings)."""
import numpy as np
import pytest

import sbpack
from conftest import run

RUNS = {
    "spheres": dict(n=30, seed=3, gamma_slow=1e-3, pressure_switch=1e5, pressure_final=1e8),
    "superballs": dict(n=20, p=1.5, seed=3, gamma_slow=1e-2, pressure_switch=1e5,
                       pressure_final=1e8),
    "speed": dict(n=20, p=1.5, seed=3, speed=3, pressure_switch=1e5, pressure_final=1e8),
    "binary superballs": dict(n=30, p=1.5, seed=3, gamma_slow=1e-2, pressure_switch=1e5,
                              pressure_final=1e8, size_ratio=1.4, large_fraction=0.4),
}
TIMES = ("wall_time_s", "cpu_time_s")


def sbgen_options(options):
    flags = {"n": "--n", "p": "--p", "seed": "--seed", "gamma_slow": "--gamma-slow",
             "speed": "--speed",
             "pressure_switch": "--pressure-switch", "pressure_final": "--pressure-final",
             "cost_limit": "--cost-limit", "size_ratio": "--size-ratio",
             "large_fraction": "--large-fraction"}
    return [a for k, v in options.items() for a in (flags[k], str(v))]


@pytest.mark.parametrize("case", RUNS)
def test_generate_equals_sbgen(sbgen, tmp_path, case):
    options = RUNS[case]
    out = tmp_path / "sbgen.h5"
    r = run([sbgen, *sbgen_options(options), "--quiet", "--out", str(out)])
    assert r.returncode == 0, r.stderr
    statuses = []
    mine = sbpack.generate(**options, progress=statuses.append, progress_interval=0.0)
    theirs = sbpack.Packing.read(out)
    assert np.array_equal(mine.positions, theirs.positions)
    assert np.array_equal(mine.orientations, theirs.orientations)
    assert (mine.box_length, mine.p, mine.semi_axis, mine.reduced_pressure, mine.seed) == (
        theirs.box_length, theirs.p, theirs.semi_axis, theirs.reduced_pressure, theirs.seed)
    assert mine.is_mixture == ("size_ratio" in options)  # docs/mixtures.md
    assert np.array_equal(mine.semi_axes, theirs.semi_axes)
    a, b = mine.provenance, theirs.provenance
    assert set(a) == set(b)
    assert {k: a[k] for k in a if k not in TIMES} == {k: b[k] for k in b if k not in TIMES}
    assert a["jammed"] == 1 and mine.reduced_pressure >= options["pressure_final"]
    assert statuses[-1]["phase"] == "done" and len(statuses) == statuses[-1]["windows"]
    assert statuses[-1]["phi"] == pytest.approx(mine.phi, rel=1e-12)


@pytest.mark.parametrize("options,message", [
    (dict(phi_init=0.7), "phi_init: must be in"),
    (dict(n=1), "n: need at least 2"),
    (dict(p=0.5), "p: must be in"),
    (dict(pressure_switch=1e9, pressure_final=1e8), "pressure_final: must be larger"),
    (dict(size_ratio=0.7), "size_ratio: must be in"),
])
def test_bad_parameters_raise_value_error(options, message):
    with pytest.raises(ValueError, match=message):
        sbpack.generate(**options)


def test_an_exception_in_progress_stops_the_run():
    def stop(status):
        raise RuntimeError(f"stop at {status['windows']}")
    with pytest.raises(RuntimeError, match="stop at 1$"):
        sbpack.generate(n=200, seed=1, progress=stop, progress_interval=0.0)


def test_generate_stops_at_the_cost_limit_as_sbgen_does(sbgen, tmp_path):
    """cost_limit = 0.01: stopped after 1 % of the expected collisions, far below the final
    pressure; sbgen exits 3 and generate warns, both writing the same packing, jammed = 0."""
    options = dict(RUNS["superballs"], cost_limit=0.01)
    out = tmp_path / "sbgen.h5"
    r = run([sbgen, *sbgen_options(options), "--quiet", "--out", str(out)])
    assert r.returncode == 3 and "stopped at the cost limit" in r.stderr, r.stderr
    with pytest.warns(RuntimeWarning, match="stopped at the cost limit"):
        mine = sbpack.generate(**options)
    theirs = sbpack.Packing.read(out)
    assert np.array_equal(mine.positions, theirs.positions)
    assert mine.provenance["jammed"] == 0 == theirs.provenance["jammed"]
    assert mine.provenance["cost_limit"] == 0.01
    expected = sbpack.expected_collisions(
        **{k: options[k] for k in ("n", "p", "gamma_slow", "pressure_switch", "pressure_final")})
    assert mine.provenance["expected_collisions"] == expected
    assert 0.01 * expected <= mine.provenance["collisions"] < 0.02 * expected
    with pytest.raises(ValueError, match="n: need at least 2"):
        sbpack.expected_collisions(n=1)
    assert mine.reduced_pressure < options["pressure_final"]


def test_misuses_are_refused_before_the_run():
    """Issue 46, defect 15: an n beyond C's int is a ValueError naming it, a progress that cannot
    be called is refused before any work."""
    with pytest.raises(ValueError, match=r"n = 1000000000000 is not in \[2, 100000000\]"):
        sbpack.generate(n=10**12)
    with pytest.raises(TypeError, match="progress must be a callable"):
        sbpack.generate(n=10**6, progress=5)
    # issue 66 item 6: Python's message with sbgen's suggestion, not pybind11's signature list
    with pytest.raises(TypeError, match=r"^generate\(\) got an unexpected keyword argument "
                                        r"'gamma'; did you mean gamma_fast or gamma_slow\?$"):
        sbpack.generate(gamma=1e-3)
    # issue 65 item 8: -1 or NaN called progress after every window (22,700 calls)
    for interval in (-1, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="progress_interval = .*: must be a finite number of "
                                             r"seconds >= 0 \(0: after every window\)"):
            sbpack.generate(n=10**6, progress=print, progress_interval=interval)


def test_speed_scales_the_default_slow_rate():
    """speed=10 on spheres is the slow rate 10 x 1e-4 = 1e-3: the same run as gamma_slow=1e-3
    (docs/design.md §3, "Speed"); with gamma_slow as well it is refused, naming speed."""
    options = dict(n=30, seed=3, pressure_switch=1e5, pressure_final=1e8)
    fast = sbpack.generate(**options, speed=10)
    same = sbpack.generate(**options, gamma_slow=1e-3)
    assert np.array_equal(fast.positions, same.positions)
    assert fast.provenance["gamma_slow"] == 1e-3
    with pytest.raises(ValueError, match="speed"):
        sbpack.generate(**options, speed=10, gamma_slow=1e-3)


def test_the_shape_is_given_by_its_family_and_parameters():
    """Issue 67: shape= and the family's parameters by name, as sbgen's --shape and --p; the same
    run whether the superball is named or not, an unknown family or parameter refused."""
    options = dict(n=20, seed=3, gamma_slow=1e-2, pressure_switch=1e5, pressure_final=1e6)
    named = sbpack.generate(**options, shape="superball", p=1.5)
    assert np.array_equal(named.positions, sbpack.generate(**options, p=1.5).positions)
    assert named.shape == {"shape": "superball", "p": 1.5}
    assert sbpack.expected_collisions(n=1000, shape="superball", p=1.5) == \
        sbpack.expected_collisions(n=1000, p=1.5)
    with pytest.raises(ValueError, match=r"shape = 'cube': unknown shape family \(the families: "
                                         r"superball\)"):
        sbpack.generate(**options, shape="cube", p=2)
    with pytest.raises(TypeError, match=r"^p must be a number, not str$"):
        sbpack.generate(**options, p="1.5")
    with pytest.raises(TypeError, match=r"shape must be a str or None, not list$"):
        sbpack.generate(**options, shape=["superball"])
    with pytest.raises(TypeError, match=r"^generate\(\) got an unexpected keyword argument 'pp'"
                                        r"; did you mean p\?$"):
        sbpack.generate(**options, pp=1.5)
