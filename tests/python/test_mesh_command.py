#!/usr/bin/python3
"""End-to-end checks of `mrsim mesh` (issue 3): every bad surface of ../shared/data/cgal exits
with code 2 and its reason, usage errors exit 2, a built-in shape gives readable levels, the
JSON report and the scenario snippet, and the same command gives the same bytes twice; a
level runs through `mrsim check` with the snippet's path."""
import argparse
import filecmp
import json
import os
import subprocess
import sys
import tempfile

FAILURES = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        FAILURES.append(what)


def run(binary, *args):
    return subprocess.run([binary, *args], capture_output=True, text=True, timeout=600)


def test_usage(binary, tmp):
    prefix = os.path.join(tmp, "u")
    check(run(binary, "mesh", "--help").returncode == 0, "mesh --help exits 0")
    check(run(binary, "mesh", "--shape", "box", "-o", prefix).returncode == 2, "missing --tets exits 2")
    r = run(binary, "mesh", "--shape", "torus", "--tets", "30", "-o", prefix)
    check(r.returncode == 2 and "unknown shape" in r.stderr, "unknown shape exits 2 with a reason")
    r = run(binary, "mesh", "--shape", "box", "--dims", "1,2", "--tets", "30", "-o", prefix)
    check(r.returncode == 2 and "3 dimension" in r.stderr, "wrong --dims count exits 2")
    r = run(binary, "mesh", "--tets", "30", "-o", prefix)
    check(r.returncode == 2 and "either a surface file or --shape" in r.stderr, "no input exits 2")
    r = run(binary, "mesh", "--shape", "box", "--tets", "30", "-o", "/nonexistent/dir/p")
    check(r.returncode == 2 and "does not exist" in r.stderr, "missing output folder exits 2")


def test_bad_surfaces(binary, shared, tmp):
    cgal = os.path.join(shared, "data", "cgal")
    if not os.path.isdir(cgal):
        print("skip bad surfaces: no shared data")
        return
    for name, reason in [("head.off", "open surface"), ("bones.off", "self-intersecting"),
                         ("cow.off", "pinched vertex"), ("mpi.off", "zero-area triangle")]:
        r = run(binary, "mesh", os.path.join(cgal, name), "--tets", "100", "-o", os.path.join(tmp, "bad"))
        check(r.returncode == 2 and reason in r.stderr and name in r.stderr,
              f"{name} exits 2 with '{reason}' ({r.stderr.strip()[:120]})")
    check(not any(f.startswith("bad") for f in os.listdir(tmp)), "rejected surfaces write nothing")


def test_shape(binary, tmp):
    a, b = os.path.join(tmp, "a"), os.path.join(tmp, "b")
    for prefix in (a, b):
        r = run(binary, "mesh", "--shape", "sphere", "--dims", "50", "--units", "mm", "--tets", "170,40", "-o", prefix, "-q")
        check(r.returncode == 0 and r.stderr == "" and r.stdout == "", f"sphere exits 0 silently ({r.stderr[:200]})")
    for suffix in ("_L0.vtu", "_L1.vtu"):  # (the JSON and YAML name their own prefix)
        check(filecmp.cmp(a + suffix, b + suffix, shallow=False), f"{suffix} identical on a second run")
    report = json.load(open(a + "_quality.json"))
    levels = report["levels"]
    check([l["requested_tets"] for l in levels] == [40, 170], "levels sorted coarse to fine")
    check(abs(report["source"]["dims_m"][0] - 0.05) < 1e-15, "--units mm converts --dims")
    check(all(l["min_dihedral_deg"] >= 10 for l in levels), "min dihedral >= 10 deg")
    snippet = open(a + "_levels.yaml").read()
    check("- mesh: a_L0.vtu" in snippet and "- mesh: a_L1.vtu" in snippet, "snippet lists the levels")
    scenario = os.path.join(tmp, "s.yaml")
    with open(scenario, "w") as f:
        f.write("name: s\nobject:\n  levels:\n    - mesh: a_L1.vtu\n  units: m\n"
                "material: {model: green_lagrange, youngs_modulus: 1.0e+5, poisson_ratio: 0.3, density: 1000}\n"
                "time: {frame_dt: 0.01, substeps: 10, duration: 0.02}\n")
    r = run(binary, "check", scenario)
    check(r.returncode == 0, f"a level passes mrsim check ({r.stderr.strip()[:200]})")


def test_reoriented_facets_are_said(binary, source, tmp):
    """Issue 18 defect 9: facets facing inwards are reoriented, and the run says how many."""
    lines = open(os.path.join(source, "scenarios", "meshes", "liver_surface_cgal_h10_mm.off")).read().split("\n")
    header = 1
    while not lines[header].strip() or lines[header].startswith("#"):
        header += 1
    points, faces = (int(x) for x in lines[header].split()[:2])
    first_face = header + 1 + points
    for k in range(30):  # every tenth facet turned round
        i = first_face + 10 * k
        n, a, b, c = lines[i].split()[:4]
        lines[i] = " ".join((n, a, c, b))
    surface = os.path.join(tmp, "flipped.off")
    open(surface, "w").write("\n".join(lines))
    r = run(binary, "mesh", surface, "--units", "mm", "--tets", "60", "-o", os.path.join(tmp, "flipped"))
    said = f"30 of {faces} triangles faced inwards and were reoriented"
    check(r.returncode == 0 and said in r.stderr, f"reoriented facets are said: {r.stderr.strip()[:300]}")


def test_gmsh_only_in_the_mesher(binary, tmp):
    """mrsim does not load gmsh (its ~80 libraries cost 0.1 s at every start); `mrsim mesh`
    hands over to mrsim-mesh beside it, and says how to build it when it is missing."""
    needed = subprocess.run(["readelf", "-d", binary], capture_output=True, text=True).stdout
    mesher = os.path.join(os.path.dirname(binary), "mrsim-mesh")
    check("NEEDED" in needed and "gmsh" not in needed, "mrsim does not link gmsh")
    check("gmsh" in subprocess.run(["readelf", "-d", mesher], capture_output=True,
                                   text=True).stdout, "mrsim-mesh does")
    alone = os.path.join(tmp, "alone")
    os.makedirs(alone)
    import shutil
    shutil.copy(binary, alone)
    r = run(os.path.join(alone, os.path.basename(binary)), "mesh", "--shape", "box", "--tets",
            "30", "-o", os.path.join(tmp, "a"))
    check(r.returncode == 1 and "mrsim-mesh" in r.stderr and "--target mrsim-mesh" in r.stderr,
          "without mrsim-mesh beside it, mrsim mesh exits 1 saying how to build it: "
          + r.stderr.strip()[:120])


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--binary", required=True)
    p.add_argument("--source", required=True)
    p.add_argument("--shared", required=True)
    a = p.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        test_usage(a.binary, tmp)
        test_gmsh_only_in_the_mesher(a.binary, tmp)
        test_bad_surfaces(a.binary, a.shared, tmp)
        test_shape(a.binary, tmp)
        test_reoriented_facets_are_said(a.binary, a.source, tmp)
    if FAILURES:
        print(f"{len(FAILURES)} failure(s)")
        sys.exit(1)


if __name__ == "__main__":
    main()
