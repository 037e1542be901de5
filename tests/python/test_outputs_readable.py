#!/usr/bin/python3
"""End-to-end check of what `mrsim run` writes (docs/output.md), read with the tools users
have: Debian's python3-vtk9, python3-h5py and the json module.

Run by ctest as
    /usr/bin/python3 test_outputs_readable.py --binary MRSIM --source REPO --shared SHARED
Exit status: 0 all checks passed, 1 a check failed, 77 skipped (no binary, scenario or
Python module yet).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

SKIP = 77
LEVEL_ARRAYS = {  # name -> number of components (docs/output.md)
    "displacement": 3,
    "velocity": 3,
    "force": 3,
    "status": 1,
    "time_level": 1,
    "criterion": 1,
    "mass": 1,
}


def skip(reason):
    print(f"SKIP: {reason}")
    sys.exit(SKIP)


class Checks:
    """Collects failures instead of stopping at the first, so one run reports them all."""

    def __init__(self):
        self.passed = 0
        self.failures = []

    def expect(self, condition, message):
        if condition:
            self.passed += 1
        else:
            self.failures.append(message)
            print(f"FAIL: {message}")
        return condition


def run_beam(binary, source, out_dir):
    scenario = os.path.join(source, "scenarios", "beam.yaml")
    if not os.path.isfile(scenario):
        skip(f"{scenario} does not exist yet")
    command = [binary, "run", scenario, "-o", out_dir, "--set", "time.duration=0.2", "--quiet"]
    result = subprocess.run(command, capture_output=True, text=True, timeout=900)
    if result.returncode != 0:
        print(" ".join(command))
        print(result.stdout)
        print(result.stderr)
        sys.exit(f"mrsim run failed with exit code {result.returncode}")


def pvd_entries(path):
    """[(time, file)] in file order; times parsed by float(), which rounds correctly."""
    root = ET.parse(path).getroot()
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]


def named_blocks(multiblock, vtk):
    blocks = {}
    for index in range(multiblock.GetNumberOfBlocks()):
        name = None
        if multiblock.HasMetaData(index):
            name = multiblock.GetMetaData(index).Get(vtk.vtkCompositeDataSet.NAME())
        blocks[name] = multiblock.GetBlock(index)
    return blocks


def check_level_block(checks, grid, log, level, row, where, np, numpy_support):
    group = log[f"/levels/level_{level}"]
    rest = group["rest_positions"][:]
    checks.expect(grid is not None and grid.IsA("vtkUnstructuredGrid"),
                  f"{where}: not an unstructured grid")
    if grid is None:
        return
    points = grid.GetNumberOfPoints()
    checks.expect(points == rest.shape[0],
                  f"{where}: {points} points, log.h5 has {rest.shape[0]} rest positions")
    checks.expect(grid.GetNumberOfCells() == group["tets"].shape[0],
                  f"{where}: {grid.GetNumberOfCells()} cells, log.h5 has "
                  f"{group['tets'].shape[0]} tets")
    data = grid.GetPointData()
    for name, components in LEVEL_ARRAYS.items():
        array = data.GetArray(name)
        if not checks.expect(array is not None, f"{where}: no point array {name}"):
            continue
        checks.expect(array.GetNumberOfComponents() == components,
                      f"{where}: {name} has {array.GetNumberOfComponents()} components")
        checks.expect(array.GetNumberOfTuples() == points,
                      f"{where}: {name} has {array.GetNumberOfTuples()} tuples")
    if data.GetArray("status") is None or data.GetArray("displacement") is None:
        return
    status = numpy_support.vtk_to_numpy(data.GetArray("status"))
    checks.expect(set(np.unique(status).tolist()) <= {0, 1, 2},
                  f"{where}: status values {sorted(set(status.tolist()))} outside {{0,1,2}}")
    checks.expect(np.array_equal(status, group["status"][row]),
                  f"{where}: status differs from log.h5 /levels/level_{level}/status[{row}]")
    # Points are the deformed positions: minus the displacement they give the rest shape.
    deformed = numpy_support.vtk_to_numpy(grid.GetPoints().GetData())
    displacement = numpy_support.vtk_to_numpy(data.GetArray("displacement"))
    if deformed.shape == rest.shape:
        checks.expect(np.allclose(deformed - displacement, rest, rtol=0, atol=1e-12),
                      f"{where}: points - displacement differ from the rest positions")


def check_frames(checks, out_dir, entries, log, vtk, np, numpy_support):
    levels = sorted(log["/levels"].keys())
    for row, (time, relative) in enumerate(entries):
        path = os.path.join(out_dir, relative)
        if not checks.expect(os.path.isfile(path), f"{relative} listed in frames.pvd is missing"):
            continue
        reader = vtk.vtkXMLMultiBlockDataReader()
        reader.SetFileName(path)
        reader.Update()
        blocks = named_blocks(reader.GetOutput(), vtk)
        checks.expect("level_0" in blocks, f"{relative}: no block level_0 (has {list(blocks)})")
        checks.expect(relative == f"frames/frame_{int(log['/frames/frame'][row]):06d}.vtm",
                      f"{relative}: name does not match /frames/frame[{row}]")
        for name in levels:
            if checks.expect(name in blocks, f"{relative}: no block {name}"):
                level = int(name.split("_")[1])
                check_level_block(checks, blocks[name], log, level, row, f"{relative}:{name}",
                                  np, numpy_support)


def check_log(checks, log, frame_count):
    for name in ("mrsim_version", "git_revision", "scenario", "start_time"):
        checks.expect(name in log.attrs, f"log.h5: no root attribute {name}")
    levels = len(log["/levels"].keys())
    for name in ("time", "kinetic_energy", "elastic_energy", "wall_time", "frame"):
        shape = log[f"/frames/{name}"].shape
        checks.expect(shape == (frame_count,), f"log.h5 /frames/{name} has shape {shape}")
    for name in ("active", "ghosts", "force_evaluations"):
        shape = log[f"/frames/{name}"].shape
        checks.expect(shape == (frame_count, levels), f"log.h5 /frames/{name} has shape {shape}")
    for name in ("frame", "kind", "level", "point"):
        checks.expect(f"/events/{name}" in log, f"log.h5: no /events/{name}")
    check_time_parts(checks, log, frame_count)


TASKS = ["internal_forces", "ghosts", "contact", "integration", "adaptivity", "output", "other"]


def check_time_parts(checks, log, frame_count):
    """Issue 17 point 3: the frame's wall time per task. The parts are >= 0, named, and without
    `output` they are /frames/wall_time (both come from the same clock reads, to 1 ms)."""
    parts = log["/frames/wall_time_parts"]
    names = [str(n) for n in parts.attrs.get("names", [])]
    checks.expect(parts.shape == (frame_count, len(TASKS)) and names == TASKS,
                  f"log.h5 /frames/wall_time_parts has shape {parts.shape}, names {names}")
    p, wall = parts[:], log["/frames/wall_time"][:]
    out = TASKS.index("output")
    checks.expect((p >= 0).all() and p[1:, TASKS.index("internal_forces")].min() > 0,
                  "wall_time_parts: every part >= 0, internal forces > 0 in every frame")
    simulated = p.sum(axis=1) - p[:, out]
    checks.expect(abs(simulated[1:] - wall[1:]).max() < 1e-3,
                  f"wall_time_parts without output = wall_time (worst "
                  f"{abs(simulated[1:] - wall[1:]).max():.2e} s)")


def check_summary_shares(checks, summary):
    shares, parts = summary.get("wall_time_shares", {}), summary.get("wall_time_parts", {})
    checks.expect(sorted(shares) == sorted(TASKS) and sorted(parts) == sorted(TASKS) and
                  abs(sum(shares.values()) - 1) < 1e-9 and
                  sum(parts.values()) <= summary["wall_time"],
                  f"summary.json wall_time_shares sum to 1 over {sorted(shares)}, parts within "
                  f"wall_time")


def check_row_writes_counted(checks, log, summary):
    """Each log row is written after it took its parts: the frame after it carries that time in
    its `output`, and the last row's is in summary.json's sum alone, so the run's output exceeds
    the frames' (equal if the writes went uncounted)."""
    frames = float(log["/frames/wall_time_parts"][:, TASKS.index("output")].sum())
    run = summary.get("wall_time_parts", {}).get("output", 0.0)
    checks.expect(run > frames, f"summary.json output {run} s > the frames' {frames} s "
                                f"(the last log row's write)")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--binary", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--shared", default="")
    args = parser.parse_args()
    if not (os.path.isfile(args.binary) and os.access(args.binary, os.X_OK)):
        skip(f"mrsim binary {args.binary} not built yet")
    try:
        import h5py
        import numpy as np
        import vtk
        from vtk.util import numpy_support
    except ImportError as error:
        skip(f"Debian's python3-vtk9 / python3-h5py / python3-numpy missing ({error})")

    checks = Checks()
    with tempfile.TemporaryDirectory(prefix="mrsim_outputs_") as out_dir:
        run_beam(args.binary, args.source, out_dir)
        for name in ("scenario.yaml", "frames.pvd", "log.h5", "summary.json"):
            checks.expect(os.path.isfile(os.path.join(out_dir, name)), f"{name} not written")
        entries = pvd_entries(os.path.join(out_dir, "frames.pvd"))
        times = [t for t, _ in entries]
        checks.expect(len(entries) >= 2, f"frames.pvd lists {len(entries)} frames")
        checks.expect(times[:1] == [0.0], f"first time in frames.pvd is not 0: {times[:1]}")
        checks.expect(all(a < b for a, b in zip(times, times[1:])), "times not increasing")
        with h5py.File(os.path.join(out_dir, "log.h5"), "r") as log:
            logged = log["/frames/time"][:].tolist()
            # Exact equality on purpose: both files must carry the very same doubles.
            checks.expect(times == logged, f"frames.pvd times {times} != /frames/time {logged}")
            check_log(checks, log, len(entries))
            check_frames(checks, out_dir, entries, log, vtk, np, numpy_support)
        with open(os.path.join(out_dir, "summary.json"), encoding="utf-8") as f:
            summary = json.load(f)
            checks.expect(isinstance(summary, dict), "summary.json is not a JSON object")
            check_summary_shares(checks, summary)
            with h5py.File(os.path.join(out_dir, "log.h5"), "r") as log:
                check_row_writes_counted(checks, log, summary)
            checks.expect(summary.get("force_kernel") in ("avx512", "avx2", "baseline"),
                          f"summary.json force_kernel: {summary.get('force_kernel')}")

    print(f"{checks.passed} passed, {len(checks.failures)} failed")
    return 1 if checks.failures else 0


if __name__ == "__main__":
    sys.exit(main())
