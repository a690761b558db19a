#!/usr/bin/env python3
"""Branch diagram of a pattern: every branch through the flat state and its bifurcations,
drawn like seed 001 Figs. 8 and 10 (fold angles of chosen creases against one crease).

Usage:
    rigidfold check P.fold --json > check.json
    rigidfold trace P.fold --branch all --csv dir/P.csv --json > trace.json
    /usr/bin/python3 python/plot_bifurcation.py check.json dir/P.b*.csv --x-edge 0 \
        --edges 12,1,7,6 --out diagram.png [--title TEXT]

One panel per crease in --edges: its fold angle (deg) against the fold angle of --x-edge
(deg), one curve per traced branch (branch id from the ".b<ID>." part of the CSV name).
Branches that keep every M/V letter (check.json "signs_match_assignment") are drawn in
colour, the others in grey; bifurcation points (check.json "bifurcations", kind
"bifurcation") are red circles; a branch ending at a fold limit (a crease at 180 deg, local
facet interference) ends with a black cross; a branch with global facet interference (faces
crossing) is dashed from there on. Agg backend (no display needed).
"""
import argparse
import csv
import json
import re
import sys

from figure_source import stamp_inputs, version_of  # python/figure_source.py (the script directory is on sys.path)
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header = rows[0]
    col = {name: i for i, name in enumerate(header)}
    return col, rows[1:]


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("check_json")
    ap.add_argument("csvs", nargs="+")
    ap.add_argument("--x-edge", type=int, default=0)
    ap.add_argument("--edges", default="")
    ap.add_argument("--out", required=True)
    ap.add_argument("--title", default="")
    a = ap.parse_args(argv)
    try:
        with open(a.check_json) as f:
            check = json.load(f)
    except (OSError, ValueError) as e:
        print(f"plot_bifurcation: {a.check_json}: {e}", file=sys.stderr)
        return 2
    info = {b["id"]: b for b in check.get("branches", []) if "id" in b}
    edges = [int(x) for x in a.edges.split(",") if x.strip()] or [a.x_edge + 1]
    fig, axes = plt.subplots(1, len(edges), figsize=(4.2 * len(edges), 4.0), squeeze=False)
    xkey = f"e{a.x_edge}_deg"
    kept = 0
    for path in sorted(a.csvs):
        m = re.search(r"\.b(\d+)\.", path)
        if not m:
            continue
        bid = int(m.group(1))
        b = info.get(bid, {})
        good = b.get("signs_match_assignment") is True
        kept += good
        try:
            col, rows = read_csv(path)
        except (OSError, IndexError) as e:
            print(f"plot_bifurcation: {path}: {e}", file=sys.stderr)
            return 2
        if not rows or xkey not in col:
            continue
        gi = b.get("global_interference")
        split = len(rows)
        if gi:
            drive = float(gi["from_driving_deg"])
            dcol = col["drive_deg"]
            for k, r in enumerate(rows):
                if abs(float(r[dcol]) - drive) < 1e-9:
                    split = k
                    break
        xs = [float(r[col[xkey]]) for r in rows]
        for ax, e in zip(axes[0], edges):
            key = f"e{e}_deg"
            if key not in col:
                continue
            ys = [float(r[col[key]]) for r in rows]
            style = dict(lw=1.6, alpha=0.9) if good else dict(lw=0.8, color="0.7")
            line = ax.plot(xs[: split + 1], ys[: split + 1], **style,
                           label=f"branch {bid}" if good else None)
            if split < len(rows) - 1:
                ax.plot(xs[split:], ys[split:], ls="--", color=line[0].get_color(), lw=style["lw"])
            if str(b.get("stopped_by", "")) == "fold limit":
                ax.plot(xs[-1], ys[-1], "kx", ms=6)
    for p in check.get("bifurcations", []):
        if p.get("kind") != "bifurcation":
            continue
        ang = p["angles_deg"]
        for ax, e in zip(axes[0], edges):
            ax.plot(ang[a.x_edge], ang[e], "o", mfc="none", mec="red", ms=9, mew=1.5)
    for ax, e in zip(axes[0], edges):
        ax.set_xlabel(f"fold angle of crease {a.x_edge} (deg)")
        ax.set_ylabel(f"fold angle of crease {e} (deg)")
        ax.axhline(0, color="0.85", lw=0.6)
        ax.axvline(0, color="0.85", lw=0.6)
        ax.grid(alpha=0.3)
    if kept:
        axes[0][0].legend(fontsize=7, loc="best")
    fig.suptitle(a.title or f"{check.get('file', '')}: branches (colour: every letter kept), bifurcations (red), fold limit (x)",
                 fontsize=9)
    fig.tight_layout()
    stamp_inputs(fig, [a.check_json, *a.csvs], version_of(check))
    fig.savefig(a.out, dpi=110)
    print(a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
