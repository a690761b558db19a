#!/usr/bin/env bash
# Installs missing Debian packages, builds rigidfold, and runs the main job: the
# foldability report of the bundled patterns (data/bundled), with figures, in out/report.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target rigidfold
./build/app/rigidfold report data/bundled --out out/report
/usr/bin/python3 python/plot_report.py out/report
# Fold-angle curves of the bundled square twists (seed 001 figures): the rigid types with
# their M-V assignment, the modified types along the branch the solver traces.
mkdir -p out/report/traces
csvs=()
for name in square_twist_30_type3 square_twist_30_type4 square_twist_30_type2m; do
  ./build/app/rigidfold trace "data/bundled/$name.fold" --steps 80 --csv "out/report/traces/$name.csv" >/dev/null
  csvs+=("out/report/traces/$name.csv")
done
for csv in "${csvs[@]}"; do
  /usr/bin/python3 python/plot_branches.py "$csv" --out "out/report/figures/$(basename "$csv" .csv)_branches.png" >/dev/null
done
echo "report: out/report/REPORT.md"
