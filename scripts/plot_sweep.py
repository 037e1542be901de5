#!/usr/bin/python3
"""Plots a sweep's results.csv: one PNG per varied parameter, to see how the figures of
summary.json move with it.

    scripts/plot_sweep.py out/sweep/results.csv            # writes out/sweep/plots/sweep_*.png
    scripts/plot_sweep.py out/sweep/results.csv -o figures/

The table has a header row and the columns `case`, `status` (done, failed, pending),
`exit_code`, `message`, one `param:<key.path>` column per varied parameter, then the figures
`peak_tool_force`, `max_displacement`, `final_active_L0`, `final_active_L1`, …, `wall_time`,
`real_time_factor`, `force_evaluations`, `steps`, `splits`, `merges`.

For each parameter, `sweep_<key.path>.png` has one small plot per figure against that
parameter. Cases that differ in the other parameters are separate series, labelled by their
values; failed cases are red x markers at the bottom of every plot; pending cases are left
out. The x axis is logarithmic (symlog when 0 is among the values) when the positive values
span more than two decades; string values are categories.

Uses Debian's python3-matplotlib (run with /usr/bin/python3). Exit codes: 0 written, 2 the
table cannot be read or has no `param:` column (the message names the file).
"""
import argparse
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the Agg backend)
import matplotlib.transforms as mtransforms  # noqa: E402

DPI = 100
PARAM = "param:"
REQUIRED = ("case", "status")
# Figures plotted, in order; final_active_L<k> columns follow (one plot per level).
FIGURES = (("peak_tool_force", "peak tool force (N)"),
           ("max_displacement", "max displacement (m)"),
           ("wall_time", "wall time (s)"),
           ("real_time_factor", "real-time factor (simulated s / wall s)"),
           ("force_evaluations", "force evaluations"))
ACTIVE = re.compile(r"^final_active_L(\d+)$")


class TableError(Exception):
    """A results table that cannot be used; the message names the file."""


# ---------------------------------------------------------------------------------------------
# Reading


def number(text):
    """A cell as a float, or None when empty or not a number (a figure may be empty, e.g.
    peak_tool_force without tools; NaN counts as missing)."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def read_table(path):
    """Rows as dicts, checking the columns a plot needs: case, status and at least one
    `param:` column."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            columns = reader.fieldnames or []
            rows = list(reader)
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise TableError("cannot read %s: %s" % (path, getattr(e, "strerror", None) or e))
    missing = [c for c in REQUIRED if c not in columns]
    if missing:
        raise TableError("%s: no column %s (is it a sweep's results.csv?)"
                         % (path, ", ".join(missing)))
    params = [c[len(PARAM):] for c in columns if c.startswith(PARAM)]
    if not params:
        raise TableError("%s: no `param:<key>` column, so no varied parameter to plot against"
                         % path)
    return columns, rows, params


def figure_columns(columns, rows):
    """(column, axis label) of the figures the table has values for, final active points per
    level last. An empty column (peak_tool_force of a sweep without tools) gets no plot."""
    figures = [(c, label) for c, label in FIGURES if c in columns]
    levels = sorted((int(m.group(1)), c) for c in columns for m in [ACTIVE.match(c)] if m)
    figures += [(c, "final active points, level %d" % k) for k, c in levels]
    return [(c, label) for c, label in figures if any(number(r.get(c)) is not None for r in rows)]


def param_values(rows, key):
    """The parameter's values: floats when every non-empty cell is a number, else strings
    (then plotted as categories)."""
    cells = [r.get(PARAM + key, "") for r in rows]
    numeric = all(number(c) is not None for c in cells if c != "")
    return [number(c) if numeric else c for c in cells], numeric


# ---------------------------------------------------------------------------------------------
# Plotting


def cell(row, key):
    """A parameter's cell: a float when it is a number, else the string."""
    text = row.get(PARAM + key, "")
    value = number(text)
    return text if value is None else value


def short(value):
    """A parameter value in a label: '5e+05' stays short, strings stay as they are."""
    return "%g" % value if isinstance(value, float) else str(value)


def series_of(rows, key, params):
    """Groups the done cases by the values of the other parameters: {label: [row indices]}."""
    others = [p for p in params if p != key]
    groups = {}
    for i, row in enumerate(rows):
        if row["status"] == "done":
            label = ", ".join("%s=%s" % (p, short(cell(row, p))) for p in others)
            groups.setdefault(label, []).append(i)
    return groups


def x_positions(values, numeric):
    """x of each row, and the categories (None for numbers): categories are sorted so that
    the same table always gives the same axis."""
    if numeric:
        return values, None
    categories = sorted(set(v for v in values if v != ""))
    return [categories.index(v) if v != "" else None for v in values], categories


def set_x_scale(ax, xs, categories):
    """Log x when the positive values span more than two decades; symlog keeps 0 visible."""
    if categories is not None:
        ax.set_xticks(range(len(categories)))
        ax.set_xticklabels(categories, rotation=30, ha="right", fontsize=8)
        return
    positive = [x for x in xs if x is not None and x > 0]
    if positive and max(positive) > 100 * min(positive):
        if any(x is not None and x <= 0 for x in xs):
            ax.set_xscale("symlog", linthresh=min(positive))
        else:
            ax.set_xscale("log")


def plot_figure(ax, rows, column, xs, groups):
    """One figure (column) against the parameter, one line per series, x sorted."""
    for label, indices in groups.items():
        points = sorted((xs[i], number(rows[i][column])) for i in indices
                        if xs[i] is not None and number(rows[i].get(column)) is not None)
        if points:
            ax.plot([p[0] for p in points], [p[1] for p in points], "o-", markersize=4,
                    label=label or None)


def mark_failed(ax, rows, xs):
    """Failed cases as red x at the bottom of the plot: x in data, y in axes coordinates, so
    they stay at the bottom whatever the figure's range, in a band added below the data so
    they do not hide a point."""
    failed = [xs[i] for i, r in enumerate(rows) if r["status"] == "failed" and xs[i] is not None]
    if failed:
        low, high = ax.get_ylim()
        ax.set_ylim(low - 0.1 * (high - low), high)
        trans = mtransforms.blended_transform_factory(ax.transData, ax.transAxes)
        ax.plot(failed, [0.04] * len(failed), "x", color="red", markersize=8, mew=2,
                transform=trans, clip_on=False, label="failed")


# Units of the parameters a sweep varies, by the last part of their key (the schema's
# descriptions give the same); a key not listed is labelled without one.
UNITS = {"lambda": "Pa", "mu": "Pa", "youngs_modulus": "Pa", "phi": "Pa·s", "psi": "Pa·s",
         "density": "kg/m³", "poisson_ratio": "dimensionless", "frame_dt": "s", "duration": "s",
         "radius": "m", "half_length": "m", "stiffness": "N/m", "refine_above": "dimensionless",
         "coarsen_below": "dimensionless", "courant": "dimensionless", "substeps": "steps per frame",
         "velocity_change": "dimensionless", "fraction": "dimensionless"}


def axis_label(key):
    """'material.lambda (Pa)'."""
    unit = UNITS.get(key.split(".")[-1])
    return "%s (%s)" % (key, unit) if unit else key


def plot_param(rows, params, figures, key):
    """The figure for one parameter: a grid of small plots, one per figure column."""
    values, numeric = param_values(rows, key)
    xs, categories = x_positions(values, numeric)
    groups = series_of(rows, key, params)
    ncols = min(3, len(figures)) or 1
    nrows = max(1, math.ceil(len(figures) / ncols))
    fig, axes = plt.subplots(nrows, ncols, figsize=(3.4 * ncols, 2.5 * nrows + 0.6), squeeze=False)
    for ax, (column, label) in zip(axes.flat, figures):
        plot_figure(ax, rows, column, xs, groups)
        mark_failed(ax, rows, xs)
        set_x_scale(ax, xs, categories)
        ax.set_title(label, fontsize=10)
        ax.set_xlabel(axis_label(key), fontsize=9)
        ax.tick_params(labelsize=8)
        ax.grid(alpha=0.3)
    for ax in list(axes.flat)[len(figures):]:
        ax.set_visible(False)
    counts = {s: sum(r["status"] == s for r in rows) for s in ("done", "failed", "pending")}
    fig.suptitle("sweep over %s: %d cases (%d done, %d failed, %d pending)" % (
        key, len(rows), counts["done"], counts["failed"], counts["pending"]))
    handles = legend_handles(axes.flat)
    if handles:
        fig.legend(list(handles.values()), list(handles), loc="lower center",
                   ncol=min(4, len(handles)), fontsize=8)
    fig.tight_layout(rect=(0, 0.04 if handles else 0, 1, 0.98))
    return fig


def legend_handles(axes):
    """One legend for the whole figure: every series and `failed`, whichever plot has them
    (a series may have no value for one figure)."""
    handles = {}
    for ax in axes:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(label, handle)
    return handles


def file_name(key):
    """sweep_<key>.png, with characters a file name should not hold replaced."""
    return "sweep_%s.png" % re.sub(r"[^A-Za-z0-9._-]", "_", key)


def write_plots(path, out_dir):
    """Writes one PNG per parameter; returns the paths written."""
    columns, rows, params = read_table(path)
    figures = figure_columns(columns, rows)
    if not figures:
        raise TableError("%s: no figure column (peak_tool_force, max_displacement, …)" % path)
    os.makedirs(out_dir, exist_ok=True)
    written = []
    for key in params:
        fig = plot_param(rows, params, figures, key)
        out = os.path.join(out_dir, file_name(key))
        fig.savefig(out, dpi=DPI, pil_kwargs={"optimize": True})
        plt.close(fig)
        written.append(out)
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("table", metavar="SWEEP_DIR/results.csv", help="a sweep's results table")
    parser.add_argument("-o", "--out", metavar="OUT_DIR",
                        help="where to write the PNGs (default: plots/ next to the table)")
    args = parser.parse_args(argv)
    out = args.out or os.path.join(os.path.dirname(os.path.abspath(args.table)), "plots")
    try:
        written = write_plots(args.table, out)
    except TableError as e:
        print("error: %s" % e, file=sys.stderr)
        return 2
    except OSError as e:
        print("error: cannot write %s: %s" % (getattr(e, "filename", None) or out,
                                              e.strerror or e), file=sys.stderr)
        return 1
    for p in written:
        print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main())
