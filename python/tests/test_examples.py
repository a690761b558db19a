"""The scripts in python/examples run and write what they say."""
import os
import subprocess
import sys

from conftest import EXAMPLES


def run(script, *args):
    return subprocess.run([sys.executable, os.path.join(EXAMPLES, script), *args], check=True,
                          capture_output=True, text=True, env=dict(os.environ, MPLBACKEND="Agg")).stdout


def test_check_bundled():
    out = run("check_bundled.py")
    assert "with its M-V assignment: foldable (model multiplier-propagation, DOF 1, proof True)" in out


def test_trace_miura_writes_png(tmp_path):
    out = run("trace_miura.py", "--out", str(tmp_path))
    png = tmp_path / "miura_trace.png"
    assert out.strip().splitlines()[-1] == str(png)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert png.stat().st_size > 20000
    error = float(out.split("closed form ")[1].split(" rad")[0])
    assert error <= 1e-10


def test_waterbomb_states():
    out = run("waterbomb_states.py")
    assert out.strip().endswith("2 stable states")


def test_plot_functions_return_axes(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import rigidfold
    import rigidfold.plot

    p = rigidfold.waterbomb_base(n=4)
    ax = rigidfold.plot.crease_pattern(p)
    assert len(ax.collections[0].get_segments()) == p.num_edges
    colours = ax.collections[0].get_colors()
    assert len({tuple(c) for c in colours}) == 3  # M, V, B


def test_branch_diagram_of_type2m(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import rigidfold
    import rigidfold.plot
    from conftest import bundled

    p = rigidfold.load(bundled("square_twist_30_type2m.fold"))
    checked = rigidfold.check(p)
    traced = rigidfold.trace(p, all_branches=True)
    assert len(traced["branches"]) == len(checked["branches"]) > 0
    assert [b["id"] for b in traced["branches"]] == [b["id"] for b in checked["branches"]]
    ax = rigidfold.plot.branch_diagram(checked, traced, x_edge=0, y_edge=12)
    bifurcations = sum(pt["kind"] == "bifurcation" for pt in checked["bifurcations"])
    assert bifurcations == 2
    red = [ln for ln in ax.lines if ln.get_marker() == "o" and ln.get_color() == "#d62728"]
    assert len(red) == bifurcations
    drawn = [ln for ln in ax.lines if ln.get_marker() in ("None", "", None)]
    assert len(drawn) == sum(b["fold_angles"].shape[0] > 0 for b in traced["branches"])
    ax.figure.savefig(tmp_path / "diagram.png")
    assert (tmp_path / "diagram.png").stat().st_size > 10000
