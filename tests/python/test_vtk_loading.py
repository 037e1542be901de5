#!/usr/bin/python3
"""VTK is loaded only when a process needs it (core/vtk_module.hpp, issue 17): `mrsim --version`
and a run whose .vtu meshes come from the result cache with its frames off never load VTK's
libraries (seen through the loader's own trace, LD_DEBUG=files); a run that reads a .vtu the
first time, or writes frames, loads libmrsim_vtk.so from beside the binary and writes the same
frames as ever; an mrsim without that library beside it says so and exits 1 only when it needs
VTK, and still runs what does not; a library of another revision is refused."""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: check, parse_args, report)

check = cli.check


def traced(binary, args, cache):
    """(exit code, stderr, whether VTK's libraries were loaded) of one mrsim command."""
    env = dict(os.environ, LD_DEBUG="files", MRSIM_CACHE_DIR=cache)
    r = subprocess.run([binary, *args], capture_output=True, text=True, env=env, timeout=600)
    return r.returncode, r.stderr, "libvtkCommonCore" in r.stderr


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    scenario = os.path.join(args.source, "scenarios", "beam_adaptive.yaml")
    with tempfile.TemporaryDirectory() as tmp:
        cache = os.path.join(tmp, "cache")
        code, _, vtk = traced(args.binary, ["--version"], cache)
        check(code == 0 and not vtk, "mrsim --version loads no VTK library")
        out = os.path.join(tmp, "run")
        quiet = ["run", scenario, "-o", out, "-q", "--set", "time.duration=0.02",
                 "--set", "output.vtk=false"]
        code, err, vtk = traced(args.binary, quiet, cache)
        check(code == 0 and vtk and "libmrsim_vtk.so" in err,
              "the first run reads its .vtu meshes through libmrsim_vtk.so (exit %d)" % code)
        code, _, vtk = traced(args.binary, quiet, cache)
        check(code == 0 and not vtk,
              "a second run, its meshes cached and its frames off, loads no VTK (exit %d)" % code)
        framed = ["run", scenario, "-o", out, "-q", "--set", "time.duration=0.04"]
        code, _, vtk = traced(args.binary, framed, cache)
        frames = cli.pvd_times(out) if code == 0 else []
        check(code == 0 and vtk and len(frames) == 3,
              "a run writing frames loads VTK and writes them (exit %d, %d frames)"
              % (code, len(frames)))

        # A binary without its library: what needs VTK fails clearly, the rest still runs.
        alone = os.path.join(tmp, "alone")
        os.mkdir(alone)
        shutil.copy2(args.binary, alone)
        lone = os.path.join(alone, os.path.basename(args.binary))
        code, err, _ = traced(lone, framed, cache)
        check(code == 1 and "cannot load " + os.path.join(alone, "libmrsim_vtk.so") in err
              and "scripts/build.sh" in err,
              "without libmrsim_vtk.so, a run writing frames exits 1 naming it (exit %d): %s"
              % (code, " ".join(l for l in err.splitlines() if "cannot load" in l)))
        code, _, _ = traced(lone, quiet, cache)
        check(code == 0, "without it, a run that needs no VTK still runs (exit %d)" % code)

        # A library from another build (here its revision string altered, nothing else): refused
        # before any of its functions runs.
        library = os.path.join(os.path.dirname(os.path.abspath(args.binary)), "libmrsim_vtk.so")
        revision = subprocess.run([args.binary, "--version"], capture_output=True,
                                  text=True).stdout.split("(")[1].split(")")[0]
        with open(library, "rb") as f:
            data = f.read()
        marked = data.replace(revision.encode() + b"\0", b"X" + revision[1:].encode() + b"\0")
        with open(os.path.join(alone, "libmrsim_vtk.so"), "wb") as f:
            f.write(marked)
        code, err, _ = traced(lone, framed, cache)
        said = " ".join(l for l in err.splitlines() if "built from revision" in l)
        check(marked != data and code == 1 and "built from revision X" + revision[1:] in said
              and "this mrsim from " + revision in said,
              "a library of another revision is refused, exit 1 (exit %d): %s" % (code, said))
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
