#!/usr/bin/python3
"""scripts/golden.py and the host its references were written on (tests/golden/README.md):
bit for bit on the same host kind, rtol 1e-9 (said on stderr) on another processor generation,
bits again with MRSIM_GOLDEN_EXACT=1; a partial update from another host is refused.

Run by ctest as
    /usr/bin/python3 test_golden_host.py --binary MRSIM --source REPO --shared SHARED
Exit status: 0 all checks passed, 1 a check failed, 77 skipped (no binary yet).
"""
import argparse
import contextlib
import importlib.util
import io
import os
import pathlib
import shutil
import sys
import tempfile

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: check, parse_args, report)

check = cli.check


def load_golden(source):
    spec = importlib.util.spec_from_file_location("golden", os.path.join(source, "scripts",
                                                                          "golden.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def point_at(golden, folder):
    """Makes the module read its cases, references and HOST from `folder`."""
    golden.GOLDEN = pathlib.Path(folder)
    golden.HOST_FILE = golden.GOLDEN / "HOST"


def tolerance_said(golden):
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        options = golden.tolerance()
    return options, err.getvalue()


def test_host_names_this_processor(golden):
    here = golden.host()
    with open("/proc/cpuinfo") as f:
        info = f.read()
    family = next((line.split(":")[1].strip() for line in info.splitlines()
                   if line.startswith("cpu family")), "?")  # "?" where /proc/cpuinfo has none
    check(("family %s model" % family) in here and "; glibc" in here,
          "host() names the processor family and the C library: %r" % here)


def test_tolerance_follows_the_host(golden, tmp):
    folder = os.path.join(tmp, "tol")
    os.makedirs(folder)
    point_at(golden, folder)
    options, said = tolerance_said(golden)
    check(options == [] and said == "", "no HOST file: bits (%r, %r)" % (options, said))
    golden.HOST_FILE.write_text(golden.host() + "\n")
    options, said = tolerance_said(golden)
    check(options == [] and said == "", "the same host: bits (%r, %r)" % (options, said))
    golden.HOST_FILE.write_text("x86_64 SomeVendor family 1 model 2; glibc 2.0\n")
    options, said = tolerance_said(golden)
    check(options == ["--rtol", "1e-9"] and "SomeVendor family 1" in said and "rtol 1e-9" in said,
          "another host: rtol 1e-9, said on stderr (%r, %r)" % (options, said))
    os.environ["MRSIM_GOLDEN_EXACT"] = "1"
    try:
        options, _ = tolerance_said(golden)
    finally:
        del os.environ["MRSIM_GOLDEN_EXACT"]
    check(options == [], "MRSIM_GOLDEN_EXACT=1: bits on another host (%r)" % options)


def test_partial_update_from_another_host_is_refused(golden, tmp):
    folder = os.path.join(tmp, "partial")
    os.makedirs(folder)
    point_at(golden, folder)
    (golden.GOLDEN / "cases.txt").write_text("a scenarios/beam.yaml\nb scenarios/beam.yaml\n")
    golden.HOST_FILE.write_text("x86_64 SomeVendor family 1 model 2; glibc 2.0\n")
    args = argparse.Namespace(names=["a"], binary=pathlib.Path("/nonexistent/mrsim"))
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        code = golden.update(args)
    check(code == 1 and "update every case" in err.getvalue() and
          "SomeVendor" in golden.HOST_FILE.read_text() and not (golden.GOLDEN / "a").exists(),
          "a partial update from another host: refused, nothing written (%d, %r)"
          % (code, err.getvalue()))


def test_check_on_another_host(golden, binary, source, tmp):
    """The beam case against its reference with one value moved by 1e-12 relative: the same
    host fails, another host passes at rtol 1e-9, MRSIM_GOLDEN_EXACT=1 fails again."""
    folder = os.path.join(tmp, "golden")
    os.makedirs(folder)
    shutil.copytree(os.path.join(source, "tests", "golden", "beam"), os.path.join(folder, "beam"))
    shutil.copy(os.path.join(source, "tests", "golden", "cases.txt"), folder)
    with h5py.File(os.path.join(folder, "beam", "log.h5"), "r+") as h5:
        energy = h5["/frames/elastic_energy"]
        values = energy[()]
        values[-1] *= 1 + 1e-12
        energy[...] = values
    point_at(golden, folder)
    args = argparse.Namespace(names=["beam"], binary=pathlib.Path(binary),
                              work=os.path.join(tmp, "work"))

    def run_check():
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            return golden.check(args)

    golden.HOST_FILE.write_text(golden.host() + "\n")
    check(run_check() == 1, "the same host: a value 1e-12 off fails")
    golden.HOST_FILE.write_text("x86_64 SomeVendor family 1 model 2; glibc 2.0\n")
    check(run_check() == 0, "another host: a value 1e-12 off passes at rtol 1e-9")
    os.environ["MRSIM_GOLDEN_EXACT"] = "1"
    try:
        check(run_check() == 1, "MRSIM_GOLDEN_EXACT=1: a value 1e-12 off fails on another host")
    finally:
        del os.environ["MRSIM_GOLDEN_EXACT"]


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    golden = load_golden(args.source)
    with tempfile.TemporaryDirectory() as tmp:
        test_host_names_this_processor(golden)
        test_tolerance_follows_the_host(golden, tmp)
        test_partial_update_from_another_host_is_refused(golden, tmp)
        test_check_on_another_host(golden, args.binary, args.source, tmp)
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
