#!/bin/sh
# The mesh fuzzer of tests/mesh/mesh_fuzz_test.cpp for longer than ctest runs it (issue 18):
# mutations of the bundled meshes (every format read_tet_mesh takes) must load as a valid
# mesh or be refused with an input error, never crash, hang or escape another exception.
# Usage: scripts/fuzz_meshes.sh [INPUTS [SEED]] (default 100000 inputs, about 3 000 per
# second in a release build and 200 under ASan on this machine; build first).
# Failing inputs are kept in ${TMPDIR:-/tmp}/mrsim_mesh_fuzz_failures/seedS_inputK/;
# MRSIM_FUZZ_REPLAY=FILE "$build/tests/test_mesh" --gtest_filter=MeshFuzz.Replay reads one
# again. A crash keeps nothing: rerun with MRSIM_FUZZ_VERBOSE=1 (each input is named before
# it is read) and take the file from the scratch folder ${TMPDIR:-/tmp}/mrsim_MeshFuzz_*.
# MRSIM_FUZZ_SLOW_SECONDS (default 10) is how long one read may take before it counts as a
# near-hang.
# Build with -DCMAKE_BUILD_TYPE=Debug -DMRSIM_SANITIZE=ON into another folder and pass it as
# MRSIM_BUILD to run it under ASan/UBSan.
set -eu
build=${MRSIM_BUILD:-$(dirname "$0")/../build}
MRSIM_FUZZ_INPUTS=${1:-100000} MRSIM_FUZZ_SEED=${2:-1} \
  exec "$build/tests/test_mesh" --gtest_filter='MeshFuzz.*-MeshFuzz.Replay'
