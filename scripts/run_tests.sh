#!/usr/bin/env bash
# Builds rigidfold (Release) and runs every test with CTest.
# Usage: bash scripts/run_tests.sh        (from the project root; installs missing packages)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
BUILD_DIR=${BUILD_DIR:-build}
# Ninja (from the bootstrap) for a new build directory: it keeps both cores busy across targets
# and logs each step's time in .ninja_log; a directory made earlier keeps its generator.
generator=()
[[ -f "$BUILD_DIR/CMakeCache.txt" ]] || generator=(-G Ninja)
cmake -S . -B "$BUILD_DIR" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release ${CMAKE_EXTRA_ARGS:-} >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$(nproc)"
