#!/usr/bin/python3
"""Issue 16 point 2, refining ahead of the loads (adaptivity.space.predict, docs/hierarchy.md
"Refining ahead of loads"): with it a first split decision is made at t = 0 on the displacement
the loads alone would add within a frame, so sudden gravity refines the beam before its first
frame and liver_press's load reaches the finest level by 0.04 s; without it nothing splits
before the first frame ends (the thesis' rule), and without loads the two runs are the same."""
import os
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: run, check, parse_args, report)
from test_tool_scenarios import blocks  # noqa: E402  (a frame's blocks by name)

check = cli.check


def run(binary, source, tmp, scenario, name, sets):
    out = os.path.join(tmp, name)
    args = ["run", os.path.join(source, "scenarios", scenario), "-o", out, "-q",
            "--set", "output.vtk=false"]
    for s in sets:
        args += ["--set", s]
    r = cli.run(binary, *args)
    check(r.returncode == 0, "%s runs (exit %d) %s" % (name, r.returncode, r.stderr[-200:]))
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        events = [(int(f), k.decode() if isinstance(k, bytes) else str(k))
                  for f, k in zip(h5["/events/frame"][:], h5["/events/kind"][:])]
        return events, h5["/frames/active"][:], h5["/frames/time"][:], out


def test_sudden_gravity(binary, source, tmp):
    sets = ["time.duration=0.04"]
    before, _, _, _ = run(binary, source, tmp, "beam_adaptive.yaml", "beam", sets)
    ahead, active, _, _ = run(binary, source, tmp, "beam_adaptive.yaml", "beam_predict",
                              sets + ["adaptivity.space.predict=true"])
    at_start = [k for f, k in ahead if f == 0]
    check(not [k for f, k in before if f == 0],
          "beam_adaptive without predict: no split at t = 0 (the criterion is zero at rest)")
    check(len(at_start) > 0 and set(at_start) == {"split"} and active[0, 1] > 0,
          "with predict, sudden gravity splits %d points at t = 0 (frame 0 shows %d level-1 "
          "points)" % (len(at_start), active[0, 1]))


def test_split_checks(binary, source, tmp):
    """adaptivity.space.split_checks: splits decided within the frame. Under sudden gravity
    the beam (calibrated, as docs/hierarchy.md "Splits within the frame" measures it) is
    almost entirely on its finest level at the end of the first frame with 8 checks (482 of
    490 active points), while with frame-end decisions it is still on level 1; its tip then
    follows beam_L2 alone's first frames closely, where the frame-end run lags by a fifth of
    the peak. With a tensor per tet the adaptive beam stays within 0.2 of the peak over the
    whole second, with checks within the frame or decisions at its end (issue 16 point 3)."""
    # The calibration's cache in the test's folder, not the user's (the runs inherit it).
    saved = os.environ.get("MRSIM_CACHE_DIR")
    os.environ["MRSIM_CACHE_DIR"] = os.path.join(tmp, "split_checks_cache")
    sets = ["time.duration=1.0", "time.substeps=256", "object.calibration=orthotropic",
            "adaptivity.space.coarsen_below=0.0001", "output.vtk=true"]
    ends, at_ends, _, out_ends = run(binary, source, tmp, "beam_adaptive.yaml", "beam_ends", sets)
    within, at_checks, _, out_checks = run(binary, source, tmp, "beam_adaptive.yaml",
                                           "beam_checks", sets + ["adaptivity.space.split_checks=8"])
    _, _, _, out_l2 = run(binary, source, tmp, "beam_adaptive.yaml", "beam_l2",
                          ["time.duration=1.0", "time.substeps=256", "output.vtk=true",
                           "object.levels=[{mesh: meshes/beam_L2.vtu}]",
                           "adaptivity.space.enabled=false"])
    finest = at_checks.shape[1] - 1
    check(at_checks[1, finest] > at_ends[1, finest]
          and at_checks[1, finest] >= 0.95 * at_checks[1].sum(),
          "after the first frame: %s active with 8 checks, %s with decisions at frame ends"
          % (at_checks[1].tolist(), at_ends[1].tolist()))
    check(len([k for f, k in within if f == 1 and k == "split"]) >
          len([k for f, k in ends if f == 1 and k == "split"]),
          "more splits in frame 1 with checks within it")
    sys.path.insert(0, os.path.join(source, "bench"))
    import calibration_effect as ce  # the tip of docs/hierarchy.md's tables
    select = ce.CASES["beam"][3]
    ref, a, b = (ce.curve(o, select) for o in (out_l2, out_ends, out_checks))
    peak = np.abs(ref).max()
    gap = lambda c: np.abs(c[:3] - ref[:3]).max() / peak  # the first two frames
    check(gap(b) < 0.06 and gap(a) > 0.15,
          "first two frames against beam_L2 alone: %.3f of the peak with 8 checks, %.3f with "
          "decisions at frame ends" % (gap(b), gap(a)))
    # Issue 16 point 3's band for the transient, every frame of the second, with a tensor per
    # tet: 0.092 with 8 checks, 0.076 at frame ends (docs/hierarchy.md "Per-tet tensors"). The
    # orthotropic levels, whose f1 alone are up to 5 % off L2's, drift further over the second
    # (0.25 with 8 checks, 0.21 at frame ends).
    for name, extra in (("beam_per_tet_checks", ["adaptivity.space.split_checks=8"]),
                        ("beam_per_tet", [])):
        per_tet = [s.replace("orthotropic", "per_tet") for s in sets] + extra
        _, _, _, out_pt = run(binary, source, tmp, "beam_adaptive.yaml", name, per_tet)
        whole = np.abs(ce.curve(out_pt, select) - ref).max() / peak
        check(whole <= 0.2, "per_tet, %s: every frame within %.3f of beam_L2 alone's peak "
              "(<= 0.2)" % ("8 checks" if extra else "decisions at frame ends", whole))
    if saved is None:
        del os.environ["MRSIM_CACHE_DIR"]
    else:
        os.environ["MRSIM_CACHE_DIR"] = saved


def test_load_ramp(binary, source, tmp):
    """The load is ramped in from zero at t = 0: with predict the profile is read as many
    frames ahead as there are levels, so the first splits come at t = 0 and the finest level
    (three splits away) is active by the second frame's end."""
    sets = ["time.duration=0.1"]
    _, before, t, _ = run(binary, source, tmp, "liver_press.yaml", "press",
                          sets + ["adaptivity.space.predict=false"])
    _, ahead, _, _ = run(binary, source, tmp, "liver_press.yaml", "press_predict",
                         sets + ["adaptivity.space.predict=true"])
    first = lambda a: t[np.argmax(a[:, -1] > 0)] if (a[:, -1] > 0).any() else None
    check(first(before) is None and first(ahead) is not None and first(ahead) <= 0.04 + 1e-9
          and ahead[0, 1] > 0,
          "liver_press: with predict, %d level-1 points at t = 0 and the finest level under the "
          "load at t = %s s; without, not before 0.1 s (%s)" % (ahead[0, 1], first(ahead), first(before)))


def test_no_loads_no_change(binary, source, tmp):
    """Without gravity or surface loads the prediction is the displacement itself: the same
    run (a tool's contact force is not a load here; the tools have their own look-ahead)."""
    sets = []  # the whole run: the probe leaves and the regions merge back (0.8-1.1 s)
    _, _, _, a = run(binary, source, tmp, "liver_probe.yaml", "probe", sets)
    _, _, _, b = run(binary, source, tmp, "liver_probe.yaml", "probe_predict",
                     sets + ["adaptivity.space.predict=true"])
    r = cli.run(binary, "compare", a, b)
    differ = [line for line in r.stdout.splitlines() if line.startswith(("log.h5", "summary"))]
    check(differ == ["log.h5 /@scenario adaptivity.space.predict: A false, B true"],
          "liver_probe (no gravity, no load) with predict: the same run, bit for bit (mrsim "
          "compare: %s)" % (differ or r.stdout.strip().splitlines()[-1:]))


def run_calibrated(binary, source, out, cache, kind="orthotropic", vtk=False):
    r = cli.run(binary, "run", os.path.join(source, "scenarios", "beam_adaptive.yaml"), "-o", out,
                "--set", "output.vtk=%s" % str(vtk).lower(), "--set", "time.duration=0.04",
                "--set", "object.calibration=" + kind,
                env=dict(os.environ, MRSIM_CACHE_DIR=cache))
    check(r.returncode == 0, "calibrated beam_adaptive runs (exit %d) %s"
          % (r.returncode, r.stderr[-200:]))
    return r.stdout + r.stderr


def test_calibration_logged(binary, source, tmp):
    """object.calibration: orthotropic gives each coarser beam level its fitted factors, says
    so on the console and logs them with the fit ratios under /levels/level_k; none logs
    nothing. The fit is cached (MRSIM_CACHE_DIR): a second run reads it and is the same run,
    bit for bit; a damaged cache file is said, ignored and rewritten."""
    cache = os.path.join(tmp, "cache")
    out = os.path.join(tmp, "calibrated")
    said = run_calibrated(binary, source, out, cache)
    lines = [line for line in said.splitlines() if line.startswith("object.calibration: level")]
    check(len(lines) == 2, "one console line per coarser level (%d)" % len(lines))
    check("read from the cache" not in said, "the first run computes the calibration")
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        levels = [h5["/levels/level_%d" % k].attrs for k in range(3)]
        scales = [np.asarray(a["calibration_scales"]) for a in levels]
        after = [np.asarray(levels[k]["calibration_sag_ratio_after"]) for k in range(2)]
        before = np.asarray(levels[0]["calibration_sag_ratio_before"])
        f1 = [float(levels[k]["calibration_frequency_ratio_after"][0]) for k in range(2)]
    check(all(len(x) == 7 for x in scales) and np.all(scales[2] == 1)
          and not np.allclose(scales[0], 1),
          "seven factors per level, all 1 on the finest (%s)" % np.round(scales[0], 3))
    check(before.min() < 0.3 and all(np.all(np.abs(a - 1) < 0.07) for a in after)
          and all(abs(f - 1) < 0.06 for f in f1),
          "beam L0 alone sagged %.2f of L2; calibrated, every sag ratio within 7 %% (%s) and f1 "
          "within 6 %% (%s)" % (before.min(), [np.round(a, 3) for a in after], np.round(f1, 3)))
    files = [f for f in os.listdir(os.path.join(cache, "calibration")) if f.endswith(".bin")]
    check(len(files) == 1, "one cache file written (%s)" % files)
    again = os.path.join(tmp, "calibrated_again")
    check("read from the cache" in run_calibrated(binary, source, again, cache),
          "the second run reads the cache")
    r = cli.run(binary, "compare", out, again)
    check(r.returncode == 0, "the cached calibration gives the same run, bit for bit (%s)"
          % r.stdout.strip().splitlines()[-1:])
    with open(os.path.join(cache, "calibration", files[0]), "w") as f:
        f.write('{"key": "torn')
    damaged = os.path.join(tmp, "calibrated_damaged")
    said = run_calibrated(binary, source, damaged, cache)
    check("ignored the calibration cache" in said and "read from the cache" not in said,
          "a damaged cache file is said and the calibration computed again")
    check(cli.run(binary, "compare", out, damaged).returncode == 0,
          "... to the same result, bit for bit")
    check("read from the cache" in run_calibrated(binary, source, damaged, cache),
          "and the rewritten file is read next time")
    _, _, _, plain = run(binary, source, tmp, "beam_adaptive.yaml", "plain",
                         ["time.duration=0.04", "object.calibration=none"])
    with h5py.File(os.path.join(plain, "log.h5"), "r") as h5:
        check("calibration_scales" not in h5["/levels/level_0"].attrs,
              "object.calibration: none logs no calibration")


def test_per_tet_calibration(binary, source, tmp):
    """object.calibration: per_tet gives each tet of a coarser beam level seven factors on top
    of the level's tensor: the console line says their range and the peaks, log.h5 has the
    range (calibration_tet_scale_range) and the fitted peaks, the frames a 7-component
    `calibration_scale` cell array on the coarser level blocks; the per-tet factors round-trip
    through the cache (a second run reads them and is the same run, bit for bit), apart from the
    level-wide fit's file."""
    cache = os.path.join(tmp, "cache_per_tet")
    out = os.path.join(tmp, "per_tet")
    said = run_calibrated(binary, source, out, cache, "per_tet", vtk=True)
    lines = [line for line in said.splitlines() if line.startswith("object.calibration: level")]
    check(len(lines) == 2 and all("per-tet factors" in line and "peak z" in line for line in lines),
          "one console line per coarser level, with its peaks and per-tet factors (%s)" % lines)
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        levels = [h5["/levels/level_%d" % k].attrs for k in range(3)]
        ranges = [np.asarray(levels[k]["calibration_tet_scale_range"]) for k in range(2)]
        level_scales = [np.asarray(levels[k]["calibration_scales"]) for k in range(2)]
        peak = np.asarray(levels[1]["calibration_peak_ratio_after"])
        local = np.asarray(levels[1]["calibration_local_ratio_after"])
        f1 = float(levels[1]["calibration_frequency_ratio_after"][0])
        check("calibration_tet_scale_range" not in levels[2], "none on the finest level")
    check(all(0 < r[0] <= r[1] for r in ranges),
          "per-tet factors positive (%s)" % [np.round(r, 3) for r in ranges])
    check(np.all(np.abs(peak - 1) < 0.05) and abs(f1 - 1) < 0.05,
          "beam L1 alone within 5 %% of L2 on its peaks (%s) and f1 (%.3f)" % (np.round(peak, 3), f1))
    check(len(local) == 12 and np.all(np.abs(local - 1) < 0.08),
          "beam L1 alone within 8 %% of L2 under its twelve local loads (%s)" % np.round(local, 3))
    frame = blocks(os.path.join(out, "frames", "frame_000001.vtm"))
    cells = [frame["level_%d" % k][1].get("cell:calibration_scale") for k in range(3)]
    check(all(c is not None for c in cells[:2]) and cells[2] is None
          and all(np.shape(cells[k]) == (frame["level_%d" % k][2].GetNumberOfCells(), 7)
                  for k in range(2))
          and all(np.isclose(cells[k].min(), ranges[k][0]) and np.isclose(cells[k].max(), ranges[k][1])
                  for k in range(2)),
          "the frames carry each coarser level's seven factors per tet (calibration_scale), none "
          "on the finest level")
    names = frame["level_0"][2].GetCellData().GetArray("calibration_scale")
    check([names.GetComponentName(j) for j in range(7)]
          == ["lambda", "xx", "yy", "zz", "yz", "xz", "xy"], "its components are named")
    check(all(np.all(cells[k] * level_scales[k] <= 5.0 + 1e-9) for k in range(2)),
          "no component of any tet's tensor above 5 times the material's (%s)"
          % [float(np.max(cells[k] * level_scales[k])) for k in range(2)])
    again = os.path.join(tmp, "per_tet_again")
    check("read from the cache" in run_calibrated(binary, source, again, cache, "per_tet", vtk=True),
          "the second per_tet run reads the cache")
    r = cli.run(binary, "compare", out, again)
    check(r.returncode == 0, "the cached per-tet factors give the same run, bit for bit (%s)"
          % r.stdout.strip().splitlines()[-1:])
    other = os.path.join(tmp, "orthotropic_after_per_tet")
    check("read from the cache" not in run_calibrated(binary, source, other, cache, vtk=True),
          "the level-wide fit does not read the per-tet fit's file")
    frame = blocks(os.path.join(other, "frames", "frame_000001.vtm"))
    check("cell:calibration_scale" not in frame["level_0"][1],
          "orthotropic frames have no calibration_scale")


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        test_sudden_gravity(args.binary, args.source, tmp)
        test_split_checks(args.binary, args.source, tmp)
        test_load_ramp(args.binary, args.source, tmp)
        test_no_loads_no_change(args.binary, args.source, tmp)
        test_calibration_logged(args.binary, args.source, tmp)
        test_per_tet_calibration(args.binary, args.source, tmp)
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
