"""Patterns: FOLD load/save, the arrays, generators, and bad input as rigidfold.InputError."""
import json
import math

import numpy as np
import pytest

import rigidfold
from conftest import bundled


def test_load_arrays_match_the_fold_file():
    path = bundled("miura_4x4_alpha60.fold")
    doc = json.load(open(path))
    p = rigidfold.load(path)
    assert isinstance(p, rigidfold.CreasePattern)
    coords = np.array(doc["vertices_coords"], dtype=float)
    assert p.vertices.shape == (len(coords), 3)
    assert np.array_equal(p.vertices[:, : coords.shape[1]], coords)
    assert p.edges.shape == (len(doc["edges_vertices"]), 2)
    assert np.array_equal(p.edges, np.array(doc["edges_vertices"]))
    assert p.assignments == [a.upper() for a in doc["edges_assignment"]]
    assert p.num_faces == len(p.faces) > 0
    assert all(len(f) >= 3 for f in p.faces)


def test_save_and_load_round_trip(tmp_path):
    p = rigidfold.square_twist("type2m")
    out = tmp_path / "twist.fold"
    rigidfold.save(p, str(out))
    q = rigidfold.load(str(out))
    assert np.array_equal(p.vertices, q.vertices)
    assert np.array_equal(p.edges, q.edges)
    assert p.assignments == q.assignments
    assert p.faces == q.faces
    assert rigidfold.parse_fold(p.to_fold_string()).assignments == p.assignments


def test_fold_angles_are_radians():
    p = rigidfold.load(bundled("miura_12x12_folded.fold"))
    doc = json.load(open(bundled("miura_12x12_folded.fold")))
    deg = np.array([np.nan if a is None else a for a in doc["edges_foldAngle"]], dtype=float)
    assert np.allclose(np.degrees(p.fold_angles), deg, equal_nan=True, rtol=0, atol=1e-12)
    assert np.nanmax(np.abs(p.fold_angles)) <= math.pi


def test_generators():
    m = rigidfold.miura_ori(rows=3, cols=5)
    assert m.num_faces == 15
    assert set(m.assignments) == {"M", "V", "B"}
    w = rigidfold.waterbomb_base(n=6)
    assert w.assignments.count("M") == 6 and w.assignments.count("V") == 6
    assert rigidfold.square_twist("type1").num_edges == rigidfold.square_twist("type4").num_edges
    assert rigidfold.corrugated_unit("P").num_edges > 12
    bundled_names = rigidfold.bundled_examples()
    assert "corrugated_p_rigid" in bundled_names
    assert bundled_names["corrugated_p_rigid"].assignments == rigidfold.load(bundled("corrugated_p_rigid.fold")).assignments


def test_bad_fold_file_raises_input_error_naming_file_and_place(tmp_path):
    bad = tmp_path / "bad.fold"
    bad.write_text('{"vertices_coords": [[0,0],[1,0],[1,1],[0,1]], '
                   '"edges_vertices": [[0,1],[1,2],[2,9],[3,0]], "edges_assignment": ["B","B","B","B"]}')
    with pytest.raises(rigidfold.InputError) as info:
        rigidfold.load(str(bad))
    message = str(info.value)
    assert str(bad) in message
    assert "edges_vertices[2][1]" in message
    assert info.value.place.startswith(str(bad))
    assert isinstance(info.value, ValueError)


def test_missing_file_and_bad_parameter():
    with pytest.raises(rigidfold.InputError, match="no_such.fold"):
        rigidfold.load("/nonexistent/no_such.fold")
    with pytest.raises(rigidfold.InputError) as info:
        rigidfold.miura_ori(alpha=2.0)
    assert info.value.place == "alpha"
    with pytest.raises(rigidfold.InputError, match="my-text"):
        rigidfold.parse_fold("{", source="my-text")


def test_pattern_from_arrays_equals_the_loaded_file():
    p = rigidfold.load(bundled("corrugated_p_rigid.fold"))
    q = rigidfold.CreasePattern(p.vertices[:, :2], p.edges, p.assignments)
    assert q.coords_2d
    assert np.array_equal(q.vertices, p.vertices)
    assert q.num_faces == p.num_faces
    assert rigidfold.check(q)["reason"] == rigidfold.check(p)["reason"]
    # Without letters: B on the boundary, U inside (as a FOLD file without edges_assignment).
    u = rigidfold.CreasePattern(p.vertices, p.edges)
    assert set(u.assignments) == {"B", "U"}
    assert u.assignments.count("B") == p.assignments.count("B")
    angles = np.full(p.num_edges, np.nan)
    angles[3] = 0.25
    f = rigidfold.CreasePattern(p.vertices, p.edges, p.assignments, fold_angles=angles)
    assert f.fold_angles[3] == 0.25 and np.isnan(f.fold_angles[0])


def test_pattern_from_bad_arrays_names_the_place():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    edges = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])
    with pytest.raises(rigidfold.InputError, match=r"^mine: assignments\[2\]"):
        rigidfold.CreasePattern(square, edges, ["B", "B", "X", "B"], source="mine")
    with pytest.raises(rigidfold.InputError, match="^arrays: "):
        rigidfold.CreasePattern(square, np.array([[0, 1], [1, 2], [2, 7], [3, 0]]))
    with pytest.raises(rigidfold.InputError, match="vertices"):
        rigidfold.CreasePattern(np.zeros((4, 4)), edges)
