#!/usr/bin/python3
"""Docs that stay true (issue 19 point 5): every key a run writes into summary.json has a row
in docs/output.md's table, and every row there is a key some run writes (a run with tools, time
levels and the real-time budget writes all of them), with the meanings the table gives
(frames after t = 0 against log.h5's rows, the energies, the wall time's parts); numbers
the README states about bundled scenarios that no other test checks; docs/validation.md is
what the validation suite measures now, and the README's validation figures are its records'."""
import glob
import json
import os
import re
import subprocess
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


def test_sweep_runs(binary, source, tmp):
    """README: every case of the bundled volume_lambda sweep runs to its end; the one that
    diverged (lambda = 0, psi = 20 Pa.s) is run here."""
    readme_number(source, r"every case runs to its end \(λ = (0), ψ = 20 Pa·s diverged")
    out = os.path.join(tmp, "sweep_case")
    base = os.path.join(source, "scenarios", "volume_lambda_5e4.yaml")
    r = cli.run(binary, "run", base, "-o", out, "-q", "--set", "time.duration=0.4",
                "--set", "output.vtk=false", "--set", "material.lambda=0",
                "--set", "material.damping.psi=20")
    check(r.returncode == 0, "volume_lambda sweep case lambda = 0, psi = 20 runs to its end "
          "(exit %d) %s" % (r.returncode, r.stderr.strip()[-200:]))


def validation_records(binary):
    """The records `ctest -L validation` left in the build (tests/validation/validation_record.hpp;
    ctest runs that suite before this test: fixture validation_records)."""
    folder = os.path.join(os.path.dirname(os.path.abspath(binary)), "validation")
    records = {}
    for path in glob.glob(os.path.join(folder, "*.json")):
        with open(path, encoding="utf-8") as f:
            record = json.load(f)
        records[record["id"]] = record
    return folder, records


def without_revision(text):
    return [line for line in text.splitlines() if not line.startswith("Generated from the records")]


def test_validation_report_current(binary, source, tmp):
    """docs/validation.md regenerated from this build's records differs only in its revision."""
    folder, records = validation_records(binary)
    check(len(records) > 0, "the validation suite left its records in %s" % folder)
    if not records:
        return
    out = os.path.join(tmp, "validation.md")
    r = subprocess.run(["/usr/bin/python3", os.path.join(source, "scripts", "validation_report.py"),
                        "--records", folder, "--out", out, "--figures", os.path.join(tmp, "validation")],
                       capture_output=True, text=True, timeout=300)
    now = without_revision(open(out, encoding="utf-8").read()) if os.path.exists(out) else []
    doc = without_revision(open(os.path.join(source, "docs", "validation.md"),
                                encoding="utf-8").read())
    first = next((i for i, (a, b) in enumerate(zip(doc, now)) if a != b), min(len(doc), len(now)))
    same = now == doc
    check(same, "docs/validation.md is what the validation suite measures now (%d checks)%s"
          % (len(records), "" if same else ": line %d is now %r, the doc says %r; regenerate it "
             "with scripts/validation_report.py --run build (%s)"
             % (first + 1, now[first] if first < len(now) else None,
                doc[first] if first < len(doc) else None, r.stderr.strip()[-200:])))


def agrees(stated, value):
    """`stated` (as written, e.g. "0.84") is `value` rounded to the decimals it shows."""
    decimals = len(stated.split(".")[1]) if "." in stated else 0
    return abs(float(stated) - value) <= 0.5 * 10 ** -decimals + 1e-12


def test_readme_validation_numbers(binary, source):
    """The validation figures the README quotes are those the suite measures."""
    _, records = validation_records(binary)
    if not records:
        return
    measured = lambda rid: records[rid]["measured"] if rid in records else float("nan")
    pairs = []
    found = readme_number(source, r"alone, its levels vibrate at\s+([\d.]+), ([\d.]+) and "
                          r"([\d.]+) Hz")
    if found:
        pairs += list(zip(found, [measured("beam_level_f1_L%d" % k) for k in range(3)],
                          ["f1 L0", "f1 L1", "f1 L2"]))
    found = readme_number(source, r"spread \(max − min\)/mean ([\d.]+), and ([\d.]+) between")
    if found:
        pairs += [(found[0], measured("beam_levels_f1_spread"), "f1 spread"),
                  (found[1], measured("beam_levels_f1_spread_L1_L2"), "f1 spread L1-L2")]
    found = readme_number(source, r"vibrates\s+within ([\d.]+) % of its finest level alone "
                          r"\(static deflection within ([\d.]+) %\), with on average (\d+) % of")
    if found:
        active = re.search(r"on average (\d+) %;",
                           records.get("beam_levels_f1_adaptive", {}).get("note", ""))
        pairs += [(found[0], 100 * abs(measured("adaptive_vs_uniform_f1")), "adaptive f1 gap %"),
                  (found[1], 100 * abs(measured("adaptive_vs_uniform_static")),
                   "adaptive static gap %"),
                  (found[2], float(active.group(1)) if active else float("nan"),
                   "finest points active %")]
    found = readme_number(source, r"Hertz slope ([\d.]+), force within\s+(\d+) %; "
                          r"Boussinesq ([\d.]+)")
    if found:
        pairs += [(found[0], measured("indentation_hertz_slope"), "Hertz slope"),
                  (found[1], 100 * abs(1 - measured("indentation_hertz_force")), "Hertz force %"),
                  (found[2], measured("indentation_punch"), "Boussinesq ratio")]
    found = readme_number(source, r"\((\d+) checks; see below\)")
    if found:
        pairs.append((found[0], len(records), "validation checks"))
    wrong = ["%s: README %s, measured %.4g" % (what, said, value)
             for said, value, what in pairs if not agrees(said, value)]
    check(pairs and not wrong, "the README's %d validation figures are the suite's records%s"
          % (len(pairs), ": " + "; ".join(wrong) if wrong else ""))


def matrix_rows(text, heading):
    """The rows of the table under `heading` in docs/stability_matrix.md, as cell lists."""
    section = text[text.index(heading):]
    section = section[section.index("|---"):]
    rows = []
    for line in section.splitlines()[1:]:
        if not line.startswith("|"):
            break
        rows.append([c.strip() for c in line.strip().strip("|").split("|")])
    return rows


def test_stability_summary(source):
    """The README's stability figures summarise docs/stability_matrix.md (generated by
    scripts/stability_matrix.py): the explicit one-step rows over whole runs and on the big
    hierarchies, and the semi-implicit whole runs, as the true limit over the estimate in force."""
    text = open(os.path.join(source, "docs", "stability_matrix.md"), encoding="utf-8").read()
    ratio = lambda row: float(row[9].split()[0])
    explicit = [r for r in matrix_rows(text, "## Whole runs")
                if r[1] in ("modified_euler", "stoermer_verlet") and r[3] == "off"]
    big = [r for r in matrix_rows(text, "## Hierarchies")
           if r[1] in ("modified_euler", "stoermer_verlet") and r[3] == "off"]
    semi = [r for r in matrix_rows(text, "## Semi-implicit over whole runs") if r[3] == "off"]
    big_semi = [r for r in matrix_rows(text, "## Hierarchies")
                if r[1] == "semi_implicit" and r[3] == "off"]
    derived = ["%.2f" % min(map(ratio, explicit)), "%.2f" % max(map(ratio, explicit)),
               str(len(explicit)), "%.2f" % min(map(ratio, big)), "%.2f" % max(map(ratio, big)),
               str(sum(1 <= ratio(r) <= 2.5 for r in semi)), str(len(semi)),
               "%.2f" % min(map(ratio, big_semi)), "%.2f" % max(map(ratio, big_semi))]
    found = readme_number(source, r"is within\s+([\d.]+)–([\d.]+) of the true limit on its (\d+) "
                          r"bundled rows and ([\d.]+)–([\d.]+) on the 15k/60k/125k-tet\s+hierarchies "
                          r"\(semi-implicit: (\d+) of (\d+) whole runs within \[1, 2.5\],\s+"
                          r"([\d.]+)–([\d.]+) on the hierarchies\)")
    check(found is not None and list(found) == derived,
          "the README's stability figures are docs/stability_matrix.md's: %s (README %s)"
          % (derived, list(found) if found else None))


def test_bundled_mesh_counts(source):
    """The tet counts the README gives for the bundled meshes are their _quality.json's."""
    meshes = os.path.join(source, "scenarios", "meshes")

    def counts(name, key):
        with open(os.path.join(meshes, name + "_quality.json"), encoding="utf-8") as f:
            return [str(level[key]) for level in json.load(f)["levels"]]

    n = r"(\d+(?: / \d+)*)"
    stated = {
        "liver": readme_number(source, r"a \*\*liver\*\* \(" + n + r" tets, asked for " + n),
        "little_man": readme_number(source, r"\*\*little man\*\* \(" + n + " of " + n),
        "beam": readme_number(source, r"\*\*beam\*\* 0.1 × 0.02 × 0.02 m \(" + n + " of " + n),
    }
    for name, found in stated.items():
        if found:
            said = [found[0].split(" / "), found[1].split(" / ")]
            real = [counts(name, "tets"), counts(name, "requested_tets")]
            check(said == real, "README's %s levels: %s tets of %s asked (quality.json: %s of %s)"
                  % (name, said[0], said[1], real[0], real[1]))
    found = readme_number(source, r"thesis' own hierarchy \(" + n + r" tets; `mrsim mesh --tets "
                          r"([\d,]+)`\)")
    if found:
        real = [counts("liver_thesis", "tets"), counts("liver_thesis", "requested_tets")]
        check([found[0].split(" / "), found[1].split(",")] == real,
              "README's liver_thesis levels: %s (quality.json: %s)" % (list(found), real))


def test_golden_size(source):
    """README: the golden files' total size."""
    found = readme_number(source, r"kept as references \(([\d.]+) MB in all\)")
    total = 0
    for root, _, names in os.walk(os.path.join(source, "tests", "golden")):
        total += sum(os.path.getsize(os.path.join(root, n)) for n in names)
    check(found is not None and agrees(found[0], total / 1e6),
          "README's golden size %s MB is the folder's %.2f MB" % (found and found[0], total / 1e6))


def main():
    args = cli.parse_args()
    if args is None:
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        test_summary_keys(args.binary, args.source, tmp)
        test_liver_press_numbers(args.binary, args.source, tmp)
        test_sweep_runs(args.binary, args.source, tmp)
        test_validation_report_current(args.binary, args.source, tmp)
        test_readme_validation_numbers(args.binary, args.source)
        test_stability_summary(args.source)
        test_bundled_mesh_counts(args.source)
        test_golden_size(args.source)
    return cli.report()


if __name__ == "__main__":
    sys.exit(main())
