#!/usr/bin/env python3
"""Fold-angle curves of traced branches (`rigidfold trace ... --csv ANGLES.csv`).

Usage:
    /usr/bin/python3 python/plot_branches.py A.csv [B.csv ...] --out branches.png
        [--edges 3,7,12] [--title TEXT] [--all-edges]

One panel per CSV: the fold angle of every crease (deg) against the driving angle (deg).
Creases whose curves coincide (to 1e-9 deg) are drawn once and labelled together; creases
that never fold are left out unless --all-edges. Events from the `events` column are marked
on the curve of their crease: M/V switch (circle) and interference, a crease reaching
+-180 deg (cross). The flat state (0, 0) starts every curve, unless --from-given-state (traces
of sheets with holes start at the file's own folded state, their first row).

CSV columns (as written by rigidfold trace):
    step,drive_deg,max_residual_rad,mismatch,events,e0_deg,e1_deg,...
Uses matplotlib's Agg backend (no display needed).
"""
import argparse
import csv
import os
import sys

from figure_source import stamp_inputs  # python/figure_source.py (the script directory is on sys.path)
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_trace(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path}: empty file")
    header = rows[0]
    required = ["step", "drive_deg", "max_residual_rad", "mismatch", "events"]
    if header[:5] != required:
        raise ValueError(f"{path}: header must start with {','.join(required)}")
    edges = []
    for i, name in enumerate(header[5:]):
        if not (name.startswith("e") and name.endswith("_deg")):
            raise ValueError(f"{path}: column {i + 5} '{name}' is not eK_deg")
        edges.append(int(name[1:-4]))
    drive, residual, events, angles = [], [], [], {e: [] for e in edges}
    for n, row in enumerate(rows[1:], start=2):
        if not row:
            continue
        if len(row) != len(header):
            raise ValueError(f"{path}: line {n}: {len(row)} fields, header has {len(header)}")
        drive.append(float(row[1]))
        residual.append(float(row[2]))
        events.append([x for x in row[4].split(";") if x])
        for e, v in zip(edges, row[5:]):
            angles[e].append(float(v))
    return {"drive": drive, "residual": residual, "events": events, "angles": angles, "edges": edges}


def group_curves(trace, chosen, all_edges):
    """Edges with identical curves, as (label edges, values) groups."""
    groups = []
    for e in chosen:
        vals = trace["angles"][e]
        if not all_edges and all(abs(v) < 1e-9 for v in vals):
            continue
        for g in groups:
            if all(abs(a - b) <= 1e-9 for a, b in zip(g[1], vals)):
                g[0].append(e)
                break
        else:
            groups.append([[e], vals])
    return groups


def label_of(edges):
    if len(edges) <= 4:
        return "e" + ", e".join(str(e) for e in edges)
    return f"e{edges[0]}, e{edges[1]}, ... ({len(edges)} creases)"


def plot(paths, out, edges_filter, title, all_edges, flat_start=True):
    fig, axes = plt.subplots(1, len(paths), figsize=(6.2 * len(paths), 4.8), squeeze=False, sharey=True)
    for ax, path in zip(axes[0], paths):
        tr = read_trace(path)
        chosen = [e for e in tr["edges"] if edges_filter is None or e in edges_filter]
        groups = group_curves(tr, chosen, all_edges)
        start = [0.0] if flat_start else []
        x = start + tr["drive"]
        for edges, vals in groups:
            ax.plot(x, start + vals, lw=1.4, label=label_of(edges))
        if not flat_start and tr["drive"]:
            ax.plot(tr["drive"][0], 0, "|", color="0.3", ms=0)  # keeps the axes; the start is the first row
            ax.axvline(tr["drive"][0], color="0.5", lw=0.8, ls=":", label="given state")
        switch_done, hit_done = False, False
        for k, evs in enumerate(tr["events"]):
            for ev in evs:
                kind, _, crease = ev.partition(":")
                e = int(crease[1:]) if crease.startswith("e") and crease[1:].isdigit() else None
                if e is None or e not in tr["angles"] or (edges_filter is not None and e not in edges_filter):
                    continue
                y = tr["angles"][e][k]
                if kind == "mv_switch":
                    ax.plot(tr["drive"][k], y, "o", mfc="none", mec="crimson", ms=9,
                            label=None if switch_done else "M/V switch")
                    switch_done = True
                elif kind == "interference":
                    ax.plot(tr["drive"][k], y, "x", color="black", ms=9, mew=2,
                            label=None if hit_done else "reaches 180 deg (interference)")
                    hit_done = True
        for level in (-180, 180):
            ax.axhline(level, color="0.6", lw=0.8, ls="--")
        ax.axhline(0, color="0.8", lw=0.6)
        worst = max(tr["residual"]) if tr["residual"] else 0.0
        ax.set_title(f"{os.path.basename(path)}\nmax closure residual {worst:.1e} rad", fontsize=9)
        ax.set_xlabel("driving crease fold angle (deg)")
        ax.grid(alpha=0.3)
        if len(groups) + switch_done + hit_done <= 14:
            ax.legend(fontsize=7, loc="best")
    axes[0][0].set_ylabel("fold angle (deg; valley > 0, mountain < 0)")
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    tmp = out + ".tmp.png"
    stamp_inputs(fig, paths)
    fig.savefig(tmp, dpi=130)
    os.replace(tmp, out)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description="Plot fold angles of traced branches (rigidfold trace --csv).")
    ap.add_argument("csv", nargs="+", help="CSV files written by rigidfold trace --csv")
    ap.add_argument("--out", required=True, help="output PNG")
    ap.add_argument("--edges", help="comma-separated crease indices to plot (default: every crease that folds)")
    ap.add_argument("--title", default="", help="figure title")
    ap.add_argument("--all-edges", action="store_true", help="also draw creases that stay flat")
    ap.add_argument("--from-given-state", action="store_true",
                    help="the trace starts at the pattern's given (folded) state, e.g. a tube: no flat start")
    args = ap.parse_args(argv)
    edges = None
    if args.edges:
        try:
            edges = {int(x) for x in args.edges.split(",") if x.strip()}
        except ValueError:
            print(f"plot_branches.py: error: --edges: '{args.edges}' is not a list of integers", file=sys.stderr)
            return 2
    try:
        plot(args.csv, args.out, edges, args.title, args.all_edges, flat_start=not args.from_given_state)
    except (OSError, ValueError) as e:
        print(f"plot_branches.py: error: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
