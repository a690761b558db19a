"""Thick vertices (seed 003 ch. 4), SORCE joints (seed 002) and the square-twist metamaterial
unit (seed 003 3.3.2) from Python, each checked against an independent computation."""
import math

import numpy as np
import pytest

import rigidfold


def closure_error(vertex, rho):
    m = vertex.loop_product(np.asarray(rho))
    return np.max(np.abs(m - np.eye(4)))


@pytest.mark.parametrize("make", [
    lambda: rigidfold.thick_bennett_vertex(math.radians(50), math.radians(80), 0.1),
    lambda: rigidfold.thick_myard_vertex(math.radians(40), 0.1),
    lambda: rigidfold.thick_diamond_vertex(math.radians(35), 0.1, 0.05),
    lambda: rigidfold.thick_waterbomb_vertex(1.0, 0.1),
])
def test_thick_vertices_close_on_the_zero_thickness_motion(make):
    v = make()
    assert len(v.sectors) == len(v.mountain_valley) == len(v.joints)
    for magnitude in np.linspace(0.05, 0.95 * math.pi, 12):
        rho = v.zero_thickness_fold_angles(v.mountain_valley[0] * magnitude)
        assert closure_error(v, rho) <= 1e-12, (v.name, magnitude)


def test_waterbomb_half_mu_leaves_the_zero_thickness_motion():
    v = rigidfold.thick_waterbomb_vertex(0.5, 0.1)
    worst = max(closure_error(v, v.zero_thickness_fold_angles(-m)) for m in np.linspace(0.2, 2.5, 8))
    assert worst > 1e-3  # seed eq 4-60: only mu = 1 keeps the motion


def test_thick_loop_product_is_a_rigid_motion_anywhere():
    v = rigidfold.thick_bennett_vertex(math.radians(50), math.radians(80), 0.1)
    m = v.loop_product(np.array([0.3, -1.1, 0.7, 2.0]))
    assert np.allclose(m[:3, :3] @ m[:3, :3].T, np.eye(3), atol=1e-14)
    assert np.allclose(m[3], [0, 0, 0, 1])
    with pytest.raises(ValueError):
        v.loop_product(np.zeros(3))


def test_sorce_circular_joints_roll_on_circles():
    # Bird's-foot vertex (folds 1 and 3 collinear: alpha_1 + alpha_2 = pi; flat-foldable:
    # alpha_1 + alpha_3 = pi): circular joints of radius r by construction.
    r = 0.05
    a1 = math.radians(60)
    sectors = [a1, math.pi - a1, math.pi - a1, a1]
    out = rigidfold.sorce_circular_vertex(sectors, r, samples=201)
    assert len(out["folds"]) == 4
    for j in (1, 2, 3):  # folds 2, 3, 4 are circular joints by construction: contact points on circles of radius r
        f = out["folds"][j]
        for key in ("s_left", "s_right"):
            pts = f[key]
            # Fit the circle through three samples and check every sample lies on it.
            p1, p2, p3 = pts[5], pts[len(pts) // 2], pts[-6]
            a = np.array([[2 * (p2 - p1)[0], 2 * (p2 - p1)[1]], [2 * (p3 - p1)[0], 2 * (p3 - p1)[1]]])
            b = np.array([p2 @ p2 - p1 @ p1, p3 @ p3 - p1 @ p1])
            centre = np.linalg.solve(a, b)
            radii = np.linalg.norm(pts - centre, axis=1)
            assert np.max(np.abs(radii - r)) <= 1e-9, (j, key)
    for f in out["folds"]:
        assert f["max_rolling_residual"] <= 1e-9
        assert f["arc_length_left"] == pytest.approx(f["arc_length_right"], rel=1e-10)


def test_sorce_linear_offsets_report():
    sectors = [math.radians(70), math.radians(80), math.radians(110), math.radians(100)]
    out = rigidfold.sorce_vertex(sectors, [0.1, -0.1, 0.1, -0.1], [0.2] * 4, samples=101)
    for f in out["folds"]:
        assert f["t"][0] == 0.0 and f["t"][-1] == 1.0
        assert f["s_left"].shape == (len(f["t"]), 2)
        assert f["max_rolling_residual"] <= 1e-9 and f["max_contact_residual"] <= 1e-9
    with pytest.raises(rigidfold.InputError):
        rigidfold.sorce_vertex(sectors, [0.1] * 4, [0.2] * 4, parameterization="spline")


def test_square_twist_unit_against_finite_differences():
    alpha = math.radians(150)
    theta, h = 1.0, 1e-6
    s = rigidfold.square_twist_unit(theta, alpha)
    lo, hi = rigidfold.square_twist_unit(theta - h, alpha), rigidfold.square_twist_unit(theta + h, alpha)
    for key in ("L", "S", "H"):
        assert s["d" + key] == pytest.approx((hi[key] - lo[key]) / (2 * h), rel=1e-7, abs=1e-9)
    # (3-31) holds: -cos a cos theta + cos a cos phi - sin a sin theta sin phi = 0
    c, sn = math.cos(alpha), math.sin(alpha)
    assert abs(-c * math.cos(theta) + c * math.cos(s["phi"]) - sn * math.sin(theta) * math.sin(s["phi"])) <= 1e-14
    assert s["nu_SL"] < 0
    tops = rigidfold.square_twist_height_stationary_points(alpha)
    assert sum(t["maximum"] for t in tops) >= 1
    for t in tops:  # nu_HL changes sign at each stationary point of H
        before = rigidfold.square_twist_unit(t["theta"] - 1e-3, alpha)["nu_HL"]
        after = rigidfold.square_twist_unit(t["theta"] + 1e-3, alpha)["nu_HL"]
        assert before * after < 0
