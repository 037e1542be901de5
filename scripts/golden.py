#!/usr/bin/python3
"""Golden-file regression: runs the short cases of tests/golden/cases.txt and compares them
with their references in tests/golden/<name>/ using `mrsim compare` (tests/golden/README.md).

    scripts/golden.py check NAME [NAME...] --binary build/mrsim --work build/golden
    scripts/golden.py update [NAME...] [--binary build/mrsim]

`check` (what ctest runs, label `golden`) exits with `mrsim compare`'s code: 0 equal, 1 differ
(the report says what and where), 2 unreadable. `update` regenerates references on purpose:
it prints what changed against the old reference first, then replaces log.h5 (repacked:
contiguous, gzip, so the files stay small), scenario.yaml and summary.json, and records the
host that wrote them in tests/golden/HOST (processor vendor, family and model; C library).

The references are checked bit for bit on a host like the one that wrote them. On another
processor generation `check` compares at a relative tolerance of 1e-9 and says so: a host of
another generation once moved some values by up to 1e-10 relative, for a reason not found
(tests/golden/README.md). MRSIM_GOLDEN_EXACT=1 asks for the bits anywhere.
"""
import argparse
import os
import pathlib
import platform
import shlex
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "golden"
HOST_FILE = GOLDEN / "HOST"
OTHER_HOST_RTOL = "1e-9"


def host():
    """What the references' bits depend on beyond the build: the processor's vendor, family
    and model, and the C library (its libm)."""
    cpu = {}
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                key, _, value = line.partition(":")
                key = key.strip()
                if key in ("vendor_id", "cpu family", "model") and key not in cpu:
                    cpu[key] = value.strip()
    except OSError:
        pass
    libc = " ".join(platform.libc_ver()) or "unknown C library"
    return (f"{platform.machine()} {cpu.get('vendor_id', '?')} family {cpu.get('cpu family', '?')}"
            f" model {cpu.get('model', '?')}; {libc}")


def recorded_host():
    """The host the references were written on (tests/golden/HOST), or None."""
    return HOST_FILE.read_text().strip() if HOST_FILE.exists() else None


def tolerance():
    """The `mrsim compare` options for this host: none (bits) on the host kind that wrote the
    references, else a relative tolerance, said on stderr."""
    written_on = recorded_host()
    here = host()
    if written_on in (None, here) or os.environ.get("MRSIM_GOLDEN_EXACT") == "1":
        return []
    print(f"golden: references written on '{written_on}', this host is '{here}': compared at "
          f"rtol {OTHER_HOST_RTOL}, not bit for bit (tests/golden/README.md)", file=sys.stderr)
    return ["--rtol", OTHER_HOST_RTOL]


def read_cases():
    cases = {}
    for number, line in enumerate((GOLDEN / "cases.txt").read_text().splitlines(), 1):
        words = shlex.split(line, comments=True)
        if not words:
            continue
        if len(words) < 2:
            raise SystemExit(f"tests/golden/cases.txt:{number}: expected NAME SCENARIO [key=value...]")
        cases[words[0]] = (words[1], words[2:] + ["output.vtk=false"])
    return cases


def run_case(binary, name, case, out):
    scenario, overrides = case
    args = [str(binary), "run", str(ROOT / scenario), "-o", str(out), "--quiet"]
    for o in overrides:
        args += ["--set", o]
    if out.exists():
        shutil.rmtree(out)
    result = subprocess.run(args, cwd=ROOT)
    if result.returncode != 0:
        print(f"golden {name}: `mrsim run` exited {result.returncode}", file=sys.stderr)
    return result.returncode


def compare(binary, run, reference, options=()):
    return subprocess.run([str(binary), "compare", str(run), str(reference), *options]).returncode


def repack(source, target):
    """Same groups, datasets and attributes (what `mrsim compare` reads), contiguous and
    gzip-compressed: a run's chunked log is mostly empty chunk space."""
    import h5py

    def copy_attrs(a, b):
        for key, value in a.attrs.items():
            b.attrs.create(key, value, dtype=a.attrs.get_id(key).dtype)

    with h5py.File(source, "r") as a, h5py.File(target, "w") as b:
        copy_attrs(a, b)

        def visit(name, obj):
            if isinstance(obj, h5py.Group):
                copy_attrs(obj, b.require_group(name))
                return
            big = obj.size > 64 and obj.dtype.kind in "iuf"
            options = dict(compression="gzip", compression_opts=9, shuffle=True) if big else {}
            data = b.create_dataset(name, data=obj[()], dtype=obj.dtype,
                                    maxshape=obj.shape, **options)
            copy_attrs(obj, data)

        a.visititems(visit)


def check(args):
    cases = read_cases()
    options = tolerance()
    worst = 0
    for name in args.names:
        if name not in cases:
            raise SystemExit(f"no golden case '{name}' in tests/golden/cases.txt")
        out = pathlib.Path(args.work) / name
        code = run_case(args.binary, name, cases[name], out)
        if code == 0:
            code = compare(args.binary, out, GOLDEN / name, options)
        worst = max(worst, code)
    return worst


def update(args):
    cases = read_cases()
    names = args.names or list(cases)
    here = host()
    written_on = recorded_host()
    if written_on not in (None, here) and set(names) != set(cases):
        print(f"golden: the other references were written on '{written_on}', this host is "
              f"'{here}': update every case so that they all come from one host", file=sys.stderr)
        return 1
    HOST_FILE.write_text(here + "\n")
    for name in names:
        if name not in cases:
            raise SystemExit(f"no golden case '{name}' in tests/golden/cases.txt")
        with tempfile.TemporaryDirectory(prefix="mrsim-golden-") as tmp:
            out = pathlib.Path(tmp) / name
            if run_case(args.binary, name, cases[name], out) != 0:
                return 1
            reference = GOLDEN / name
            if (reference / "log.h5").exists():
                print(f"== {name}: changes against the old reference")
                compare(args.binary, out, reference)
            reference.mkdir(parents=True, exist_ok=True)
            repack(out / "log.h5", reference / "log.h5")
            for f in ("scenario.yaml", "summary.json"):
                shutil.copy(out / f, reference / f)
            size = sum(p.stat().st_size for p in reference.iterdir())
            print(f"== {name}: reference written ({size / 1024:.0f} KiB)")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    c = sub.add_parser("check", help="run cases and compare them with their references")
    c.add_argument("names", nargs="+")
    c.add_argument("--binary", required=True)
    c.add_argument("--work", required=True, help="folder for the runs")
    u = sub.add_parser("update", help="regenerate references (all cases when none is named)")
    u.add_argument("names", nargs="*")
    u.add_argument("--binary", default=str(ROOT / "build" / "mrsim"))
    args = parser.parse_args()
    args.binary = pathlib.Path(os.path.abspath(args.binary))
    return check(args) if args.command == "check" else update(args)


if __name__ == "__main__":
    sys.exit(main())
