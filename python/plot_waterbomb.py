#!/usr/bin/env python3
"""Energy and force against apex height of a waterbomb base (seed 004 Figs 2.9-2.11, 3.x).

Usage:
    rigidfold waterbomb --n 4 --theta0-deg 60 --json > wb.json
    rigidfold waterbomb --n 4 --theta0-deg 60 --curve wb.csv
    /usr/bin/python3 python/plot_waterbomb.py wb.csv wb.json --out waterbomb.png [--title TEXT]

Left: spring energy V against the path angle theta (deg), the equilibria of the JSON marked
(stable states filled, maxima and the flat cusp open). Right: force against the apex
height h (push > 0; h falls as the base is pushed), the general model's reaction force as the line and eq. 3.9's closed form as
dots; stretches where the loaded symmetric state is unstable (a negative eigenvalue of the
reduced Hessian, the base buckles out of symmetry) drawn dashed. The flat state splits the
force curve in two (the path has a corner there: the force jumps).

CSV columns (as written by rigidfold waterbomb --curve):
    theta_deg,gamma_m_deg,gamma_v_deg,energy,height,deflection,force,force_closed_form,
    min_reduced_hessian_eigenvalue,stable
Sweep mode (the table of rigidfold waterbomb --sweep-n ... --plot DIR):
    /usr/bin/python3 python/plot_waterbomb.py --sweep sweep.csv --out sweep.png
Left: the second stable state's theta against n, one line per (split width, k ratio); right:
the symmetric-path barrier from the rest state against n. Rows without numbers are skipped.

Uses matplotlib's Agg backend (no display needed).
"""
import argparse
import csv
import json
import sys

from figure_source import stamp_inputs, version_of  # python/figure_source.py (the script directory is on sys.path)
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLUMNS = ["theta_deg", "gamma_m_deg", "gamma_v_deg", "energy", "height", "deflection", "force",
           "force_closed_form", "min_reduced_hessian_eigenvalue", "stable"]


def read_curve(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows or rows[0] != COLUMNS:
        raise ValueError(f"{path}: header must be {','.join(COLUMNS)}")
    out = []
    for i, row in enumerate(rows[1:], start=2):
        if len(row) != len(COLUMNS):
            raise ValueError(f"{path}: line {i}: {len(row)} fields, expected {len(COLUMNS)}")
        try:
            out.append({k: float(v) for k, v in zip(COLUMNS, row)})
        except ValueError as e:
            raise ValueError(f"{path}: line {i}: {e}") from None
    if len(out) < 3:
        raise ValueError(f"{path}: fewer than 3 samples")
    return out


def runs(samples, key):
    """Consecutive samples with the same value of key and on the same side of the flat state."""
    groups = []
    for s in samples:
        tag = (s[key], s["theta_deg"] < 90.0)
        if groups and groups[-1][0] == tag:
            groups[-1][1].append(s)
        else:
            groups.append((tag, [s]))
    return groups


SWEEP_COLUMNS = ["n", "split_deg", "k_ratio", "theta0_deg", "status", "stable_states", "state2_theta_deg",
                 "state2_gamma_m_deg", "state2_gamma_v_deg", "state2_energy", "barrier_from_rest",
                 "barrier_from_state2", "switching_force"]


def main_sweep(argv):
    ap = argparse.ArgumentParser(description="waterbomb design sweep")
    ap.add_argument("--sweep", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args(argv)
    try:
        with open(a.sweep, newline="") as f:
            rows = list(csv.reader(f))
        if not rows or rows[0] != SWEEP_COLUMNS:
            raise ValueError(f"{a.sweep}: header must be {','.join(SWEEP_COLUMNS)}")
        table = [dict(zip(SWEEP_COLUMNS, r)) for r in rows[1:]]
    except (OSError, ValueError) as e:
        print(f"plot_waterbomb: {e}", file=sys.stderr)
        return 2
    series = {}
    for r in table:
        if r["status"] != "ok" or not r["state2_theta_deg"]:
            continue
        key = (float(r["split_deg"]), float(r["k_ratio"]))
        series.setdefault(key, []).append((int(r["n"]), float(r["state2_theta_deg"]),
                                           float(r["barrier_from_rest"]) if r["barrier_from_rest"] else float("nan")))
    fig, (ax_t, ax_b) = plt.subplots(1, 2, figsize=(11, 4.2))
    for (b, k), pts in sorted(series.items()):
        pts.sort()
        label = ("plain" if b == 0 else f"b = {b:g} deg") + f", k_m/k_v = {k:g}"
        ax_t.plot([p[0] for p in pts], [p[1] for p in pts], "o-", ms=3, lw=1.2, label=label)
        ax_b.plot([p[0] for p in pts], [p[2] for p in pts], "o-", ms=3, lw=1.2, label=label)
    ax_t.axhline(90.0, color="0.7", lw=0.8, ls=":")
    ax_t.set_xlabel("degree n")
    ax_t.set_ylabel("second stable state theta (deg)")
    ax_t.set_title("second stable state")
    ax_b.set_xlabel("degree n")
    ax_b.set_ylabel("barrier from the rest state (symmetric path)")
    ax_b.set_title("energy barrier over the flat state")
    ax_t.legend(fontsize=7)
    t0 = table[0]["theta0_deg"] if table else "?"
    fig.suptitle(f"waterbomb design sweep, rest theta0 = {t0} deg")
    fig.tight_layout()
    stamp_inputs(fig, [a.sweep])
    fig.savefig(a.out, dpi=120)
    return 0


def main():
    if "--sweep" in sys.argv[1:]:
        return main_sweep(sys.argv[1:])
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("curve")
    ap.add_argument("summary")
    ap.add_argument("--out", required=True)
    ap.add_argument("--title", default=None)
    a = ap.parse_args()
    try:
        samples = read_curve(a.curve)
        with open(a.summary) as f:
            summary = json.load(f)
        equilibria = summary["equilibria"]
    except (OSError, ValueError, KeyError) as e:
        print(f"plot_waterbomb: {e}", file=sys.stderr)
        return 2
    fig, (ax_e, ax_f) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax_e.plot([s["theta_deg"] for s in samples], [s["energy"] for s in samples], color="black", lw=1.2)
    for e in equilibria:
        stable = e["stable"]
        ax_e.plot(e["theta_deg"], e["energy"], "o", ms=7, color="tab:blue" if stable else "tab:red",
                  mfc="tab:blue" if stable else "white")
        ax_e.annotate(f"{e['theta_deg']:.2f}", (e["theta_deg"], e["energy"]), textcoords="offset points",
                      xytext=(4, 6), fontsize=8)
    ax_e.axvline(90.0, color="0.7", lw=0.8, ls=":")
    ax_e.set_xlabel("theta (deg)")
    ax_e.set_ylabel("spring energy V")
    ax_e.set_title("energy on the symmetric path (filled: stable)")
    for (stable, _), group in runs(samples, "stable"):
        ax_f.plot([s["height"] for s in group], [s["force"] for s in group], color="tab:blue",
                  ls="-" if stable else "--", lw=1.4)
    ax_f.plot([s["height"] for s in samples[::6]], [s["force_closed_form"] for s in samples[::6]], ".",
              color="black", ms=3, label="closed form (eq. 3.9; split fold: dV/dh of eqs 3.15-3.31)")
    ax_f.plot([], [], color="tab:blue", label="general model, stable")
    ax_f.plot([], [], color="tab:blue", ls="--", label="general model, unstable (buckles)")
    ax_f.axhline(0.0, color="0.7", lw=0.8)
    # F = V'(theta) / (r sin theta) grows without bound toward theta = 0 (the base standing
    # upright): show the middle 90% of the forces, with room around them.
    forces = sorted(s["force"] for s in samples)
    lo, hi = forces[len(forces) // 20], forces[-1 - len(forces) // 20]
    pad = 0.3 * max(hi - lo, 1e-12)
    ax_f.set_ylim(min(lo, 0.0) - pad, max(hi, 0.0) + pad)
    ax_f.axvline(0.0, color="0.7", lw=0.8, ls=":")  # the flat state: h = 0
    ax_f.set_xlabel("apex height h (radius-1 base, unit creases if split; flat at 0)")
    ax_f.set_ylabel("force F (push > 0)")
    ax_f.set_title("force against apex height (displacement control)")
    ax_f.legend(fontsize=8)
    n, t0 = summary.get("n"), summary.get("theta0_deg")
    kind = "waterbomb base" if "split_deg" not in summary else f"split-fold waterbomb base (b = {summary['split_deg']} deg)"
    fig.suptitle(a.title or f"{kind} n = {n}, rest theta0 = {t0} deg, k_m = {summary.get('k_m')}, "
                 f"k_v = {summary.get('k_v')}")
    fig.tight_layout()
    stamp_inputs(fig, [a.curve, a.summary], version_of(summary))
    fig.savefig(a.out, dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
