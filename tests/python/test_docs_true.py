#!/usr/bin/python3
"""Docs that stay true (issue 19 point 5): every key a run writes into summary.json has a row
in docs/output.md's table, and every row there is a key some run writes (a run with tools, time
levels and the real-time budget writes all of them), with the meanings the table gives
(frames after t = 0 against log.h5's rows, the energies, the wall time's parts); and numbers
the README states about bundled scenarios that no other test checks."""
import json
import os
import re
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: run, check)

check = cli.check


def documented_keys(source):
    """The backquoted names in the first column of the summary.json table."""
    text = open(os.path.join(source, "docs", "output.md"), encoding="utf-8").read()
    section = text[text.index("## summary.json"):text.index("## Reading the outputs")]
    keys = set()
    for line in section.splitlines():
        if line.startswith("| `"):
            keys.update(re.findall(r"`([a-z_0-9]+)`", line.split("|")[1]))
    return keys


def test_summary_keys(binary, source, tmp):
    out = os.path.join(tmp, "thesis")
    r = cli.run(binary, "run", os.path.join(source, "scenarios", "liver_thesis.yaml"), "-o", out,
                "-q", "--set", "time.duration=0.2", "--set", "output.vtk=false",
                "--set", "adaptivity.budget.realtime=true")
    check(r.returncode == 0, "liver_thesis with the budget runs (exit %d) %s"
          % (r.returncode, r.stderr[-300:]))
    summary = json.load(open(os.path.join(out, "summary.json")))
    written, documented = set(summary), documented_keys(source)
    check(written == documented, "summary.json keys are the documented ones (written only: %s; "
          "documented only: %s)" % (sorted(written - documented), sorted(documented - written)))
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        rows = len(h5["/frames/time"])
        kinetic = h5["/frames/kinetic_energy"][-1]
    check(rows == summary["frames"] + 1, "frames (%d) counts the frames after t = 0: log.h5 has "
          "%d rows" % (summary["frames"], rows))
    check(kinetic == summary["final_kinetic_energy"],
          "final_kinetic_energy is /frames/kinetic_energy's last row")
    check(abs(summary["simulated_time"] - summary["frames"] * 0.02) < 1e-12,
          "simulated_time = frames x frame_dt")
    check(abs(sum(summary["wall_time_shares"].values()) - 1) < 1e-9
          and sum(summary["wall_time_parts"].values()) <= summary["wall_time"],
          "wall_time_shares sum to 1; the parts leave out the set-up that wall_time has")


def readme_number(source, pattern):
    text = open(os.path.join(source, "README.md"), encoding="utf-8").read()
    found = re.search(pattern, text)
    check(found is not None, "README states %r" % pattern)
    return found.groups() if found else None


def test_liver_press_numbers(binary, source, tmp):
    """README and scenarios/liver_press.yaml: the finest points active at the peak."""
    (stated,) = readme_number(source, r"load \((\d+) of 3386 points at the peak\)") or ("-1",)
    out = os.path.join(tmp, "press")
    r = cli.run(binary, "run", os.path.join(source, "scenarios", "liver_press.yaml"), "-o", out,
                "-q", "--set", "output.vtk=false")
    check(r.returncode == 0, "liver_press runs (exit %d)" % r.returncode)
    with h5py.File(os.path.join(out, "log.h5"), "r") as h5:
        peak = int(h5["/frames/active"][:, -1].max())
    comment = open(os.path.join(source, "scenarios", "liver_press.yaml")).read()
    check(peak == int(stated) and ("up to %d of its 3386 points" % peak) in comment,
          "liver_press: %d finest points at the peak (README: %s; the scenario's comment says "
          "the same)" % (peak, stated))


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        test_summary_keys(args.binary, args.source, tmp)
        test_liver_press_numbers(args.binary, args.source, tmp)
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
