#!/usr/bin/python3
"""Determinism (issue 7 point 3): every integrator, with space and time adaptivity on, writes
the same outputs bit for bit when run twice and when run with 1 or 2 threads (the threaded
loops forced on whatever their size). Checked with `mrsim compare` at zero tolerance (every
log.h5 dataset and attribute but wall times, every VTU array, the resolved scenarios, the
summary) and byte for byte on the VTU pieces; a scenario with a tool covers the contact path.
The first run measures the levels' spectra into a fresh cache (MRSIM_CACHE_DIR) and the others
read them there (simulation/spectrum_cache.hpp): the cache changes no bit."""
import filecmp
import json
import os
import sys
import tempfile

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: check, run, parse_args, report)

INTEGRATORS = ("modified_euler", "stoermer_verlet", "semi_implicit", "semi_implicit_momentum")


check = cli.check


run = cli.run


def frame_files(folder):
    out = []
    for root, _, files in os.walk(os.path.join(folder, "frames")):
        out += [os.path.relpath(os.path.join(root, f), folder) for f in files]
    return sorted(out)


def same_bytes(a, b):
    files = frame_files(a)
    if not files or files != frame_files(b):
        return False
    _, mismatch, errors = filecmp.cmpfiles(a, b, files, shallow=False)
    return not mismatch and not errors


def adaptivity_happened(folder):
    """The runs must exercise what they claim: splits and more than one time level."""
    with h5py.File(os.path.join(folder, "log.h5"), "r") as f:
        kinds = set(k.decode() if isinstance(k, bytes) else k for k in f["/events/kind"][()])
        used_levels = (f["/frames/time_levels"][()].sum(axis=0) > 0).sum()
    return "split" in kinds and used_levels >= 2


def runs_agree(binary, scenario, tmp, name, sets):
    cache = os.path.join(tmp, name + "_cache")
    env = dict(os.environ, MRSIM_PARALLEL_THRESHOLD="1", MRSIM_CACHE_DIR=cache)
    extra = [a for s in sets for a in ("--set", s)]
    outs = {}
    for tag, threads in (("first", "1"), ("again", "1"), ("two_threads", "2")):
        out = os.path.join(tmp, "%s_%s" % (name, tag))
        r = run(binary, "run", scenario, "-o", out, "--threads", threads, *extra, env=env)
        check(r.returncode == 0, "%s (%s) runs: %s" % (name, tag, r.stderr.strip()[-200:]))
        reused = "levels: reused from" in r.stdout + r.stderr
        check(reused == (tag != "first"), "%s (%s): the levels' spectra %s the cache"
              % (name, tag, "measured into" if tag == "first" else "read from"))
        outs[tag] = out
    check(adaptivity_happened(outs["first"]), "%s: splits and several time levels happened" % name)
    for tag in ("again", "two_threads"):
        r = run(binary, "compare", outs["first"], outs[tag], "--rtol", "0", "--atol", "0")
        check(r.returncode == 0, "%s: mrsim compare finds the %s run identical%s"
              % (name, tag, "" if r.returncode == 0 else ":\n" + r.stdout[-2000:]))
        check(same_bytes(outs["first"], outs[tag]),
              "%s: every VTU/VTP piece and .vtm of the %s run is byte-identical" % (name, tag))
    with open(os.path.join(outs["first"], "summary.json")) as f:
        return json.load(f)


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    scenarios = os.path.join(args.source, "scenarios")
    adaptive = ["adaptivity.time.enabled=true"]
    with tempfile.TemporaryDirectory() as tmp:
        for integrator in INTEGRATORS:
            runs_agree(args.binary, os.path.join(scenarios, "beam_adaptive.yaml"), tmp,
                       "beam_adaptive_" + integrator,
                       adaptive + ["time.duration=0.2", "time.integrator=" + integrator])
        summary = runs_agree(args.binary, os.path.join(scenarios, "liver_probe.yaml"), tmp,
                             "liver_probe", adaptive + ["time.duration=0.3"])
        check((summary.get("peak_tool_force") or 0) > 0, "liver_probe: the probe touched the liver")
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
