#!/usr/bin/python3
"""What `object.calibration` (orthotropic, or per_tet with --calibration per_tet) does to the adaptive runs (issue 16 point 1; the
tables of docs/hierarchy.md "Calibrated levels"): each scenario run adaptively with and without
calibrated coarse levels, and on its coarser levels alone (adaptivity.space.max_level), against
its finest level alone, frames every 20 ms.

- beam_adaptive (1 s, 256 substeps): the tip, mean uz of the finest level's points at x = L;
- liver_press (1.2 s): the press, mean uz of liver_L3's points under the load patch.

Prints, per run, the peak against the finest level alone and the largest difference at any
frame over that peak. Accuracy only (the runs go two at a time): timings are bench/'s
adaptive_vs_uniform.py. The calibration is computed into a temporary cache folder.

    /usr/bin/python3 bench/calibration_effect.py [--binary build/mrsim] [--only beam|liver]
        [--calibration orthotropic|per_tet]
"""
import argparse
import glob
import os
import subprocess
import sys
import tempfile

import numpy as np
from vtk.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader

CAL = "object.calibration=orthotropic"
ALL_FINE = ["adaptivity.space.refine_above=1.0e-12", "adaptivity.space.coarsen_below=0"]
CASES = {
    "beam": ("beam_adaptive.yaml", ["time.duration=1.0", "time.substeps=256"],
             ["object.levels=[{mesh: meshes/beam_L2.vtu}]", "adaptivity.space.enabled=false"],
             lambda P: P[:, 0] >= P[:, 0].max() - 1e-6,
             {"adaptive": [], "adaptive, calibrated": [CAL],
              "L0 alone": ["adaptivity.space.max_level=0"],
              "L0 alone, calibrated": ["adaptivity.space.max_level=0", CAL],
              "L1 alone": ["adaptivity.space.max_level=1"] + ALL_FINE,
              "L1 alone, calibrated": ["adaptivity.space.max_level=1", CAL] + ALL_FINE}),
    "liver": ("liver_press.yaml", ["time.duration=1.2"],
              ["object.levels=[{mesh: meshes/liver_L3.vtu}]", "adaptivity.space.enabled=false"],
              lambda P: ((P[:, 0] >= 0.07) & (P[:, 0] <= 0.11) & (P[:, 1] >= 0.08)
                         & (P[:, 1] <= 0.12) & (P[:, 2] >= 0.16)),
              {"adaptive": [], "adaptive, calibrated": [CAL],
               "L0 alone": ["adaptivity.space.max_level=0"],
               "L0 alone, calibrated": ["adaptivity.space.max_level=0", CAL]}),
}


def finest_uz(frame, select):
    """Mean uz of the selected points of the finest level block of one frame."""
    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(frame)
    reader.Update()
    mb = reader.GetOutput()
    names = [mb.GetMetaData(b).Get(vtkCompositeDataSet.NAME()) for b in range(mb.GetNumberOfBlocks())]
    last = max((n for n in names if n.startswith("level_")), key=lambda n: int(n.split("_")[1]))
    grid = mb.GetBlock(names.index(last))
    P = vtk_to_numpy(grid.GetPoints().GetData())
    u = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
    return u[select(P), 2].mean()


def curve(out, select):
    return np.array([finest_uz(f, select)
                     for f in sorted(glob.glob(os.path.join(out, "frames", "frame_*.vtm")))])


def run_all(binary, scenario, base, runs, work, env):
    procs = []
    for name, sets in runs.items():
        args = [binary, "run", scenario, "-o", os.path.join(work, name.replace(" ", "_")), "-q"]
        for s in base + sets:
            args += ["--set", s]
        procs.append((name, subprocess.Popen(args, env=env)))
        if len(procs) % 2 == 0:
            procs[-2][1].wait()
    for name, p in procs:
        if p.wait() != 0:
            sys.exit(f"{name}: mrsim exited {p.returncode}")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--binary", default=os.path.join(here, "..", "build", "mrsim"))
    ap.add_argument("--only", choices=sorted(CASES))
    ap.add_argument("--calibration", choices=["orthotropic", "per_tet"], default="orthotropic")
    args = ap.parse_args()
    cal = "object.calibration=" + args.calibration
    with tempfile.TemporaryDirectory() as work:
        env = dict(os.environ, MRSIM_CACHE_DIR=os.path.join(work, "cache"))
        for key, (scenario, base, finest, select, runs) in CASES.items():
            if args.only and key != args.only:
                continue
            path = os.path.join(here, "..", "scenarios", scenario)
            runs = {name: [cal if s == CAL else s for s in sets] for name, sets in runs.items()}
            run_all(args.binary, path, base, {"finest alone": finest, **runs}, work, env)
            ref = curve(os.path.join(work, "finest_alone"), select)
            peak = np.abs(ref).max()
            print(f"{scenario}: against its finest level alone (peak {ref.min() * 1e3:.3f} mm)")
            for name in runs:
                c = curve(os.path.join(work, name.replace(" ", "_")), select)
                n = min(len(c), len(ref))
                print(f"  {name:24s} peak {c[:n].min() * 1e3:8.3f} mm ({(c[:n].min() / ref[:n].min() - 1) * 100:+6.1f} %),"
                      f" largest difference {np.abs(c[:n] - ref[:n]).max() / peak:.2f} of the peak")
    return 0


if __name__ == "__main__":
    sys.exit(main())
