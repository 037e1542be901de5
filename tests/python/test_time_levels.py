#!/usr/bin/python3
"""End-to-end checks of per-particle time levels (issue 5): adaptivity.time in a scenario, the
outputs that show them (/frames/time_levels, /frames/time_level_evaluations, the VTU
time_level array, time-level events), the computed finest step, the power-of-two rule, and
bit-identical outputs for 1 and 2 threads with space and time adaptivity on."""
import json
import os
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: run, check, VTU blocks, threads)

check = cli.check
TIME = ["adaptivity.time.enabled=true"]


def test_liver_with_time_levels(binary, source, tmp):
    """The bundled local press with time levels: the levels of the finer meshes step finer, every
    integrated particle is counted once, and the VTU shows each particle's level."""
    out = os.path.join(tmp, "liver_time")
    scenario = os.path.join(source, "scenarios", "liver_press.yaml")
    r = cli.run(binary, "run", scenario, "-o", out, "-q", "--set", "time.duration=0.6",
                "--set", "time.substeps=256",  # the finest time level: 9 columns
                "--set", TIME[0], "--set", "adaptivity.time.velocity_change=1.0e-5")
    check(r.returncode == 0, "liver_press with time levels runs (exit %d) %s"
          % (r.returncode, r.stderr[-300:]))
    summary = json.load(open(os.path.join(out, "summary.json")))
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        levels = h5["/frames/time_levels"][:]
        evals = h5["/frames/time_level_evaluations"][:]
        steps = h5["/frames/time_level_step"][:]
        active = h5["/frames/active"][:]
        force_evals = h5["/frames/force_evaluations"][:]
        kinds = [k.decode() if isinstance(k, bytes) else str(k) for k in h5["/events/kind"][:]]
    check(levels.shape == (31, 9) and evals.shape == (31, 9),
          "/frames/time_levels and time_level_evaluations are [F, 9] for substeps 256: %s"
          % (levels.shape,))
    check(np.allclose(steps, 0.02 / 2.0 ** np.arange(9), rtol=0, atol=0),
          "/frames/time_level_step[k] is frame_dt / 2^k")
    check(bool(np.all(levels.sum(axis=1) <= active.sum(axis=1))) and levels[-1].sum() > 0,
          "every integrated particle on one time level (free active points)")
    used = sorted({k for row in levels for k in np.nonzero(row)[0]})
    check(len(used) >= 3, "finer meshes step on finer levels: levels used %s" % used)
    check(bool(np.all(np.diff(evals, axis=0) >= 0)) and
          evals[-1].sum() == force_evals[-1].sum(),
          "force evaluations per time level add up to those per mesh level (%d)"
          % evals[-1].sum())
    check("time_refine" in kinds and "time_coarsen" in kinds,
          "time-level refinements and coarsenings are logged in /events")
    check(summary["steps"] > 0 and len(summary["time_level_evaluations"]) == 9,
          "summary.json has the work per time level")
    for frame in (10, 30):
        vtm = os.path.join(out, "frames", "frame_%06d.vtm" % frame)
        counts = np.zeros(9, dtype=np.int64)
        for level in range(4):
            a = cli.block_arrays(vtm, level)
            tl, status = a["time_level"], a["status"]
            check(bool(np.all(tl[status != 2] == -1)),
                  "frame %d level %d: time_level is -1 where nothing is integrated" % (frame, level))
            for k in tl[tl >= 0]:
                counts[k] += 1
        check(list(counts) == list(levels[frame]),
              "frame %d: VTU time_level counts match /frames/time_levels %s" % (frame, list(counts)))


def test_finest_step(binary, source, tmp):
    """substeps must be a power of two with time levels; omitted, it is 4 x the power of two of
    the Courant value."""
    scenario = os.path.join(source, "scenarios", "beam.yaml")
    r = cli.run(binary, "check", scenario, "--set", TIME[0], "--set", "time.substeps=100")
    check(r.returncode == 2 and "power of two" in r.stderr and "time.substeps" in r.stderr,
          "substeps 100 with time levels exits 2 naming time.substeps: " + r.stderr.strip()[-150:])
    text = open(scenario).read()
    meshes = os.path.join(os.path.abspath(source), "scenarios", "meshes") + "/"
    path = os.path.join(tmp, "no_substeps.yaml")
    with open(path, "w") as f:
        f.write("\n".join(l.replace("meshes/", meshes) for l in text.splitlines()
                          if not l.strip().startswith("substeps:")) + "\n")
    plain = cli.run(binary, "check", path)
    timed = cli.run(binary, "check", path, "--set", TIME[0])

    def substeps(res):
        m = [l for l in res.stdout.splitlines() if l.strip().startswith("substeps:")]
        return int(m[0].split(":")[1]) if m else 0
    # One global step takes the fewest steps that fit; time levels the power of two at or above.
    pow2 = 1 << max(0, substeps(plain) - 1).bit_length()
    check(timed.returncode == 0 and substeps(plain) > 0 and substeps(timed) == 4 * pow2,
          "computed finest step with time levels: %d = 4 x %d, the power of two at or above %d"
          % (substeps(timed), pow2, substeps(plain)))


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    scenarios = os.path.join(args.source, "scenarios")
    with tempfile.TemporaryDirectory() as tmp:
        test_finest_step(args.binary, args.source, tmp)
        test_liver_with_time_levels(args.binary, args.source, tmp)
        for integrator in ("modified_euler", "stoermer_verlet", "semi_implicit_momentum"):
            cli.test_threads_bit_identical(
                args.binary, os.path.join(scenarios, "liver_press.yaml"), tmp, 0.3, (5, 15),
                sets=TIME + ["time.integrator=" + integrator], tag="_time_" + integrator)
    print("%d passed, %d failed" % (len(cli.PASSED), len(cli.FAILURES)))
    return 1 if cli.FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
