"""enumerate_assignments and waterbomb_bistability, against seed 003 and the CLI."""
import math

import pytest

import rigidfold
from conftest import bundled


def test_unit_p_has_10_classes_4_foldable():
    r = rigidfold.enumerate_assignments(rigidfold.load(bundled("corrugated_p_rigid.fold")))
    assert r["assignments"] == 32
    assert r["classes"] == 10
    assert r["foldable_classes"] == 4
    assert r["complete"] is True
    assert sum(c["orbit_size"] for c in r["listed"]) == 32
    assert sum(c["verdict"] == "foldable" for c in r["listed"]) == 4
    assert all(len(c["letters"]) == len(r["creases"]) for c in r["listed"])


def without_seconds(doc):
    return {k: v for k, v in doc.items() if k != "seconds"}


def test_square_twist_assignments_are_the_clis_json(cli):
    path = bundled("square_twist_30_type1.fold")
    r = rigidfold.enumerate_assignments(rigidfold.load(path), max_listed=50, source=path)
    assert (r["assignments"], r["classes"], r["foldable_classes"]) == (16, 4, 2)
    assert without_seconds(r) == without_seconds(cli("assignments", path))


def test_stopped_assignment_search_has_no_class_count(cli):
    path = bundled("corrugated_p_rigid.fold")
    r = rigidfold.enumerate_assignments(rigidfold.load(path), max_assignments=5, max_listed=50, source=path)
    assert r["complete"] is False and r["classes"] is None
    assert without_seconds(r) == without_seconds(cli("assignments", path, "--max-assignments", "5"))


def test_waterbomb_bistability_matches_cli(cli):
    r = rigidfold.waterbomb_bistability(4, math.radians(60))
    expected = cli("waterbomb", "--n", "4", "--theta0-deg", "60")
    assert len(r["stable_states"]) == 2
    assert [e["kind"] for e in r["equilibria"]] == [e["kind"] for e in expected["equilibria"]]
    for got, want in zip(r["equilibria"], expected["equilibria"]):
        assert math.degrees(got["theta"]) == pytest.approx(want["theta_deg"], abs=1e-12)
        assert got["energy"] == want["energy"]
        assert got["closure_residual"] <= 1e-12
    with pytest.raises(rigidfold.InputError) as info:
        rigidfold.waterbomb_bistability(2, 0.5)
    assert info.value.place == "n"


def test_string_design_recovers_a_known_string():
    import numpy as np

    alpha1 = [math.radians(40 + 3 * k) for k in range(6)]
    alpha2 = [math.radians(55 - 2 * k) for k in range(6)]
    lengths = [1.0] * 7
    theta0 = math.radians(30)
    folded = rigidfold.string_forward(alpha1, alpha2, lengths, theta0)
    assert folded["spine"].shape == (8, 3)
    assert folded["shared_crease_mismatch"] <= 1e-12
    pattern = rigidfold.string_pattern(alpha1, alpha2, lengths)
    assert len(folded["edge_fold_angles"]) == pattern.num_edges
    design = rigidfold.design_string_from_curve(folded["spine"], theta0=theta0)
    assert design["feasible"]
    error = max(np.max(np.abs(np.subtract(design["alpha1"], alpha1))),
                np.max(np.abs(np.subtract(design["alpha2"], alpha2))))
    assert error <= 1e-9
    with pytest.raises(ValueError):
        rigidfold.string_forward(alpha1, alpha2, lengths[:-1], theta0)
