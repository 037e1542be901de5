#!/usr/bin/python3
"""scripts/validation_report.py (issue 7 point 5): the report is built from the records the
validation tests write, one table row per record with its measured value and band, one PNG per
record with a series, and a record outside its band is flagged and makes the script fail."""
import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli_run as cli  # noqa: E402  (shared helpers: check, run, parse_args, report)



check = cli.check


def record(folder, rid, measured, lower, upper, series=None, title="a check"):
    r = {"id": rid, "group": "Group " + rid[0], "title": title, "quantity": "q", "unit": "m",
         "measured": measured, "reference": 1.0, "reference_source": "validation.md §0",
         "lower": lower, "upper": upper, "tolerance": "±10 %", "note": "",
         "pass": lower <= measured <= upper}
    if series:
        r["series"] = {"file": rid + ".csv", "x_label": "t (s)", "y_label": "u (m)",
                       "kind": "line"}
        with open(os.path.join(folder, rid + ".csv"), "w") as f:
            f.write("t_s,mrsim_m,reference_m\n")
            for k in range(20):
                f.write("%g,%g,%g\n" % (0.1 * k, 1 + 0.01 * k, 1.0))
    with open(os.path.join(folder, rid + ".json"), "w") as f:
        json.dump(r, f)


def report(script, records, out):
    r = subprocess.run(["/usr/bin/python3", script, "--records", records, "--out", out],
                       capture_output=True, text=True, timeout=300)
    text = open(out, encoding="utf-8").read() if os.path.exists(out) else ""
    return r.returncode, text


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--binary")
    ap.add_argument("--source", required=True)
    ap.add_argument("--shared")
    args = ap.parse_args()
    script = os.path.join(args.source, "scripts", "validation_report.py")
    with tempfile.TemporaryDirectory() as tmp:
        records = os.path.join(tmp, "records")
        os.makedirs(records)
        record(records, "a_static", 1.02, 0.9, 1.1, title="tip |u| of a beam")
        record(records, "b_dynamic", 0.98, 0.9, 1.1, series=True)
        out = os.path.join(tmp, "docs", "validation.md")
        os.makedirs(os.path.dirname(out))
        code, text = report(script, records, out)
        check(code == 0, "all records within their band: exit 0")
        check("## Group a" in text and "## Group b" in text, "one section per group")
        check("**1.02 m**" in text and "**0.98 m**" in text, "measured values in the table")
        check("[0.9, 1.1] m" in text, "the band asserted by the test is shown")
        check("tip \\|u\\| of a beam" in text, "pipes in titles are escaped")
        png = os.path.join(tmp, "docs", "validation", "b_dynamic.png")
        check(os.path.exists(png) and os.path.getsize(png) > 1000, "a PNG for the dynamic check")
        check("](validation/b_dynamic.png)" in text, "the PNG is linked relative to the report")
        check(not os.path.exists(os.path.join(tmp, "docs", "validation", "a_static.png")),
              "no plot for a static check")
        record(records, "c_outside", 1.5, 0.9, 1.1)
        code, text = report(script, records, out)
        check(code == 1, "a record outside its band: exit 1")
        check("**Outside their band:** c_outside" in text and "✗ outside" in text,
              "the failing check is flagged")
        empty = os.path.join(tmp, "empty")
        os.makedirs(empty)
        code, _ = report(script, empty, os.path.join(tmp, "none.md"))
        check(code != 0, "no records: an error, not an empty report")
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
