#!/usr/bin/env bash
# One command for the whole test suite: installs what is missing (Debian 12), builds, runs
# every test with ctest (unit, physics validation, Python end-to-end). Idempotent.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install_deps.sh"
"$root/scripts/build.sh"
cd "${MRSIM_BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "$(nproc)" --timeout 900 "$@"
