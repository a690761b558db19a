#!/usr/bin/env python3
"""Mountain-valley classes of a crease pattern (`rigidfold assignments PATTERN --json`).

Usage:
    rigidfold assignments P.fold --json > P.classes.json
    /usr/bin/python3 python/plot_assignments.py P.fold P.classes.json --out P_classes.png [--title TEXT]

One small crease-pattern drawing per listed class (mountains red, valleys blue, other edges
grey), titled with the class number, the assignments in it and its verdict ("rigid, DOF 1"
in green, "not rigid" in black). The letters apply to the JSON's "creases" (edge indices).
Uses matplotlib's Agg backend (no display needed).
"""
import argparse
import json
import math
import sys

from figure_source import stamp_inputs, version_of  # python/figure_source.py (the script directory is on sys.path)
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"M": "#d62728", "V": "#1f77b4"}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pattern")
    ap.add_argument("classes")
    ap.add_argument("--out", required=True)
    ap.add_argument("--title", default=None)
    a = ap.parse_args()
    try:
        with open(a.pattern) as f:
            fold = json.load(f)
        with open(a.classes) as f:
            summary = json.load(f)
        coords = fold["vertices_coords"]
        edges = fold["edges_vertices"]
        creases = summary["creases"]
        listed = summary["listed"]
        if any(len(c["letters"]) != len(creases) for c in listed):
            raise ValueError("a class's letters do not match the crease list")
        if any(e < 0 or e >= len(edges) for e in creases):
            raise ValueError("a crease index is not an edge of the pattern")
    except (OSError, ValueError, KeyError, TypeError) as e:
        print(f"plot_assignments: {e}", file=sys.stderr)
        return 2
    if not listed:
        print("plot_assignments: no class listed", file=sys.stderr)
        return 2
    cols = min(5, len(listed))
    rows = math.ceil(len(listed) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(2.4 * cols, 2.6 * rows), squeeze=False)
    letter_of = {}
    for k, c in enumerate(listed):
        ax = axes[k // cols][k % cols]
        letter_of = dict(zip(creases, c["letters"]))
        for e, (u, v) in enumerate(edges):
            letter = letter_of.get(e)
            colour = COLOURS.get(letter, "0.6")
            ax.plot([coords[u][0], coords[v][0]], [coords[u][1], coords[v][1]], color=colour,
                    lw=1.6 if letter else 0.8, ls="--" if letter == "V" else "-")
        ax.set_aspect("equal")
        ax.axis("off")
        verdict = c.get("verdict")
        rigid = verdict == "foldable"
        text = f"class {k + 1} ({c['orbit_size']})\n"
        text += (f"rigid, DOF {c['dof']}" if rigid else ("not rigid" if verdict else "no verdict"))
        ax.set_title(text, fontsize=8, color="tab:green" if rigid else "black")
    for k in range(len(listed), rows * cols):
        axes[k // cols][k % cols].axis("off")
    fig.suptitle(a.title or (f"{summary['classes']} classes of {summary['assignments']} flat-folding assignments, "
                             f"{summary['foldable_classes']} rigid (M red, V blue dashed)"), fontsize=10)
    fig.tight_layout()
    stamp_inputs(fig, [a.pattern, a.classes], version_of(summary))
    fig.savefig(a.out, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
