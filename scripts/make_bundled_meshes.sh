#!/usr/bin/env bash
# Regenerates the level hierarchies the bundled scenarios use, into scenarios/meshes/:
#   liver_L0..L3.vtu       from liver_surface_cgal_h10_mm.off (CC0, see scenarios/meshes/SOURCES.md),
#                          near 30 / 170 / 1900 / 15000 tets (the thesis had 28 / 172 / 1874)
#   liver_thesis_L0..L2.vtu  the same surface near the thesis' own 28 / 172 / 1874 tets
#   little_man_L0..L2.vtu  the thesis' Fig. 5.10 "bonhomme" (built-in shape), 300 / 2400 / 19200
#                          (its arms and head cannot be meshed with fewer than ~250 good tets)
#   beam_L0..L2.vtu        the 0.1 x 0.02 x 0.02 m validation cantilever, 30 / 170 / 1900
# each with its _quality.json and _levels.yaml. mrsim mesh is deterministic, so re-running
# this script on the same mrsim gives the same bytes; the outputs are committed.
# Usage: scripts/make_bundled_meshes.sh [path/to/mrsim]   (default: build it with build.sh)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mrsim="${1:-}"
if [[ -z "$mrsim" ]]; then
  "$root/scripts/build.sh" >/dev/null
  mrsim="${MRSIM_BUILD_DIR:-$root/build}/mrsim"
fi
out="$root/scenarios/meshes"

timed() {
  local start=$SECONDS
  "$@"
  echo "  ($((SECONDS - start)) s)" >&2
}

timed "$mrsim" mesh "$out/liver_surface_cgal_h10_mm.off" --units mm --tets 30,170,1900,15000 -o "$out/liver"
timed "$mrsim" mesh "$out/liver_surface_cgal_h10_mm.off" --units mm --tets 28,172,1874 -o "$out/liver_thesis"
timed "$mrsim" mesh --shape little_man --dims 0.2 --tets 300,2400,19200 -o "$out/little_man"
timed "$mrsim" mesh --shape beam --dims 0.1,0.02,0.02 --tets 30,170,1900 -o "$out/beam"
