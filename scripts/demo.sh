#!/usr/bin/env bash
# One command for a new user: installs what is missing (Debian 12), builds the mrsim program
# only (no tests, no benchmarks), and runs the thesis' Fig. 5.9 on the thesis' own hierarchy
# (scenarios/liver_thesis.yaml: three liver meshes of 32 / 204 / 1563 tets, a probe, per-particle
# time levels), then plots its log. Idempotent.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install_deps.sh"
MRSIM_TARGETS=mrsim "$root/scripts/build.sh"
out="$root/out/liver_thesis"
start=$SECONDS
"$root/build/mrsim" run "$root/scenarios/liver_thesis.yaml" -o "$out"
/usr/bin/python3 "$root/scripts/plot_run.py" "$out" >/dev/null
seconds=$((SECONDS - start))
cat <<MSG

The demo ran in ${seconds} s: a 1 cm probe presses the liver 8 mm deep, holds, and lets go. Each
region is simulated on one of three meshes of the liver: the finest appears under the probe
while it pushes and is handed back to the coarsest after the release. Outputs in $out:
  plots/points_per_level.png  active points of each mesh over time: level 2 (1563 tets) rises
                              under the probe, then falls back to level 0
  plots/tool_force.png        the force on the probe at every kicking step (1.6-3.2 kHz)
  plots/time_levels.png       particles per time level: each one steps frame_dt / 2^k
  frames.pvd                  open in ParaView (File > Open), press Play; colour the finest
                              block (level_2) by its cell array 'simulated_by': the liver once,
                              each part in the colour of the mesh that simulates it. Or, from
                              this folder: paraview --state=scripts/paraview_levels.pvsm
                              (README "ParaView": getting ParaView's Python on Debian)
  log.h5, summary.json        everything measured (docs/output.md)
Next: scripts/test.sh runs the whole test suite; README.md lists every scenario.
MSG
