#!/usr/bin/python3
"""End-to-end checks of `mrsim sweep` (issue 8): a real sweep of 4 short beam cases with -j 2
(one diverges), results.csv against each summary.json, resume (finished cases skipped,
--retry-failed, a deleted status.json), an invalid sweep (exit 2, nothing written),
--case K, --collect, and scripts/plot_sweep.py on the produced table."""
import csv
import glob
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: check, run, parse_args, report)



check = cli.check


def run(binary, *args, cwd=None):
    return subprocess.run([binary, *args], capture_output=True, text=True, cwd=cwd, timeout=300)


# psi = 20 with 256 steps per frame diverges within the first frame (the step is kept fixed):
# case_0003 fails.
SWEEP = """base: {base}
output: out/s
set: ["time.duration=0.04", "time.adapt_substeps=false"]
product:
  material.damping.psi: [2, 20]
  time.substeps: [512, 256]
"""


def read_rows(path):
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        return reader.fieldnames, list(reader)


def status_mtimes(folder):
    return {os.path.basename(os.path.dirname(p)): os.stat(p).st_mtime_ns
            for p in glob.glob(os.path.join(folder, "case_*", "status.json"))}


def same_number(cell, value):
    return float(cell) == float(value) if value is not None else cell == ""


def check_row_figures(row, folder):
    summary = json.load(open(os.path.join(folder, row["case"], "summary.json")))
    ok = (same_number(row["max_displacement"], summary["max_displacement"])
          and same_number(row["wall_time"], summary["wall_time"])
          and same_number(row["real_time_factor"], summary["real_time_factor"])
          and int(row["force_evaluations"]) == sum(summary["force_evaluations"])
          and int(row["steps"]) == summary["steps"]
          and int(row["final_active_L0"]) == summary["final_active"][0]
          and row["peak_tool_force"] == "")
    check(ok, "%s: figures equal its summary.json" % row["case"])


def test_full_sweep(binary, tmp, sweep):
    out = os.path.join(tmp, "out", "s")
    r = run(binary, "sweep", sweep, "-j", "2", cwd=tmp)
    check(r.returncode == 1, "a sweep with one failed case exits 1 (got %d: %s)"
          % (r.returncode, r.stderr.strip()[-300:]))
    check("sweep: 4/4 done, 1 failed, 0 running" in r.stderr,
          "progress lines on stderr: " + r.stderr.strip().splitlines()[-1][:80])
    for name in ("sweep.yaml", "cases.csv", "results.csv"):
        check(os.path.isfile(os.path.join(out, name)), "DIR/%s written" % name)
    columns, rows = read_rows(os.path.join(out, "results.csv"))
    check(columns[:6] == ["case", "status", "exit_code", "message", "param:material.damping.psi",
                          "param:time.substeps"], "results.csv columns: %s" % columns[:6])
    check(columns[-6:] == ["wall_time", "real_time_factor", "force_evaluations", "steps", "splits",
                           "merges"],
          "results.csv ends with the work counters")
    check(len(rows) == 4, "results.csv has 4 rows")
    params = [(r["param:material.damping.psi"], r["param:time.substeps"]) for r in rows]
    check(params == [("2", "512"), ("2", "256"), ("20", "512"), ("20", "256")],
          "rows in product order with their params: %s" % params)
    check([r["status"] for r in rows] == ["done", "done", "done", "failed"],
          "three done, the diverging one failed")
    failed = rows[3]
    check(failed["exit_code"] == "1" and "diverged" in failed["message"],
          "the failure's exit code and message are recorded: " + failed["message"][:80])
    for row in rows:
        check_row_figures(row, out)
    params_json = json.load(open(os.path.join(out, "case_0002", "params.json")))
    check(params_json == {"material.damping.psi": 20, "time.substeps": 512},
          "params.json holds the case's values")
    status = json.load(open(os.path.join(out, "case_0003", "status.json")))
    check(status["exit_code"] == 1 and status["wall_time"] > 0, "status.json of the failure")
    resolved = open(os.path.join(out, "case_0001", "scenario.yaml")).read()
    check("substeps: 256" in resolved and "duration: 0.04" in resolved,
          "the case ran with its overrides (resolved scenario.yaml)")
    check(os.path.isfile(os.path.join(out, "case_0003", "stderr.txt")), "stderr.txt captured")
    return out


def test_resume(binary, tmp, sweep, out):
    before = status_mtimes(out)
    r = run(binary, "sweep", sweep, "-j", "2", "-q", cwd=tmp)
    check(r.returncode == 1 and r.stderr == "", "re-run exits 1 again, quietly")
    check(status_mtimes(out) == before, "re-running skips every finished case (failed too)")
    r = run(binary, "sweep", sweep, "-j", "2", "-q", "--retry-failed", cwd=tmp)
    after = status_mtimes(out)
    changed = sorted(k for k in after if after[k] != before[k])
    check(r.returncode == 1 and changed == ["case_0003"],
          "--retry-failed re-runs only the failed case: %s" % changed)
    os.remove(os.path.join(out, "case_0001", "status.json"))
    before = status_mtimes(out)
    r = run(binary, "sweep", sweep, "-q", cwd=tmp)
    after = status_mtimes(out)
    changed = sorted(k for k in after if before.get(k) != after[k])
    check(changed == ["case_0001"], "a case without status.json is re-run, alone: %s" % changed)
    _, rows = read_rows(os.path.join(out, "results.csv"))
    check(rows[1]["status"] == "done", "and results.csv lists it done again")


KILL_SWEEP = """base: {base}
output: {out}
set: ["output.checkpoint_every=4"]
product:
  material.damping.psi: [1.0]
"""


def frames_listed(folder):
    import xml.etree.ElementTree as ET
    try:
        return len(list(ET.parse(os.path.join(folder, "frames.pvd")).getroot().iter("DataSet")))
    except (OSError, ET.ParseError):
        return 0


def wait_for_unlock(folder, timeout=60):
    """Until no process holds the run folder's lock (docs/output.md "One run per folder")."""
    import fcntl
    import time
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            with open(os.path.join(folder, ".mrsim.lock"), "a") as f:
                fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
                return
        except BlockingIOError:
            time.sleep(0.01)


def test_stopped_cases_go_on(binary, source, tmp):
    """A sweep stopped by a time limit (SIGTERM to the whole job) or killed (SIGKILL) while a
    case runs: the next run of the sweep resumes that case from its checkpoint.h5 (mrsim run
    --resume: the log keeps the first start_time) and the case's outputs are identical at
    rtol = atol = 0 to those of a sweep never stopped."""
    import signal
    import time
    import h5py
    base = os.path.relpath(os.path.join(source, "scenarios", "liver_thesis.yaml"), tmp)
    specs = {}
    for name in ("whole", "term", "kill"):
        specs[name] = os.path.join(tmp, "kill_%s.yaml" % name)
        with open(specs[name], "w") as f:
            f.write(KILL_SWEEP.format(base=base, out="out/" + name))
    r = run(binary, "sweep", specs["whole"], "-q", cwd=tmp)
    check(r.returncode == 0, "the sweep left alone runs (%s)" % r.stderr[-200:])
    for name, sig in (("term", signal.SIGTERM), ("kill", signal.SIGKILL)):
        case = os.path.join(tmp, "out", name, "case_0000")
        p = subprocess.Popen([binary, "sweep", specs[name], "-q"], cwd=tmp, start_new_session=True,
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for _ in range(30000):
            if p.poll() is not None or (frames_listed(case) >= 14 and
                                        os.path.exists(os.path.join(case, "checkpoint.h5"))):
                break
            time.sleep(0.002)
        if p.poll() is None:
            os.killpg(p.pid, sig)
        p.wait()
        wait_for_unlock(case)  # the case's run finishes its frame and checkpoint (SIGTERM)
        with h5py.File(os.path.join(case, "log.h5"), "r") as h5:
            started = h5.attrs["start_time"]
        stopped = frames_listed(case)
        r = run(binary, "sweep", specs[name], "-q", cwd=tmp)
        with h5py.File(os.path.join(case, "log.h5"), "r") as h5:
            kept = h5.attrs["start_time"] == started
        c = run(binary, "compare", os.path.join(tmp, "out", "whole", "case_0000"), case,
                "--rtol", "0", "--atol", "0")
        status = json.load(open(os.path.join(case, "status.json")))
        ok = r.returncode == 0 and status["exit_code"] == 0 and kept and c.returncode == 0
        why = "" if ok else " sweep exit %d, case exit %d: %s" % (
            r.returncode, status["exit_code"], status.get("message", "")[-300:])
        check(ok, "%s after %d frames: the next sweep goes on from the checkpoint (log start kept: "
              "%s), the case is identical to the sweep left alone (%s)%s"
              % (sig.name, stopped, kept, (c.stdout + c.stderr).strip().splitlines()[-1:], why))


def test_invalid(binary, tmp, base):
    path = os.path.join(tmp, "bad.yaml")
    with open(path, "w") as f:
        f.write("base: %s\noutput: out/bad\nproduct:\n  material.lambdaa: [0, 1]\n" % base)
    r = run(binary, "sweep", path, cwd=tmp)
    check(r.returncode == 2 and "material.lambdaa" in r.stderr and "case_0000" in r.stderr,
          "unknown key path: exit 2 naming the case and the key: " + r.stderr.strip()[:160])
    check(not os.path.exists(os.path.join(tmp, "out", "bad")), "and nothing is written")
    with open(path, "w") as f:
        f.write("base: %s\noutput: out/bad\nzip:\n  a: [0, 1]\n  b: [1]\n" % base)
    r = run(binary, "sweep", path, cwd=tmp)
    check(r.returncode == 2 and "bad.yaml:5:3" in r.stderr and "same length" in r.stderr,
          "unequal zip lists: exit 2 with line:column: " + r.stderr.strip()[:160])


def test_case_and_collect(binary, tmp, sweep):
    out = os.path.join(tmp, "one")
    r = run(binary, "sweep", sweep, "-o", out, "--case", "1", "-q", cwd=tmp)
    cases = sorted(os.path.basename(p) for p in glob.glob(os.path.join(out, "case_*")))
    check(r.returncode == 0 and cases == ["case_0001"],
          "--case 1 runs case 1 alone (exit %d, %s)" % (r.returncode, cases))
    r = run(binary, "sweep", sweep, "-o", out, "--collect", cwd=tmp)
    _, rows = read_rows(os.path.join(out, "results.csv"))
    check(r.returncode == 0 and [row["status"] for row in rows] ==
          ["pending", "done", "pending", "pending"], "--collect lists case 1 done, others pending")
    r = run(binary, "sweep", sweep, "-o", out, "--case", "9", cwd=tmp)
    check(r.returncode == 2, "--case out of range exits 2")


def test_plot(source, out):
    plots = os.path.join(out, "plots")
    r = subprocess.run(["/usr/bin/python3", os.path.join(source, "scripts", "plot_sweep.py"),
                        os.path.join(out, "results.csv"), "-o", plots],
                       capture_output=True, text=True, timeout=120)
    pngs = glob.glob(os.path.join(plots, "*.png"))
    check(r.returncode == 0 and len(pngs) == 2,
          "plot_sweep.py accepts results.csv (%d PNGs) %s" % (len(pngs), r.stderr[-200:]))


def test_bundled_sweeps(binary, source, tmp):
    """scenarios/sweeps/*.yaml are valid for an independent validator (editors use the schema)
    and every case of each loads (an --emit run checks them all and runs nothing)."""
    import jsonschema
    import yaml
    with open(os.path.join(source, "schemas", "sweep.schema.json")) as f:
        schema = json.load(f)
    files = sorted(glob.glob(os.path.join(source, "scenarios", "sweeps", "*.yaml")))
    check(bool(files), "bundled sweep files exist")
    for path in files:
        name = os.path.basename(path)
        with open(path) as f:
            errors = list(jsonschema.Draft7Validator(schema).iter_errors(yaml.safe_load(f)))
        check(not errors, "%s validates with jsonschema %s" % (name, [e.message for e in errors]))
        out = os.path.join(tmp, "emit_" + name)
        r = run(binary, "sweep", path, "-o", out, "--emit", "slurm")
        check(r.returncode == 0 and os.path.isfile(os.path.join(out, "sweep.sbatch"))
              and not glob.glob(os.path.join(out, "case_*", "log.h5")),
              "%s: every case loads; --emit slurm writes the scripts and runs nothing" % name)


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    args.binary = os.path.abspath(args.binary)  # the sweeps run in a temporary folder
    base_abs = os.path.join(args.source, "scenarios", "beam.yaml")
    if not os.path.isfile(base_abs):
        print("skip: no scenarios/beam.yaml")
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        base = os.path.relpath(base_abs, tmp)  # relative to the sweep file
        sweep = os.path.join(tmp, "sweep.yaml")
        with open(sweep, "w") as f:
            f.write(SWEEP.format(base=base))
        out = test_full_sweep(args.binary, tmp, sweep)
        test_resume(args.binary, tmp, sweep, out)
        test_invalid(args.binary, tmp, base)
        test_case_and_collect(args.binary, tmp, sweep)
        test_plot(args.source, out)
        test_stopped_cases_go_on(args.binary, args.source, tmp)
        test_bundled_sweeps(args.binary, args.source, tmp)
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
