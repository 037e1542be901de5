#!/usr/bin/python3
"""End-to-end checks of `mrsim compare RUN_A RUN_B` (issue 7; docs/output.md "Comparing runs"):
two runs of the same scenario are identical; a perturbed float, integer counter, VTU point array
or scenario key is reported with its name, place and both values; tolerances forgive floats
but never integers; output.dir and wall times are ignored; unreadable inputs exit 2.

Run by ctest as
    /usr/bin/python3 test_compare.py --binary MRSIM --source REPO --shared SHARED
Exit status: 0 all checks passed, 1 a check failed, 77 skipped (no binary yet).
"""
import json
import os
import re
import shutil
import sys
import tempfile

import h5py
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: check, run, parse_args, report)

NUMBER = r"(-?[0-9.]+(?:e[-+][0-9]+)?|nan|-?inf)"


def check(cond, what, detail=""):
    """cli.check, with the output that explains a failure."""
    cli.check(cond, what + ("" if cond or not detail else "\n" + detail))


run = cli.run


def compare(binary, a, b, *options):
    return run(binary, "compare", a, b, *options)


def scenario_with_lambda(source, tmp):
    """beam_adaptive with Lamé parameters, so the resolved scenario holds material.lambda."""
    text = open(os.path.join(source, "scenarios", "beam_adaptive.yaml")).read()
    meshes = os.path.join(os.path.abspath(source), "scenarios", "meshes") + "/"
    text = text.replace("meshes/", meshes).replace("youngs_modulus: 1.0e+6", "lambda: 5.0e+5")
    text = text.replace("poisson_ratio: 0.3", "mu: 4.0e+5")
    path = os.path.join(tmp, "beam_lambda.yaml")
    with open(path, "w") as f:
        f.write(text)
    return path


def copy_run(src, tmp, name):
    dst = os.path.join(tmp, name)
    shutil.copytree(src, dst)
    return dst


def edit_dataset(run_dir, path, edit):
    with h5py.File(os.path.join(run_dir, "log.h5"), "r+") as log:
        values = log[path][()]
        edit(values)
        log[path][...] = values


def values_in(line, index_text):
    """The A and B values the report gives at `index_text` ("[3]", "point 7 component 2")."""
    m = re.search(re.escape(index_text) + r" \(A " + NUMBER + ", B " + NUMBER + r"\)", line)
    return (float(m.group(1)), float(m.group(2))) if m else None


def line_about(stdout, subject):
    return next((l for l in stdout.splitlines() if l.startswith(subject)), "")


def test_identical(binary, a, b):
    r = compare(binary, a, b)
    check(r.returncode == 0 and "identical" in r.stdout, "two runs of one scenario are identical (exit %d)"
          % r.returncode, r.stdout + r.stderr)
    check("ignored:" in r.stdout and "/frames/wall_time" in r.stdout and "output.dir" in r.stdout,
          "the report lists what it ignored", r.stdout)
    dir_a = [l for l in open(os.path.join(a, "scenario.yaml")) if "dir:" in l]
    dir_b = [l for l in open(os.path.join(b, "scenario.yaml")) if "dir:" in l]
    check(dir_a != dir_b and r.returncode == 0, "runs written to different output.dir compare equal")


def test_wall_times_ignored(binary, a, b, tmp):
    c = copy_run(b, tmp, "wall")
    edit_dataset(c, "/frames/wall_time", lambda v: v.__iadd__(123.0))
    with h5py.File(os.path.join(c, "log.h5"), "r+") as log:
        log.attrs["start_time"] = "1999-12-31T23:59:59Z"
    summary = json.load(open(os.path.join(c, "summary.json")))
    summary["wall_time"] = 1.0e6
    json.dump(summary, open(os.path.join(c, "summary.json"), "w"), indent=2)
    r = compare(binary, a, c)
    check(r.returncode == 0, "wall times and start_time are ignored (exit %d)" % r.returncode, r.stdout)


def test_float_perturbation(binary, a, b, tmp):
    c = copy_run(b, tmp, "float")
    with h5py.File(os.path.join(c, "log.h5"), "r") as log:
        old = float(log["/frames/kinetic_energy"][3])
    new = old * (1 + 1e-6)
    edit_dataset(c, "/frames/kinetic_energy", lambda v: v.__setitem__(3, new))
    r = compare(binary, a, c)
    line = line_about(r.stdout, "log.h5 /frames/kinetic_energy")
    check(r.returncode == 1, "a perturbed float exits 1 (got %d)" % r.returncode, r.stdout + r.stderr)
    check("1 of" in line and values_in(line, "[3]") == (old, new),
          "the report names the dataset, index [3] and both values exactly", r.stdout)
    r = compare(binary, a, c, "--atol", "%g" % (abs(new - old) * 10))
    check(r.returncode == 0, "--atol above the perturbation forgives it (exit %d)" % r.returncode, r.stdout)
    r = compare(binary, a, c, "--rtol", "1e-5")
    check(r.returncode == 0, "--rtol above the perturbation forgives it (exit %d)" % r.returncode, r.stdout)


def test_integer_counter(binary, a, b, tmp):
    c = copy_run(b, tmp, "integer")
    edit_dataset(c, "/frames/force_evaluations", lambda v: v.__setitem__((2, 1), v[2, 1] + 1))
    r = compare(binary, a, c, "--rtol", "1e9", "--atol", "1e9")
    line = line_about(r.stdout, "log.h5 /frames/force_evaluations")
    check(r.returncode == 1 and "[2, 1]" in line,
          "an integer counter off by one differs whatever the tolerance, at [2, 1] (exit %d)" % r.returncode,
          r.stdout + r.stderr)


def rewrite_piece(piece, array, point, component, delta):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(piece)
    reader.Update()
    grid = reader.GetOutput()
    values = grid.GetPointData().GetArray(array)
    old = values.GetComponent(point, component)
    values.SetComponent(point, component, old + delta)
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(piece)
    writer.SetInputData(grid)
    writer.SetCompressorTypeToZLib()
    writer.Write()
    return old, old + delta


def test_vtu_point_array(binary, a, b, tmp):
    c = copy_run(b, tmp, "vtu")
    piece = os.path.join(c, "frames", "frame_000003", "frame_000003_0.vtu")
    old, new = rewrite_piece(piece, "velocity", 7, 2, 1e-7)
    r = compare(binary, a, c)
    line = line_about(r.stdout, "frame 3 (t = 0.06 s) block level_0 point array velocity")
    check(r.returncode == 1 and line != "", "a changed VTU point value exits 1 naming frame, block and array",
          r.stdout + r.stderr)
    check(values_in(line, "point 7 component 2") == (old, new), "and the point, component and both values", line)


def test_scenario_key(binary, a, b, tmp):
    c = copy_run(b, tmp, "lambda")
    path = os.path.join(c, "scenario.yaml")
    text = open(path).read()
    changed = re.sub(r"(?m)^  lambda: .*$", "  lambda: 6.0e+5", text, count=1)
    open(path, "w").write(changed)
    r = compare(binary, a, c)
    m = re.search(r"^scenario.yaml material.lambda: A " + NUMBER + ", B " + NUMBER + "$", r.stdout, re.M)
    check(changed != text and r.returncode == 1 and m is not None and
          (float(m.group(1)), float(m.group(2))) == (5.0e5, 6.0e5),
          "a changed material.lambda exits 1 naming the key and both values (exit %d)" % r.returncode,
          r.stdout + r.stderr)


def expect_error(binary, a, b, what, names):
    r = compare(binary, a, b)
    check(r.returncode == 2 and r.stderr.startswith("error:") and names in r.stderr,
          "%s exits 2 with an error naming %s (exit %d)" % (what, names, r.returncode), r.stdout + r.stderr)


def truncate(path):
    os.truncate(path, os.path.getsize(path) // 2)


def test_unreadable_inputs(binary, a, b, tmp):
    expect_error(binary, a, os.path.join(tmp, "no_such_run"), "a missing folder", "no_such_run")
    c = copy_run(b, tmp, "cut_log")
    truncate(os.path.join(c, "log.h5"))
    expect_error(binary, a, c, "a truncated log.h5", "log.h5")
    c = copy_run(b, tmp, "cut_vtu")
    truncate(os.path.join(c, "frames", "frame_000002", "frame_000002_1.vtu"))
    expect_error(binary, a, c, "a truncated .vtu piece", "frame_000002_1.vtu")
    c = copy_run(b, tmp, "no_vtu")
    os.remove(os.path.join(c, "frames", "frame_000004", "frame_000004_2.vtu"))
    expect_error(binary, a, c, "a missing .vtu piece", "frame_000004_2.vtu")
    c = copy_run(b, tmp, "bad_yaml")
    open(os.path.join(c, "scenario.yaml"), "a").write("material: [unclosed\n")
    expect_error(binary, a, c, "a malformed scenario.yaml", "scenario.yaml")


def test_usage(binary, a, b):
    r = run(binary, "compare", "--help")
    check(r.returncode == 0 and "exactly" in r.stdout and "wall_time" in r.stdout,
          "compare --help says integers are exact and what is ignored", r.stdout)
    check(compare(binary, a, b, "--rtol", "-1").returncode == 2, "a negative --rtol is a usage error (exit 2)")
    check(compare(binary, a, b, "--atol", "nan").returncode == 2, "--atol nan is a usage error (exit 2)")




def main():
    args = cli.parse_args()
    if args is None:
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        scenario = scenario_with_lambda(args.source, tmp)
        runs = []
        for name in ("run_a", "run_b"):
            out = os.path.join(tmp, name)
            r = run(args.binary, "run", scenario, "-o", out, "-q", "--set", "time.duration=0.1")
            if r.returncode != 0:
                print("FAIL mrsim run exited %d: %s" % (r.returncode, r.stderr[-500:]))
                return 1
            runs.append(out)
        a, b = runs
        test_identical(args.binary, a, b)
        test_wall_times_ignored(args.binary, a, b, tmp)
        test_float_perturbation(args.binary, a, b, tmp)
        test_integer_counter(args.binary, a, b, tmp)
        test_vtu_point_array(args.binary, a, b, tmp)
        test_scenario_key(args.binary, a, b, tmp)
        test_unreadable_inputs(args.binary, a, b, tmp)
        test_usage(args.binary, a, b)
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
