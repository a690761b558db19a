#!/usr/bin/env python3
"""Traces a 4 x 4 Miura-ori from flat to 170 deg, compares every step with the closed form and
plots the crease pattern, the fold-angle curves and the last folded state to one PNG.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/trace_miura.py [--out DIR]

Writes DIR/miura_trace.png (default: a new temporary directory) and prints its path.
"""
import argparse
import math
import os
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rigidfold  # noqa: E402
import rigidfold.plot  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", help="output directory (default: a new temporary directory)")
    args = parser.parse_args()
    out = args.out or tempfile.mkdtemp(prefix="rigidfold_miura_")
    os.makedirs(out, exist_ok=True)

    params = dict(rows=4, cols=4, alpha=math.radians(60))
    pattern = rigidfold.miura_ori(**params)
    # Drive a straight crease that the closed form folds with the straight-crease angle itself.
    probe = rigidfold.miura_fold_angles(pattern, rho_straight=0.5, **params)
    drive = int(np.flatnonzero(np.abs(probe - 0.5) == 0.0)[0])
    result = rigidfold.trace(pattern, drive=drive, to=math.radians(170), steps=40)
    branch = result["branches"][0]

    error = 0.0
    for s, rho_drive in enumerate(branch["drive"]):
        closed = rigidfold.miura_fold_angles(pattern, rho_straight=rho_drive, **params)
        known = ~np.isnan(closed)
        error = max(error, float(np.max(np.abs(branch["fold_angles"][s, known] - closed[known]))))
    print(f"model {result['model']}: {len(branch['drive'])} steps to {math.degrees(branch['reached']):.1f} deg, "
          f"stopped: {branch['stop_reason']}; max error against the closed form {error:.3g} rad")

    fig = plt.figure(figsize=(15, 4.8))
    rigidfold.plot.crease_pattern(pattern, ax=fig.add_subplot(1, 3, 1), title="Miura-ori 4 x 4, alpha 60 deg")
    rigidfold.plot.fold_angle_curves(branch, pattern, ax=fig.add_subplot(1, 3, 2))
    rigidfold.plot.folded_state(branch, pattern, ax=fig.add_subplot(1, 3, 3, projection="3d"))
    fig.tight_layout()
    png = os.path.join(out, "miura_trace.png")
    fig.savefig(png, dpi=90)
    print(png)


if __name__ == "__main__":
    main()
