#!/usr/bin/env python3
"""Turns the Google Benchmark JSON of scripts/bench_report.sh into out/bench/BENCH.md and plots.

Usage: plot_bench.py RESULTS.json OUTDIR
Writes OUTDIR/BENCH.md (tables: time, error and peak memory per benchmark and size; fitted
exponents of time against size), OUTDIR/time_vs_size.png (log-log, with the fitted exponent
over 1e4..1e6+ creases), OUTDIR/time_vs_error.png (solver settings), OUTDIR/memory.png and
OUTDIR/accuracy_vs_size.png (traced / corrected Miura against its closed form).
"""
import json
import math
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ORDERINGS = {0: "default", 1: "AMD", 2: "METIS", 3: "NESDIS"}


def load(path):
    with open(path) as f:
        data = json.load(f)
    runs = [b for b in data["benchmarks"] if b.get("run_type", "iteration") == "iteration"]
    return data.get("context", {}), runs


def family(run):
    return run["name"].split("/")[0]


def seconds(run):
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[run.get("time_unit", "ns")]
    return run["real_time"] * scale, run["cpu_time"] * scale


def fit_exponent(xs, ys, lo=1e4):
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x >= lo and y > 0]
    if len(pts) < 2:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx if sxx > 0 else None


def fmt(v):
    if v is None:
        return ""
    if isinstance(v, float) and (abs(v) >= 1e4 or (v != 0 and abs(v) < 1e-2)):
        return f"{v:.3g}"
    return f"{v:.4g}" if isinstance(v, float) else str(v)


def main():
    path, outdir = sys.argv[1], sys.argv[2]
    ctx, runs = load(path)
    fams = defaultdict(list)
    for r in runs:
        fams[family(r)].append(r)
    lines = ["# rigidfold benchmarks (issue 5)", ""]
    lines.append(f"Host: {ctx.get('host_name', '?')}, {ctx.get('num_cpus', '?')} CPUs, "
                 f"load average {ctx.get('load_avg', '?')}, date {ctx.get('date', '?')}. "
                 "Times in seconds: wall (real) and process CPU (all threads). "
                 "Errors in radians. Peak memory: RSS of the benchmark's own process.")
    lines.append("")
    # Time against size (main families only: the default settings).
    fig, ax = plt.subplots(figsize=(7, 5))
    exps = {}
    for fam, rs in sorted(fams.items()):
        main_rs = [r for r in rs if r.get("ordering", 0) == 0 and r.get("tolerance", 1e-12) == 1e-12]
        main_rs.sort(key=lambda r: r["edges"])
        if len(main_rs) < 2:
            continue
        xs = [r["edges"] for r in main_rs]
        ys = [seconds(r)[0] for r in main_rs]
        e = fit_exponent(xs, ys)
        exps[fam] = e
        ax.loglog(xs, ys, "o-", label=f"{fam} (exp {e:.2f})" if e else fam)
    ax.set_xlabel("creases (edges)")
    ax.set_ylabel("wall time [s]")
    ax.set_title("time against size (exponent fitted for >= 1e4 creases)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(f"{outdir}/time_vs_size.png", dpi=120)
    plt.close(fig)

    lines.append("## Time against size")
    lines.append("")
    lines.append("| benchmark | fitted exponent (>= 1e4 creases) |")
    lines.append("|---|---|")
    for fam, e in sorted(exps.items()):
        lines.append(f"| {fam} | {fmt(e) if e is not None else 'n/a'} |")
    lines.append("")
    lines.append("![time against size](time_vs_size.png)")
    lines.append("")

    # Full tables.
    lines.append("## All runs")
    lines.append("")
    keys = ["residual", "error_vs_closed_form", "linear_residual", "max_defect", "mismatch", "dof", "iterations",
            "points", "reached_deg", "max_fold", "converged"]
    lines.append("| benchmark | creases | wall s | CPU s | " + " | ".join(keys) + " | peak MB |")
    lines.append("|---|---|---|---|" + "---|" * len(keys) + "---|")
    for fam, rs in sorted(fams.items()):
        for r in sorted(rs, key=lambda r: (r["edges"], r["name"])):
            wall, cpu = seconds(r)
            cells = [fmt(r.get(k)) for k in keys]
            lines.append(f"| {r['name']} | {int(r['edges'])} | {wall:.4g} | {cpu:.4g} | " + " | ".join(cells) +
                         f" | {r.get('peak_rss_mb', 0):.0f} |")
    lines.append("")

    # Time against error: solver settings at the shared mid size.
    fig, ax = plt.subplots(figsize=(7, 5))
    settings = []
    for r in fams.get("BM_Corrector", []):
        mid = max(r2["edges"] for r2 in fams["BM_Corrector"] if r2.get("ordering", 0) != 0 or r2.get("tolerance") != 1e-12) \
            if any(r2.get("ordering", 0) != 0 or r2.get("tolerance") != 1e-12 for r2 in fams["BM_Corrector"]) else None
        if mid is not None and r["edges"] == mid:
            label = f"CHOLMOD {ORDERINGS.get(int(r.get('ordering', 0)), '?')} tol {r.get('tolerance', 0):.0e}"
            settings.append((label, seconds(r)[0], max(r.get("error_vs_closed_form", 0), 1e-17), r["edges"]))
    for label, t, err, edges in settings:
        ax.loglog([t], [err], "o", label=label)
    for fam, marker in [("BM_GradedMultiplier", "s"), ("BM_GradedCorrector", "^")]:
        for r in fams.get(fam, []):
            err = r.get("mismatch", r.get("error_vs_closed_form", 0))
            ax.loglog([seconds(r)[0]], [max(err, 1e-17)], marker, color="k" if "Multiplier" in fam else "gray",
                      alpha=0.6)
    ax.plot([], [], "ks", label="graded mesh: multiplier propagation (all sizes)")
    ax.plot([], [], "^", color="gray", label="graded mesh: general corrector (all sizes)")
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel("error reached [rad]")
    ax.set_title("time against error per solver setting")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(f"{outdir}/time_vs_error.png", dpi=120)
    plt.close(fig)
    lines.append("## Time against error (solver settings)")
    lines.append("")
    lines.append("| setting | creases | wall s | error vs closed form |")
    lines.append("|---|---|---|---|")
    for label, t, err, edges in settings:
        lines.append(f"| {label} | {int(edges)} | {t:.4g} | {err:.3g} |")
    lines.append("")
    lines.append("![time against error](time_vs_error.png)")
    lines.append("")

    # Multiplier propagation against the general solver.
    gm = {r["edges"]: r for r in fams.get("BM_GradedMultiplier", [])}
    gc = {r["edges"]: r for r in fams.get("BM_GradedCorrector", [])}
    if gm and gc:
        lines.append("## Multiplier propagation against the general corrector (graded Miura)")
        lines.append("")
        lines.append("| creases | propagation s | general s | speed-up | propagation mismatch | general error |")
        lines.append("|---|---|---|---|---|---|")
        for e in sorted(set(gm) & set(gc)):
            tm, tg = seconds(gm[e])[0], seconds(gc[e])[0]
            lines.append(f"| {int(e)} | {tm:.4g} | {tg:.4g} | {tg / tm:.1f}x | {fmt(gm[e].get('mismatch'))} | "
                         f"{fmt(gc[e].get('error_vs_closed_form'))} |")
        lines.append("")

    # Memory and accuracy against size.
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    for fam in ["BM_Corrector", "BM_Trace", "BM_Factorize", "BM_GradedMultiplier"]:
        rs = sorted([r for r in fams.get(fam, []) if r.get("ordering", 0) == 0 and r.get("tolerance", 1e-12) == 1e-12],
                    key=lambda r: r["edges"])
        if rs:
            ax1.loglog([r["edges"] for r in rs], [r["peak_rss_mb"] for r in rs], "o-", label=fam)
    ax1.set_xlabel("creases")
    ax1.set_ylabel("peak RSS [MB]")
    ax1.set_title("peak memory")
    ax1.grid(True, which="both", alpha=0.3)
    ax1.legend(fontsize=7)
    for fam in ["BM_Trace", "BM_Corrector", "BM_ContinuationStep"]:
        rs = sorted([r for r in fams.get(fam, []) if r.get("ordering", 0) == 0 and r.get("tolerance", 1e-12) == 1e-12],
                    key=lambda r: r["edges"])
        if rs:
            ax2.loglog([r["edges"] for r in rs], [max(r.get("error_vs_closed_form", 0), 1e-17) for r in rs], "o-",
                       label=fam)
    ax2.axhline(1e-10, color="r", ls="--", lw=1, label="target 1e-10")
    ax2.set_xlabel("creases")
    ax2.set_ylabel("max |rho - closed form| [rad]")
    ax2.set_title("Miura: error against its closed form")
    ax2.grid(True, which="both", alpha=0.3)
    ax2.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(f"{outdir}/memory_accuracy.png", dpi=120)
    plt.close(fig)
    lines.append("## Peak memory and accuracy against size")
    lines.append("")
    lines.append("![memory and accuracy](memory_accuracy.png)")
    lines.append("")
    with open(f"{outdir}/BENCH.md", "w") as f:
        f.write("\n".join(lines))
    print(f"{outdir}/BENCH.md")


if __name__ == "__main__":
    main()
