"""Sweep throughput against worker count (rigidfold.sweep on Dask LocalClusters).

    PYTHONPATH=build/python /usr/bin/python3 benchmarks/sweep_bench.py [--rows 6 --cols 5]
        [--workers 1,2] [--tasks 64] [--verdicts] [--json out/bench/sweep.json]

1. Every M-V assignment of a rows x cols-panel Miura-ori (enumeration only, unless --verdicts),
   split into about --tasks subtrees, on each worker count: wall time and speed-up against one
   worker. The merged results must be equal on every worker count (checked, else exit 1), and
   with --serial equal to enumerate_assignments run whole in this process (also timed).
2. Per-task overhead: 2,000 metamaterial points (microseconds of work each) on each worker count,
   against the same calls in a loop here: (sweep time - loop time) / tasks.
A cluster's start-up is not timed (the cluster is made first). Run it alone: both cores are used.
"""
import argparse
import json
import os
import sys
import time

import numpy as np

import rigidfold
import rigidfold.sweep as sweep
from distributed import Client, LocalCluster


def timed(fn):
    start = time.perf_counter()
    value = fn()
    return value, time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rows", type=int, default=6)
    parser.add_argument("--cols", type=int, default=5)
    parser.add_argument("--workers", default="1,2")
    parser.add_argument("--tasks", type=int, default=64)
    parser.add_argument("--verdicts", action="store_true", help="give every class its verdict")
    parser.add_argument("--serial", action="store_true", help="also run the whole search here, timed and compared")
    parser.add_argument("--json", help="write the figures here as JSON")
    args = parser.parse_args()
    counts = [int(w) for w in args.workers.split(",")]
    spec = {"generator": "miura_ori", "rows": args.rows, "cols": args.cols}
    options = {} if args.verdicts else {"max_verdicts": 0}

    pattern = sweep.load_pattern(spec)
    serial, serial_s = None, None
    if args.serial:
        serial, serial_s = timed(lambda: rigidfold.enumerate_assignments(pattern, max_listed=2**31 - 1, **options))
    tasks = sweep.assignment_tasks(spec, tasks_wanted=args.tasks, **options)
    points = [{"kind": "metamaterial", "theta": float(t)} for t in np.linspace(0.1, 3.0, 2000)]
    _, loop_s = timed(lambda: [sweep.run_task(p) for p in points])
    rows = []
    reference = None
    for n in counts:
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
        try:
            records, enum_s = timed(lambda: rigidfold.sweep(tasks, client=client))
            merged = sweep.merge_assignments(records)
            merged.pop("search_steps")
            reference = reference if rows else merged
            if merged != reference or (serial and merged["listed"] != sweep.plain(serial["listed"])):
                print(f"{n} workers: the merged result differs from the first run's or the serial search's",
                      file=sys.stderr)
                return 1
            _, points_s = timed(lambda: rigidfold.sweep(points, client=client))
        finally:
            client.close()
            cluster.close()
        rows.append({"workers": n, "tasks": len(tasks), "seconds": enum_s, "points_seconds": points_s,
                     "overhead_ms_per_task": 1e3 * (points_s - loop_s) / len(points) * n})
    base = rows[0]["seconds"]
    serial_text = f"; serial enumerate_assignments {serial_s:.2f} s" if serial else ""
    print(f"Miura-ori {args.rows} x {args.cols} panels: {reference['assignments']} assignments in "
          f"{reference['classes']} classes, {reference['foldable_classes']} foldable "
          f"({'with' if args.verdicts else 'without'} verdicts){serial_text}; {len(tasks)} subtree tasks; "
          f"machine: {os.cpu_count()} cores")
    print("| workers | enumeration (s) | speed-up | assignments/s | overhead per task (ms, per worker) |")
    print("|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['workers']} | {r['seconds']:.2f} | {base / r['seconds']:.2f} | "
              f"{reference['assignments'] / r['seconds']:.0f} | {r['overhead_ms_per_task']:.2f} |")
    print(f"(overhead: {len(points)} metamaterial points, {loop_s:.3f} s in a loop here)")
    if args.json:
        os.makedirs(os.path.dirname(os.path.abspath(args.json)), exist_ok=True)
        with open(args.json, "w") as f:
            json.dump({"rows": args.rows, "cols": args.cols, "assignments": reference["assignments"],
                       "classes": reference["classes"], "serial_seconds": serial_s, "runs": rows}, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
