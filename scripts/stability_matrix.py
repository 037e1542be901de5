#!/usr/bin/python3
"""Stability test matrix (issue 15 point 3, docs/integrators.md "Stability matrix").

For every case (the bundled scenarios, and liver_probe on hierarchies whose finest level has
~15k, ~60k and ~125k tets), every integrator, psi as given and 20 Pa.s, with and without time
levels:

1. `time.substeps` left out: mrsim computes the step; the run must not diverge.
2. The true limit, measured: without time levels the smallest number of substeps per frame
   that still runs (bisection, `time.adapt_substeps=false` so the step stays what it is asked
   to be), as a step against the smallest estimate in force during the automatic run
   (/frames/stable_step): for the explicit integrators true limit / estimate must lie in
   [1.0, 2.5]. Against the set-up estimate too (reported): every point that may become
   active counts there, so one global step chosen in advance is more cautious. With time levels the largest `time.courant` that still
   runs, the velocity-change rule switched off (it would refine the particles that start to
   blow up): every particle's step is the largest power-of-two division of the frame within
   courant x its estimate, so on one ladder that factor is between 1 and 2 times the true
   ratio ([1.0, 5.0]). So it is measured on up to --ladder-shifts ladders (frame_dt x
   2^(j/n), each with its own automatic run, which must finish too) and the smallest is kept,
   against the band [1.0, 2.5]: every ladder's limit is above the true ratio, so the next
   ladder is tried only while the smallest so far is above 2.5; after all n it is within
   2^(1/n) above the true ratio (a row still above 2.5 is then at least 2.5 / 2^(1/n) times
   cautious).
   The semi-implicit step (eq. 5.1) damps what would grow: its runs are only required never
   to be optimistic (>= 1.0); the measured factor is reported.

    scripts/stability_matrix.py [--binary build/mrsim] [--work build/stability]
                                [--cases NAME...] [--integrators NAME...] [--psi given|VALUE...]
                                [--time-levels off|on...] [--duration S] [--quick] [--table FILE]
                                [--set KEY=VALUE ...]

--quick: the beam cases, two integrators, shortened runs (what ctest runs, py.test_stability).
--table: write the markdown table there (docs/integrators.md quotes it).
--set: a scenario override for every run of every row (before the row's own), e.g.
       --set object.calibration=per_tet to measure the matrix on calibrated levels.
Exit status: 0 when every automatic run finished and every ratio is in the band, 1 otherwise.
Generated meshes (mrsim mesh on the bundled liver surface) are cached in --work.
"""
import argparse
import json
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time

import yaml

ROOT = pathlib.Path(__file__).resolve().parent.parent
SCENARIOS = ROOT / "scenarios"
BAND = (1.0, 2.5)       # explicit, one global step: true limit / estimate
# Time levels measured on one ladder: each particle's step is its estimate × courant rounded
# down to a power-of-two division of the frame, so the largest stable courant is 1 to 2 times
# the true ratio. With ladder shifts (frame_dt × 2^(j/n), j < n) the smallest of the n limits
# is within 2^(1/n) above it, and the band is the one-step band itself.
TIME_LEVEL_BAND = (1.0, 5.0)
LADDER_SHIFTS = 4


SHORT_RUN_SEMI_BAND = (1.0, 4.0)


def band(row, short_runs=False):
    """The same for every integrator: the semi-implicit estimate is the filter's own limit
    (docs/integrators.md), no longer the explicit one doubled. With --quick's short runs the
    body hardly deforms, so the semi-implicit estimate's Green-Lagrange allowance (at least
    0.1 lambda_K on the filtered spectrum) is not used yet there: the adaptive beam's global semi-implicit step is then 4.0 below its limit in 0.1 s,
    2.0 over the whole run."""
    if short_runs and row["integrator"].startswith("semi_implicit") and not row["time_levels"]:
        return SHORT_RUN_SEMI_BAND
    if row["time_levels"] and "shifts" not in row:  # one ladder only (--ladder-shifts 1)
        return TIME_LEVEL_BAND
    return BAND
INTEGRATORS = ["modified_euler", "stoermer_verlet", "semi_implicit"]
ESTIMATE = re.compile(r"stable step estimate ([0-9.eE+-]+) s")
COMPUTED = re.compile(r"time\.substeps computed: (\d+)")


def bundled_cases():
    names = ["beam", "beam_adaptive", "liver_press", "liver_probe", "little_man_shake",
             "volume_lambda_0", "volume_lambda_5e4", "volume_lambda_5e5", "liver_thesis"]
    return {n: {"scenario": SCENARIOS / (n + ".yaml"), "finest": None} for n in names}


def hierarchy_cases():
    """liver_probe with its finest level replaced by a finer mesh of the same surface."""
    return {
        "liver_probe_15k": {"scenario": SCENARIOS / "liver_probe.yaml", "finest": None},
        "liver_probe_60k": {"scenario": SCENARIOS / "liver_probe.yaml", "finest": 60000},
        "liver_probe_125k": {"scenario": SCENARIOS / "liver_probe.yaml", "finest": 125000},
    }


def finest_mesh(binary, work, tets):
    """A liver level of about `tets` tets, made once by `mrsim mesh` and kept in `work`."""
    prefix = work / "meshes" / ("liver%d" % tets)
    mesh = pathlib.Path(str(prefix) + "_L0.vtu")
    if not mesh.exists():
        prefix.parent.mkdir(parents=True, exist_ok=True)
        surface = SCENARIOS / "meshes" / "liver_surface_cgal_h10_mm.off"
        subprocess.run([str(binary), "mesh", str(surface), "--units", "mm", "--tets", str(tets),
                        "-o", str(prefix), "-q"], check=True)
    return mesh


def absolute_paths(doc, folder):
    """Mesh, skin and trajectory files relative to the original scenario's folder."""
    for level in doc["object"]["levels"]:
        level["mesh"] = str((folder / level["mesh"]).resolve())
    skin = doc["object"].get("skin")
    if isinstance(skin, dict) and "file" in skin:
        skin["file"] = str((folder / skin["file"]).resolve())
    tools = doc.get("tools", [doc["tool"]] if "tool" in doc else [])
    for tool in tools:
        trajectory = tool.get("trajectory")
        if isinstance(trajectory, dict) and "csv" in trajectory:
            trajectory["csv"] = str((folder / trajectory["csv"]).resolve())


def prepare(binary, work, name, case, duration):
    """The case's scenario without time.substeps, paths made absolute, written to `work`."""
    doc = yaml.safe_load(case["scenario"].read_text())
    absolute_paths(doc, case["scenario"].parent)
    doc["time"].pop("substeps", None)
    if case["finest"]:
        doc["object"]["levels"][-1]["mesh"] = str(finest_mesh(binary, work, case["finest"]))
    if duration:
        doc["time"]["duration"] = min(float(doc["time"].get("duration", 1.0)), duration)
    path = work / (name + ".yaml")
    path.write_text(yaml.safe_dump(doc, sort_keys=False))
    return path, float(doc["time"].get("frame_dt", 0.04))


def settings(integrator, psi, time_levels):
    s = ["time.integrator=" + integrator, "adaptivity.time.enabled=" + str(time_levels).lower(),
         "output.vtk=false"]
    if psi is not None:
        s.append("material.damping.psi=%r" % psi)
    return s


EXTRA_SETS = []  # --set: overrides for every run, before each row's own


def mrsim(binary, command, scenario, sets, out=None, keep=False):
    args = [str(binary), command, str(scenario)]
    if out is not None:
        args += ["-o", str(out), "--quiet"]
    for s in EXTRA_SETS + sets:
        args += ["--set", s]
    t0 = time.time()
    r = subprocess.run(args, capture_output=True, text=True)
    if out is not None and pathlib.Path(out).exists() and not keep:
        shutil.rmtree(out)
    return r, time.time() - t0


def energies(out):
    """(kinetic, elastic) energy of every frame."""
    import h5py
    with h5py.File(pathlib.Path(out) / "log.h5", "r") as h5:
        return h5["/frames/kinetic_energy"][:], h5["/frames/elastic_energy"][:]


def grew(run, reference):
    """An instability shows as growth: the kinetic energy above 10 times the reference's peak,
    or the elastic energy above twice its peak. Kinetic alone hides the damping-limited
    instability of stoermer_verlet, whose full-step velocity is the half-step one times
    (1 - dt gamma / 2), about 0 where dt gamma = 2: the growing mode shows in the displacements.
    Growth, not the distance to the reference: a coarser step shifts the phase of a vibration
    (and the semi-implicit filter damps it more), which is accuracy, not stability."""
    (k, e), (k_ref, e_ref) = run, reference
    return bool(k.max() > 10 * k_ref.max() + 1e-12 or e.max() > 2 * e_ref.max() + 1e-12)


def runs(binary, scenario, sets, out, reference):
    """True when the run finishes and has not grown against the reference run (the automatic
    one, grew()): an instability that grows slowly over the run has not reached mrsim's
    divergence guard yet, but it shows there. Raises on anything but a divergence (exit 1
    'diverged')."""
    r, _ = mrsim(binary, "run", scenario, sets, out, keep=True)
    try:
        if r.returncode == 0:
            return reference is None or not grew(energies(out), reference)
        if r.returncode == 1 and "diverged" in r.stderr:
            return False
        raise RuntimeError("mrsim run %s %s: exit %d: %s" % (scenario, " ".join(sets),
                                                            r.returncode, r.stderr.strip()[-400:]))
    finally:
        shutil.rmtree(out, ignore_errors=True)


def smallest_stable_substeps(binary, scenario, sets, out, stable, reference):
    """Smallest n with frame_dt / n stable, to 5 %, starting from the computed n. That one need
    not hold over the whole run: where the estimate in force falls below the set-up one (a
    Green-Lagrange body deforming far), the automatic run takes more steps as it goes, so n is
    doubled until it holds (until 2026-12-03 it was taken as stable, which put a soft hanging
    beam's limit at the 29 substeps that diverge)."""
    hi = stable
    while not runs(binary, scenario, sets + ["time.substeps=%d" % hi], out, reference):
        if hi >= 64 * stable:
            raise RuntimeError("%s: no fixed step up to %d substeps holds" % (scenario, hi))
        hi *= 2
    if hi > stable:
        lo = hi // 2  # the last one that did not hold
    else:
        lo = max(1, stable // 2)
        while lo > 1 and runs(binary, scenario, sets + ["time.substeps=%d" % lo], out, reference):
            hi, lo = lo, max(1, lo // 2)
        if lo == 1 and runs(binary, scenario, sets + ["time.substeps=1"], out, reference):
            return 1
    while hi > lo * 1.05 and hi - lo > 1:
        mid = int(round(math.sqrt(lo * hi)))
        mid = min(max(mid, lo + 1), hi - 1)
        if runs(binary, scenario, sets + ["time.substeps=%d" % mid], out, reference):
            hi = mid
        else:
            lo = mid
    return hi


# Few substeps per frame are a coarse measure: n stable and n - 1 not puts the limit anywhere in
# [frame / n, frame / (n - 1)), 33 % wide at n = 4. Below 1 / SUBSTEP_RESOLUTION substeps the
# step is refined by stretching the frame (largest_stable_step()).
SUBSTEP_RESOLUTION = 0.05


def largest_stable_step(binary, scenario, sets, out, frame_dt, n, reference):
    """The largest stable step between frame_dt / n (stable) and frame_dt / (n - 1) (not;
    twice frame_dt for n = 1, doubled while stable), to SUBSTEP_RESOLUTION: n substeps of a
    frame stretched by s (the adaptivity decides at other times; the step is what counts). A
    frame is never stretched beyond the run's duration: a step still stable there is returned
    as it is (a lower bound)."""
    def stable(scale):
        return runs(binary, scenario, sets + ["time.substeps=%d" % n,
                                              "time.frame_dt=%r" % (frame_dt * scale)],
                    out, reference)
    doc = yaml.safe_load(pathlib.Path(scenario).read_text())
    top = float(doc["time"].get("duration", frame_dt)) / frame_dt  # largest stretch
    lo, hi = 1.0, min(n / (n - 1) if n > 1 else 2.0, top)
    if hi <= lo:
        return frame_dt / n
    while n == 1 and hi < min(64, top) and stable(hi):
        lo, hi = hi, min(2 * hi, top)
    if hi == top and stable(hi):
        return frame_dt * hi / n
    while hi > lo * (1 + SUBSTEP_RESOLUTION):
        mid = math.sqrt(lo * hi)
        if stable(mid):
            lo = mid
        else:
            hi = mid
    return frame_dt * lo / n


def largest_stable_courant(binary, scenario, sets, out, reference, top=8.0):
    """Largest time.courant that still runs (every particle's step scaled), to 5 %."""
    lo, hi = 1.0, 2.0
    while hi <= top and runs(binary, scenario, sets + ["time.courant=%r" % hi], out, reference):
        lo, hi = hi, hi * 2
    if hi > top:
        return lo
    while hi > lo * 1.05:
        mid = math.sqrt(lo * hi)
        if runs(binary, scenario, sets + ["time.courant=%.4f" % mid], out, reference):
            lo = mid
        else:
            hi = mid
    return lo


def shifted_limits(binary, scenario, sets, out, frame_dt, shifts, first):
    """Time levels: the largest stable courant on up to `shifts` ladders (frame_dt ×
    2^(j/shifts)), each against the automatic run of its own ladder, which must finish
    (`first`: the scenario's own, (exit status, energies)). Each ladder's limit is above the
    true ratio, so once one is within the band's top the row is known to be within it and the
    other ladders are not run. Returns [(frame_dt, automatic run's exit status, largest
    courant)]."""
    found = []
    for j in range(shifts):
        if found and min(c for _, _, c in found) <= BAND[1]:
            break
        frame = frame_dt * 2 ** (j / shifts)
        shifted = sets + (["time.frame_dt=%r" % frame] if j else [])
        status, reference = first
        if j:
            r, _ = mrsim(binary, "run", scenario, shifted, out, keep=True)
            status, reference = r.returncode, energies(out) if r.returncode == 0 else None
            shutil.rmtree(out, ignore_errors=True)
        limit = largest_stable_courant(
            binary, scenario, shifted + ["adaptivity.time.velocity_change=1.0e+6"], out,
            reference)
        found.append((frame, status, limit))
    return found


def measure(binary, work, name, scenario, frame_dt, integrator, psi, time_levels,
            short_runs=False, shifts=1):
    sets = settings(integrator, psi, time_levels)
    out = work / "run"
    checked, _ = mrsim(binary, "check", scenario, sets)
    if checked.returncode != 0:
        raise RuntimeError("mrsim check %s: %s" % (name, checked.stderr.strip()[-400:]))
    estimate = float(ESTIMATE.search(checked.stderr).group(1))
    substeps = int(COMPUTED.search(checked.stderr).group(1))
    r, seconds = mrsim(binary, "run", scenario, sets, out, keep=True)
    in_force, reference = estimate, None
    if r.returncode == 0:
        import h5py
        with h5py.File(out / "log.h5", "r") as h5:
            in_force = float(min(h5["/frames/stable_step"][:]))
        reference = energies(out)
    shutil.rmtree(out, ignore_errors=True)
    row = {"case": name, "integrator": integrator, "psi": psi, "time_levels": time_levels,
           "substeps": substeps, "estimate": estimate, "in_force": in_force,
           "auto_exit": r.returncode, "auto_seconds": round(seconds, 1)}
    if time_levels and shifts > 1:
        found = shifted_limits(binary, scenario, sets, out, frame_dt, shifts,
                               (r.returncode, reference))
        row["shifts"] = [{"frame_dt": f, "auto_exit": e, "limit_factor": c} for f, e, c in found]
        row["auto_exit"] = max([row["auto_exit"]] + [e for _, e, _ in found], key=abs)
        row["limit_factor"] = min(c for _, _, c in found)
        row["ratio"] = row["limit_factor"]
    elif time_levels:
        fixed = sets + ["adaptivity.time.velocity_change=1.0e+6"]
        row["limit_factor"] = largest_stable_courant(binary, scenario, fixed, out, reference)
        row["ratio"] = row["limit_factor"]
    else:
        fixed = sets + ["time.adapt_substeps=false"]
        n = smallest_stable_substeps(binary, scenario, fixed, out, substeps, reference)
        row["limit_substeps"] = n
        step = frame_dt / n
        if n < 1 / SUBSTEP_RESOLUTION and not short_runs:
            step = largest_stable_step(binary, scenario, fixed, out, frame_dt, n, reference)
            row["limit_step"] = step
        # Against the smallest estimate in force during the run (the configurations that
        # really occurred); against the set-up estimate (every point that may become active,
        # whole stars) as well: how cautious one global step chosen in advance is.
        row["ratio"] = step / in_force
        row["setup_ratio"] = step / estimate
    lo, hi = band(row, short_runs)
    row["band"] = [lo, hi if math.isfinite(hi) else None]
    row["ok"] = r.returncode == 0 and lo <= row["ratio"] <= hi
    return row


def table(rows):
    lines = ["| case | integrator | ψ (Pa·s) | time levels | substeps (auto) | estimate at "
             "set-up (s) | smallest in force (s) | automatic run | true limit | true limit / "
             "estimate in force | band | true limit / set-up estimate |",
             "|---|---|---:|---|---:|---:|---:|---|---|---:|---|---:|"]
    for r in rows:
        limit = ("courant × %.2f" % r["limit_factor"] if r["time_levels"]
                 else "%d substeps" % r["limit_substeps"])
        if "limit_step" in r:
            limit += " (step %.3g s)" % r["limit_step"]
        if len(r.get("shifts", [])) > 1:
            limit += " (ladders: %s)" % " / ".join("%.2f" % x["limit_factor"]
                                                   for x in r["shifts"])
        lo, hi = r["band"]
        lines.append("| %s | %s | %s | %s | %d | %.3g | %.3g | %s | %s | %.2f %s | [%g, %s] | %s |" % (
            r["case"], r["integrator"], "as given" if r["psi"] is None else r["psi"],
            "on" if r["time_levels"] else "off", r["substeps"], r["estimate"], r["in_force"],
            "finished" if r["auto_exit"] == 0 else "**exit %d**" % r["auto_exit"], limit,
            r["ratio"], "✓" if r["ok"] else "✗", lo, "∞" if hi is None else "%g" % hi,
            "%.2f" % r["setup_ratio"] if "setup_ratio" in r else "–"))
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--binary", default=str(ROOT / "build" / "mrsim"))
    ap.add_argument("--work", default=str(ROOT / "build" / "stability"))
    ap.add_argument("--cases", nargs="*", help="case names (default: all)")
    ap.add_argument("--quick", action="store_true", help="the beam cases, short runs")
    ap.add_argument("--duration", type=float, help="cap every run at this simulated time (s)")
    ap.add_argument("--integrators", nargs="*", help="default: %s" % " ".join(INTEGRATORS))
    ap.add_argument("--psi", nargs="*", help="'given' and/or values in Pa.s (default: given 20)")
    ap.add_argument("--time-levels", nargs="*", choices=["off", "on"], help="default: off on")
    ap.add_argument("--table", help="write the markdown table to this file")
    ap.add_argument("--ladder-shifts", type=int, default=LADDER_SHIFTS,
                    help="time levels: measure on up to this many ladders frame_dt x 2^(j/n) "
                         "(the next while the smallest limit is above 2.5) and keep the "
                         "smallest (default %d; --quick: 1)" % LADDER_SHIFTS)
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="a scenario override for every run (repeatable)")
    args = ap.parse_args()
    EXTRA_SETS.extend(args.set)
    binary = pathlib.Path(args.binary).resolve()
    work = pathlib.Path(args.work).resolve()
    work.mkdir(parents=True, exist_ok=True)
    cases = {**bundled_cases(), **hierarchy_cases()}
    integrators, psis, duration = INTEGRATORS, [None, 20.0], args.duration
    if args.quick:
        cases = {n: cases[n] for n in ["beam", "beam_adaptive"]}
        integrators, psis, duration = ["modified_euler", "semi_implicit"], [None], 0.1
        args.ladder_shifts = 1
    if args.integrators:
        integrators = args.integrators
    if args.psi:
        psis = [None if p == "given" else float(p) for p in args.psi]
    modes = [m == "on" for m in (args.time_levels or ["off", "on"])]
    if args.cases:
        unknown = [n for n in args.cases if n not in cases]
        if unknown:
            raise SystemExit("unknown case(s): %s (known: %s)" % (", ".join(unknown),
                                                                   ", ".join(cases)))
        cases = {n: cases[n] for n in args.cases}
    rows = []
    for name, case in cases.items():
        scenario, frame_dt = prepare(binary, work, name, case, duration)
        for integrator in integrators:
            for psi in psis:
                for time_levels in modes:
                    row = measure(binary, work, name, scenario, frame_dt, integrator, psi,
                                  time_levels, args.quick, max(1, args.ladder_shifts))
                    rows.append(row)
                    print(json.dumps(row), flush=True)
    (work / "stability.json").write_text(json.dumps(rows, indent=1))
    text = table(rows)
    if args.table:
        pathlib.Path(args.table).write_text(text)
    print(text)
    bad = [r for r in rows if not r["ok"]]
    print("%d passed, %d failed" % (len(rows) - len(bad), len(bad)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
