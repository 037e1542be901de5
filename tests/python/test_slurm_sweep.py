#!/usr/bin/python3
"""A real single-node Slurm (scripts/slurm_local.sh, Debian's slurmctld/slurmd/munge) runs a job
array of 3 tasks and an `afterany` job depending on it, the way `mrsim sweep --emit slurm`
submits sweep.sbatch and collect.sbatch (docs/slurm.md). When `mrsim sweep --help` mentions
`--emit`, a tiny sweep of beam.yaml (3 cases) also goes through Slurm and DIR/results.csv must
hold 3 done rows. Exit 77 (skipped) when Slurm cannot be started here, saying why."""
import csv
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: check, run, parse_args, report)

TERMINAL = {"COMPLETED", "FAILED", "CANCELLED", "TIMEOUT", "NODE_FAIL", "OUT_OF_MEMORY",
            "BOOT_FAIL", "DEADLINE", "PREEMPTED"}


check = cli.check


def sh(args, env, cwd=None, timeout=120):
    return subprocess.run(args, capture_output=True, text=True, env=env, cwd=cwd,
                          timeout=timeout)


def submit(args, env, cwd):
    """sbatch --parsable ARGS; returns the job id (str) or None, printing why."""
    r = sh(["sbatch", "--parsable", *args], env, cwd=cwd)
    if r.returncode != 0:
        print("sbatch %s failed (exit %d): %s" % (" ".join(args), r.returncode, r.stderr.strip()))
        return None
    return r.stdout.strip().split(";")[0]  # "id" or "id;cluster"


def job_states(job, env):
    """Every JobState of `job` (all tasks of an array); [] once Slurm forgot it."""
    r = sh(["scontrol", "show", "job", job], env)
    if r.returncode != 0:
        return []
    return re.findall(r"JobState=(\S+)", r.stdout)


def wait_jobs(jobs, env, timeout, done=None):
    """Waits until every job's states are terminal (or `done()` is true); returns
    (finished, {job: states}) after at most `timeout` seconds."""
    t0 = time.time()
    states = {}
    while True:
        states = {j: job_states(j, env) for j in jobs}
        if all(s and all(x in TERMINAL for x in s) for s in states.values()):
            return True, states
        if done is not None and done():
            return True, states
        if time.time() - t0 > timeout:
            return False, states
        time.sleep(0.5)


def show_logs(folder):
    for name in sorted(os.listdir(folder)):
        if name.endswith(".out") or name.endswith(".err"):
            text = open(os.path.join(folder, name), errors="replace").read().strip()
            if text:
                print("----- %s\n%s" % (name, text[-1500:]))


def test_array_and_dependency(env, tmp):
    """3 array tasks write their $SLURM_ARRAY_TASK_ID; an afterany job concatenates them."""
    work = os.path.join(tmp, "array")
    os.makedirs(work)
    with open(os.path.join(work, "tasks.sbatch"), "w") as f:
        f.write("#!/bin/bash\n"
                "#SBATCH --job-name=mrsim-test-array\n"
                "#SBATCH --array=0-2\n"
                "#SBATCH --cpus-per-task=1\n"
                "#SBATCH --output=%s/task_%%A_%%a.out\n" % work +
                "echo \"$SLURM_ARRAY_TASK_ID $SLURM_ARRAY_JOB_ID\""
                " > %s/task_$SLURM_ARRAY_TASK_ID.txt\n" % work)
    with open(os.path.join(work, "collect.sbatch"), "w") as f:
        f.write("#!/bin/bash\n"
                "#SBATCH --job-name=mrsim-test-collect\n"
                "#SBATCH --output=%s/collect_%%j.out\n" % work +
                "cd %s && cat task_0.txt task_1.txt task_2.txt > all.txt\n" % work)
    t0 = time.time()
    array = submit([os.path.join(work, "tasks.sbatch")], env, work)
    check(array is not None and array.isdigit(), "sbatch --parsable gives the array job id (%s)"
          % array)
    if array is None:
        return
    dep = submit(["--dependency=afterany:" + array, os.path.join(work, "collect.sbatch")],
                 env, work)
    check(dep is not None and dep.isdigit(), "the afterany job is accepted (%s)" % dep)
    if dep is None:
        return
    states = job_states(dep, env)
    check(bool(states) and states[0] in ("PENDING", "RUNNING", "COMPLETED"),
          "scontrol shows the dependent job (%s)" % states)
    finished, states = wait_jobs([array, dep], env, 60)
    check(finished, "array and collect jobs end within 60 s (%.1f s; %s)"
          % (time.time() - t0, states))
    check(states.get(array) == ["COMPLETED"] * 3, "the 3 array tasks completed %s"
          % states.get(array))
    check(states.get(dep) == ["COMPLETED"], "the collect job completed %s" % states.get(dep))
    all_txt = os.path.join(work, "all.txt")
    text = open(all_txt).read() if os.path.exists(all_txt) else ""
    expected = "".join("%d %s\n" % (k, array) for k in range(3))
    check(text == expected, "all.txt holds tasks 0,1,2 of array %s, in order: %r"
          % (array, text))
    if cli.FAILURES:
        show_logs(work)


def sweep_has_emit(binary):
    try:
        r = subprocess.run([binary, "sweep", "--help"], capture_output=True, text=True,
                           timeout=60)
    except OSError:
        return False
    return r.returncode == 0 and "--emit" in r.stdout + r.stderr


def test_sweep(binary, source, env, tmp):
    """mrsim sweep S.yaml -o DIR --emit slurm; sbatch DIR/sweep.sbatch; sbatch
    --dependency=afterany:ID DIR/collect.sbatch; DIR/results.csv has 3 done rows."""
    sweep = os.path.join(tmp, "psi.yaml")
    with open(sweep, "w") as f:
        f.write("base: %s\n" % os.path.join(source, "scenarios", "beam.yaml") +
                "set:\n  - time.duration=0.02\n"
                "product:\n  material.damping.psi: [1, 2, 3]\n")
    out = os.path.join(tmp, "sweep_out")
    r = sh([binary, "sweep", sweep, "-o", out, "--emit", "slurm"], env, cwd=tmp)
    check(r.returncode == 0, "mrsim sweep --emit slurm exits 0 (%d) %s"
          % (r.returncode, r.stderr.strip()[-300:]))
    scripts = [os.path.join(out, n) for n in ("sweep.sbatch", "collect.sbatch")]
    check(all(os.path.isfile(s) for s in scripts), "it writes DIR/sweep.sbatch and "
          "DIR/collect.sbatch")
    if r.returncode != 0 or not all(os.path.isfile(s) for s in scripts):
        return
    text = open(scripts[0]).read()
    check("--array=0-2" in text, "sweep.sbatch is an array of the 3 cases")
    check("--case" in text and "SLURM_ARRAY_TASK_ID" in text,
          "each task runs --case $SLURM_ARRAY_TASK_ID")
    check("--collect" in open(scripts[1]).read(), "collect.sbatch runs --collect")
    t0 = time.time()
    array = submit([scripts[0]], env, out)
    dep = submit(["--dependency=afterany:%s" % array, scripts[1]], env, out) if array else None
    check(array is not None and dep is not None, "both scripts are accepted (%s, %s)"
          % (array, dep))
    if array is None or dep is None:
        return
    finished, states = wait_jobs([array, dep], env, 300)
    check(finished, "the sweep and its collect job end within 300 s (%.1f s; %s)"
          % (time.time() - t0, states))
    results = os.path.join(out, "results.csv")
    rows = []
    if os.path.exists(results):
        with open(results, newline="") as f:
            rows = list(csv.DictReader(f))
    done = [row for row in rows if row.get("status") == "done"]
    check(len(rows) == 3 and len(done) == 3, "results.csv has 3 done rows (%s)"
          % [row.get("status") for row in rows])
    psis = []
    for row in rows:
        try:
            psis.append(float(row.get("param:material.damping.psi", "")))
        except ValueError:
            psis.append(row.get("param:material.damping.psi"))
    check(sorted(psis, key=str) == [1.0, 2.0, 3.0], "one row per psi value %s" % psis)
    check(all(os.path.isdir(os.path.join(out, "case_%04d" % k)) for k in range(3)),
          "case_0000..case_0002 exist")
    # the resume rule: resubmitting runs nothing again (finished cases are skipped)
    if len(done) == 3:
        status = [os.path.join(out, "case_%04d" % k, "status.json") for k in range(3)]
        mtimes = [os.path.getmtime(p) for p in status]
        again = submit([scripts[0]], env, out)
        if again:
            finished, states = wait_jobs([again], env, 120)
            check(finished and states[again] == ["COMPLETED"] * 3,
                  "a resubmitted array completes %s" % states.get(again))
            check(mtimes == [os.path.getmtime(p) for p in status],
                  "and leaves the finished cases untouched (status.json not rewritten)")
    if cli.FAILURES:
        show_logs(out)


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    t_start = time.time()
    script = os.path.join(args.source, "scripts", "slurm_local.sh")
    env = dict(os.environ)
    r = sh(["bash", script, "env"], env)
    for line in r.stdout.splitlines():
        m = re.match(r"export (\w+)=(.*)$", line)
        if m:
            env[m.group(1)] = m.group(2)
    running = sh(["bash", script, "status"], env).returncode == 0
    started_here = False
    if not running:
        try:
            r = sh(["bash", script, "start"], env, timeout=900)
        except subprocess.TimeoutExpired:
            print("skipped: scripts/slurm_local.sh start did not finish in 900 s")
            return 77
        if r.returncode != 0:
            print(r.stdout + r.stderr)
            sh(["bash", script, "stop"], env)  # what a failed start left running
            reason = (r.stderr.strip().splitlines() or ["no message"])[-1]
            print("skipped: a local Slurm cannot be started here (%s)" % reason)
            return 77
        started_here = True
        print("started Slurm: " + r.stdout.strip().splitlines()[-1])
    else:
        print("using the local Slurm already running (it stays up)")
    try:
        with tempfile.TemporaryDirectory(prefix="mrsim-slurm-test-") as tmp:
            os.chmod(tmp, 0o755)
            test_array_and_dependency(env, tmp)
            if not os.path.exists(args.binary):
                print("skipped: no binary at %s for the sweep part" % args.binary)
            elif sweep_has_emit(args.binary):
                test_sweep(args.binary, args.source, env, tmp)
            else:
                print("skipped: mrsim sweep --emit not available yet")
    finally:
        if started_here:
            r = sh(["bash", script, "stop"], env)
            check(r.returncode == 0, "slurm_local.sh stop exits 0 %s" % r.stderr.strip())
    print("run time %.1f s" % (time.time() - t_start))
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
