"""Validation records from the Python end-to-end tests, in the format of
tests/validation/validation_record.hpp, so scripts/validation_report.py puts their rows in
docs/validation.md beside the C++ checks.

A record is `<dir>/<id>.json` (and `<dir>/<id>.csv` for a curve). `<dir>` is
$MRSIM_VALIDATION_OUT, else $MRSIM_BINARY_DIR/validation (ctest sets it for the tests labelled
`validation`); run by hand without either, nothing is written. The test asserts on its own: a
record is a report, written whether the check passes or fails."""
import csv
import json
import os


def record_dir():
    out = os.environ.get("MRSIM_VALIDATION_OUT")
    if not out and os.environ.get("MRSIM_BINARY_DIR"):
        out = os.path.join(os.environ["MRSIM_BINARY_DIR"], "validation")
    if out:
        os.makedirs(out, exist_ok=True)
    return out


def record(check_id, group, title, quantity, measured, lower, upper, tolerance="",
           reference=0.0, reference_source="", note="", unit="", series=None):
    """Writes the record; `series` is (x_label, y_label, column names, rows), the abscissa
    first. Returns whether `measured` is within [lower, upper]."""
    passed = lower <= measured <= upper
    folder = record_dir()
    if not folder:
        return passed
    j = {"id": check_id, "group": group, "title": title, "quantity": quantity, "unit": unit,
         "measured": float(measured), "reference": float(reference),
         "reference_source": reference_source, "lower": float(lower), "upper": float(upper),
         "tolerance": tolerance, "note": note, "pass": bool(passed)}
    if series is not None:
        x_label, y_label, columns, rows = series
        with open(os.path.join(folder, check_id + ".csv"), "w", newline="",
                  encoding="utf-8") as f:
            w = csv.writer(f)
            w.writerow(columns)
            for row in rows:
                w.writerow(["%.10g" % v for v in row])
        j["series"] = {"file": check_id + ".csv", "x_label": x_label, "y_label": y_label,
                       "kind": "line"}
    with open(os.path.join(folder, check_id + ".json"), "w", encoding="utf-8") as f:
        f.write(json.dumps(j, indent=2) + "\n")
    return passed
