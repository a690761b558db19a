"""Figures of rigidfold objects with matplotlib (Debian python3-matplotlib).

crease_pattern(pattern)          the crease pattern in Origami Simulator's colours
                                 (M red, V blue, B black, F yellow, U magenta, C green, J grey)
fold_angle_curves(branch)        every crease's fold angle (degrees) against the driving crease's
folded_state(branch, pattern)    the faces placed at one step of a traced branch (3D)
branch_diagram(check, traced, x, y)  every branch and bifurcation, crease y against crease x

Each takes an optional matplotlib Axes and returns the Axes it drew on. Inputs are the objects
rigidfold returns (CreasePattern; a branch dict of rigidfold.trace(...)["branches"]).
"""

import numpy as np

ASSIGNMENT_COLOURS = {
    "M": "#d62728",
    "V": "#1f5fd0",
    "B": "black",
    "F": "#d4b000",
    "U": "#c000c0",
    "C": "#2ca02c",
    "J": "0.5",
}


def _axes(ax, projection=None):
    if ax is not None:
        return ax
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(6, 5))
    return fig.add_subplot(111, projection=projection) if projection else fig.add_subplot(111)


def crease_pattern(pattern, ax=None, title=None, linewidth=1.5):
    """Draws the crease pattern in the xy-plane, seen from +z, each edge in its letter's colour."""
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D

    ax = _axes(ax)
    xy = pattern.vertices[:, :2]
    edges = pattern.edges
    letters = pattern.assignments
    segments = xy[edges]
    colours = [ASSIGNMENT_COLOURS.get(a, "0.3") for a in letters]
    widths = [linewidth * (1.3 if a == "B" else 1.0) for a in letters]
    ax.add_collection(LineCollection(segments, colors=colours, linewidths=widths))
    ax.autoscale()
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    present = [a for a in ASSIGNMENT_COLOURS if a in set(letters)]
    names = {"M": "mountain", "V": "valley", "B": "boundary", "F": "flat", "U": "unassigned", "C": "cut", "J": "join"}
    ax.legend(
        [Line2D([0], [0], color=ASSIGNMENT_COLOURS[a]) for a in present],
        [names[a] for a in present],
        loc="upper right",
        fontsize="small",
    )
    if title:
        ax.set_title(title)
    return ax


def fold_angle_curves(branch, pattern=None, ax=None, title=None, edges=None):
    """Plots each crease's fold angle (degrees) against the driving crease's fold angle (degrees).

    branch: a dict of rigidfold.trace(...)["branches"]; pattern: colours the curves by letter;
    edges: the edges to draw (default every edge that folds somewhere along the branch).
    """
    ax = _axes(ax)
    drive = np.degrees(np.asarray(branch["drive"]))
    rho = np.degrees(np.asarray(branch["fold_angles"]))
    if edges is None:
        edges = [e for e in range(rho.shape[1]) if np.nanmax(np.abs(rho[:, e])) > 0.0]
    letters = pattern.assignments if pattern is not None else None
    for e in edges:
        colour = ASSIGNMENT_COLOURS.get(letters[e], "0.3") if letters else None
        ax.plot(drive, rho[:, e], color=colour, linewidth=0.9)
    ax.axhline(0.0, color="0.6", linewidth=0.6)
    ax.set_xlabel(f"driving crease {branch['drive_edge']} fold angle (deg)")
    ax.set_ylabel("fold angle (deg; valley > 0)")
    ax.set_title(title or f"branch {branch['id']}: {len(edges)} creases, stopped: {branch['stop_reason']}")
    return ax


def folded_state(branch, pattern, step=-1, ax=None, title=None):
    """Draws the faces of `pattern` placed at one step of a traced branch (3D, file units)."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    ax = _axes(ax, projection="3d")
    pts = np.asarray(branch["folded_vertices"])[step]
    polys = [pts[face] for face in pattern.faces]
    ax.add_collection3d(Poly3DCollection(polys, facecolor="#e8d8b0", edgecolor="0.2", linewidths=0.5, alpha=0.9))
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    centre, half = (lo + hi) / 2.0, max(np.max(hi - lo) / 2.0, 1e-12)
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)
    drive = np.degrees(branch["drive"][step])
    ax.set_title(title or f"step {step % len(branch['drive']) + 1}: driving crease at {drive:.1f} deg")
    return ax


def branch_diagram(check_result, traced, x_edge, y_edge, ax=None, title=None):
    """Branch diagram (seed 001 Figs. 8 and 10): crease y_edge's fold angle against crease x_edge's
    (degrees), one curve per traced branch, and the points where branches meet.

    check_result: rigidfold.check(pattern); traced: rigidfold.trace(pattern, all_branches=True).
    Branches that keep every M/V letter (check_result's "signs_match_assignment") are drawn in
    colour, the others in grey; located bifurcations are red circles, the flat state a black dot.
    """
    ax = _axes(ax)
    keeps = {b["id"]: b.get("signs_match_assignment", False) for b in check_result.get("branches", [])}
    for branch in traced["branches"]:
        rho = np.degrees(np.asarray(branch["fold_angles"]))
        if rho.shape[0] == 0:
            continue
        if keeps.get(branch["id"]):
            ax.plot(rho[:, x_edge], rho[:, y_edge], linewidth=1.4, label=f"branch {branch['id']}")
        else:
            ax.plot(rho[:, x_edge], rho[:, y_edge], color="0.7", linewidth=0.8)
    for point in check_result.get("bifurcations", []):
        angles = point["angles_deg"]
        if point["kind"] == "bifurcation":
            ax.plot(angles[x_edge], angles[y_edge], "o", color="#d62728", markersize=7, fillstyle="none", mew=1.8)
        elif point["kind"] == "flat":
            ax.plot(angles[x_edge], angles[y_edge], "o", color="black", markersize=4)
    ax.set_xlabel(f"crease {x_edge} fold angle (deg)")
    ax.set_ylabel(f"crease {y_edge} fold angle (deg)")
    if any(keeps.values()):
        ax.legend(fontsize="small")
    ax.set_title(title or f"{len(traced['branches'])} branches, "
                 f"{sum(p['kind'] == 'bifurcation' for p in check_result.get('bifurcations', []))} bifurcations")
    return ax
