#!/usr/bin/python3
"""Plots a run's log.h5 (docs/output.md) as PNGs, to see at a glance what a run did.

    scripts/plot_run.py out/liver_probe                # writes out/liver_probe/plots/*.png
    scripts/plot_run.py out/liver_probe -o figures/

Writes points_per_level.png (active and ghost points per level), time_levels.png (integrated
particles per time level), tool_force.png (|F| and F_z of every tool at every simulation step;
only when the scenario has tools), energies.png (kinetic and elastic energy), events.png
(splits and merges per frame) and time_shares.png (each frame's wall time per task, stacked,
with the run's shares in the legend: internal forces, ghosts, contact, integration,
adaptivity, output, other; a dashed line at real time, frame_dt a frame, and the count of
frames above it in the title; only when the log has /frames/wall_time_parts). A killed run is plotted up to its last complete frame: the
length of /frames/frame counts the complete frames and extra rows are ignored. A run still
going can be plotted too (the file is opened without HDF5 file locking).

Uses Debian's python3-h5py and python3-matplotlib (run with /usr/bin/python3). Exit codes:
0 written, 2 the log cannot be read (the message names the file).
"""
import argparse
import os
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the Agg backend)

DPI = 100
EVENT_KINDS = ("split", "merge", "time_refine", "time_coarsen", "budget_hold", "budget_shed")


class LogError(Exception):
    """A log.h5 that cannot be read; the message names the file (and the dataset)."""


# ---------------------------------------------------------------------------------------------
# Reading


def log_path(run):
    """RUN_DIR or its log.h5 itself: both are accepted, so tab completion works either way."""
    return run if os.path.isfile(run) else os.path.join(run, "log.h5")


def open_log(path):
    """Opens without file locking, so a run that is still writing its log can be plotted."""
    if not os.path.exists(path):
        raise LogError("cannot read %s: no such file" % path)
    try:
        return h5py.File(path, "r", locking=False)
    except (OSError, ValueError) as e:
        raise LogError("cannot read %s: %s" % (path, e))


def dataset(log, name, rows=None):
    """Reads a dataset, at most `rows` rows, naming file and dataset when it is missing."""
    if name not in log:
        raise LogError("cannot read %s: dataset %s is missing" % (log.filename, name))
    try:
        d = log[name]
        return d[()] if d.shape == () else (d[:rows] if rows is not None else d[:])
    except (OSError, ValueError, TypeError) as e:
        raise LogError("cannot read %s: dataset %s: %s" % (log.filename, name, e))


def scenario(log):
    """The resolved scenario (root attribute `scenario`) as a dict, {} when it cannot be read:
    it only names the run and labels the time levels, which is not worth failing a plot for."""
    try:
        import yaml
        text = log.attrs["scenario"]
        value = yaml.safe_load(text.decode() if isinstance(text, bytes) else text)
        return value if isinstance(value, dict) else {}
    except Exception:  # noqa: BLE001
        return {}


def frame_dt(resolved, steps):
    """frame_dt, to label time levels as frame_dt/2^k; without a readable scenario, the coarsest
    time level's step (= frame_dt with time levels)."""
    try:
        value = float(resolved["time"]["frame_dt"])
        if value > 0:
            return value
    except (KeyError, TypeError, ValueError):
        pass
    return float(steps[0]) if len(steps) > 1 else None


def tool_groups(log):
    """The tool groups in the scenario's order: /tool, /tool_1, /tool_2, …"""
    names = []
    while True:
        name = "tool" if not names else "tool_%d" % len(names)
        if name not in log:
            return names
        names.append(name)


def read_tool(log, group, t_end):
    """One tool's samples: `time` is written last, so its length counts the complete rows;
    rows after the last complete frame (a killed run) are dropped. The tolerance absorbs the
    round-off of the accumulated step time (0.6000000000000186 against a frame at 0.6)."""
    t = dataset(log, group + "/time")
    force = dataset(log, group + "/force", len(t))
    steps = np.diff(t)
    tol = 1e-3 * steps[steps > 0].min() if np.any(steps > 0) else 1e-12
    keep = t <= t_end + tol
    name = log[group].attrs.get("name", group)
    if isinstance(name, bytes):
        name = name.decode()
    return {"group": group, "name": str(name), "time": t[keep], "force": force[keep]}


def read_events(log, frames):
    """Events of the complete frames: the four datasets are cut to their common length and to
    the frames that have a row (a killed run may hold the next frame's events)."""
    n = min(log["events/" + k].shape[0] for k in ("frame", "kind", "level", "point"))
    frame = dataset(log, "events/frame", n)
    try:
        kind = log["events/kind"].asstr()[:n]
    except (OSError, ValueError, TypeError) as e:
        raise LogError("cannot read %s: dataset events/kind: %s" % (log.filename, e))
    last = frames[-1] if len(frames) else -1
    keep = frame <= last
    return {"frame": frame[keep], "kind": np.asarray(kind, dtype=object)[keep]}


def read_parts(log, rows):
    """/frames/wall_time_parts and its column names; (None, []) in logs written before it."""
    if "frames/wall_time_parts" not in log:
        return None, []
    parts = dataset(log, "frames/wall_time_parts", rows)
    names = [n.decode() if isinstance(n, bytes) else str(n)
             for n in log["frames/wall_time_parts"].attrs.get("names", [])]
    if parts.ndim != 2 or len(names) != parts.shape[1]:
        raise LogError("cannot read %s: dataset frames/wall_time_parts has %s columns and %d "
                       "names" % (log.filename, parts.shape[1:], len(names)))
    return parts, names


def read_run(path):
    """Everything the plots need, cut to the complete frames (docs/output.md, Guarantees)."""
    with open_log(path) as log:
        try:
            frames = dataset(log, "frames/frame")
            n = len(frames)
            if n == 0:
                raise LogError("cannot plot %s: it holds no complete frame" % path)
            run = {"path": path, "frame": frames}
            for key in ("time", "kinetic_energy", "elastic_energy", "active", "ghosts",
                        "time_levels"):
                run[key] = dataset(log, "frames/" + key, n)
                if len(run[key]) < n:
                    raise LogError("cannot read %s: dataset frames/%s has %d rows, "
                                   "frames/frame %d" % (path, key, len(run[key]), n))
            run["time_level_step"] = dataset(log, "frames/time_level_step")
            run["wall_time_parts"], run["task_names"] = read_parts(log, n)
            resolved = scenario(log)
            run["frame_dt"] = frame_dt(resolved, run["time_level_step"])
            run["tools"] = [read_tool(log, g, run["time"][-1]) for g in tool_groups(log)]
            run["events"] = read_events(log, frames)
            run["name"] = str(resolved.get("name") or
                              os.path.basename(os.path.dirname(os.path.abspath(path))))
        except KeyError as e:
            raise LogError("cannot read %s: %s" % (path, e))
    return run


# ---------------------------------------------------------------------------------------------
# Plots: each returns a Figure (the tests read the plotted data back from it)


def level_colour(k):
    return plt.get_cmap("tab10")(k % 10)


def count_axis(ax, values):
    """Counts often span decades (20 coarse points, 3000 fine ones): symlog keeps the small
    levels readable and still shows 0."""
    positive = values[values > 0]
    if len(positive) and positive.max() > 50 * max(positive.min(), 1):
        ax.set_yscale("symlog", linthresh=1, linscale=0.3)
    ax.set_ylim(bottom=0)


def plot_points_per_level(run):
    """Active (solid) and ghost (dashed) points per level, one colour per level."""
    fig, ax = plt.subplots(figsize=(8, 4.5))
    t = run["time"]
    for k in range(run["active"].shape[1]):
        ax.plot(t, run["active"][:, k], "-", color=level_colour(k), label="L%d active" % k)
        ax.plot(t, run["ghosts"][:, k], "--", color=level_colour(k), label="L%d ghosts" % k)
    count_axis(ax, np.concatenate([run["active"].ravel(), run["ghosts"].ravel()]))
    ax.set_xlabel("simulated time (s)")
    ax.set_ylabel("points")
    ax.set_title("%s: active (solid) and ghost (dashed) points per level" % run["name"])
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1))
    fig.tight_layout()
    return fig


def step_label(step, dt):
    """'frame_dt/4 = 1.25e-4 s': the column's step as a fraction of frame_dt, and in seconds."""
    seconds = "%.3g s" % step
    if not dt:
        return seconds
    ratio = dt / step
    if abs(ratio - round(ratio)) > 1e-6 * ratio:
        return seconds
    return ("frame_dt = " if round(ratio) == 1 else "frame_dt/%d = " % round(ratio)) + seconds


def plot_time_levels(run):
    """Integrated particles per time level, stacked (the top is the number integrated); the
    columns that are never used are left out of the legend to keep it readable."""
    fig, ax = plt.subplots(figsize=(8, 4.5))
    counts, steps = run["time_levels"], run["time_level_step"]
    used = [k for k in range(counts.shape[1]) if counts[:, k].any()]
    cmap = plt.get_cmap("viridis")
    colours = [cmap(0.9 * i / max(1, len(used) - 1)) for i in range(len(used))]
    labels = [step_label(steps[k], run["frame_dt"]) for k in used]
    if used:
        ax.stackplot(run["time"], *[counts[:, k] for k in used], labels=labels, colors=colours,
                     alpha=0.85)
    ax.set_xlabel("simulated time (s)")
    ax.set_ylabel("integrated particles")
    unused = counts.shape[1] - len(used)
    note = "; %d unused time level%s not shown" % (unused, "s"[:unused > 1]) if unused else ""
    ax.set_title("%s: particles per time level (stacked)%s" % (run["name"], note))
    ax.grid(alpha=0.3)
    if used:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=8, title="step")
    fig.tight_layout()
    return fig


def sample_rate(t):
    """'12.8 kHz' for a fixed step; 'min–max kHz' when time levels make the step vary."""
    steps = np.diff(t)
    steps = steps[steps > 0]
    if len(steps) == 0:
        return "no samples"
    fast, slow = 1.0 / steps.min(), 1.0 / steps.max()
    fmt = lambda hz: "%.3g kHz" % (hz / 1e3) if hz >= 1e3 else "%.3g Hz" % hz  # noqa: E731
    if fast <= slow * 1.001:
        return fmt(1.0 / np.median(steps))
    return "%s–%s" % (fmt(slow).split()[0], fmt(fast))


def plot_tool_force(run):
    """|F| and F_z of each tool at every logged step (not just per frame): contact forces
    change within a frame, and the peak is what a haptic device would feel."""
    if not run["tools"]:
        return None
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 6))
    rates = []
    for i, tool in enumerate(run["tools"]):
        colour = level_colour(i)
        rate = sample_rate(tool["time"])
        rates.append(rate)
        magnitude = np.linalg.norm(tool["force"], axis=1)
        top.plot(tool["time"], magnitude, color=colour, lw=1,
                 label="%s (%s, %d samples)" % (tool["name"], rate, len(tool["time"])))
        bottom.plot(tool["time"], tool["force"][:, 2], color=colour, lw=1, label=tool["name"])
        if len(magnitude):
            j = int(np.argmax(magnitude))
            top.plot(tool["time"][j], magnitude[j], "v", color=colour, markersize=6)
            late = tool["time"][j] > 0.5 * (tool["time"][0] + tool["time"][-1])
            top.annotate("peak %.3g N" % magnitude[j], (tool["time"][j], magnitude[j]),
                         textcoords="offset points", xytext=(-6 if late else 6, 6),
                         ha="right" if late else "left", fontsize=8)
    top.margins(y=0.15)
    top.set_ylabel("|F| (N)")
    bottom.set_ylabel("F_z (N)")
    bottom.set_xlabel("simulated time (s)")
    rate = rates[0] if len(set(rates)) == 1 else "per tool"
    top.set_title("%s: force of the object on the tool%s, sampled at %s" % (
        run["name"], "s" if len(rates) > 1 else "", rate))
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    top.legend(fontsize=8, loc="best")
    fig.tight_layout()
    return fig


def plot_energies(run):
    """Kinetic and elastic energy; log scale when they span decades (a settling body)."""
    fig, ax = plt.subplots(figsize=(8, 4.5))
    t = run["time"]
    ax.plot(t, run["kinetic_energy"], label="kinetic")
    ax.plot(t, run["elastic_energy"], label="elastic")
    both = np.concatenate([run["kinetic_energy"], run["elastic_energy"]])
    positive = both[both > 0]
    if len(positive) and positive.max() > 1e3 * positive.min():
        ax.set_yscale("log", nonpositive="mask")
    ax.set_xlabel("simulated time (s)")
    ax.set_ylabel("energy (J)")
    ax.set_title("%s: energies" % run["name"])
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    return fig


def event_counts(run):
    """Counts of each event kind per written frame (a frame's events are those whose frame
    index is after the previous row's and up to this row's)."""
    frames, events = run["frame"], run["events"]
    bins = np.searchsorted(frames, events["frame"], side="left")
    counts = {}
    for kind in EVENT_KINDS:
        mask = events["kind"] == kind
        if kind in ("split", "merge") or mask.any():
            counts[kind] = np.bincount(bins[mask], minlength=len(frames))[:len(frames)]
    return counts


def plot_events(run):
    """Splits and merges (and time-level changes, budget frames when present) per frame."""
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for kind, count in event_counts(run).items():
        ax.step(run["time"], count, where="pre", label="%s (%d)" % (kind, count.sum()))
    ax.set_xlabel("simulated time (s)")
    ax.set_ylabel("events per frame")
    ax.set_title("%s: events per frame" % run["name"])
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    return fig


def plot_time_shares(run):
    """Each frame's wall time per task, stacked (ms), as the thesis reports its time shares
    (§5: model 60 %, surface 5 %, collision 20 %, display 15 %); the legend gives each task's
    share of the whole run. Frame 0 (set-up output only) is left out. A dashed line marks real
    time (frame_dt of wall time per frame): a stack above it is a frame that fell behind the
    clock, and the title counts them."""
    parts = run["wall_time_parts"]
    if parts is None or len(parts) < 2:
        return None
    fig, ax = plt.subplots(figsize=(8, 4.5))
    total = parts[1:].sum()
    shares = parts[1:].sum(axis=0) / total if total > 0 else np.zeros(parts.shape[1])
    cmap = plt.get_cmap("tab10")
    labels = ["%s %.1f %%" % (name.replace("_", " "), 100 * share)
              for name, share in zip(run["task_names"], shares)]
    ax.stackplot(run["time"][1:], *(1e3 * parts[1:, k] for k in range(parts.shape[1])),
                 labels=labels, colors=[cmap(k) for k in range(parts.shape[1])], alpha=0.85)
    title = "%s: wall time per task (stacked), %.3g s over %d frames" % (
        run["name"], total, len(parts) - 1)
    if run["frame_dt"]:
        real_time = 1e3 * run["frame_dt"]
        ax.axhline(real_time, color="black", linestyle="--", linewidth=1)
        ax.annotate("real time (%.3g ms a frame)" % real_time, (0, real_time),
                    xycoords=("axes fraction", "data"), xytext=(4, 3),
                    textcoords="offset points", fontsize=8)
        behind = int(np.sum(1e3 * parts[1:].sum(axis=1) > real_time))
        title += "\n%d of %d frames slower than real time" % (behind, len(parts) - 1)
    ax.set_xlabel("simulated time (s)")
    ax.set_ylabel("wall time per frame (ms)")
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=8, title="share of the run")
    fig.tight_layout()
    return fig


PLOTS = (("points_per_level.png", plot_points_per_level),
         ("time_levels.png", plot_time_levels),
         ("tool_force.png", plot_tool_force),
         ("energies.png", plot_energies),
         ("events.png", plot_events),
         ("time_shares.png", plot_time_shares))


def write_plots(run, out_dir):
    """Writes every plot that applies; returns the paths written."""
    os.makedirs(out_dir, exist_ok=True)
    written = []
    for name, plot in PLOTS:
        fig = plot(run)
        if fig is None:
            continue
        path = os.path.join(out_dir, name)
        fig.savefig(path, dpi=DPI, pil_kwargs={"optimize": True})
        plt.close(fig)
        written.append(path)
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n")[0],
        epilog="Files: points_per_level.png, time_levels.png, tool_force.png (with tools), "
               "energies.png, events.png, time_shares.png.")
    parser.add_argument("run", metavar="RUN_DIR", help="output folder of `mrsim run` "
                        "(or its log.h5)")
    parser.add_argument("-o", "--out", metavar="OUT_DIR",
                        help="where to write the PNGs (default RUN_DIR/plots)")
    args = parser.parse_args(argv)
    path = log_path(args.run)
    try:
        run = read_run(path)
    except LogError as e:
        print("error: %s" % e, file=sys.stderr)
        return 2
    out = args.out or os.path.join(os.path.dirname(os.path.abspath(path)), "plots")
    try:
        written = write_plots(run, out)
    except OSError as e:
        print("error: cannot write %s: %s" % (getattr(e, "filename", None) or out,
                                              e.strerror or e), file=sys.stderr)
        return 1
    for p in written:
        print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main())
