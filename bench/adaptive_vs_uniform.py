#!/usr/bin/python3
"""What the hierarchy buys (issue 17 points 1, 2, 5): a scenario run adaptively on its levels
against the same run on its finest level alone (same integrator, steps and tool), one thread,
paired runs in alternation (the machine is noisy), CPU time of the whole process (user + sys).

Prints both CPU times (median, and the fastest of each), their ratio (and the median of each
pair's own ratio), the ratios of point-force
evaluations and of tet updates (log.h5 /frames/tet_updates), the tool force of the adaptive run
against the uniform one at every step (max difference over the peak), and the real-time factor
of each run (simulated seconds per wall second, VTK output off: the simulation, contact and
log), for the whole process and for the step loop alone (log.h5 /frames/wall_time, the set-up
excluded).

The runs keep the levels' spectra in a cache of their own (MRSIM_CACHE_DIR in the bench's
temporary folder, simulation/spectrum_cache.hpp). --cache warm (the default) fills it with one
untimed run of each kind first, as every run of a sweep after its first finds it; --cache cold
empties it before each run, as a hierarchy's very first run.

    /usr/bin/python3 bench/adaptive_vs_uniform.py [--binary build/mrsim]
        [--scenario scenarios/liver_probe.yaml] [--repeats 3] [--json out.json] [--callgrind]
        [--cache warm|cold] [--no-frames] [--matched]

After the pairs, the adaptive run is also timed as bundled, with its VTK frames written (unless
--no-frames): its real-time factor then, and the frames' own wall time. For both, the frames
that took longer than frame_dt of wall time (log.h5 /frames/wall_time_parts, output included)
and the slowest: a real-time loop misses those, whatever the average. The framed runs go into one
folder, as a user re-runs a scenario: from the second on, each writes its frames over the files
of the one before (io/file_recycler.hpp), so the median is a re-run's, not a first run's.

--matched also times pairs whose adaptive side is K runs back to back, K the ratio of the two
kinds' median CPU (liver_probe: about 15), so that it spans the seconds the uniform run beside
it spans: on a shared host the load moves over seconds, and a 0.3-s run samples one moment of
it where a 4.7-s run averages several. Each pair's ratio is the mean of its K runs over the
uniform run; the median of those is printed. Every run counts (a mean, not a fastest).

--callgrind also runs each kind once under valgrind's callgrind and prints the instructions each
executes (user space, the whole process) and their ratio: a count that does not move with the
machine's load, where CPU times on a shared host vary by 40 % between minutes. It is not a
time (cache misses and stalls are not in it), so it complements the CPU ratio, never replaces
it. About 60 times slower than a native run (the uniform liver_probe: some 10 minutes).
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np
import yaml


CACHE = {"dir": None, "cold": False}  # the runs' MRSIM_CACHE_DIR, and whether to empty it


def run_env():
    if CACHE["cold"]:
        shutil.rmtree(CACHE["dir"], ignore_errors=True)
    return dict(os.environ, MRSIM_CACHE_DIR=CACHE["dir"])


def behind_real_time(out):
    """(frames whose wall time, output included, exceeded frame_dt; frames; the slowest frame's
    wall time over frame_dt) of the run in `out`: the average real-time factor hides the frames
    a real-time loop would have missed."""
    with open(os.path.join(out, "scenario.yaml")) as f:
        frame_dt = float(yaml.safe_load(f)["time"]["frame_dt"])
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        per_frame = h5["/frames/wall_time_parts"][1:].sum(axis=1)  # frame 0: output only
    return int(np.sum(per_frame > frame_dt)), len(per_frame), float(per_frame.max() / frame_dt)


def timed_run(binary, scenario, out, sets, frames=False):
    """Runs mrsim once; returns (CPU s of the process, wall s, wall s of the step loop). With
    `frames` the scenario's own VTK output is written (as a user runs it), else none."""
    args = [binary, "run", scenario, "-o", out, "-q", "--threads", "1"]
    if not frames:
        args += ["--set", "output.vtk=false"]
    for s in sets:
        args += ["--set", s]
    env = run_env()
    start = time.monotonic()
    p = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env)
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.monotonic() - start
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("mrsim failed: " + " ".join(args) + "\n" + p.stderr.read().decode())
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        loop = float(h5["/frames/wall_time"][:].sum())  # the frames, set-up excluded
    return usage.ru_utime + usage.ru_stime, wall, loop


def instructions(binary, scenario, out, sets):
    """Instructions executed by one run under callgrind (its "Collected" total), or None without
    valgrind."""
    if shutil.which("valgrind") is None:
        return None
    with tempfile.TemporaryDirectory() as tmp:
        args = ["valgrind", "--tool=callgrind", "--callgrind-out-file=" + os.path.join(tmp, "cg"),
                binary, "run", scenario, "-o", out, "-q", "--threads", "1",
                "--set", "output.vtk=false"]
        for s in sets:
            args += ["--set", s]
        r = subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                           env=run_env())
    found = re.search(r"Collected : (\d+)", r.stderr)
    if r.returncode != 0 or not found:
        sys.exit("callgrind run failed: " + " ".join(args) + "\n" + r.stderr[-2000:])
    return int(found.group(1))


def counters(out):
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        evaluations = int(h5["/frames/force_evaluations"][-1].sum())
        tets = int(h5["/frames/tet_updates"][-1].sum())
        duration = float(h5["/frames/time"][-1])
        force = h5["/tool/force"][:] if "tool" in h5 else None
    return evaluations, tets, duration, force


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--binary", default=os.path.join(here, "..", "build", "mrsim"))
    ap.add_argument("--scenario", default=os.path.join(here, "..", "scenarios", "liver_probe.yaml"))
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--json", help="also write the figures to this file")
    ap.add_argument("--callgrind", action="store_true",
                    help="also count each kind's instructions under valgrind (slow, steady)")
    ap.add_argument("--no-frames", dest="frames", action="store_false",
                    help="leave out the adaptive runs with the scenario's VTK frames written")
    ap.add_argument("--matched", action="store_true",
                    help="also time pairs in which the adaptive side is as many back-to-back runs"
                         " as take the uniform run's CPU (slow: twice the pairs' time)")
    ap.add_argument("--cache", choices=("warm", "cold"), default="warm",
                    help="the levels' spectra cached by an earlier run (warm) or measured (cold)")
    a = ap.parse_args()
    with open(a.scenario) as f:
        levels = yaml.safe_load(f)["object"]["levels"]
    finest = json.dumps([levels[-1]])  # a YAML flow sequence mrsim's --set reads
    runs = {"adaptive": [], "uniform": []}
    with tempfile.TemporaryDirectory() as tmp:
        outs = {k: os.path.join(tmp, k) for k in runs}
        CACHE["dir"], CACHE["cold"] = os.path.join(tmp, "cache"), a.cache == "cold"
        uniform = ["object.levels=" + finest]
        if not CACHE["cold"]:  # one short untimed run of each kind fills the cache
            short = ["time.duration=%s" % 0.02]
            timed_run(a.binary, a.scenario, outs["adaptive"], short)
            timed_run(a.binary, a.scenario, outs["uniform"], uniform + short)
        for _ in range(a.repeats):
            runs["adaptive"].append(timed_run(a.binary, a.scenario, outs["adaptive"], []))
            if len(uniform) == 1:  # the same steps: the adaptive run's, computed or given
                with open(os.path.join(outs["adaptive"], "scenario.yaml")) as f:
                    uniform.append("time.substeps=%d" % yaml.safe_load(f)["time"]["substeps"])
            runs["uniform"].append(timed_run(a.binary, a.scenario, outs["uniform"], uniform))
        # Time-matched pairs: a short run samples a minute of this host's load, the uniform run
        # several seconds of it; K adaptive runs back to back (K: the CPU ratio of the medians
        # above, rounded) span as long as the uniform run beside them, in alternating order,
        # and each pair's ratio is their mean over it. Every run counts, none is dropped.
        matched = []
        if a.matched:
            cpu_a = statistics.median(c for c, _, _ in runs["adaptive"])
            cpu_u = statistics.median(c for c, _, _ in runs["uniform"])
            batch = max(1, round(cpu_u / cpu_a))
            for i in range(a.repeats):
                def adaptive_batch():
                    return statistics.mean(
                        timed_run(a.binary, a.scenario, outs["adaptive"], [])[0]
                        for _ in range(batch))
                if i % 2 == 0:
                    un = timed_run(a.binary, a.scenario, outs["uniform"], uniform)[0]
                    ad = adaptive_batch()
                else:
                    ad = adaptive_batch()
                    un = timed_run(a.binary, a.scenario, outs["uniform"], uniform)[0]
                matched.append((ad, un))
        # The adaptive run as bundled, its VTK frames written: what a user who runs the scenario
        # sees (the frames' own time is /frames/wall_time_parts "output").
        framed = []
        if a.frames:
            for _ in range(a.repeats):
                out = os.path.join(tmp, "frames")
                cpu_s, wall_s, _ = timed_run(a.binary, a.scenario, out, [], frames=True)
                with open(os.path.join(out, "summary.json")) as f:
                    output_s = json.load(f)["wall_time_parts"]["output"]
                framed.append((cpu_s, wall_s, output_s) + behind_real_time(out))
        figures = {k: counters(outs[k]) for k in runs}
        late = behind_real_time(outs["adaptive"])  # the last adaptive run, no VTK output
        with open(os.path.join(outs["adaptive"], "summary.json")) as f:
            kernel = json.load(f).get("force_kernel", "unknown")  # it sets the speed, not the bits
        counted = {"adaptive": instructions(a.binary, a.scenario, outs["adaptive"], []),
                   "uniform": instructions(a.binary, a.scenario, outs["uniform"], uniform)} \
            if a.callgrind else None
    cpu = {k: statistics.median(c for c, _, _ in v) for k, v in runs.items()}
    # On a shared machine other work only ever adds time: each kind's fastest run is the least
    # disturbed one, a steadier figure than the median when the noise is larger than the effect.
    fastest = {k: min(c for c, _, _ in v) for k, v in runs.items()}
    wall = {k: statistics.median(w for _, w, _ in v) for k, v in runs.items()}
    loop = {k: statistics.median(x for _, _, x in v) for k, v in runs.items()}
    (ea, ta, duration, fa), (eu, tu, _, fu) = figures["adaptive"], figures["uniform"]
    la, lu = loop["adaptive"], loop["uniform"]
    result = {
        "scenario": os.path.basename(a.scenario), "repeats": a.repeats,
        "cpu_adaptive_s": cpu["adaptive"], "cpu_uniform_s": cpu["uniform"],
        "cpu_ratio": cpu["adaptive"] / cpu["uniform"],
        "cpu_fastest_adaptive_s": fastest["adaptive"], "cpu_fastest_uniform_s": fastest["uniform"],
        "cpu_fastest_ratio": fastest["adaptive"] / fastest["uniform"],
        # Each pair ran back to back: the median of its ratios follows the host's slow drifts
        # (a busier quarter of an hour slows both runs of a pair) that the medians of each kind
        # taken apart do not.
        "cpu_pair_ratio": statistics.median(
            ad[0] / un[0] for ad, un in zip(runs["adaptive"], runs["uniform"])),
        "evaluation_ratio": ea / eu, "tet_update_ratio": ta / tu if tu else float("nan"),
        "realtime_adaptive": duration / wall["adaptive"],
        "realtime_uniform": duration / wall["uniform"],
        # The step loop alone (log.h5 /frames/wall_time summed, medians): what a haptic loop
        # started after the set-up sees.
        "realtime_loop_adaptive": duration / la, "realtime_loop_uniform": duration / lu,
        # The step loop's cost against the work it does (one thread: wall = CPU there).
        "loop_ratio": la / lu,
        # What the step loop does not hold: start-up, set-up and the end of the run.
        "outside_loop_adaptive_s": wall["adaptive"] - la,
        "outside_loop_uniform_s": wall["uniform"] - lu,
    }
    if fa is not None and fu is not None and len(fa) == len(fu):
        na, nu = np.linalg.norm(fa, axis=1), np.linalg.norm(fu, axis=1)
        result["tool_force_peak_uniform_N"] = float(nu.max())
        result["tool_force_peak_difference"] = float(abs(na.max() - nu.max()) / nu.max())
        result["tool_force_max_difference"] = float(np.abs(na - nu).max() / nu.max())
        result["tool_samples"] = int(len(fa))
    result["frames_behind_real_time"], result["slowest_frame_over_frame_dt"] = late[0], late[2]
    if framed:
        result["cpu_adaptive_with_frames_s"] = statistics.median(f[0] for f in framed)
        result["realtime_adaptive_with_frames"] = duration / statistics.median(f[1] for f in framed)
        result["frames_output_s"] = statistics.median(f[2] for f in framed)
        result["frames_behind_real_time_with_frames"] = statistics.median(f[3] for f in framed)
        result["slowest_frame_with_frames"] = statistics.median(f[5] for f in framed)
    result["cache"] = a.cache
    result["force_kernel"] = kernel
    print("%s, one thread, median of %d paired runs (CPU = user + sys of the process), %s cache,"
          " %s force kernel (MRSIM_KERNEL)" % (result["scenario"], a.repeats, a.cache, kernel))
    print("  CPU adaptive %.2f s, uniform finest %.2f s: ratio %.3f"
          % (cpu["adaptive"], cpu["uniform"], result["cpu_ratio"]))
    print("  point-force evaluations ratio %.3f, tet updates ratio %.3f (CPU / tet ratio %.2f)"
          % (result["evaluation_ratio"], result["tet_update_ratio"],
             result["cpu_ratio"] / result["tet_update_ratio"]))
    print("  fastest of each: adaptive %.2f s, uniform %.2f s: ratio %.3f (%.2f x the tet ratio)"
          % (fastest["adaptive"], fastest["uniform"], result["cpu_fastest_ratio"],
             result["cpu_fastest_ratio"] / result["tet_update_ratio"]))
    print("  median of the %d pairs' own ratios: %.3f (%.2f x the tet ratio)"
          % (a.repeats, result["cpu_pair_ratio"],
             result["cpu_pair_ratio"] / result["tet_update_ratio"]))
    if matched:
        result["matched_batch"] = max(1, round(cpu["uniform"] / cpu["adaptive"]))
        result["matched_pair_ratio"] = statistics.median(ad / un for ad, un in matched)
        result["matched_adaptive_s"] = statistics.median(ad for ad, _ in matched)
        result["matched_uniform_s"] = statistics.median(un for _, un in matched)
        print("  time-matched pairs (%d; each the mean of %d adaptive runs back to back against"
              " one uniform run): adaptive %.3f s, uniform %.2f s; median of the pairs' ratios"
              " %.3f (%.2f x the tet ratio)"
              % (len(matched), result["matched_batch"], result["matched_adaptive_s"],
                 result["matched_uniform_s"], result["matched_pair_ratio"],
                 result["matched_pair_ratio"] / result["tet_update_ratio"]))
    if "tool_force_max_difference" in result:
        print("  tool force: peak %.4f N uniform, peak differs by %.2f %%, worst step by %.2f %%"
              " of the peak (%d samples)"
              % (result["tool_force_peak_uniform_N"], 100 * result["tool_force_peak_difference"],
                 100 * result["tool_force_max_difference"], result["tool_samples"]))
    print("  real time (simulated s per wall s, no VTK output): adaptive %.2fx, uniform %.2fx"
          % (result["realtime_adaptive"], result["realtime_uniform"]))
    print("  real time of the step loop (set-up excluded): adaptive %.2fx, uniform %.2fx"
          % (result["realtime_loop_adaptive"], result["realtime_loop_uniform"]))
    print("  step loop alone: time ratio %.3f (%.2f x the tet-update ratio)"
          % (result["loop_ratio"], result["loop_ratio"] / result["tet_update_ratio"]))
    print("  outside the step loop (start-up, set-up, end; wall): adaptive %.3f s, uniform %.3f s"
          % (result["outside_loop_adaptive_s"], result["outside_loop_uniform_s"]))
    print("  frames slower than real time (wall > frame_dt), adaptive, no VTK output: %d of %d,"
          " the slowest %.2f x frame_dt (the last run)" % late)
    if framed:
        print("  adaptive with its VTK frames written (as bundled): CPU %.2f s, real time %.2fx,"
              " the frames' own wall time %.3f s (medians of %d)"
              % (result["cpu_adaptive_with_frames_s"], result["realtime_adaptive_with_frames"],
                 result["frames_output_s"], len(framed)))
        print("  with its VTK frames: %g of %d frames slower than real time, the slowest %.2f x"
              " frame_dt (medians)" % (result["frames_behind_real_time_with_frames"], late[1],
                                       result["slowest_frame_with_frames"]))
    if counted and counted["adaptive"] is None:
        print("  instructions: skipped (no valgrind on PATH)")
    elif counted:
        result["instructions_adaptive"] = counted["adaptive"]
        result["instructions_uniform"] = counted["uniform"]
        result["instruction_ratio"] = counted["adaptive"] / counted["uniform"]
        print("  instructions (callgrind, whole process): adaptive %.3g, uniform %.3g: ratio %.3f"
              " (%.2f x the tet-update ratio)"
              % (counted["adaptive"], counted["uniform"], result["instruction_ratio"],
                 result["instruction_ratio"] / result["tet_update_ratio"]))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(result, f, indent=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
