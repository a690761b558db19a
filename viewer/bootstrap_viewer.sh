#!/usr/bin/env bash
# Installs what the viewer needs, only what is missing: Debian's chromium
# (headless browser of the end-to-end test and the main job's screenshot),
# nodejs and npm when node/npm are not on PATH, then `npm ci` in viewer/
# (three, esbuild, playwright-core at the versions in package-lock.json)
# when node_modules does not match the lock file.
# Idempotent and quiet: one line per action, nothing when all is present.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

packages=(chromium)
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
fi
bash "$here/../scripts/install_missing_packages.sh" bootstrap_viewer "${packages[@]}"

# npm ci only when node_modules is missing or older than the lock file
# (npm writes node_modules/.package-lock.json on every install).
stamp="$here/node_modules/.package-lock.json"
if [ ! -f "$stamp" ] || [ "$here/package-lock.json" -nt "$stamp" ]; then
  echo "bootstrap_viewer: npm ci in viewer/"
  (cd "$here" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
fi
if [ "$(node -p 'process.versions.node.split(".")[0]')" -lt 20 ]; then
  echo "bootstrap_viewer: warning: node $(node --version) < 20; playwright-core (the viewer test) needs node >= 20"
fi
