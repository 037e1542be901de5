#!/usr/bin/python3
"""Builds docs/validation.md and its plots from the records of the validation suite.

Every check of `ctest -L validation` (tests/validation/) writes `<id>.json` (reference, band,
measured value) and, for a dynamic check, `<id>.csv` (its signal) into a records folder. This
script turns them into one table per group and one PNG per dynamic check, so the numbers in
the document are the ones the current code measured, never typed by hand.

    scripts/validation_report.py --run build          # run the suite, then write the report
    scripts/validation_report.py --records DIR        # only write it from existing records

Uses Debian's python3-matplotlib (run with /usr/bin/python3).
"""
import argparse
import csv
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
# Sections in the order of validation.md (§2.3 statics and modes, §2.8 damping, §2.4 waves,
# §2.5 compression, §2.6 free body, §2.9 tools), then the method's own claim; others follow.
# Curves named like these are references (dashed); the others are measured (solid).
REFERENCE_WORDS = ("reference", "calculix", "hertz", "boussinesq", "static", "analytic",
                   "predict", "exact")
GROUP_ORDER = ["Beam", "Beam levels: first bending frequency", "Levels alone (calibrated)",
               "Damping", "Waves",
               "Uniaxial compression (patch test)", "Free body", "Indentation",
               "Adaptive vs uniform"]


def load_records(folder):
    records = []
    for path in sorted(pathlib.Path(folder).glob("*.json")):
        with open(path, encoding="utf-8") as f:
            record = json.load(f)
        for key in ("id", "group", "title", "measured", "lower", "upper", "pass"):
            if key not in record:
                raise SystemExit(f"{path}: record without '{key}'")
        records.append(record)
    if not records:
        raise SystemExit(f"no validation records in {folder}: run `ctest -L validation` first")
    return records


def number(x, unit=""):
    """Four significant digits; exponent form for very small or large magnitudes."""
    if x is None:
        return "–"
    if x == 0:
        text = "0"
    elif abs(x) < 1e-3 or abs(x) >= 1e5:
        mantissa, exponent = f"{x:.3e}".split("e")
        text = f"{mantissa}·10<sup>{int(exponent)}</sup>"
    else:
        text = f"{x:.4g}"
    return f"{text} {unit}".strip()


def cell(text):
    """Table cells may not contain a bare '|' (|L| in a title would split the row)."""
    return str(text).replace("|", "\\|")


def band(record):
    lo, hi, unit = record["lower"], record["upper"], record.get("unit", "")
    words = record.get("tolerance", "")
    span = f"[{number(lo)}, {number(hi)}] {unit}".strip()
    return f"{words}: {span}" if words else span


def read_series(folder, record):
    with open(pathlib.Path(folder) / record["series"]["file"], encoding="utf-8") as f:
        rows = list(csv.reader(f))
    header, data = rows[0], [[float(v) for v in row] for row in rows[1:] if row]
    return header, data


def plot(folder, record, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    header, data = read_series(folder, record)
    series = record["series"]
    fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=100)
    xs = [row[0] for row in data]
    for c in range(1, len(header)):
        ys = [row[c] for row in data]
        reference = any(w in header[c].lower() for w in REFERENCE_WORDS)
        style = dict(linestyle="--", linewidth=1.2) if reference else dict(linewidth=1.5)
        if series.get("kind") == "loglog":
            pts = [(x, y) for x, y in zip(xs, ys) if x > 0 and y > 0]
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], label=header[c], **style)
        else:
            ax.plot(xs, ys, label=header[c], **style)
    ax.set_xlabel(series["x_label"])
    ax.set_ylabel(series["y_label"])
    ax.set_title(record["title"] if len(record["title"]) < 70 else record["id"], fontsize=9)
    ax.grid(True, alpha=0.3)
    if len(header) > 2:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png)
    plt.close(fig)


def git_revision():
    try:
        git = ["git", "-C", str(ROOT)]
        rev = subprocess.run(git + ["rev-parse", "--short", "HEAD"], capture_output=True,
                             text=True, check=True).stdout.strip()
        dirty = subprocess.run(git + ["status", "--porcelain", "--untracked-files=no",
                                      "--", "src", "tests"],
                               capture_output=True, text=True, check=True).stdout.strip()
        return rev + (" with uncommitted changes to src/ or tests/" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def write_report(records, folder, out_md, figures):
    figures.mkdir(parents=True, exist_ok=True)
    for old in figures.glob("*.png"):
        old.unlink()
    failed = [r["id"] for r in records if not r["pass"]]
    lines = [
        "# Validation: what the current code measures",
        "",
        "<!-- Generated by scripts/validation_report.py from the records of "
        "`ctest -L validation`; do not edit by hand. -->",
        "",
        f"Generated from the records of `ctest -L validation` (tests/validation/) at revision "
        f"`{git_revision()}`: {len(records)} checks, {len(records) - len(failed)} within their "
        "band. The references and the reasoning behind each band are in "
        "`../shared/design/validation.md` (the section is named in each row); a band is what "
        "the test asserts, so a value outside it fails the suite. Regenerate with "
        "`scripts/validation_report.py --run build`.",
        "",
    ]
    if failed:
        lines += [f"**Outside their band:** {', '.join(failed)}.", ""]
    groups = [g for g in GROUP_ORDER if any(r["group"] == g for r in records)]
    for r in records:
        if r["group"] not in groups:
            groups.append(r["group"])
    for group in groups:
        rows = [r for r in records if r["group"] == group]
        lines += [f"## {group}", "",
                  "| check | quantity | measured | band | reference | source | |",
                  "|---|---|---|---|---|---|---|"]
        for r in rows:
            unit = r.get("unit", "")
            mark = "✓" if r["pass"] else "✗ outside"
            cells = [r["title"], r["quantity"], f"**{number(r['measured'], unit)}**", band(r),
                     number(r["reference"], unit), r["reference_source"], mark]
            lines.append("| " + " | ".join(cell(c) for c in cells) + " |")
        notes = [f"- `{r['id']}`: {r['note']}" for r in rows if r.get("note")]
        if notes:
            lines += ["", *notes]
        lines.append("")
        for r in rows:
            if "series" in r:
                png = figures / f"{r['id']}.png"
                plot(folder, r, png)
                rel = os.path.relpath(png, out_md.parent)
                lines += [f"![{r['id']}]({rel})", ""]
    out_md.write_text("\n".join(lines), encoding="utf-8")
    return failed


def run_suite(build):
    records = pathlib.Path(tempfile.mkdtemp(prefix="mrsim-validation-"))
    env = dict(os.environ, MRSIM_VALIDATION_OUT=str(records))
    result = subprocess.run(["ctest", "--test-dir", str(build), "-L", "validation",
                             "--output-on-failure", "-j2"], env=env)
    if result.returncode != 0:
        print("some validation checks failed; the report marks them", file=sys.stderr)
    return records


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--records", help="folder of <id>.json/.csv records")
    parser.add_argument("--run", metavar="BUILD", help="run `ctest -L validation` in BUILD first")
    parser.add_argument("--out", default=str(ROOT / "docs" / "validation.md"))
    parser.add_argument("--figures", help="PNG folder (default: docs/validation/ beside --out)")
    args = parser.parse_args()
    if bool(args.records) == bool(args.run):
        parser.error("give exactly one of --records and --run")
    folder = run_suite(args.run) if args.run else pathlib.Path(args.records)
    out_md = pathlib.Path(args.out)
    figures = pathlib.Path(args.figures) if args.figures else out_md.parent / "validation"
    failed = write_report(load_records(folder), folder, out_md, figures)
    if args.run:
        shutil.rmtree(folder, ignore_errors=True)
    print(f"wrote {out_md} and {len(list(figures.glob('*.png')))} plots in {figures}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
