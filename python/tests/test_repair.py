"""repair(), add_creases() and nearest_closed_state(): the objects the CLI prints with --json
(`repair`, `repair --add-creases`, `fold --target`'s nearest_state), plus the resulting pattern."""
import math

import numpy as np
import pytest

import rigidfold


def without_timings(value):
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k not in ("seconds", "exploration_seconds")}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def test_repair_of_a_jittered_miura_matches_the_cli_and_folds(cli, tmp_path):
    p = rigidfold.miura_ori(rows=4, cols=5, perturbation=0.03, seed=2)
    path = str(tmp_path / "jittered.fold")
    rigidfold.save(p, path)
    r = rigidfold.repair(p)
    assert r["termination"] == "repaired"
    assert r["violation"]["kawasaki_after"] <= 1e-13
    repaired = r.pop("repaired")
    assert rigidfold.check(repaired)["verdict_class"] == "foldable"
    expected = cli("repair", path, "--out", str(tmp_path / "repaired.fold"))
    assert expected.pop("file") == path
    assert expected.pop("out") == str(tmp_path / "repaired.fold")
    assert without_timings(r) == without_timings(expected)


def test_repair_bad_arguments_are_value_errors():
    p = rigidfold.miura_ori(rows=3, cols=3, perturbation=0.03)
    with pytest.raises(ValueError, match="fixed vertex 99"):
        rigidfold.repair(p, fixed_vertices=[99])
    with pytest.raises(ValueError, match="max move"):
        rigidfold.repair(p, max_move=-1.0)


def test_add_creases_finds_the_type2_diagonal():
    p = rigidfold.square_twist("type2", twist=math.radians(30))
    r = rigidfold.add_creases(p, max_added=1)
    assert r["termination"] == "creases added"
    assert len(r["patterns"]) == len(r["found"]) > 0
    for entry, pattern in zip(r["found"], r["patterns"]):
        assert entry["verdict_class"] == "foldable"
        assert rigidfold.check(pattern)["verdict_class"] == "foldable"
    assert any(e["dof"] == 1 and e["creases"][0]["letter"] == "V" for e in r["found"])


def test_nearest_closed_state_closes_a_noisy_target():
    p = rigidfold.miura_ori(rows=4, cols=4)
    state = np.nan_to_num(rigidfold.miura_fold_angles(p, rows=4, cols=4, rho_straight=0.8))
    rng = np.random.default_rng(5)
    target = state + rng.uniform(-0.01, 0.01, size=state.shape) * (state != 0)
    r = rigidfold.nearest_closed_state(p, target, held_edges=[])
    assert r["converged"] is True
    assert r["residual"] <= 1e-12
    assert np.linalg.norm(r["angles"] - target) <= np.linalg.norm(state - target) * (1 + 1e-9)
    with pytest.raises(ValueError, match="angles for"):
        rigidfold.nearest_closed_state(p, target[:-1])
