#!/usr/bin/python3
"""mrsim against CalculiX's explicit dynamics on the same mesh (issue 17 point 5): the bundled
liver's finest level alone, the same linear material (Cauchy strain, no damping), clamped
where z <= 0.1 m, released under gravity, the same step and number of steps, one thread each.
Prints both CPU times (user + sys of each process, set-up included), their ratio, CalculiX's
own stable increment, and the vertical displacement of the lowest-free top point in both
(they must agree: the same physics).

    /usr/bin/python3 bench/calculix_side_by_side.py [--binary build/mrsim] [--steps 1000]

Skipped (exit 77, saying why) when `ccx` (Debian package calculix-ccx) is not installed.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

E, NU, RHO, G = 3.0e4, 0.4, 1000.0, 9.81
Z_FIXED = 0.1  # m: points at or below are clamped


def read_mesh(path):
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    grid = r.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)
    return points, cells


def timed(args, cwd=None, env=None):
    """Runs a process; returns (CPU s of it, wall s, its stdout)."""
    start = time.monotonic()
    with tempfile.TemporaryFile() as out:
        p = subprocess.Popen(args, cwd=cwd, env=env, stdout=out, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(p.pid, 0)
        out.seek(0)
        text = out.read().decode(errors="replace")
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("failed: %s\n%s" % (" ".join(args), text[-2000:]))
    return usage.ru_utime + usage.ru_stime, time.monotonic() - start, text


def calculix_input(points, cells, probe, dt, steps):
    lines = ["*HEADING", "mrsim side by side", "*NODE"]
    lines += ["%d, %.17g, %.17g, %.17g" % (i + 1, *p) for i, p in enumerate(points)]
    lines.append("*ELEMENT, TYPE=C3D4, ELSET=EALL")
    lines += ["%d, %d, %d, %d, %d" % (k + 1, *(c + 1)) for k, c in enumerate(cells)]
    fixed = np.nonzero(points[:, 2] <= Z_FIXED)[0] + 1
    lines.append("*NSET, NSET=FIXED")
    lines += [", ".join(str(n) for n in fixed[i:i + 16]) for i in range(0, len(fixed), 16)]
    lines += ["*NSET, NSET=PROBE", str(probe + 1)]
    lines += ["*BOUNDARY", "FIXED, 1, 3",
              "*MATERIAL, NAME=M", "*ELASTIC", "%.17g, %.17g" % (E, NU),
              "*DENSITY", "%.17g" % RHO,
              "*SOLID SECTION, ELSET=EALL, MATERIAL=M",
              "*STEP, INC=%d" % (steps + 10),
              # initial increment, period, minimum and maximum increment: DIRECT keeps dt fixed
              "*DYNAMIC, EXPLICIT, DIRECT", "%.10e, %.10e, %.10e, %.10e" % (dt, dt * steps, dt, dt),
              "*DLOAD", "EALL, GRAV, %.17g, 0., 0., -1." % G,
              "*NODE PRINT, NSET=PROBE, FREQUENCY=%d" % steps, "U",
              "*END STEP"]
    return "\n".join(lines) + "\n"


def last_probe_uz(dat):
    values = re.findall(r"^\s*\d+\s+(\S+)\s+(\S+)\s+(\S+)\s*$", open(dat).read(), re.M)
    return float(values[-1][2])


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--binary", default=os.path.join(here, "..", "build", "mrsim"))
    ap.add_argument("--mesh", default=os.path.join(here, "..", "scenarios", "meshes",
                                                   "liver_L3.vtu"))
    ap.add_argument("--steps", type=int, default=1000)
    a = ap.parse_args()
    ccx = shutil.which("ccx")
    if not ccx:
        print("skipped: CalculiX (ccx, Debian package calculix-ccx) is not installed")
        return 77
    points, cells = read_mesh(a.mesh)
    free = points[:, 2] > Z_FIXED
    probe = int(np.argmax(np.where(free, points[:, 2], -np.inf)))  # the highest point
    with tempfile.TemporaryDirectory() as tmp:
        scenario = os.path.join(tmp, "side.yaml")
        with open(scenario, "w") as f:
            f.write("name: side_by_side\nobject:\n  levels:\n    - mesh: %s\n  units: m\n"
                    "material:\n  model: cauchy\n  youngs_modulus: %.17g\n  poisson_ratio: %.17g\n"
                    "  density: %.17g\n  damping: {phi: 0.0, psi: 0.0}\n"
                    "fixed:\n  - box: {min: [-10.0, -10.0, -10.0], max: [10.0, 10.0, %.17g]}\n"
                    "gravity: [0, 0, %.17g]\n"
                    "time:\n  frame_dt: 0.01\n  duration: 0.01\n"
                    "output:\n  vtk: false\n"
                    % (os.path.abspath(a.mesh), E, NU, RHO, Z_FIXED, -G))
        # mrsim's own step for this mesh (computed substeps), then exactly `steps` of them.
        out = os.path.join(tmp, "probe_step")
        subprocess.run([a.binary, "run", scenario, "-o", out, "-q"], check=True)
        with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
            dt = float(h5["/frames/step"][-1])
            substeps = int(round(0.01 / dt))
        frames = max(1, a.steps // substeps)
        steps = frames * substeps
        out = os.path.join(tmp, "mrsim")
        cpu_m, wall_m, _ = timed([a.binary, "run", scenario, "-o", out, "-q", "--threads", "1",
                               "--set", "time.duration=%.17g" % (0.01 * frames),
                               "--set", "time.substeps=%d" % substeps,
                               "--set", "time.adapt_substeps=false"])
        with open(os.path.join(tmp, "side.inp"), "w") as f:
            f.write(calculix_input(points, cells, probe, dt, steps))
        env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
        cpu_c, wall_c, log = timed([ccx, "-i", "side"], cwd=tmp, env=env)
        courant = re.search(r"COURANT initial stable time increment:\s*(\S+)", log)
        own_step = float(courant.group(1)) if courant else float("nan")
        uz_c = last_probe_uz(os.path.join(tmp, "side.dat"))
        # mrsim's displacement of the probe at the end, from the last frame of a run with VTK.
        final = os.path.join(tmp, "final")
        subprocess.run([a.binary, "run", scenario, "-o", final, "-q", "--threads", "1",
                        "--set", "time.duration=%.17g" % (0.01 * frames),
                        "--set", "time.substeps=%d" % substeps,
                        "--set", "time.adapt_substeps=false", "--set", "output.vtk=true",
                        "--set", "output.every=%d" % frames], check=True)
        r = vtkXMLUnstructuredGridReader()
        r.SetFileName(os.path.join(final, "frames", "frame_%06d" % frames,
                                   "frame_%06d_0.vtu" % frames))
        r.Update()
        uz_m = float(vtk_to_numpy(r.GetOutput().GetPointData().GetArray("displacement"))[probe, 2])
    print("liver %d points, %d tets, linear (Cauchy) E = %g Pa, nu = %g, rho = %g, gravity, "
          "clamped at z <= %g m; %d explicit steps of %.4g s, one thread"
          % (len(points), len(cells), E, NU, RHO, Z_FIXED, steps, dt))
    print("  CPU mrsim %.2f s, CalculiX %.2f s: ratio %.3f (wall %.2f s / %.2f s)"
          % (cpu_m, cpu_c, cpu_m / cpu_c, wall_m, wall_c))
    print("  CalculiX's own stable increment (volumetric Courant) %.4g s: mrsim's step is %.2f "
          "times it" % (own_step, dt / own_step))
    print("  uz of the highest point after %.4g s: mrsim %.6e m, CalculiX %.6e m (%.2f %% apart)"
          % (dt * steps, uz_m, uz_c, 100 * abs(uz_m - uz_c) / max(abs(uz_c), 1e-300)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
