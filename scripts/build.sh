#!/usr/bin/env bash
# Configures and builds mrsim (Release) into build/. Idempotent: rebuilds only what changed.
# MRSIM_TARGETS="mrsim" builds only those targets (the demo: no tests, no benchmarks); extra
# arguments go to CMake's configure step.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MRSIM_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE="${MRSIM_BUILD_TYPE:-Release}" "$@" >/dev/null
targets=()
for t in ${MRSIM_TARGETS:-}; do targets+=(--target "$t"); done
cmake --build "$build" -j "$(nproc)" "${targets[@]}"
