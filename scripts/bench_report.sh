#!/usr/bin/env bash
# Benchmark report for large tessellations: builds Release, runs every benchmark
# of benchmarks/scaling_bench (one process per benchmark, so that each peak-memory figure
# is its own), plus verdict_bench and amg_bench (where hypre is found), and writes
# out/bench/BENCH.md with tables and plots (python/plot_bench.py, matplotlib from Debian).
#   bash scripts/bench_report.sh             quick set, Miura up to 200 x 200 cells (80k creases;
#                                            about 1.5 minutes of runs on 2 cores, plus the build)
#   bash scripts/bench_report.sh --large     adds 160 and 320 x 320 cells (205k creases), traces
#                                            at 160 and 320, solver settings at 320
#   bash scripts/bench_report.sh --large1000 as --large, plus residual, Jacobian, factorisation
#                                            and one corrector at 1000 x 1000 cells (2M creases;
#                                            the corrector alone: ~8 s, 2.3 GB peak on 2 cores)
# Environment: BUILD_DIR (default build-bench), OUT (default out/bench).
set -euo pipefail
cd "$(dirname "$0")/.."
build="${BUILD_DIR:-build-bench}"
out="${OUT:-out/bench}"
case "${1:-}" in
  "") ;;
  --large) export RIGIDFOLD_BENCH_LARGE=1 ;;
  --large1000) export RIGIDFOLD_BENCH_LARGE=2 ;;
  *) echo "usage: $0 [--large | --large1000]" >&2; exit 2 ;;
esac
bash scripts/bootstrap.sh
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target scaling_bench verdict_bench
# amg_bench exists where hypre and MPI were found (benchmarks/CMakeLists.txt).
amg=""
if cmake --build "$build" --target help | grep -c '\bamg_bench\b' >/dev/null; then  # -c reads it all (pipefail)
  cmake --build "$build" -j"$(nproc)" --target amg_bench
  amg="$build/benchmarks/amg_bench"
fi
mkdir -p "$out/runs"
rm -f "$out"/runs/*.json
bench="$build/benchmarks/scaling_bench"
i=0
while IFS= read -r name; do
  i=$((i + 1))
  # Anchored regex of this one benchmark (its name contains '/' and digits only).
  "$bench" --benchmark_filter="^${name}\$" --benchmark_format=json --benchmark_out_format=json \
    --benchmark_out="$out/runs/$(printf '%03d' "$i").json" >/dev/null
  echo "bench: $name ($SECONDS s)"
done < <("$bench" --benchmark_list_tests=true)
"$build/benchmarks/verdict_bench" --benchmark_format=json --benchmark_out_format=json \
  --benchmark_out="$out/runs/verdict.json" >/dev/null
# Optional: if it fails (e.g. MPI cannot start here), the report is written without its section.
if [ -n "$amg" ]; then
  if "$amg" --benchmark_format=json --benchmark_out_format=json --benchmark_out="$out/runs/amg.json" >/dev/null; then
    echo "bench: amg_bench ($SECONDS s)"
  else
    rm -f "$out/runs/amg.json"
    echo "bench: amg_bench failed; BENCH.md is written without its section" >&2
  fi
fi
/usr/bin/python3 - "$out" <<'PY'
import glob, json, sys
out = sys.argv[1]
merged = None
for path in sorted(glob.glob(f"{out}/runs/*.json")):  # scaling_bench runs, amg.json, verdict.json
    with open(path) as f:
        d = json.load(f)
    if merged is None:
        merged = d
    else:
        merged["benchmarks"].extend(d["benchmarks"])
with open(f"{out}/results.json", "w") as f:
    json.dump(merged, f, indent=1)
PY
# Debian's python3 (matplotlib); the python3 first on PATH may not have it.
/usr/bin/python3 python/plot_bench.py "$out/results.json" "$out"
echo "bench report: $out/BENCH.md"
