#!/usr/bin/python3
"""Each level where it simulates (issue 19 point 2): the per-cell arrays `simulated` and
`simulated_by` of the level blocks, checked with VTK's own filters against an independent
Monte-Carlo ownership (a location belongs to the finest level whose tet there has no inactive
vertex, the rule of the skin's `level`): the finest block thresholded by `simulated_by` shows the
object once, each level's part within 2 % of the object's volume of its true share; and
scripts/paraview_levels.py, run by pvbatch when ParaView is installed, writes a picture that is
not blank and a state file."""
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import (vtkCellLocator, vtkDataObject, vtkGenericCell,
                                           vtkUnstructuredGrid)
from vtkmodules.vtkFiltersCore import vtkThreshold
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: run, check)
import test_tool_scenarios as tool_scenarios  # noqa: E402  (blocks, tet_volume, level_tets)

check = cli.check


def read_blocks(vtm):
    """{block name: grid}."""
    return {name: grid for name, (_, _, grid) in tool_scenarios.blocks(vtm).items()}


def volume(grid):
    if grid.GetNumberOfCells() == 0:
        return 0.0
    return float(tool_scenarios.tet_volume(vtk_to_numpy(grid.GetPoints().GetData()),
                                           tool_scenarios.level_tets(grid)).sum())


def threshold(grid, array, lo, hi):
    f = vtkThreshold()
    f.SetInputData(grid)
    f.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_CELLS, array)
    f.SetLowerThreshold(lo)
    f.SetUpperThreshold(hi)
    f.SetThresholdFunction(vtkThreshold.THRESHOLD_BETWEEN)
    f.Update()
    return f.GetOutput()


def monte_carlo_owners(levels, samples=20000):
    """Volume fraction owned by each level, sampling the finest mesh uniformly at rest."""
    located = []
    for g in levels:
        rest = vtk_to_numpy(g.GetPoints().GetData()) - vtk_to_numpy(
            g.GetPointData().GetArray("displacement"))
        copy = vtkUnstructuredGrid()
        copy.DeepCopy(g)
        pts = vtkPoints()
        pts.SetData(numpy_to_vtk(rest.copy()))
        copy.SetPoints(pts)
        loc = vtkCellLocator()
        loc.SetDataSet(copy)
        loc.BuildLocator()
        tets = vtk_to_numpy(g.GetCells().GetConnectivityArray()).reshape(-1, 4)
        status = vtk_to_numpy(g.GetPointData().GetArray("status"))
        located.append((loc, tets, status, rest))
    loc, tets, status, rest = located[-1]
    a, b, c, d = (rest[tets[:, k]] for k in range(4))
    v = np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a)) / 6
    rng = np.random.default_rng(7)
    pick = rng.choice(len(tets), samples, p=v / v.sum())
    bary = rng.dirichlet([1, 1, 1, 1], samples)
    x = np.einsum("nk,nkj->nj", bary, rest[tets[pick]])
    counts = np.zeros(len(levels))
    cell, pc, w = vtkGenericCell(), [0.0] * 3, [0.0] * 4
    for p in x:
        owner = 0
        for m in range(len(levels) - 1, 0, -1):
            loc_m, tets_m, status_m, _ = located[m]
            cid = loc_m.FindCell(p.tolist(), 1e-10, cell, pc, w)
            if cid >= 0 and np.all(status_m[tets_m[cid]] != 0):
                owner = m
                break
        counts[owner] += 1
    return counts / samples


def test_arrays(binary, source, tmp):
    out = os.path.join(tmp, "probe")
    r = cli.run(binary, "run", os.path.join(source, "scenarios", "liver_probe.yaml"), "-o", out,
                "-q", "--set", "time.duration=0.44")
    check(r.returncode == 0, "liver_probe runs (exit %d) %s" % (r.returncode, r.stderr[-300:]))
    blocks = read_blocks(os.path.join(out, "frames", "frame_000021.vtm"))
    levels = [blocks["level_%d" % l] for l in range(4)]
    finest = levels[-1]
    whole = volume(finest)
    parts = [volume(threshold(finest, "simulated_by", l, l)) for l in range(4)]
    truth = monte_carlo_owners(levels)
    print("frame 21 (t = 0.42 s): object %.1f cm^3; simulated_by on the finest block: %s cm^3; "
          "Monte-Carlo ownership: %s cm^3" % (whole * 1e6, ["%.1f" % (p * 1e6) for p in parts],
                                              ["%.1f" % (t * whole * 1e6) for t in truth]))
    check(abs(sum(parts) - whole) <= 1e-9 * whole and sum(p > 0 for p in parts) >= 3,
          "the finest block by simulated_by shows the object once (%d levels in it)"
          % sum(p > 0 for p in parts))
    check(all(abs(p / whole - t) < 0.02 for p, t in zip(parts, truth)),
          "each level's part within 2 % of the object of the Monte-Carlo ownership")
    shares = [vtk_to_numpy(g.GetCellData().GetArray("simulated")) for g in levels]
    check(all(s.min() >= 0 and s.max() <= 1 for s in shares) and shares[-1].max() == 1,
          "simulated is a share in [0, 1] on every level block")
    # The finest level's own share agrees with who simulates its tets.
    by = vtk_to_numpy(finest.GetCellData().GetArray("simulated_by"))
    check(bool(np.all((shares[-1] > 0.5) <= (by == 3))),
          "a finest tet that level 3 simulates for more than half is simulated_by 3")
    return out


def test_script(source, run, tmp):
    script = os.path.join(source, "scripts", "paraview_levels.py")
    r = subprocess.run(["/usr/bin/python3", script, "--help"], capture_output=True, text=True)
    check(r.returncode == 0 and "pvbatch" in r.stdout, "paraview_levels.py --help without ParaView")
    r = subprocess.run(["/usr/bin/python3", script, tmp], capture_output=True, text=True)
    check(r.returncode == 2 and "not an mrsim run folder" in r.stderr,
          "paraview_levels.py on a folder without frames: exit 2, says why")
    pvbatch = shutil.which("pvbatch")
    # ParaView's Python module unpacked beside python3-vtk9 (README "ParaView").
    pv_python = os.environ.get("MRSIM_PARAVIEW_PYTHONPATH",
                               "/opt/paraview-python/usr/lib/python3/dist-packages")
    if not pvbatch or not os.path.isdir(os.path.join(pv_python, "paraview")):
        print("skipped: no pvbatch with ParaView's Python here (README \"ParaView\")")
        return
    env = dict(os.environ, PYTHONPATH=pv_python)
    xvfb = [shutil.which("xvfb-run"), "-a"] if shutil.which("xvfb-run") else []
    png, state = os.path.join(tmp, "levels.png"), os.path.join(tmp, "levels.pvsm")
    for extra in ([], ["--tets"]):
        r = subprocess.run(xvfb + [pvbatch, script, run, "--time", "0.42", "--png", png,
                                   "--state", state] + extra,
                           capture_output=True, text=True, timeout=300, env=env)
        ok = r.returncode == 0 and os.path.exists(png) and os.path.getsize(state) > 1000
        spread = 0.0
        if ok:
            reader = vtkPNGReader()
            reader.SetFileName(png)
            reader.Update()
            img = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
            spread = float(img.astype(float).std())
        check(ok and spread > 5, "pvbatch paraview_levels.py %s: picture not blank (pixel spread "
              "%.1f) and a state file (exit %d) %s" % (" ".join(extra), spread, r.returncode,
                                                      r.stderr[-300:]))


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        run = test_arrays(args.binary, args.source, tmp)
        test_script(args.source, run, tmp)
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
