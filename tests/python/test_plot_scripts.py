#!/usr/bin/python3
"""scripts/plot_run.py and scripts/plot_sweep.py (issue 8 point 4): the PNGs are written and
valid, the numbers plotted are the log's and the table's (read back from the figures), a
killed run is cut to its complete frames, a run without tools has no tool plot, failed sweep
cases are marked, and unreadable inputs exit 2 naming the file."""
import csv
import importlib.util
import os
import shutil
import struct
import subprocess
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: check, run, parse_args, report)

PYTHON = "/usr/bin/python3"


check = cli.check


def load(source, name):
    """Imports scripts/<name>.py as a module, to call its reading and plotting functions."""
    spec = importlib.util.spec_from_file_location(name, os.path.join(source, "scripts",
                                                                     name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def script(source, name, *args):
    return subprocess.run([PYTHON, os.path.join(source, "scripts", name), *args],
                          capture_output=True, text=True, timeout=300)


def png_size(path):
    """(width, height) from the IHDR chunk, None when the file is not a PNG."""
    with open(path, "rb") as f:
        head = f.read(24)
    if len(head) < 24 or head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        return None
    return struct.unpack(">II", head[16:24])


def check_pngs(paths, what):
    """Every file exists, is a PNG of plot size (300–2000 px a side) and 5–300 KB."""
    bad = []
    for p in paths:
        size = png_size(p) if os.path.exists(p) else None
        kb = os.path.getsize(p) / 1024 if size else 0
        if not size or not all(300 <= s <= 2000 for s in size) or not 5 <= kb <= 300:
            bad.append("%s %s %.0f KB" % (os.path.basename(p), size, kb))
    check(paths and not bad, "%s: %d valid PNGs %s" % (what, len(paths), bad or ""))


def lines_by_label(ax):
    return {line.get_label(): line for line in ax.get_lines()}


# ---------------------------------------------------------------------------------------------
# plot_run.py


def simulate(binary, source, tmp):
    """A short liver_probe (one tool, contact from 0.18 s) and a short beam_adaptive with
    time levels (several columns of /frames/time_levels, no tool)."""
    runs = {"liver": ("liver_probe.yaml", ["--set", "time.duration=0.3"]),
            "beam": ("beam_adaptive.yaml", ["--set", "time.duration=0.2",
                                            "--set", "adaptivity.time.enabled=true"])}
    out = {}
    for name, (scenario, sets) in runs.items():
        folder = os.path.join(tmp, name)
        r = subprocess.run([binary, "run", os.path.join(source, "scenarios", scenario), "-o",
                            folder, "-q", *sets], capture_output=True, text=True, timeout=300)
        check(r.returncode == 0, "mrsim run %s (exit %d) %s" % (scenario, r.returncode,
                                                               r.stderr.strip()[-200:]))
        if r.returncode == 0:
            out[name] = folder
    return out


def test_cli(source, liver, beam, tmp):
    r = script(source, "plot_run.py", "--help")
    check(r.returncode == 0 and "RUN_DIR" in r.stdout, "plot_run.py --help exits 0")
    r = script(source, "plot_run.py", liver)
    names = ["points_per_level.png", "time_levels.png", "tool_force.png", "energies.png",
             "events.png", "time_shares.png"]
    expected = [os.path.join(liver, "plots", n) for n in names]
    check(r.returncode == 0 and r.stdout.split() == expected,
          "liver run: default OUT_DIR RUN_DIR/plots, the six files printed (exit %d) %s"
          % (r.returncode, r.stderr.strip()[-200:]))
    check_pngs(expected, "liver run")
    out = os.path.join(tmp, "beam_plots")
    r = script(source, "plot_run.py", beam, "-o", out)
    listed = sorted(os.listdir(out)) if os.path.isdir(out) else []
    check(r.returncode == 0 and "tool_force.png" not in listed and len(listed) == 5
          and len(r.stdout.split()) == 5, "run without tools: no tool_force.png (%s)" % listed)
    check_pngs([os.path.join(out, n) for n in listed], "beam run (-o)")


def test_errors(source, tmp):
    empty = os.path.join(tmp, "empty_run")
    os.makedirs(empty)
    r = script(source, "plot_run.py", empty)
    check(r.returncode == 2 and os.path.join(empty, "log.h5") in r.stderr,
          "missing log.h5 exits 2 naming it: " + r.stderr.strip())
    with open(os.path.join(empty, "log.h5"), "wb") as f:
        f.write(b"not an HDF5 file\n" * 10)
    r = script(source, "plot_run.py", empty)
    check(r.returncode == 2 and "log.h5" in r.stderr and "Traceback" not in r.stderr,
          "corrupt log.h5 exits 2 naming it: " + r.stderr.strip()[:160])
    with h5py.File(os.path.join(empty, "log.h5"), "w") as f:
        f.create_dataset("frames/time", data=np.zeros(2))
    r = script(source, "plot_run.py", empty)
    check(r.returncode == 2 and "frames/frame" in r.stderr and "log.h5" in r.stderr,
          "log.h5 without /frames/frame exits 2 naming the dataset: " + r.stderr.strip())
    check(not os.path.exists(os.path.join(empty, "plots")), "and writes no plots folder")


def test_series(pr, liver):
    """The series read and the lines drawn are the log's values (independent h5py reads)."""
    run = pr.read_run(os.path.join(liver, "log.h5"))
    with h5py.File(os.path.join(liver, "log.h5"), "r") as log:
        t, active = log["frames/time"][:], log["frames/active"][:]
        ghosts = log["frames/ghosts"][:]
        kinetic, elastic = log["frames/kinetic_energy"][:], log["frames/elastic_energy"][:]
        tool_t, force = log["tool/time"][:], log["tool/force"][:]
        kinds = list(log["events/kind"].asstr()[:])
    check(np.array_equal(run["time"], t) and np.array_equal(run["active"], active),
          "read_run: time and active equal the log's")
    ax = pr.plot_points_per_level(run).axes[0]
    lines = lines_by_label(ax)
    ok = all(np.array_equal(lines["L%d active" % k].get_ydata(), active[:, k]) and
             np.array_equal(lines["L%d ghosts" % k].get_ydata(), ghosts[:, k]) and
             np.array_equal(lines["L%d active" % k].get_xdata(), t)
             and lines["L%d ghosts" % k].get_linestyle() == "--"
             for k in range(active.shape[1]))
    check(ok and len(lines) == 2 * active.shape[1],
          "points_per_level: one solid active and one dashed ghost line per level, the log's "
          "values (%d levels)" % active.shape[1])
    fig = pr.plot_tool_force(run)
    top, bottom = fig.axes[:2]
    curve = [l for l in top.get_lines() if len(l.get_xdata()) > 1][0]
    fz = [l for l in bottom.get_lines() if len(l.get_xdata()) > 1][0]
    check(np.array_equal(curve.get_xdata(), tool_t) and
          np.array_equal(curve.get_ydata(), np.linalg.norm(force, axis=1)) and
          np.array_equal(fz.get_ydata(), force[:, 2]),
          "tool_force: |F| and F_z at every one of the %d rows of /tool/force" % len(tool_t))
    khz = "%.3g kHz" % (1e-3 / (tool_t[1] - tool_t[0]))  # one sample per step (5.15 kHz)
    check(khz in top.get_title() and "probe" in curve.get_label(),
          "tool_force: %s in the title, the tool named: %r / %r"
          % (khz, top.get_title(), curve.get_label()))
    check(np.linalg.norm(force, axis=1).max() > 0.1, "the probe touches in 0.3 s (peak %.3g N)"
          % np.linalg.norm(force, axis=1).max())
    lines = lines_by_label(pr.plot_energies(run).axes[0])
    check(np.array_equal(lines["kinetic"].get_ydata(), kinetic) and
          np.array_equal(lines["elastic"].get_ydata(), elastic), "energies: the log's values")
    counts = pr.event_counts(run)
    check(counts["split"].sum() == kinds.count("split") > 0 and
          counts["merge"].sum() == kinds.count("merge"),
          "events: %d splits, %d merges, as in /events/kind" % (kinds.count("split"),
                                                                 kinds.count("merge")))


def test_time_shares(pr, liver):
    """The stack is the log's /frames/wall_time_parts (ms per frame, frame 0 left out), the
    legend names every task with its share of the run, and the shares sum to 1."""
    run = pr.read_run(os.path.join(liver, "log.h5"))
    with h5py.File(os.path.join(liver, "log.h5"), "r") as log:
        parts = log["frames/wall_time_parts"][:]
        names = [str(n) for n in log["frames/wall_time_parts"].attrs["names"]]
    ax = pr.plot_time_shares(run).axes[0]
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    shares = [float(l.split()[-2]) for l in labels]
    top = max(p.vertices[:, 1].max() for c in ax.collections for p in c.get_paths())
    check(len(labels) == len(names) == 7 and
          all(l.startswith(n.replace("_", " ")) for l, n in zip(labels, names)) and
          abs(sum(shares) - 100) < 0.5 and np.isclose(top, 1e3 * parts[1:].sum(axis=1).max()),
          "time_shares: %s; stack top %.1f ms = the longest frame" % (labels, top))
    # Real time: a dashed line at frame_dt a frame, and the frames above it counted.
    lines = [l for l in ax.get_lines() if l.get_linestyle() == "--"]
    behind = int(np.sum(parts[1:].sum(axis=1) > run["frame_dt"]))
    check(len(lines) == 1 and np.allclose(lines[0].get_ydata(), 1e3 * run["frame_dt"]) and
          ("%d of %d frames slower than real time" % (behind, len(parts) - 1)) in ax.get_title(),
          "time_shares: real time at %.3g ms; title %r" % (1e3 * run["frame_dt"], ax.get_title()))


def test_time_levels(pr, beam):
    """Columns are labelled by their step (frame_dt/2^k), the unused ones left out, and the stack
    reaches the number of integrated particles."""
    run = pr.read_run(os.path.join(beam, "log.h5"))
    with h5py.File(os.path.join(beam, "log.h5"), "r") as log:
        counts, steps = log["frames/time_levels"][:], log["frames/time_level_step"][:]
    ax = pr.plot_time_levels(run).axes[0]
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    used = [k for k in range(counts.shape[1]) if counts[:, k].any()]
    expected = ["frame_dt/%d = %.3g s" % (round(0.02 / steps[k]), steps[k]) for k in used]
    check(len(steps) > 2 and labels == expected,
          "time_levels: %d columns, used ones labelled %s" % (len(steps), labels))
    top = max(p.vertices[:, 1].max() for c in ax.collections for p in c.get_paths())
    check(top == counts.sum(axis=1).max(), "time_levels: stack top %g = max integrated %d"
          % (top, counts.sum(axis=1).max()))


def test_killed_run(source, pr, liver, tmp):
    """Rows beyond /frames/frame (and tool rows after the last frame) are ignored."""
    folder = os.path.join(tmp, "killed")
    os.makedirs(folder)
    path = os.path.join(folder, "log.h5")
    shutil.copy(os.path.join(liver, "log.h5"), path)
    with h5py.File(path, "r+") as log:
        n = log["frames/frame"].shape[0]
        t_end = log["frames/time"][-1]
        s = log["tool/time"].shape[0]
        for name in ("time", "kinetic_energy", "elastic_energy", "active", "ghosts",
                     "time_levels", "wall_time_parts"):
            d = log["frames/" + name]
            d.resize(n + 1, axis=0)
            d[n] = 999999
        for name in ("time", "force"):
            d = log["tool/" + name]
            d.resize(s + 2, axis=0)
            d[s:] = t_end + 0.001 if name == "time" else 999999
        for name in ("frame", "kind", "level", "point"):
            d = log["events/" + name]
            d.resize(d.shape[0] + 1, axis=0)
            d[-1] = "split" if name == "kind" else n + 5
    run = pr.read_run(path)
    check(len(run["time"]) == n and run["active"].shape[0] == n and
          (run["active"] != 999999).all() and len(run["tools"][0]["time"]) == s and
          np.abs(run["tools"][0]["force"]).max() < 999999,
          "killed run: %d complete frames and %d tool rows kept, extra rows ignored" % (n, s))
    with h5py.File(os.path.join(liver, "log.h5"), "r") as log:
        splits = list(log["events/kind"].asstr()[:]).count("split")
    check(pr.event_counts(run)["split"].sum() == splits, "killed run: the next frame's event "
          "is dropped (%d splits)" % splits)
    r = script(source, "plot_run.py", folder)
    check(r.returncode == 0 and len(r.stdout.split()) == 6, "killed run plots (exit %d)"
          % r.returncode)
    check(run["wall_time_parts"].shape[0] == n and run["wall_time_parts"].max() < 999999,
          "killed run: the extra row of /frames/wall_time_parts is ignored")


# ---------------------------------------------------------------------------------------------
# plot_sweep.py


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)


def test_sweep_fixture(source, ps, tmp):
    table = os.path.join(source, "tests", "data", "sweep", "results.csv")
    with open(table, newline="") as f:
        rows = list(csv.DictReader(f))
    params = [c[len("param:"):] for c in rows[0] if c.startswith("param:")]
    out = os.path.join(tmp, "sweep_plots")
    r = script(source, "plot_sweep.py", table, "-o", out)
    expected = [os.path.join(out, "sweep_%s.png" % p) for p in params]
    check(r.returncode == 0 and r.stdout.split() == expected,
          "fixture: one PNG per param column %s (exit %d) %s"
          % ([os.path.basename(e) for e in expected], r.returncode, r.stderr.strip()[-200:]))
    check_pngs(expected, "sweep fixture")
    check(any(row["status"] == "failed" for row in rows), "the fixture has a failed case")
    columns, table_rows, keys = ps.read_table(table)
    fig = ps.plot_param(table_rows, keys, ps.figure_columns(columns, table_rows),
                        "material.lambda")
    axes = {ax.get_title(): ax for ax in fig.axes if ax.get_visible()}
    check("peak tool force (N)" in axes and "final active points, level 3" in axes
          and "real-time factor (simulated s / wall s)" in axes and len(axes) == 9,
          "lambda figure: 9 plots %s" % sorted(axes))
    check({ax.get_xlabel() for ax in axes.values()} == {"material.lambda (Pa)"}
          and ps.axis_label("material.damping.psi") == "material.damping.psi (Pa·s)",
          "x axes carry the parameter's unit: %s" % {ax.get_xlabel() for ax in axes.values()})
    lines = lines_by_label(axes["max displacement (m)"])
    for psi in ("2", "20"):
        done = sorted((float(r["param:material.lambda"]), float(r["max_displacement"]))
                      for r in rows if r["param:material.damping.psi"] == psi
                      and r["status"] == "done")
        line = lines.get("material.damping.psi=%s" % psi)
        check(line is not None and list(line.get_xdata()) == [d[0] for d in done]
              and list(line.get_ydata()) == [d[1] for d in done],
              "series psi=%s: the done cases' max_displacement against lambda (%d points)"
              % (psi, len(done)))
    failed = [float(r["param:material.lambda"]) for r in rows if r["status"] == "failed"]
    marks = [lines_by_label(ax).get("failed") for ax in axes.values()]
    check(all(m is not None and list(m.get_xdata()) == failed and m.get_color() == "red"
              and m.get_marker() == "x" for m in marks),
          "every plot marks the failed case(s) with a red x at lambda = %s" % failed)


def test_sweep_variants(source, ps, tmp):
    header = ["case", "status", "exit_code", "message", "param:material.lambda",
              "param:time.integrator", "peak_tool_force", "max_displacement",
              "final_active_L0", "final_active_L1", "wall_time", "force_evaluations", "steps",
              "splits", "merges"]
    rows = [["case_%04d" % i, status, code, msg, lam, integ, "", disp, 10, 20, 1.5, 1000,
             100, 3, 1] for i, (status, code, msg, lam, integ, disp) in enumerate([
                 ("done", 0, "", 0, "modified_euler", 0.01),
                 ("done", 0, "", 100, "modified_euler", 0.02),
                 ("failed", 1, "diverged at frame 3", 1e5, "modified_euler", ""),
                 ("done", 0, "", 0, "symplectic_euler", 0.011),
                 ("pending", "", "", 100, "symplectic_euler", ""),
                 ("done", 0, "", 1e5, "symplectic_euler", 0.03)])]
    table = os.path.join(tmp, "variant.csv")
    write_csv(table, header, rows)
    out = os.path.join(tmp, "variant_plots")
    r = script(source, "plot_sweep.py", table, "-o", out)
    check(r.returncode == 0 and len(r.stdout.split()) == 2,
          "failed and pending rows, a string parameter, no tool force: exit %d %s"
          % (r.returncode, r.stderr.strip()[-200:]))
    check_pngs(r.stdout.split(), "variant table")
    columns, table_rows, keys = ps.read_table(table)
    figures = ps.figure_columns(columns, table_rows)
    check("peak_tool_force" not in [c for c, _ in figures], "an empty figure column gets no plot")
    ax = ps.plot_param(table_rows, keys, figures, "material.lambda").axes[0]
    check(ax.get_xscale() == "symlog", "lambda 0…1e5: symlog x (got %s)" % ax.get_xscale())
    ax = ps.plot_param(table_rows, keys, figures, "time.integrator").axes[0]
    ticks = [t.get_text() for t in ax.get_xticklabels()]
    check(ticks == ["modified_euler", "symplectic_euler"], "string parameter as categories %s"
          % ticks)
    no_param = os.path.join(tmp, "no_param.csv")
    write_csv(no_param, [h for h in header if not h.startswith("param:")],
              [[c for h, c in zip(header, row) if not h.startswith("param:")] for row in rows])
    r = script(source, "plot_sweep.py", no_param, "-o", out)
    check(r.returncode == 2 and "no_param.csv" in r.stderr and "param:" in r.stderr,
          "a table without param: columns exits 2: " + r.stderr.strip())
    r = script(source, "plot_sweep.py", os.path.join(tmp, "missing.csv"))
    check(r.returncode == 2 and "missing.csv" in r.stderr, "a missing table exits 2: "
          + r.stderr.strip())
    check(script(source, "plot_sweep.py", "--help").returncode == 0, "plot_sweep.py --help")




def main():
    args = cli.parse_args()
    if args is None:
        return 77
    pr, ps = load(args.source, "plot_run"), load(args.source, "plot_sweep")
    with tempfile.TemporaryDirectory() as tmp:
        test_errors(args.source, tmp)
        test_sweep_fixture(args.source, ps, tmp)
        test_sweep_variants(args.source, ps, tmp)
        runs = simulate(args.binary, args.source, tmp)
        if len(runs) == 2:
            test_cli(args.source, runs["liver"], runs["beam"], tmp)
            test_series(pr, runs["liver"])
            test_time_levels(pr, runs["beam"])
            test_time_shares(pr, runs["liver"])
            test_killed_run(args.source, pr, runs["liver"], tmp)
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
