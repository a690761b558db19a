#!/usr/bin/env bash
# Installs the Debian packages rigidfold needs, only those that are missing.
# Idempotent and quiet: prints one line per action, nothing when all is present.
set -euo pipefail

# libhypre-dev, libopenmpi-dev, openmpi-bin: only for benchmarks/amg_bench (hypre's BoomerAMG
# against CHOLMOD on the corrector's system; hypre needs MPI even on one process, and Open MPI's
# MPI_Init without mpirun starts its orted, from openmpi-bin).
# python3-venv, python3-build: `pip install .` and wheels of the Python package (pyproject.toml);
# python3-distributed: Dask, on which rigidfold.sweep runs many tasks at once.
# libopenblas0-pthread: Debian's alternatives then serve OpenBLAS (threaded) as libblas.so.3 and
# liblapack.so.3; CHOLMOD's supernodal factorisation of large systems runs on it (at 2M unknowns
# 2.0 s, against 4.7 s on ATLAS and 9.1 s for the simplicial factor: kernel/solve/newton_projection.hpp).
packages=(
  build-essential cmake pkg-config
  libeigen3-dev libsuitesparse-dev libceres-dev libnlopt-dev libnlopt-cxx-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev
  pybind11-dev python3-dev python3-matplotlib python3-numpy python3-scipy python3-pytest
  python3-venv python3-build python3-distributed
  libboost-dev libfcl-dev libspectra-dev libexpat1-dev clang libclang-rt-14-dev lld ninja-build
  libopenblas0-pthread libhypre-dev libopenmpi-dev openmpi-bin
)

bash "$(dirname "$0")/install_missing_packages.sh" bootstrap "${packages[@]}"

# The browser viewer's needs (Debian chromium, node/npm if missing, npm ci in viewer/).
bash "$(dirname "$0")/../viewer/bootstrap_viewer.sh"
