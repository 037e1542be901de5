#!/usr/bin/python3
"""Issue 16 points 2 and 3: the adaptive liver answers like its finest level where the tool or
the load is, and one pair of criterion thresholds serves both bundled liver hierarchies.

- liver_probe adaptive against the same run on liver_L3 alone (same integrator, steps and
  tool, the bundled 1.4 s): the tool force within 5 % of the uniform run's
  peak at every step, with at most 7 % of its tet updates (docs/hierarchy.md, "One pair of
  thresholds for both livers").
- liver_press adaptive (refining ahead of its load) against liver_L3 alone, the whole bundled
  2 s: the mean vertical displacement of liver_L3's points under the loaded patch within 5 % of
  the uniform run's peak at every frame, with at most 12 % of its tet updates.
- liver_probe (4 levels, 14 260 finest tets) and liver_thesis (3 levels, the thesis' sizes) use
  the same refine_above and coarsen_below; with them each refines a patch under the probe,
  never its whole finest level, and is back on level 0 after the probe leaves.

The first two also leave validation records (tests/python/validation_record.py): their rows and
curves are in docs/validation.md, "Adaptive vs uniform"."""
import glob
import json
import os
import sys
import tempfile

import h5py
import numpy as np
import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: run, check, parse_args, report)
import validation_record  # noqa: E402
from test_tool_scenarios import blocks  # noqa: E402  (a frame's blocks by name)

check = cli.check


def run(binary, scenario, out, sets, frames=False):
    args = ["run", scenario, "-o", out, "-q", "--set", "output.vtk=%s" % str(frames).lower()]
    for s in sets:
        args += ["--set", s]
    r = cli.run(binary, *args)
    check(r.returncode == 0, "%s runs (exit %d) %s" % (out, r.returncode, r.stderr[-300:]))
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        tool = (h5["/tool/time"][:], h5["/tool/force"][:]) if "tool" in h5 else (None, None)
        return tool, int(h5["/frames/tet_updates"][-1].sum()), h5["/frames/active"][:]


GROUP = "Adaptive vs uniform"
SOURCE = "no analytic reference: the same run on the finest level alone (same steps)"


def check_tet_updates(name, duration, ta, tu, upper, asked, note):
    """The adaptive run's tet updates against liver_L3 alone's: checked, and recorded as the
    stand-in for the CPU the issue asks (`asked`)."""
    check(ta <= upper * tu,
          "%s adaptive makes %.3f of liver_L3 alone's tet updates (<= %g)" % (name, ta / tu, upper))
    validation_record.record(
        name + "_tet_updates", GROUP,
        "%s, adaptive 4 levels vs liver_L3 alone: tet updates over %s" % (name, duration),
        "tet updates adaptive / L3 alone", ta / tu, 0, upper,
        tolerance=asked + " of the finest level's CPU, as the work counted (the CPU is measured "
        "by bench/adaptive_vs_uniform.py, never in a test)",
        reference_source=SOURCE, note=note)


def test_probe_follows_finest(binary, source, tmp):
    scenario = os.path.join(source, "scenarios", "liver_probe.yaml")
    with open(scenario) as f:
        finest = yaml.safe_load(f)["object"]["levels"][-1]
    adaptive_out = os.path.join(tmp, "probe_adaptive")
    (t, fa), ta, _ = run(binary, scenario, adaptive_out, [])  # the bundled 1.4 s, as issue 17
    with open(os.path.join(adaptive_out, "scenario.yaml")) as f:
        substeps = yaml.safe_load(f)["time"]["substeps"]
    (_, fu), tu, _ = run(binary, scenario, os.path.join(tmp, "probe_finest"),
                         ["object.levels=" + json.dumps([finest]),
                          "time.substeps=%d" % substeps])
    check(fa.shape == fu.shape, "the adaptive and uniform runs log the same steps (%s, %s)"
          % (fa.shape, fu.shape))
    if fa.shape != fu.shape:
        return
    na, nu = np.linalg.norm(fa, axis=1), np.linalg.norm(fu, axis=1)
    worst = np.abs(na - nu).max() / nu.max()
    check(nu.max() > 1.0 and worst <= 0.05,
          "liver_probe adaptive: tool force within %.2f %% of liver_L3 alone's peak (%.3f N) at "
          "every one of %d steps (<= 5 %%)" % (100 * worst, nu.max(), len(nu)))
    note = ("peak %.4f N adaptive, %.4f N on liver_L3 alone (%+.2f %%), %d tool samples; the "
            "adaptive run makes %.3f of liver_L3 alone's tet updates (%d against %d)"
            % (na.max(), nu.max(), 100 * (na.max() / nu.max() - 1), len(nu), ta / tu, ta, tu))
    validation_record.record(
        "liver_probe_tool_force", GROUP,
        "liver_probe, adaptive 4 levels vs liver_L3 alone: tool force, largest difference at "
        "any step over 1.4 s", "max | |F|_adaptive - |F|_L3 | / peak |F|_L3", worst, 0, 0.05,
        tolerance="issue 16: within 5 % of the finest level's peak at every step",
        reference_source=SOURCE, note=note,
        series=("t (s)", "tool force |F| (N)", ["t", "adaptive (liver_probe.yaml)", "L3 alone"],
                zip(t, na, nu)))
    check_tet_updates("liver_probe", "1.4 s", ta, tu, 0.07, "issue 17's tenth", note)


def patch_displacement(out, box):
    """Per frame, the mean uz of the finest level's points under the loaded patch (m)."""
    curve = []
    for vtm in sorted(glob.glob(os.path.join(out, "frames", "frame_*.vtm"))):
        b = blocks(vtm)
        finest = max((n for n in b if n.startswith("level_")), key=lambda n: int(n.split("_")[1]))
        points, arrays, _ = b[finest]
        rest = points - arrays["displacement"]
        under = np.all((rest >= box[0]) & (rest <= box[1]), axis=1)
        curve.append(arrays["displacement"][under, 2].mean())
    return np.array(curve)


def test_press_follows_finest(binary, source, tmp):
    scenario = os.path.join(source, "scenarios", "liver_press.yaml")
    with open(scenario) as f:
        spec = yaml.safe_load(f)
    finest = spec["object"]["levels"][-1]
    box = (np.array(spec["loads"][0]["box"]["min"]), np.array(spec["loads"][0]["box"]["max"]))
    fast = ["output.compression=none"]
    adaptive_out = os.path.join(tmp, "press_adaptive")
    _, ta, _ = run(binary, scenario, adaptive_out, fast, frames=True)
    with open(os.path.join(adaptive_out, "scenario.yaml")) as f:
        substeps = yaml.safe_load(f)["time"]["substeps"]
    uniform_out = os.path.join(tmp, "press_finest")
    _, tu, _ = run(binary, scenario, uniform_out,
                   fast + ["object.levels=" + json.dumps([finest]), "time.substeps=%d" % substeps],
                   frames=True)
    a, u = patch_displacement(adaptive_out, box), patch_displacement(uniform_out, box)
    check(len(a) == len(u) and len(u) > 50, "both runs wrote every frame (%d, %d)" % (len(a), len(u)))
    n = min(len(a), len(u))
    peak = np.abs(u).max()
    worst = np.abs(a[:n] - u[:n]).max() / peak
    check(peak > 1e-4 and worst <= 0.05,
          "liver_press adaptive: the loaded patch within %.2f %% of liver_L3 alone's peak "
          "(%.3f mm) at every one of %d frames (<= 5 %%)" % (100 * worst, 1e3 * peak, n))
    with h5py.File(os.path.join(adaptive_out, "log.h5"), "r") as h5:
        times = h5["/frames/time"][:]  # one row per written frame, as the frames
    note = ("peak %.4f mm adaptive, %.4f mm on liver_L3 alone (%+.2f %%), %d frames; the "
            "adaptive run makes %.3f of liver_L3 alone's tet updates (%d against %d)"
            % (-1e3 * a[:n].min(), -1e3 * u[:n].min(), 100 * (a[:n].min() / u[:n].min() - 1), n,
               ta / tu, ta, tu))
    validation_record.record(
        "liver_press_patch", GROUP,
        "liver_press, adaptive 4 levels (refining ahead of its load) vs liver_L3 alone: the "
        "loaded patch, largest difference at any frame over 2 s",
        "max |uz_adaptive - uz_L3| / peak |uz_L3| (mean uz of L3's points under the patch)",
        worst, 0, 0.05, tolerance="issue 16: within 5 % of the finest level's peak at every "
        "frame", reference_source=SOURCE, note=note,
        series=("t (s)", "mean uz under the loaded patch (mm)",
                ["t", "adaptive (liver_press.yaml)", "L3 alone"],
                [(times[k], 1e3 * a[k], 1e3 * u[k]) for k in range(min(n, len(times)))]))
    check_tet_updates("liver_press", "2 s", ta, tu, 0.12, "issue 16's 0.15", note)


def test_one_pair_of_thresholds(binary, source, tmp):
    pairs = {}
    for name in ("liver_probe", "liver_thesis"):
        scenario = os.path.join(source, "scenarios", name + ".yaml")
        with open(scenario) as f:
            space = yaml.safe_load(f)["adaptivity"]["space"]
        pairs[name] = (space["refine_above"], space["coarsen_below"])
        out = os.path.join(tmp, name)
        _, _, active = run(binary, scenario, out, [])
        with open(os.path.join(out, "summary.json")) as f:
            total = json.load(f)["points"][-1]
        finest = active[:, -1]
        check(0 < finest.max() <= 0.25 * total and finest[-1] == 0
              and np.array_equal(active[-1], active[0]),
              "%s with refine_above %g, coarsen_below %g: at most %d of its %d finest points "
              "active (a patch under the probe, <= 25 %%), level 0 alone again at the end"
              % (name, pairs[name][0], pairs[name][1], finest.max(), total))
    check(pairs["liver_probe"] == pairs["liver_thesis"],
          "liver_probe and liver_thesis share their thresholds (%s, %s)"
          % (pairs["liver_probe"], pairs["liver_thesis"]))


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        test_probe_follows_finest(args.binary, args.source, tmp)
        test_press_follows_finest(args.binary, args.source, tmp)
        test_one_pair_of_thresholds(args.binary, args.source, tmp)
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
