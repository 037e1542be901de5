#!/usr/bin/python3
"""Issue 18, restart: a run stopped by SIGTERM, SIGINT or SIGKILL and taken up again with
`mrsim run --resume OUTDIR` writes outputs that `mrsim compare` finds identical at rtol = atol
= 0 to those of the same run left alone: one level, space adaptivity, time levels and a tool,
every integrator, a surface load. A checkpoint that does not belong to the folder's run, to
this build or to an unfinished run is refused (exit 2) and nothing in the folder changes."""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: check, parse_args, report)

check = cli.check


def run(binary, *args):
    return subprocess.run([binary, *args], capture_output=True, text=True, timeout=600)


def frames_listed(folder):
    try:
        root = ET.parse(os.path.join(folder, "frames.pvd")).getroot()
        return len(list(root.iter("DataSet")))
    except (OSError, ET.ParseError):
        return 0


def start(binary, scenario, out, sets):
    args = [binary, "run", scenario, "-o", out, "-q"]
    for s in sets:
        args += ["--set", s]
    return subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def stop_after(p, out, frames, sig):
    """Sends `sig` once frames.pvd lists `frames` frames (or the run ended)."""
    for _ in range(60000):
        if p.poll() is not None or frames_listed(out) >= frames:
            break
        time.sleep(0.002)
    if p.poll() is None:
        p.send_signal(sig)
    _, err = p.communicate(timeout=600)
    return err


def identical(binary, a, b):
    c = run(binary, "compare", a, b, "--rtol", "0", "--atol", "0")
    return c.returncode == 0, c.stdout.strip().splitlines()[-1:] + c.stderr.strip().splitlines()


# (name, scenario, --set overrides, frames before the signal)
CASES = [
    ("one level, modified Euler", "beam.yaml", ["time.duration=0.3"], 6),
    ("space adaptivity, Stoermer-Verlet", "beam_adaptive.yaml",
     ["time.duration=0.3", "time.integrator=stoermer_verlet"], 6),
    ("one level, Newton-Cotes (undamped: its parasitic root grows under damping)", "beam.yaml",
     ["time.duration=0.3", "time.integrator=newton_cotes", "material.damping.psi=0.0"], 6),
    ("four levels under a load, semi-implicit", "liver_press.yaml",
     ["time.duration=0.5", "time.integrator=semi_implicit"], 12),
    ("time levels, space adaptivity and a tool", "liver_thesis.yaml", [], 30),
]


def test_resume_after_interruption(binary, source, tmp):
    """SIGTERM (or SIGINT) after some frames: exit 143 (130), a checkpoint; --resume finishes
    the run; the outputs are those of the run left alone, at zero tolerance."""
    for k, (name, scenario, sets, frames) in enumerate(CASES):
        path = os.path.join(source, "scenarios", scenario)
        a, b = os.path.join(tmp, "whole_%d" % k), os.path.join(tmp, "stopped_%d" % k)
        whole = start(binary, path, a, sets)
        whole.communicate(timeout=600)
        sig = signal.SIGINT if k % 2 else signal.SIGTERM
        p = start(binary, path, b, sets)
        err = stop_after(p, b, frames, sig)
        summary = json.load(open(os.path.join(b, "summary.json")))
        stopped_at = summary["frames"]
        has_checkpoint = os.path.exists(os.path.join(b, "checkpoint.h5"))
        r = run(binary, "run", "--resume", b, "-q")
        same, why = identical(binary, a, b)
        check(whole.returncode == 0 and p.returncode == 128 + sig and has_checkpoint and
              r.returncode == 0 and same,
              "%s: %s after frame %d (exit %d, checkpoint %s), --resume exit %d, identical to "
              "the whole run at rtol=atol=0: %s %s"
              % (name, sig.name, stopped_at, p.returncode, has_checkpoint, r.returncode, same,
                 why if not same else "", ) + (err + r.stderr).strip()[-200:])


def test_resume_after_kill(binary, source, tmp):
    """SIGKILL at any moment after a periodic checkpoint: the frames written after it are
    dropped from log.h5, frames.pvd and frames/, and the resumed run is identical to the whole
    one; twice in a row (a resumed run killed again). A kill while the run flushes log.h5 can
    tear it (HDF5 files are not crash-consistent): the first kill's log is torn on purpose, and
    the resumed run goes on from the checkpoint's copy of it."""
    path = os.path.join(source, "scenarios", "liver_thesis.yaml")
    a = os.path.join(tmp, "whole_4")  # the whole run of CASES[4]
    b = os.path.join(tmp, "killed")
    p = start(binary, path, b, ["output.checkpoint_every=4"])
    stop_after(p, b, 23, signal.SIGKILL)
    with h5py.File(os.path.join(b, "checkpoint.h5"), "r") as h5:
        first = int(h5["/run/frame"][0])
    listed = frames_listed(b)
    log = os.path.join(b, "log.h5")
    os.truncate(log, os.path.getsize(log) // 3)
    with open(log, "ab") as f:
        f.write(b"torn by a kill")
    # Killed again, while resuming from the first checkpoint.
    again = subprocess.Popen([binary, "run", "--resume", b, "-q"], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    stop_after(again, b, 45, signal.SIGKILL)
    with h5py.File(os.path.join(b, "checkpoint.h5"), "r") as h5:
        second = int(h5["/run/frame"][0])
    r = run(binary, "run", "--resume", b, "-q")
    same, why = identical(binary, a, b)
    leftovers = [f for f in os.listdir(b) if f.endswith(".tmp")]
    check(p.returncode == -signal.SIGKILL and first % 4 == 0 and listed > first and
          second > first and r.returncode == 0 and same and not leftovers,
          "killed with %d frames written (checkpoint at frame %d), resumed and killed again "
          "(checkpoint at frame %d), resumed: exit %d, identical at rtol=atol=0: %s %s %s"
          % (listed, first, second, r.returncode, same, why if not same else "",
             r.stderr.strip()[-200:]))


def snapshot(folder):
    """Name, size and modification time of every file of a run folder."""
    files = {}
    for root, _, names in os.walk(folder):
        for n in names:
            f = os.path.join(root, n)
            if n != ".mrsim.lock":
                st = os.stat(f)
                files[os.path.relpath(f, folder)] = (st.st_size, st.st_mtime_ns)
    return files


def refused(binary, folder, expected, what):
    before = snapshot(folder)
    r = run(binary, "run", "--resume", folder, "-q")
    check(r.returncode == 2 and expected in r.stderr and snapshot(folder) == before,
          "%s: exit %d, folder untouched, says %r" % (what, r.returncode,
                                                       r.stderr.strip()[-220:]))


def test_refusals(binary, source, tmp):
    """What --resume refuses, with exit 2, before it changes anything."""
    beam = os.path.join(source, "scenarios", "beam.yaml")
    done = os.path.join(tmp, "whole_0")  # completed
    refused(binary, done, "nothing to resume", "a completed run")
    r = run(binary, "run", beam, "--resume", done)
    check(r.returncode == 2, "a scenario and --resume together: exit %d" % r.returncode)
    refused(binary, os.path.join(tmp, "nowhere"), "no such run folder", "no folder")

    # A run stopped before its first checkpoint: no checkpoint.h5 (killed at once).
    early = os.path.join(tmp, "early")
    p = start(binary, beam, early, ["time.duration=0.3"])
    stop_after(p, early, 2, signal.SIGKILL)
    if os.path.exists(os.path.join(early, "checkpoint.h5")):
        os.remove(os.path.join(early, "checkpoint.h5"))
    refused(binary, early, "no checkpoint here", "a folder without checkpoint.h5")

    # Checkpoints that are not this folder's run's, or not this build's.
    stopped = os.path.join(tmp, "stopped_0")  # interrupted beam run of CASES[0]
    other = os.path.join(tmp, "stopped_1")    # interrupted beam_adaptive run
    foreign = os.path.join(tmp, "foreign")
    shutil.copytree(stopped, foreign)
    os.remove(os.path.join(foreign, "summary.json"))
    shutil.copy(os.path.join(other, "checkpoint.h5"), os.path.join(foreign, "checkpoint.h5"))
    refused(binary, foreign, "belongs to another scenario", "another run's checkpoint")
    for attribute, value, expected in (("mrsim_version", "0.0.1", "was written by mrsim 0.0.1"),
                                       ("format_version", 99, "format version 99")):
        tampered = os.path.join(tmp, "tampered_" + attribute)
        shutil.copytree(stopped, tampered)
        os.remove(os.path.join(tampered, "summary.json"))
        with h5py.File(os.path.join(tampered, "checkpoint.h5"), "r+") as h5:
            h5.attrs[attribute] = value
        refused(binary, tampered, expected, "a checkpoint with %s %s" % (attribute, value))
    torn = os.path.join(tmp, "torn")
    shutil.copytree(stopped, torn)
    os.remove(os.path.join(torn, "summary.json"))
    ck = os.path.join(torn, "checkpoint.h5")
    with open(ck, "r+b") as f:
        f.truncate(os.path.getsize(ck) // 2)
    refused(binary, torn, "damaged checkpoint", "a checkpoint cut in half")


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        test_resume_after_interruption(args.binary, args.source, tmp)
        test_resume_after_kill(args.binary, args.source, tmp)
        test_refusals(args.binary, args.source, tmp)
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
