"""trace(): fold angles per step (radians, FOLD sign) against the kernel's Miura closed form."""
import math

import numpy as np
import pytest

import rigidfold

PARAMS = dict(rows=4, cols=4, alpha=math.radians(60))


def straight_drive(pattern):
    probe = rigidfold.miura_fold_angles(pattern, rho_straight=0.5, **PARAMS)
    return int(np.flatnonzero(probe == 0.5)[0])


def closed_form_error(pattern, branch):
    error = 0.0
    for s, rho in enumerate(branch["drive"]):
        closed = rigidfold.miura_fold_angles(pattern, rho_straight=rho, **PARAMS)
        known = ~np.isnan(closed)
        assert known.sum() > 0
        error = max(error, float(np.max(np.abs(branch["fold_angles"][s, known] - closed[known]))))
    return error


@pytest.mark.parametrize("force_general", [False, True])
def test_miura_trace_matches_closed_form(force_general):
    pattern = rigidfold.miura_ori(**PARAMS)
    drive = straight_drive(pattern)
    steps = 30 if force_general else 40
    result = rigidfold.trace(pattern, drive=drive, to=math.radians(150), steps=steps, force_general=force_general)
    assert result["model"].startswith("general" if force_general else "multiplier")
    (branch,) = result["branches"]
    assert branch["traced"] and branch["drive_edge"] == drive
    assert branch["fold_angles"].shape == (steps, pattern.num_edges)
    assert branch["drive"].shape == (steps,)
    assert np.array_equal(branch["fold_angles"][:, drive], branch["drive"])
    assert branch["drive"][-1] == pytest.approx(math.radians(150), abs=1e-12)
    assert np.all(np.diff(branch["drive"]) > 0)
    assert closed_form_error(pattern, branch) <= 1e-10
    assert np.max(branch["residual"]) <= 1e-10
    assert branch["folded_vertices"].shape == (steps, pattern.num_vertices, 3)
    # Folded: the sheet has left the plane.
    assert np.ptp(branch["folded_vertices"][-1][:, 2]) > 0.5


def test_trace_bad_drive_raises_input_error():
    pattern = rigidfold.miura_ori(**PARAMS)
    with pytest.raises(rigidfold.InputError) as info:
        rigidfold.trace(pattern, drive=pattern.num_edges + 5)
    assert info.value.place == "drive"


def test_trace_states_its_coordinate_precision():
    pattern = rigidfold.miura_ori(**PARAMS)
    assert rigidfold.trace(pattern, steps=2, coordinate_tolerance=0.0)["coordinate_precision"] == \
        "coordinates taken as exact (--tolerance exact)"
    with pytest.raises(rigidfold.InputError) as info:
        rigidfold.trace(pattern, coordinate_tolerance=-1.0)
    assert info.value.place == "tolerance"


# Every bundled pattern with one motion from flat to trace (the others: no rigid motion with
# their letters, several DOF, or a sheet with holes traced both ways from its given state).
@pytest.mark.parametrize("name", ["corrugated_p_rigid.fold", "corrugated_q_rigid.fold", "miura_12x12_folded.fold",
                                  "miura_4x4_alpha60.fold", "square_twist_30_type1m.fold",
                                  "square_twist_30_type2m.fold", "square_twist_30_type3.fold",
                                  "square_twist_30_type4.fold"])
def test_trace_equals_the_cli_csv_bit_for_bit(tmp_path, name):
    import csv
    import subprocess

    from conftest import bundled, cli_path

    path = bundled(name)
    out = tmp_path / "angles.csv"
    subprocess.run([cli_path(), "trace", path, "--steps", "12", "--csv", str(out)], check=True, capture_output=True)
    rows = list(csv.DictReader(open(out)))
    pattern = rigidfold.load(path)
    (branch,) = rigidfold.trace(pattern, steps=12)["branches"]
    assert len(rows) == len(branch["drive"]) == 12
    for s, row in enumerate(rows):
        assert float(row["drive_deg"]) == np.degrees(branch["drive"][s])
        assert float(row["max_residual_rad"]) == branch["residual"][s]
        got = np.degrees(branch["fold_angles"][s])
        want = np.array([float(row[f"e{e}_deg"]) for e in range(pattern.num_edges)])
        assert np.array_equal(got, want)
