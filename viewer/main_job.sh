#!/usr/bin/env bash
# The main job's viewer: bash viewer/main_job.sh out/report
# (run from the repository root after rigidfold is built in ./build).
# Traces the bundled Type 2M square twist (every branch), Miura 4x4 and the
# Miura tube with ./build/app/rigidfold, builds the viewer with them into
# OUT/viewer/ (open OUT/viewer/index.html from disk or any static server) and
# writes the screenshot OUT/viewer/type2m.png with headless chromium.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
if [ $# -ne 1 ]; then
  echo "usage: bash viewer/main_job.sh OUT_DIR" >&2
  exit 2
fi
out="$1"
rigidfold="$root/build/app/rigidfold"
if [ ! -x "$rigidfold" ]; then
  echo "viewer main job: $rigidfold not built" >&2
  exit 1
fi
traces="$(mktemp -d)"
trap 'rm -rf "$traces"' EXIT
bash "$here/trace_patterns.sh" "$rigidfold" "$traces" \
  "$root/data/bundled/square_twist_30_type2m.fold" \
  "$root/data/bundled/miura_4x4_alpha60.fold" \
  "$root/data/bundled/miura_tube_6_alpha60.fold"
rm -rf "$out/viewer"
bash "$here/build.sh" "$out/viewer" "$traces"/*.fold "$traces"/*.json
# Branch 20 of Type 2M runs from flat to the bifurcation at crease 12 = 85.88 deg;
# crease 12 is picked so its fold angle is shown.
node "$here/test/screenshot.mjs" "$out/viewer" "$out/viewer/type2m.png" \
  "?set=square_twist_30_type2m&branch=20&step=last&crease=12"
