#!/usr/bin/env bash
# CTest entry of Viewer.EndToEnd:
#   bash viewer/test/run_e2e.sh RIGIDFOLD WORK_DIR
# Traces the bundled Type 2M square twist (every branch) and Miura 4x4 with
# the built rigidfold, builds the viewer into WORK_DIR/viewer and drives it in
# headless chromium (test/e2e.mjs), writing WORK_DIR/type2m_e2e.png.
# Exit 77 (CTest SKIP_RETURN_CODE) only when node or chromium is not found.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
root="$(cd "$here/.." && pwd)"
if [ $# -ne 2 ]; then
  echo "usage: bash viewer/test/run_e2e.sh RIGIDFOLD WORK_DIR" >&2
  exit 2
fi
rigidfold="$1"; work="$2"
if ! command -v node >/dev/null 2>&1; then
  echo "SKIP Viewer.EndToEnd: node not found on PATH; install it with bash viewer/bootstrap_viewer.sh"
  exit 77
fi
major="$(node -p 'process.versions.node.split(".")[0]')"
if [ "$major" -lt 20 ]; then
  echo "Viewer.EndToEnd: node $(node --version) is too old; playwright-core needs node >= 20" >&2
  exit 1
fi
chromium=""
for c in "${CHROMIUM:-}" /usr/bin/chromium /usr/bin/chromium-browser; do
  if [ -n "$c" ] && [ -x "$c" ]; then chromium="$c"; break; fi
done
if [ -z "$chromium" ]; then
  echo "SKIP Viewer.EndToEnd: chromium not found (/usr/bin/chromium, or CHROMIUM=...); install it with bash viewer/bootstrap_viewer.sh"
  exit 77
fi
export CHROMIUM="$chromium"
rm -rf "$work"
mkdir -p "$work"
bash "$here/trace_patterns.sh" "$rigidfold" "$work/traces" \
  "$root/data/bundled/square_twist_30_type2m.fold" "$root/data/bundled/miura_4x4_alpha60.fold"
bash "$here/build.sh" "$work/viewer" "$work"/traces/*.fold "$work"/traces/*.json
node "$here/test/e2e.mjs" "$work/viewer" --set square_twist_30_type2m --screenshot "$work/type2m_e2e.png"
