#!/usr/bin/python3
"""End-to-end checks of the tools (issue 6): the haptic-rate log (/tool/* at every step), the
surface and tool blocks of every VTU frame, refinement under the probe, CSV trajectories,
the real-time budget, bad tool input, and the bundled scenarios of the thesis' figures:
liver_probe (Fig. 5.9), little_man_shake (Fig. 5.10), volume_lambda_* (Fig. 5.8; the volume
changes printed here are the ones the README reports)."""
import json
import os
import re
import sys
import tempfile

import h5py
import numpy as np
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: run, check)

check = cli.check


def blocks(vtm):
    """{block name: (points, point arrays, cells as an index array or None)}."""
    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(vtm)
    reader.Update()
    mb = reader.GetOutput()
    out = {}
    for b in range(mb.GetNumberOfBlocks()):
        name = mb.GetMetaData(b).Get(vtkCompositeDataSet.NAME())
        data = mb.GetBlock(b)
        pd = data.GetPointData()
        arrays = {pd.GetArrayName(i): vtk_to_numpy(pd.GetArray(i)) for i in range(pd.GetNumberOfArrays())}
        cd = data.GetCellData()
        for i in range(cd.GetNumberOfArrays()):
            arrays["cell:" + cd.GetArrayName(i)] = vtk_to_numpy(cd.GetArray(i))
        out[name] = (vtk_to_numpy(data.GetPoints().GetData()), arrays, data)
    return out


def tet_volume(points, cells):
    a, b, c, d = (points[cells[:, k]] for k in range(4))
    return np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a)) / 6.0


def level_tets(grid):
    conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    return conn.reshape(-1, 4)


def test_liver_probe(binary, source, tmp):
    """Fig. 5.9: the finest level appears under the probe and leaves after it; the force on the
    probe is logged at every step; every frame has the deformed skin and the probe."""
    out = os.path.join(tmp, "liver_probe")
    r = cli.run(binary, "run", os.path.join(source, "scenarios", "liver_probe.yaml"), "-o", out, "-q")
    check(r.returncode == 0, "liver_probe runs (exit %d) %s" % (r.returncode, r.stderr[-300:]))
    summary = json.load(open(os.path.join(out, "summary.json")))
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        t = h5["/tool/time"][:]
        pos = h5["/tool/position"][:]
        force = h5["/tool/force"][:]
        contacts = h5["/tool/contacts"][:]
        frame_force = h5["/frames/tool_force"][:]
        frame_time = h5["/frames/time"][:]
        active = h5["/frames/active"][:]
        name = h5["/tool"].attrs["name"]
        name = name.decode() if isinstance(name, bytes) else str(name)
    # What the README's Fig. 5.9 row states: finest points at the strongest push, peak, rate.
    readme = open(os.path.join(source, "README.md"), encoding="utf-8").read()
    row = re.search(r"\((\d+) of 3386 points at the strongest push, peak ([\d.]+) N\) and the "
                    r"liver is back on level 0 at the end; `/tool/force` at ([\d.]+) kHz", readme)
    check(row is not None, "README states liver_probe's figures")
    stated_points, stated_peak, stated_khz = row.groups() if row else ("-1", "-1", "-1")
    rate = 1.0 / np.diff(t)
    check(len(t) == summary["steps"] and force.shape == (len(t), 3) and pos.shape == (len(t), 3),
          "/tool/* has one sample per simulation step (%d)" % len(t))
    khz = 1000 * float(stated_khz)
    check(bool(np.all(rate >= 1000)) and abs(rate.min() - khz) < 1e-6 * khz,
          "the force is logged at %.0f Hz of simulated time (>= 1 kHz; README: %s kHz)"
          % (rate.min(), stated_khz))
    check(name == "probe", "/tool is named after the scenario's tool (%s)" % name)
    at_frames = np.searchsorted(t, frame_time[1:] - 1e-12)
    check(frame_force.shape == (len(frame_time), 1, 3) and
          np.array_equal(frame_force[1:, 0, :], force[at_frames]),
          "/frames/tool_force is the force at each frame's last step")
    peak = np.linalg.norm(force, axis=1).max()
    check(abs(summary["peak_tool_force"] - peak) <= 1e-12 * peak and
          "%.2f" % peak == stated_peak,
          "summary peak_tool_force = max |/tool/force| = %.3f N (README: %s N)"
          % (peak, stated_peak))
    touching = contacts > 0
    check(bool(np.all(force[~touching] == 0)) and bool(np.all(force[touching, 2] > 0)),
          "the force is zero without contact and pushes the probe up while touching")
    fine = active[:, -1]
    pressed = np.argmax(frame_force[:, 0, 2])
    check(str(fine[pressed]) == stated_points and fine[-1] == 0 and active[-1, 0] == active[0, 0],
          "finest level active under the probe (%d points at the strongest push, README: %s), "
          "back to level 0 at the end" % (fine[pressed], stated_points))
    vtm = os.path.join(out, "frames", "frame_%06d.vtm" % pressed)
    b = blocks(vtm)
    check("surface" in b and "tool" in b, "frame %d has the surface and tool blocks" % pressed)
    spts, sarr, _ = b["surface"]
    tpts, tarr, _ = b["tool"]
    f_skin = sarr["contact_force"].sum(axis=0)
    check(np.allclose(f_skin, -frame_force[pressed, 0], rtol=1e-9, atol=1e-12),
          "the skin's contact forces sum to minus the force on the probe")
    centre = pos[at_frames[pressed - 1]]
    dist = np.linalg.norm(tpts - centre, axis=1)
    check(abs(dist.max() - 0.01) < 1e-9, "the tool block is the probe's sphere at its position")
    tri = vtk_to_numpy(b["surface"][2].GetPolys().GetConnectivityArray()).reshape(-1, 3)
    rest = spts - sarr["displacement"]
    edge = np.mean([np.linalg.norm(rest[tri[:, i]] - rest[tri[:, (i + 1) % 3]], axis=1).mean()
                    for i in range(3)])
    inside = np.linalg.norm(spts - centre, axis=1) < 0.01
    deepest = 0.01 - np.linalg.norm(spts - centre, axis=1).min()
    check(inside.sum() > 0 and deepest < 0.4 * edge,
          "skin vertices inside the probe by at most 0.4 of a skin edge (%.1f mm): deepest "
          "%.2f mm, %d inside" % (edge * 1e3, deepest * 1e3, inside.sum()))
    levels = sarr["level"]
    near = np.linalg.norm(spts - centre, axis=1) < 0.015
    check(bool(np.all(levels[near] == 3)), "skin near the probe is moved by the finest level")


def test_liver_thesis(binary, source, tmp):
    """Fig. 5.9 on the thesis' own hierarchy (28 / 172 / 1874 tets asked of mrsim mesh) with
    time levels on, as the thesis ran it: the numbers the README states for it."""
    out = os.path.join(tmp, "liver_thesis")
    r = cli.run(binary, "run", os.path.join(source, "scenarios", "liver_thesis.yaml"), "-o", out, "-q")
    check(r.returncode == 0, "liver_thesis runs (exit %d) %s" % (r.returncode, r.stderr[-300:]))
    summary = json.load(open(os.path.join(out, "summary.json")))
    tets = summary["tets"]
    check(all(abs(n / asked - 1) <= 0.2 for n, asked in zip(tets, (28, 172, 1874))),
          "levels of %s tets, each within 20 %% of the thesis' 28 / 172 / 1874" % tets)
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        active = h5["/frames/active"][:]
        push = np.argmax(h5["/frames/tool_force"][:, 0, 2])
        levels = h5["/frames/time_levels"][push]
        t = h5["/tool/time"][:]
    fine = active[push, -1]
    check(fine == 33 and active[:, -1].max() == 44 and active[-1, -1] == 0 and active[-1, 0] == active[0, 0],
          "finest level active under the probe (%d of %d points at the strongest push, README: "
          "33, at most 44), back to level 0 at the end" % (fine, summary["points"][-1]))
    # Two time levels at least: the graded finest patch and the coarse body around it. (Three
    # before the ghosts' stiffness bounds were shared by the masses receiving them: the third
    # held a few fringe points whose estimate was too cautious; docs/integrators.md.)
    check(np.count_nonzero(levels) >= 2,
          "particles on %d time levels at the strongest push (%s)" % (np.count_nonzero(levels), levels))
    peak = summary["peak_tool_force"]
    check(abs(peak - 1.271) < 0.0005, "peak force on the probe %.4f N (README: 1.271 N)" % peak)
    # What the README's Fig. 5.9 row states: finest points at the strongest push, peak, rate.
    readme = open(os.path.join(source, "README.md"), encoding="utf-8").read()
    row = re.search(r"\((\d+) of 3386 points at the strongest push, peak ([\d.]+) N\) and the "
                    r"liver is back on level 0 at the end; `/tool/force` at ([\d.]+) kHz", readme)
    check(row is not None, "README states liver_probe's figures")
    stated_points, stated_peak, stated_khz = row.groups() if row else ("-1", "-1", "-1")
    rate = 1.0 / np.diff(t)
    check(rate.min() >= 1000, "force logged at %.0f-%.0f Hz (>= 1 kHz)" % (rate.min(), rate.max()))


def test_time_levels_rate(binary, source, tmp):
    """With time levels a frame may have few kicking ticks: the force is still sampled at every
    kicking tick and at least every millisecond."""
    out = os.path.join(tmp, "probe_time_levels")
    r = cli.run(binary, "run", os.path.join(source, "scenarios", "liver_probe.yaml"), "-o", out,
                "-q", "--set", "adaptivity.time.enabled=true", "--set", "time.substeps=1024")
    check(r.returncode == 0, "liver_probe with time levels runs (exit %d) %s" % (r.returncode, r.stderr[-200:]))
    summary = json.load(open(os.path.join(out, "summary.json")))
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        t = h5["/tool/time"][:]
        f = h5["/tool/force"][:]
        frame_t = h5["/frames/time"][:]
        frame_f = h5["/frames/tool_force"][:, 0, :]
    gap = np.diff(t).max()
    # Samples cover (frame start, frame end] as without time levels: every frame's end, the
    # last one included, is sampled once. (Its force is the one before the frame boundary's
    # splits and merges; /frames/tool_force is after them, so the two may differ slightly.)
    at_end = [np.flatnonzero(np.abs(t - x) < 1e-9) for x in frame_t[1:]]
    scale = np.abs(frame_f).max()
    check(t[0] > 0 and all(len(i) == 1 for i in at_end)
          and all(np.abs(f[i[0]] - frame_f[k + 1]).max() < 0.02 * scale
                  for k, i in enumerate(at_end)),
          "with time levels: one sample at every frame's end (the last frame's too, t = %.3f s), "
          "next to the frame's force" % frame_t[-1])
    check(len(t) >= summary["steps"] and gap <= 1e-3 + 1e-12 and f[:, 2].max() > 0.5,
          "with time levels: %d samples for %d sub-steps, longest gap %.3f ms (<= 1 ms), peak %.2f N"
          % (len(t), summary["steps"], gap * 1e3, f[:, 2].max()))


def first_split_and_contact(log):
    """(time of the first frame with a level above 0 active, time of the first contact)."""
    with h5py.File(log, "r") as h5:
        t, contacts = h5["/tool/time"][:], h5["/tool/contacts"][:]
        frame_time, active = h5["/frames/time"][:], h5["/frames/active"][:]
        push = np.argmax(h5["/frames/tool_force"][:, 0, 2])
    refined = active[:, 1:].sum(axis=1) > 0
    return frame_time[np.argmax(refined)], t[np.argmax(contacts > 0)], active, push


def test_criterion_refines_under_tool(binary, source, tmp):
    """Issue 16 point 2: with adaptivity.space.contact_refine false only the Laplacian criterion
    decides (the thesis' Fig. 5.9): nothing splits before the probe touches, the finest level
    takes over under it, and the liver is back on level 0 after it leaves. With the look-ahead
    (the default, test_liver_probe) the splits come before the contact."""
    probe = os.path.join(source, "scenarios", "liver_probe.yaml")
    runs = {}
    for refine in ("true", "false"):
        out = os.path.join(tmp, "probe_contact_refine_" + refine)
        r = cli.run(binary, "run", probe, "-o", out, "-q", "--set", "output.vtk=false",
                    "--set", "adaptivity.space.contact_refine=" + refine)
        check(r.returncode == 0, "liver_probe with contact_refine=%s runs (exit %d) %s"
              % (refine, r.returncode, r.stderr[-300:]))
        runs[refine] = first_split_and_contact(os.path.join(out, "log.h5"))
    split_on, contact_on, _, _ = runs["true"]
    split, contact, active, push = runs["false"]
    check(split_on < contact_on,
          "look-ahead on: first split at t = %.2f s, before the first contact at %.3f s"
          % (split_on, contact_on))
    check(split >= contact and active[push, -1] > 0 and np.array_equal(active[-1], active[0]),
          "criterion alone: first split at t = %.2f s, after the first contact at %.3f s; %d "
          "finest points at the strongest push; level 0 alone again at the end"
          % (split, contact, active[push, -1]))


def write_scenario(path, base, replace):
    text = open(base).read()
    meshes = os.path.join(os.path.dirname(os.path.abspath(base)), "meshes") + "/"
    text = text.replace("meshes/", meshes)
    for a, b in replace:
        check(a in text, "scenario edit applies: " + a[:40])
        text = text.replace(a, b)
    open(path, "w").write(text)


def test_csv_trajectory(binary, source, tmp):
    """A device recording with the same samples as keyframes gives the same run, bit for bit;
    a malformed recording exits 2 naming the file and line, before anything is written."""
    base = os.path.join(source, "scenarios", "liver_probe.yaml")
    keys = [(0.0, 0.21), (0.4, 0.1975), (0.7, 0.1975), (1.0, 0.22)]
    csv = os.path.join(tmp, "probe.csv")
    with open(csv, "w") as f:
        f.write("# recorded probe\nt, x, y, z, qw, qx, qy, qz\n")
        for t, z in keys:
            f.write("%r, 0.09, 0.10, %r, 1, 0, 0, 0\n" % (t, z))
    old = """  trajectory:
    - {t: 0.0, position: [0.09, 0.10, 0.21]}
    - {t: 0.4, position: [0.09, 0.10, 0.1975]}
    - {t: 0.7, position: [0.09, 0.10, 0.1975]}
    - {t: 1.0, position: [0.09, 0.10, 0.22]}
  interpolation: smooth"""
    a, b = os.path.join(tmp, "keys.yaml"), os.path.join(tmp, "csv.yaml")
    write_scenario(a, base, [(old, old.replace("smooth", "linear"))])
    write_scenario(b, base, [(old, "  trajectory: {csv: %s}\n  interpolation: linear" % csv)])
    outs = []
    for path, tag in ((a, "keys"), (b, "csv")):
        out = os.path.join(tmp, "traj_" + tag)
        r = cli.run(binary, "run", path, "-o", out, "-q", "--set", "time.duration=0.3")
        check(r.returncode == 0, "%s trajectory runs (exit %d) %s" % (tag, r.returncode, r.stderr[-200:]))
        outs.append(out)
    with h5py.File(os.path.join(outs[0], "log.h5"), "r") as h0, \
            h5py.File(os.path.join(outs[1], "log.h5"), "r") as h1:
        same = all(np.array_equal(h0[k][:], h1[k][:])
                   for k in ("/tool/position", "/tool/force", "/frames/kinetic_energy"))
    check(same, "keyframes and the same samples as CSV give bit-identical tool logs and energies")
    bad = os.path.join(tmp, "bad.csv")
    with open(bad, "w") as f:
        f.write("t,x,y,z\n0,0.09,0.1,0.21\n0.5,0.09,oops,0.2\n")
    c = os.path.join(tmp, "bad_csv.yaml")
    write_scenario(c, base, [(old, "  trajectory: {csv: %s}" % bad)])
    out = os.path.join(tmp, "bad_out")
    r = cli.run(binary, "run", c, "-o", out)
    check(r.returncode == 2 and "bad.csv:3" in r.stderr and "tool.trajectory.csv" in r.stderr
          and not os.path.exists(out),
          "a malformed CSV exits 2 naming the key, file and line, nothing written: "
          + r.stderr.strip()[-160:])


def test_skin_surface(binary, source, tmp):
    """object.skin.surface: a separate surface (here the liver's source surface, in mm) is the
    skin the probe touches and the surface block shows; it is bound to every level."""
    base = os.path.join(source, "scenarios", "liver_probe.yaml")
    path = os.path.join(tmp, "skin.yaml")
    surface = os.path.join(os.path.abspath(source), "scenarios", "meshes", "liver_surface_cgal_h10_mm.off")
    write_scenario(path, base, [("  units: m\n", "  units: m\n  skin: {surface: %s, units: mm}\n" % surface)])
    out = os.path.join(tmp, "skin_out")
    r = cli.run(binary, "run", path, "-o", out, "-q", "--set", "time.duration=0.5")
    check(r.returncode == 0, "a separate skin surface runs (exit %d) %s" % (r.returncode, r.stderr[-200:]))
    b = blocks(os.path.join(out, "frames", "frame_000025.vtm"))
    pts, arr, data = b["surface"]
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        f = h5["/tool/force"][:, 2]
    check(len(pts) == 1496 and data.GetNumberOfPolys() == 2988,
          "the surface block is the given surface (%d vertices)" % len(pts))
    check(np.abs(pts - arr["displacement"]).max() < 0.25 and f.max() > 0.5,
          "read in mm and converted; the probe pushes it (peak %.2f N)" % f.max())
    bad = os.path.join(tmp, "skin_bad.yaml")
    write_scenario(bad, base, [("  units: m\n", "  units: m\n  skin: {surface: missing.stl}\n")])
    r = cli.run(binary, "check", bad)
    check(r.returncode == 2 and "missing.stl" in r.stderr,
          "a missing skin surface exits 2 naming it: " + r.stderr.strip()[-120:])


def test_budget(binary, source, tmp):
    """adaptivity.budget: over fraction x frame_dt splits are held (shedding over the whole frame
    is tested in C++, SpaceAdaptivity.Budget…: it needs a frame slower than real time, which
    depends on the machine). Each such frame is an event and counted in summary.json."""
    base = os.path.join(source, "scenarios", "liver_probe.yaml")
    out = os.path.join(tmp, "budget_shed")
    # A budget of a millionth of the frame: every frame is over it (held or, over 20 ms, shed).
    r = cli.run(binary, "run", base, "-o", out, "-q", "--set", "time.duration=0.6",
                "--set", "adaptivity.budget.realtime=true",
                "--set", "adaptivity.budget.fraction=1.0e-6")
    check(r.returncode == 0, "budget run (exit %d) %s" % (r.returncode, r.stderr[-200:]))
    s = json.load(open(os.path.join(out, "summary.json")))
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        kinds = [k.decode() if isinstance(k, bytes) else str(k) for k in h5["/events/kind"][:]]
        wall = h5["/frames/wall_time"][1:]
        active = h5["/frames/active"][:]
    over = int(np.sum(wall > 0.02))
    check(s["budget_shed_frames"] + s["budget_hold_frames"] == len(wall) and
          kinds.count("budget_shed") == s["budget_shed_frames"] and
          kinds.count("budget_hold") == s["budget_hold_frames"] and s["splits"] == 0 and
          bool(np.all(active[:, 1:] == 0)),
          "with the real-time budget over the frame time (%d of %d frames over 20 ms), "
          "nothing splits: %d shed, %d held" % (over, len(wall), s["budget_shed_frames"],
                                                s["budget_hold_frames"]))
    off = os.path.join(tmp, "budget_off")
    r = cli.run(binary, "run", base, "-o", off, "-q", "--set", "time.duration=0.6")
    s_off = json.load(open(os.path.join(off, "summary.json")))
    check(s_off["splits"] > 0 and "budget_hold_frames" not in s_off,
          "without it the same run splits (%d) and logs no budget" % s_off["splits"])


def test_volume_lambda(binary, source, tmp):
    """Fig. 5.8: the same indentation with lambda = 0, 5e4, 5e5 Pa; the volume change of the
    liver on the last frame (finest level, showing the whole deformed body)."""
    changes = {}
    for tag, lam in (("0", 0.0), ("5e4", 5e4), ("5e5", 5e5)):
        out = os.path.join(tmp, "volume_" + tag)
        r = cli.run(binary, "run", os.path.join(source, "scenarios", "volume_lambda_%s.yaml" % tag),
                    "-o", out, "-q")
        check(r.returncode == 0, "volume_lambda_%s runs (exit %d) %s" % (tag, r.returncode, r.stderr[-200:]))
        frames = sorted(os.listdir(os.path.join(out, "frames")))
        last = os.path.join(out, "frames", [f for f in frames if f.endswith(".vtm")][-1])
        b = blocks(last)
        pts, arr, grid = b["level_3"]
        tets = level_tets(grid)
        rest = pts - arr["displacement"]
        v0 = tet_volume(rest, tets).sum()
        v1 = tet_volume(pts, tets).sum()
        with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
            f = h5["/tool/force"][-1, 2]
        changes[tag] = (v1 - v0, v0, f)
    cap = np.pi * 0.015 ** 2 * (3 * 0.015 - 0.015) / 3  # volume of the tool below the rest surface
    for tag, (dv, v0, f) in changes.items():
        print("volume_lambda_%s: dV = %.3f cm^3 (%.4f %% of %.1f cm^3; %.1f %% of the %.2f cm^3 "
              "the probe pushed in), probe force %.3f N"
              % (tag, dv * 1e6, 100 * dv / v0, v0 * 1e6, 100 * dv / cap, cap * 1e6, f))
    dvs = [abs(changes[t][0]) for t in ("0", "5e4", "5e5")]
    check(changes["0"][0] < 0 and dvs[0] > dvs[1] > dvs[2],
          "the volume lost decreases with lambda: %s cm^3" % ["%.3f" % (d * 1e6) for d in dvs])
    check(dvs[2] < 0.5 * dvs[0], "lambda = 5e5 loses less than half of lambda = 0's volume")
    forces = [changes[t][2] for t in ("0", "5e4", "5e5")]
    check(forces[0] < forces[1] < forces[2], "the stiffer in volume, the harder the probe pushes: %s N"
          % ["%.3f" % f for f in forces])
    # The README's table, row by row: lambda, nu, dV (cm3, % of the liver), % of the cap, force.
    readme = open(os.path.join(source, "README.md"), encoding="utf-8").read()
    rows = dict((m.group(1), m.groups()[1:]) for m in re.finditer(
        r"^\| (0|5·10⁴|5·10⁵) \| [\d.]+ \| (\S+) cm³ \((\S+) %\) \| (\S+) % \| ([\d.]+) N \|$",
        readme, re.M))
    for label, tag in (("0", "0"), ("5·10⁴", "5e4"), ("5·10⁵", "5e5")):
        dv, v0, f = changes[tag]
        ours = tuple(x.replace("-", "−") for x in (
            "%.3g" % (dv * 1e6), "%.2f" % (100 * dv / v0), "%.0f" % (100 * dv / cap), "%.2f" % f))
        check(rows.get(label) == ours, "volume_lambda_%s: the README's table says %s (dV cm^3, "
              "%% of the liver, %% of the cap, N), the run %s" % (tag, rows.get(label), ours))


def test_little_man(binary, source, tmp):
    """Fig. 5.10: the belly is shaken by two tools; the arms keep oscillating after release."""
    out = os.path.join(tmp, "little_man")
    r = cli.run(binary, "run", os.path.join(source, "scenarios", "little_man_shake.yaml"), "-o", out, "-q")
    check(r.returncode == 0, "little_man_shake runs (exit %d) %s" % (r.returncode, r.stderr[-200:]))
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        t = h5["/frames/time"][:]
        names = [h5[g].attrs["name"] for g in ("/tool", "/tool_1")]
        f0 = h5["/tool/force"][:]
        f1 = h5["/tool_1/force"][:]
        finest_share = h5["/frames/active"][:, -1].mean() / 4410
    names = [n.decode() if isinstance(n, bytes) else str(n) for n in names]
    check(names == ["front", "back"], "two tools logged as /tool and /tool_1: %s" % names)
    check(f0[:, 1].min() < -0.1 and f1[:, 1].max() > 0.1,
          "the belly pushes the front tool (-y side) to -y and the back tool to +y: %.2f, %.2f N"
          % (f0[:, 1].min(), f1[:, 1].max()))
    tips = []
    for k in range(len(t)):
        pts, arr, _ = blocks(os.path.join(out, "frames", "frame_%06d.vtm" % k))["level_0"]
        rest = pts - arr["displacement"]
        tip = np.abs(rest[:, 0]) > 0.1
        tips.append(arr["displacement"][tip, 1].mean())
    tips = np.array(tips)
    free = t > 1.45
    swing = tips[free] - tips[free].mean()
    crossings = int(np.sum(np.diff(np.sign(swing)) != 0))
    print("little_man_shake: arm tips' y-displacement after release: amplitude %.2f mm, "
          "%d zero crossings in %.2f s" % (np.abs(swing).max() * 1e3, crossings, t[-1] - 1.45))
    check(np.abs(tips).max() > 2e-3, "the arms move by more than 2 mm while shaken (%.1f mm)"
          % (np.abs(tips).max() * 1e3))
    stated = ("18.2", "17.3", 5, "2.22", "2.01")  # README's Fig. 5.10 row
    measured = ("%.1f" % (np.abs(tips).max() * 1e3), "%.1f" % (np.abs(swing).max() * 1e3),
                crossings, "%.2f" % -f0[:, 1].min(), "%.2f" % f1[:, 1].max())
    check(measured == stated, "little_man_shake: README says arms up to %s mm, %s mm after "
          "release, %d crossings, %s and %s N; the run gives %s" % (stated + (measured,)))
    check(round(100 * finest_share) == 77, "little_man_shake: %.1f %% of the finest points active "
          "on average (README: 77 %%)" % (100 * finest_share))
    check(crossings >= 2 and np.abs(swing).max() > 2e-4,
          "the arms keep oscillating after the tools let go")


def write_box_vtu(path, n):
    """A (2n x 2n x n)-cell box of 2 x 2 x 1 cm, Kuhn-split into tets (n even: nested levels)."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid, VTK_TETRA
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
    nx, ny, nz = 2 * n, 2 * n, n
    pts = vtkPoints()
    idx = lambda i, j, k: i + (nx + 1) * (j + (ny + 1) * k)
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                pts.InsertNextPoint(0.02 * i / nx, 0.02 * j / ny, 0.01 * k / nz)
    grid = vtkUnstructuredGrid()
    grid.SetPoints(pts)
    paths = [(1, 3), (1, 5), (2, 3), (2, 6), (4, 5), (4, 6)]
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                v = [idx(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)) for c in range(8)]
                for a, b in paths:
                    t = [v[0], v[a], v[b], v[7]]
                    p = [np.array(pts.GetPoint(q)) for q in t]
                    if np.dot(p[1] - p[0], np.cross(p[2] - p[0], p[3] - p[0])) < 0:
                        t[2], t[3] = t[3], t[2]
                    grid.InsertNextCell(VTK_TETRA, 4, t)
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(path)
    w.SetInputData(grid)
    w.Write()


def test_shared_points_warning(binary, tmp):
    """Nested levels (sharing many points) run at the computed step with no warning: their
    interface masses match the stiffness a coincident ghost hands on (docs/hierarchy.md)."""
    for n in (2, 4):
        write_box_vtu(os.path.join(tmp, "nested_%d.vtu" % n), n)
    path = os.path.join(tmp, "nested.yaml")
    with open(path, "w") as f:
        f.write("name: nested\nobject:\n  levels:\n    - mesh: nested_2.vtu\n    - mesh: nested_4.vtu\n"
                "material: {youngs_modulus: 1.0e+4, poisson_ratio: 0.3, density: 1000}\n"
                "fixed:\n  - box: {min: [-1, -1, -1], max: [1, 1, 1.0e-4]}\n"
                "time: {frame_dt: 0.01, duration: 0.01}\n")
    r = cli.run(binary, "run", path, "-o", os.path.join(tmp, "nested_out"),
                "--set", "time.duration=0.2", "--set", "adaptivity.space.refine_above=1.0e-4",
                "--set", "adaptivity.space.coarsen_below=2.5e-5")
    events = []
    if r.returncode == 0:
        with h5py.File(os.path.join(tmp, "nested_out", "log.h5"), "r") as h5:
            events = [k.decode() if isinstance(k, bytes) else k for k in h5["/events/kind"][:]]
    check(r.returncode == 0 and "split" in events and "warning" not in r.stderr,
          "nested levels split and run at the computed step, unwarned: " + r.stderr.strip()[-200:])
    r = cli.run(binary, "run", path, "-o", os.path.join(tmp, "nested_force"),
                "--set", "adaptivity.space.coupling=force")
    check(r.returncode == 0 and "shares" not in r.stderr, "not with the force coupling")


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        test_shared_points_warning(args.binary, tmp)
        test_liver_probe(args.binary, args.source, tmp)
        test_liver_thesis(args.binary, args.source, tmp)
        test_time_levels_rate(args.binary, args.source, tmp)
        test_criterion_refines_under_tool(args.binary, args.source, tmp)
        probe = os.path.join(args.source, "scenarios", "liver_probe.yaml")
        cli.test_threads_bit_identical(args.binary, probe, tmp, 0.3, (5, 15))
        cli.test_threads_bit_identical(
            args.binary, probe, tmp, 0.3, (5, 15), tag="_time_sv",
            sets=["adaptivity.time.enabled=true", "time.substeps=1024",
                  "time.integrator=stoermer_verlet"])
        test_csv_trajectory(args.binary, args.source, tmp)
        test_skin_surface(args.binary, args.source, tmp)
        test_budget(args.binary, args.source, tmp)
        test_volume_lambda(args.binary, args.source, tmp)
        test_little_man(args.binary, args.source, tmp)
    print("%d passed, %d failed" % (len(cli.PASSED), len(cli.FAILURES)))
    return 1 if cli.FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
