#!/usr/bin/python3
"""Figures for `rigidfold report`: crease patterns, folded states, single-vertex modes.

Usage: python3 python/plot_report.py OUTDIR [--cli build/app/rigidfold]
Reads OUTDIR/report.json (written by `rigidfold report`) and writes OUTDIR/figures/*.png.
Colours follow the usual convention: mountain red, valley blue, boundary black, flat grey.
"""
import argparse
import json
import math
import os
import subprocess
import sys

from figure_source import stamp_inputs, version_of  # python/figure_source.py (the script directory is on sys.path)
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

COLOURS = {"M": "#d62728", "V": "#1f77b4", "B": "black", "F": "#bbbbbb", "U": "#2ca02c", "C": "#9467bd", "J": "#8c564b"}


def load(path):
    with open(path) as f:
        return json.load(f)


def draw_crease_pattern(ax, fold, title):
    coords = [list(v) + [0.0] * (3 - len(v)) for v in fold["vertices_coords"]]
    # Draw in the plane of the two widest coordinates (Origami Simulator files use x-z).
    spans = [max(c[k] for c in coords) - min(c[k] for c in coords) for k in range(3)]
    k0, k1 = sorted(sorted(range(3), key=lambda k: -spans[k])[:2])
    xy = [(c[k0], c[k1]) for c in coords]
    if min(spans) > 1e-9 * max(spans):  # a pattern given in 3D (e.g. a tube): say it is a projection
        title += f"\n(given in 3D; projected on the {'xyz'[k0]}{'xyz'[k1]}-plane)"
    assignment = fold.get("edges_assignment", ["U"] * len(fold["edges_vertices"]))
    for (a, b), letter in zip(fold["edges_vertices"], assignment):
        style = "--" if letter == "M" else "-"
        ax.plot([xy[a][0], xy[b][0]], [xy[a][1], xy[b][1]], style, color=COLOURS.get(letter, "grey"),
                lw=1.6 if letter in "MV" else 1.0)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=9)
    ax.axis("off")


def draw_folded(ax, fold, title):
    frame = fold["file_frames"][-1]
    pts = frame["vertices_coords"]
    polys = [[pts[v] for v in face] for face in fold["faces_vertices"]]
    ax.add_collection3d(Poly3DCollection(polys, facecolor="#9ecae1", edgecolor="#333333", linewidths=0.4, alpha=0.9))
    xs, ys, zs = zip(*pts)
    span = max(max(xs) - min(xs), max(ys) - min(ys), max(zs) - min(zs), 1e-9) / 2
    cx, cy, cz = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2, (max(zs) + min(zs)) / 2
    ax.set_xlim(cx - span, cx + span)
    ax.set_ylim(cy - span, cy + span)
    ax.set_zlim(cz - span, cz + span)
    ax.set_title(title, fontsize=9)
    ax.set_axis_off()


def s4r_sweep(cli, twists):
    """Both branches of a spherical 4R over its input range, from `rigidfold vertex s4r`."""
    inputs, branches = [], [[], []]
    for k in range(-179, 180, 2):
        out = subprocess.run([cli, "vertex", "s4r", "--twists", ",".join(f"{t:.17g}" for t in twists),
                              "--input", str(k), "--json"], capture_output=True, text=True, check=True)
        res = json.loads(out.stdout)
        if len(res["branches"]) < 2:
            continue
        inputs.append(k)
        for i in range(2):
            branches[i].append(res["branches"][i]["angles_deg"])
    return inputs, branches


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir")
    parser.add_argument("--cli", default=os.path.join(os.path.dirname(__file__), "..", "build", "app", "rigidfold"))
    args = parser.parse_args()
    report = load(os.path.join(args.outdir, "report.json"))
    figdir = os.path.join(args.outdir, "figures")
    os.makedirs(figdir, exist_ok=True)
    patterns = report["patterns"]

    # 1. All crease patterns on one sheet.
    cols = min(4, len(patterns))
    rows = math.ceil(len(patterns) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(3.2 * cols, 3.2 * rows), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for ax, p in zip(axes.flat, patterns):
        draw_crease_pattern(ax, load(p["file"]), f"{p['name']}\n{p['local_verdict'][:60]}")
    fig.suptitle("Bundled crease patterns (mountain red dashed, valley blue)")
    fig.tight_layout()
    stamp_inputs(fig, [p["file"] for p in patterns], version_of(report))
    fig.savefig(os.path.join(figdir, "crease_patterns.png"), dpi=110)
    plt.close(fig)

    # 2. Folded states, one per pattern that carries fold angles.
    folded = [p for p in patterns if "folded_file" in p]
    for p in folded:
        fig = plt.figure(figsize=(8, 4))
        draw_crease_pattern(fig.add_subplot(1, 2, 1), load(p["file"]), p["name"])
        draw_folded(fig.add_subplot(1, 2, 2, projection="3d"), load(p["folded_file"]),
                    f"folded; closure mismatch {p['relative_closure_mismatch']:.1e} (relative)")
        fig.tight_layout()
        stamp_inputs(fig, [p["file"], p["folded_file"]], version_of(report))
        fig.savefig(os.path.join(figdir, f"{p['name']}_folded.png"), dpi=110)
        plt.close(fig)

    # 3. Single-vertex modes: the spherical 4R of a Miura vertex (60 deg) and of a generic
    #    flat-foldable vertex, both branches, from the closed form.
    if os.path.exists(args.cli):
        fig, axes = plt.subplots(1, 2, figsize=(10, 4))
        for ax, twists, name in [(axes[0], [60, 60, 120, 120], "Miura vertex 60/60/120/120"),
                                 (axes[1], [50, 110, 130, 70], "flat-foldable vertex 50/110/130/70")]:
            inputs, branches = s4r_sweep(args.cli, twists)
            # Dots, not lines: the two roots are not ordered along the motion, and +-180 are
            # one angle, so joining them would draw false jumps.
            for i, marker in enumerate(["o", "x"]):
                for j, colour in zip(range(1, 4), ["C0", "C1", "C2"]):
                    ax.plot(inputs, [b[j] for b in branches[i]], marker, ms=2.5, color=colour, linestyle="none",
                            label=f"theta{j + 1} root {i}")
            ax.set_xlabel("theta1 (deg, valley > 0)")
            ax.set_ylabel("fold angle (deg)")
            ax.set_title(name, fontsize=10)
            ax.grid(alpha=0.3)
        axes[1].legend(fontsize=7, ncol=2)
        fig.tight_layout()
        stamp_inputs(fig, [f"{args.cli} vertex s4r (closed form, twists in the titles)"])
        fig.savefig(os.path.join(figdir, "vertex_modes.png"), dpi=110)
        plt.close(fig)
    print(f"figures: {figdir}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
