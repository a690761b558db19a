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
echo "report: out/report/REPORT.md"
