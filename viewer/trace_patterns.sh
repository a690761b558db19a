#!/usr/bin/env bash
# Traces crease patterns for the viewer with the built rigidfold:
#   bash viewer/trace_patterns.sh RIGIDFOLD OUT_DIR PATTERN.fold ...
# For each pattern NAME: OUT_DIR/NAME.fold (or NAME.b<ID>.fold, one per
# branch) from `trace --branch all --out`, NAME.trace.json (trace --json) and
# NAME.check.json (check --json: the branch graph and located bifurcations).
# A pattern that traces nothing (exit 3) is reported and left out.
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: bash viewer/trace_patterns.sh RIGIDFOLD OUT_DIR PATTERN.fold ..." >&2
  exit 2
fi
rigidfold="$1"; out="$2"; shift 2
mkdir -p "$out"
for p in "$@"; do
  name="$(basename "${p%.*}")"
  rc=0
  "$rigidfold" trace "$p" --branch all --out "$out/$name.fold" --json > "$out/$name.trace.json" 2> "$out/$name.trace.err" || rc=$?
  if [ "$rc" -eq 3 ]; then
    echo "viewer: $name traces nothing (exit 3), left out: $(head -c 200 "$out/$name.trace.err")"
    rm -f "$out/$name.trace.json"
    continue
  elif [ "$rc" -ne 0 ]; then
    echo "viewer: rigidfold trace $p failed (exit $rc):" >&2
    cat "$out/$name.trace.err" >&2
    exit 1
  fi
  "$rigidfold" check "$p" --json > "$out/$name.check.json"
  rm -f "$out/$name.trace.err"
done
