"""The closure Jacobian (scipy.sparse) against finite differences, and the flat-foldable
degree-4 closed forms against the vertex closure condition."""
import math

import numpy as np
import pytest

import rigidfold

scipy_sparse = pytest.importorskip("scipy.sparse", reason="python3-scipy is not installed")


def rx(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def rz(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def vertex_product(rho, sectors):
    r = np.eye(3)
    for a, b in zip(rho, sectors):
        r = r @ rx(a) @ rz(b)
    return r


def test_jacobian_equals_finite_difference_of_residual():
    pattern = rigidfold.square_twist("type2m")
    rng = np.random.default_rng(7)
    angles = rng.uniform(-1.0, 1.0, pattern.num_edges)
    residual, jac, free = rigidfold.closure_jacobian(pattern, angles)
    system = rigidfold.ClosureSystem(pattern)
    x = system.unknowns_from_edges(angles)
    assert scipy_sparse.issparse(jac)
    assert jac.shape == (system.num_rows, system.num_unknowns) == (3 * system.num_vertices, len(free))
    assert np.array_equal(residual, system.residual(x))
    assert np.max(np.abs(residual)) > 1e-3  # a random point does not close
    h = 1e-6
    fd = np.empty(jac.shape)
    for k in range(len(x)):
        step = np.zeros_like(x)
        step[k] = h
        fd[:, k] = (system.residual(x + step) - system.residual(x - step)) / (2 * h)
    error = np.max(np.abs(jac.toarray() - fd))
    assert error <= 1e-8, error


def test_jacobian_at_a_folded_miura_has_one_dimensional_kernel():
    params = dict(rows=2, cols=2, alpha=math.radians(60))
    pattern = rigidfold.miura_ori(**params)
    closed = np.nan_to_num(rigidfold.miura_fold_angles(pattern, rho_straight=1.0, **params))
    residual, jac, _ = rigidfold.closure_jacobian(pattern, closed)
    assert np.max(np.abs(residual)) <= 1e-14
    s = np.linalg.svd(jac.toarray(), compute_uv=False)
    n = jac.shape[1]
    rank = int(np.sum(s > 1e-9 * s[0]))
    assert n - rank == 1


def test_flat_fold_angles_close_the_vertex():
    a = math.radians(60)
    sectors = [a, a, math.pi - a, math.pi - a]
    # equal13 of this vertex (d = 0) folds the straight line 1-3 alone: crease 0 stays flat.
    for mode, driver in (("equal02", 0), ("equal13", 1)):
        for rho in (0.3, -1.2, 2.5):
            angles = rigidfold.flat_fold_angles(sectors, mode, rho, driver=driver)
            assert angles.shape == (4,)
            assert angles[driver] == rho
            assert np.max(np.abs(vertex_product(angles, sectors) - np.eye(3))) <= 1e-14
    m = rigidfold.flat_fold_angles(sectors, "equal02", 0.7)
    assert m[2] == pytest.approx(m[0], abs=1e-15) and m[3] == pytest.approx(-m[1], abs=1e-15)
    w = rigidfold.flat_fold_multipliers(sectors, "equal02")
    assert w["odd_crease"] == 1
    assert np.array_equal(rigidfold.flat_fold_angles(sectors, "equal13", 0.4, driver=1)[[0, 2]], [0.0, 0.0])
    with pytest.raises(ValueError, match="stays flat"):
        rigidfold.flat_fold_angles(sectors, "equal13", 0.5, driver=0)
    with pytest.raises(ValueError):
        rigidfold.flat_fold_angles([1.0, 1.0, 1.0, 1.0], "equal02", 0.5)
    with pytest.raises(rigidfold.InputError):
        rigidfold.flat_fold_angles(sectors, "sideways", 0.5)


def test_miura_vertex_equals_cli_and_closes(cli):
    v = rigidfold.miura_vertex(math.radians(50), math.radians(70), math.radians(40))
    expected = cli("vertex", "miura", "--alpha1", "50", "--alpha2", "70", "--theta", "40")
    assert math.degrees(v["phi"]) == pytest.approx(expected["phi_deg"], abs=1e-12)
    assert math.degrees(v["psi"]) == pytest.approx(expected["psi_deg"], abs=1e-12)
    assert math.degrees(v["theta_limit"]) == pytest.approx(expected["theta_limit_deg"], abs=1e-12)
    assert v["crease_names"] == [c["crease"] for c in expected["fold_angles_deg"]]
    assert np.allclose(np.degrees(v["fold_angles"]), [c["fold_angle_deg"] for c in expected["fold_angles_deg"]],
                       rtol=0, atol=1e-12)
    assert v["closure_residual"] == expected["closure_residual_rad"]
    assert np.max(np.abs(vertex_product(v["fold_angles"], v["sectors"]) - np.eye(3))) <= 1e-14
    assert v["fold_angles"][2] == pytest.approx(2 * math.radians(40), abs=1e-15)  # rho_c = 2 theta


def test_error_classes():
    assert issubclass(rigidfold.InputError, ValueError)
    assert issubclass(rigidfold.NoAnswerError, RuntimeError)
    with pytest.raises(ValueError, match="theta_limit"):
        rigidfold.miura_vertex(math.radians(50), math.radians(70), math.radians(80))  # beyond theta_limit


def test_vertex_of_block_checks_its_index():
    """An index outside [0, num_vertices) raises IndexError (it read out of bounds, or crashed
    the interpreter, before)."""
    system = rigidfold.ClosureSystem(rigidfold.square_twist("type2m"))
    n = system.num_vertices
    assert n > 0
    assert all(0 <= system.vertex_of_block(k) for k in range(n))
    for bad in (-1, n, 10**9, -(10**12), 2**40):
        with pytest.raises(IndexError):
            system.vertex_of_block(bad)
