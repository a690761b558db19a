#!/usr/bin/env bash
# Installs the Debian packages rigidfold needs, only those that are missing.
# Idempotent and quiet: prints one line per action, nothing when all is present.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libsuitesparse-dev libceres-dev libnlopt-dev libnlopt-cxx-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev
  pybind11-dev python3-dev python3-matplotlib python3-numpy python3-scipy python3-pytest
  libboost-dev libfcl-dev libspectra-dev libexpat1-dev clang libclang-rt-14-dev
)

# The browser viewer's needs (Debian chromium, node/npm, npm ci in viewer/): its own script.
bash "$(dirname "$0")/../viewer/bootstrap_viewer.sh"

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "bootstrap: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq >/dev/null
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "bootstrap: done"
