#!/usr/bin/python3
"""Every build of the Green-Lagrange force kernel this processor runs gives the same run, bit for
bit (issue 17 point 4: faster instruction sets without changing a result): liver_probe (four
adaptive levels, a tool, Green-Lagrange, damped) cut short, run with MRSIM_KERNEL set to each
build `mrsim --version` lists, compared at rtol = atol = 0 with `mrsim compare` (log.h5, every
VTU array, summary.json); summary.json names the build that ran. The same for the kernels'
per-tet form (object.calibration: per_tet, each coarse tet its own tensor) on beam_adaptive, and
two threads against one. An unknown or unsupported build is an input error (exit 2) that names
the builds the processor runs."""
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: check, parse_args, report, run)

check = cli.check


def run(binary, *args, kernel=None, cache=None):
    """mrsim with MRSIM_KERNEL set to `kernel` (unset for None) and its own cache folder."""
    env = dict(os.environ)
    env.pop("MRSIM_KERNEL", None)
    if kernel is not None:
        env["MRSIM_KERNEL"] = kernel
    if cache is not None:
        env["MRSIM_CACHE_DIR"] = cache
    return cli.run(binary, *args, env=env)


def builds_listed(binary):
    """The builds `mrsim --version` says this processor runs, and the one it runs by default."""
    lines = run(binary, "--version").stdout.splitlines()
    line = next((l for l in lines if l.startswith("Green-Lagrange force kernel:")), "")
    default = line.split(":")[1].split()[0] if ":" in line else ""
    listed = line.split("runs ")[1].split(";")[0].split(", ") if "runs " in line else []
    return default, listed


def same_runs(binary, tmp, cache, scenario, sets, builds, default, what):
    """Runs `scenario` with each build (one thread) and the default build on two threads;
    checks that they all give the first's run bit for bit."""
    outs = {}
    for build, threads in [(b, "1") for b in builds] + [(default, "2")]:
        out = os.path.join(tmp, "%s_%s_%s" % (what, build, threads))
        args = ["run", scenario, "-o", out, "-q", "--threads", threads]
        for s in sets:
            args += ["--set", s]
        r = run(binary, *args, kernel=build, cache=cache)
        if check(r.returncode == 0, "%s, MRSIM_KERNEL=%s, %s thread(s): exits 0 (%s)"
                 % (what, build, threads, r.stderr.strip()[-300:])):
            outs[(build, threads)] = out
    first = outs.get((default, "1"))
    for key, out in outs.items():
        if first is None or out == first:
            continue
        r = run(binary, "compare", first, out, "--rtol", "0", "--atol", "0")
        check(r.returncode == 0 and "identical" in r.stdout,
              "%s: %s on %s thread(s) gives the %s one-thread run bit for bit: %s"
              % (what, key[0], key[1], default, r.stdout.strip().splitlines()[-1:]))


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    default, listed = builds_listed(args.binary)
    check(default in ("avx512", "avx2", "baseline") and listed and listed[0] == default
          and listed[-1] == "baseline",
          "--version: runs %r by default, the widest of %r" % (default, listed))
    scenario = os.path.join(args.source, "scenarios", "liver_probe.yaml")
    with tempfile.TemporaryDirectory() as tmp:
        cache = os.path.join(tmp, "cache")
        outs = {}
        for build in listed:
            out = os.path.join(tmp, build)
            r = run(args.binary, "run", scenario, "-o", out, "-q", "--threads", "1",
                    "--set", "time.duration=0.5", kernel=build, cache=cache)
            if not check(r.returncode == 0, "MRSIM_KERNEL=%s: the run exits 0 (%s)"
                         % (build, r.stderr.strip()[-300:])):
                continue
            with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
                ran = json.load(f).get("force_kernel")
            check(ran == build, "MRSIM_KERNEL=%s: summary.json force_kernel is %r" % (build, ran))
            outs[build] = out
        for build, out in outs.items():
            if build == default:
                continue
            r = run(args.binary, "compare", outs[default], out, "--rtol", "0", "--atol", "0")
            check(r.returncode == 0 and "identical" in r.stdout,
                  "%s and %s give the same run bit for bit: %s"
                  % (default, build, r.stdout.strip().splitlines()[-1:]))
        same_runs(args.binary, tmp, cache, os.path.join(args.source, "scenarios", "beam_adaptive.yaml"),
                  ["time.duration=0.2", "object.calibration=per_tet"], listed, default, "per_tet beam")
        r = run(args.binary, "run", scenario, "-o", os.path.join(tmp, "bad"), "-q",
                kernel="sse9", cache=cache)
        check(r.returncode == 2 and "MRSIM_KERNEL" in r.stderr and "baseline" in r.stderr
              and not os.path.exists(os.path.join(tmp, "bad")),
              "MRSIM_KERNEL=sse9: exit 2 naming the builds, nothing written (%d: %s)"
              % (r.returncode, r.stderr.strip()))
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
