#!/usr/bin/env bash
# Builds the viewer into OUT_DIR with the given traces:
#   bash viewer/build.sh OUT_DIR [TRACE.fold ...] [TRACE_SUMMARY.json ...] [CHECK.json ...]
# TRACE.fold: `rigidfold trace P --out TRACE.fold` (with --branch all, the
# TRACE.b<ID>.fold files); the JSON files, optional: `trace ... --json` and
# `check P --json` output (branch stops, events, bifurcations).
# Runs `npm ci` first when viewer/node_modules is missing (needs the npm registry).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if [ $# -lt 1 ]; then
  echo "usage: bash viewer/build.sh OUT_DIR [TRACE.fold ...] [SUMMARY.json ...]" >&2
  exit 2
fi
if [ ! -d "$here/node_modules/three" ] || [ ! -d "$here/node_modules/esbuild" ]; then
  echo "viewer: npm ci (node_modules missing)"
  (cd "$here" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
fi
exec node "$here/build.mjs" "$@"
