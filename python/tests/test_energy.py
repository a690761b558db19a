"""stable_states: the general crease-spring search, bit for bit the CLI's `energy --json`."""
import math

import numpy as np
import pytest

import rigidfold
from conftest import SOURCE_DIR, bundled

REST = f"{SOURCE_DIR}/data/energy/waterbomb_base_rest60.json"


def test_stable_states_equal_the_cli_bit_for_bit(cli):
    path = bundled("waterbomb_base.fold")
    expected = cli("energy", path, "--rest", REST, "--starts", "6")
    assert expected.pop("file") == path and expected.pop("rest") == REST
    got = rigidfold.stable_states(rigidfold.load(path), REST, starts=6)
    assert got == expected  # same floats, not approximately: one kernel, one serialiser
    assert len(got["stable_states"]) >= 1
    for s in got["stable_states"]:
        assert s["closure_residual_rad"] <= 1e-12
        assert s["min_reduced_hessian_eigenvalue"] is None or s["min_reduced_hessian_eigenvalue"] > 0


def test_rest_as_an_array_equals_rest_from_its_file():
    import json
    pattern = rigidfold.load(bundled("waterbomb_base.fold"))
    with open(REST) as f:
        degrees = json.load(f)  # one entry per edge, null for edges that are not creases
    # Radians as the CLI reader converts them (degrees * (pi / 180)), 0 for the boundary.
    rest = np.array([a * (math.pi / 180) if a is not None else 0.0 for a in degrees])
    assert rigidfold.stable_states(pattern, rest, starts=3) == rigidfold.stable_states(pattern, REST, starts=3)


def test_bad_rest_names_the_place(tmp_path):
    pattern = rigidfold.load(bundled("waterbomb_base.fold"))
    bad = tmp_path / "open.json"
    bad.write_text('{"0": 30, "1": -30}\n')  # two creases folded, the rest flat: does not close
    with pytest.raises(rigidfold.InputError) as e:
        rigidfold.stable_states(pattern, bad)
    assert str(bad) in str(e.value) and "does not close" in str(e.value)
    with pytest.raises(rigidfold.InputError) as e:
        rigidfold.stable_states(pattern, np.zeros(len(pattern.edges) + 1))
    assert e.value.place == "rest"
    with pytest.raises(rigidfold.InputError) as e:
        rigidfold.stable_states(pattern, REST, k_m=-1.0)
    assert e.value.place == "stiffness.mountain"
