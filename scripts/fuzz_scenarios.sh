#!/bin/sh
# The scenario fuzzer of tests/scenario/scenario_fuzz_test.cpp for longer than ctest runs it
# (issue 18): mutations of the bundled scenarios must load or be refused with an input error,
# never crash, hang or accept a NaN. Usage: scripts/fuzz_scenarios.sh [INPUTS [SEED]]
# (default 100000 inputs, about 4 000 per second on this machine; build first).
# Build with -DCMAKE_BUILD_TYPE=Debug -DMRSIM_SANITIZE=ON into another folder and pass it as
# MRSIM_BUILD to run it under ASan/UBSan.
set -eu
build=${MRSIM_BUILD:-$(dirname "$0")/../build}
MRSIM_FUZZ_INPUTS=${1:-100000} MRSIM_FUZZ_SEED=${2:-1} \
  exec "$build/tests/test_scenario" --gtest_filter='ScenarioFuzz.*'
