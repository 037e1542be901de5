#!/usr/bin/python3
"""The stability test matrix (issue 15 point 3, scripts/stability_matrix.py) in its quick form:
the beam and the adaptive beam, modified Euler and semi-implicit, with and without time levels,
liver_press's explicit row cut at 0.15 s (the finest level comes in ahead of the load),
volume_lambda_5e4's semi-implicit row over its whole run (the deepest Green-Lagrange stiffening),
the adaptive beam's at nu = 0.49 (nearly incompressible), and a soft beam hanging far under
gravity, explicit (the estimate follows the strain).
Every run with a computed step finishes, and the measured true limit lies between 1.0 and 2.5
times mrsim's estimate for one global step, explicit or semi-implicit (1.0 and 5.0 with time
levels on one ladder of power-of-two steps; 1.0 and 4.0 for a global semi-implicit step in
these short runs, where the body has not deformed enough to need the estimate's Green-Lagrange
allowance): an optimistic estimate (a step that blows up) or a uselessly cautious one fails
here. The finer measures of the whole matrix are checked on one row each: time levels on
shifted ladders (liver_press), the step refined below 20 substeps (liver_thesis). The whole matrix (every bundled scenario, liver hierarchies
up to 125k tets, ψ up to 20) is run by hand; its table is in docs/stability_matrix.md."""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_cli_run import check, parse_args, report  # noqa: E402


def check_one_row(script, binary, case, integrator, extra, what):
    """One row of the matrix (psi as given, no time levels): the computed step runs and the true
    limit lies within [1, 2.5] of the estimate in force."""
    with tempfile.TemporaryDirectory() as work:
        r = subprocess.run(["/usr/bin/python3", script, "--binary", binary, "--work", work,
                            "--cases", case, "--integrators", integrator, "--psi", "given",
                            "--time-levels", "off"] + extra,
                           capture_output=True, text=True, timeout=900)
        path = os.path.join(work, "stability.json")
        rows = json.load(open(path)) if os.path.exists(path) else []
    check(len(rows) == 1 and rows[0]["auto_exit"] == 0 and 1.0 <= rows[0]["ratio"] <= 2.5,
          "%s: true limit / estimate in force in [1, 2.5]: %s"
          % (what, rows[0]["ratio"] if rows else (r.stdout + r.stderr)[-600:]))


def main():
    args = parse_args()
    if args is None:
        return 77
    script = os.path.join(args.source, "scripts", "stability_matrix.py")
    with tempfile.TemporaryDirectory() as work:
        r = subprocess.run(["/usr/bin/python3", script, "--binary", args.binary, "--work", work,
                            "--quick"], capture_output=True, text=True, timeout=1200)
        check(r.returncode == 0, "the quick matrix passes (exit %d): %s"
              % (r.returncode, (r.stdout + r.stderr).strip()[-600:]))
        path = os.path.join(work, "stability.json")
        rows = json.load(open(path)) if os.path.exists(path) else []
    check(len(rows) == 8, "2 cases x 2 integrators x time levels off/on: %d rows" % len(rows))
    for row in rows:
        what = "%s %s time levels %s" % (row["case"], row["integrator"],
                                         "on" if row["time_levels"] else "off")
        check(row["auto_exit"] == 0, what + ": the computed step runs")
        lo, hi = row["band"]
        check(lo >= 1.0 and lo <= row["ratio"] <= (hi or float("inf")),
              what + ": true limit / estimate %.2f in [%g, %s]" % (row["ratio"], lo, hi))
        if not row["time_levels"] and row["integrator"] == "modified_euler":
            check(row["ratio"] <= 2.5, what + ": one global explicit step, within 2.5")
    # liver_press refines ahead of its load (adaptivity.space.predict): while the finest level
    # comes in, light fine points at the fringe of the refined region receive what coarse
    # ghosts pass on. Shared by the masses that receive it, the estimate in force stays within
    # the band (with the weights alone it fell to 0.149 ms at t = 0.08 s: 2.7 times below the
    # true limit; docs/integrators.md "The stable step").
    check_one_row(script, args.binary, "liver_press", "modified_euler", ["--duration", "0.15"],
                  "liver_press cut at 0.15 s, one global explicit step")
    # A deep indentation stiffens Green-Lagrange far beyond the semi-implicit estimate's set-up
    # allowance (tangent growth up to 1.2 under the probe at lambda = 5e4): the estimate follows
    # the strain (physics/tangent_growth.hpp). With the fixed allowance this whole run was
    # 0.94, optimistic.
    check_one_row(script, args.binary, "volume_lambda_5e4", "semi_implicit", [],
                  "volume_lambda_5e4 whole run, one global semi-implicit step")
    # Nearly incompressible (nu = 0.49), Green-Lagrange: the filter's J_i is the rest tangent's
    # diagonal block, the one the estimate counts. The thesis' finite one-sided probe of it
    # left more explicit than that: this run diverged at its computed step at t = 0.1 s
    # (time/semi_implicit_filter.hpp); now 1.33.
    check_one_row(script, args.binary, "beam_adaptive", "semi_implicit",
                  ["--set", "material.poisson_ratio=0.49"],
                  "beam_adaptive at nu = 0.49 whole run, one global semi-implicit step")
    # A soft Green-Lagrange beam hanging under gravity (E = 15 kPa, 3100 kg/m3) stretches far
    # (tangent growth about 8): the explicit estimate follows the growth its spectral margin
    # does not cover (physics/spectral_bound.hpp explicit_stiffening()). Without it the computed
    # step diverged at t = 0.14 s (0.76 of the true limit); now 1.91. Its computed 29 substeps
    # do not hold over the run at a fixed step: the limit is searched upwards from there.
    check_one_row(script, args.binary, "beam", "stoermer_verlet",
                  ["--set", "material.youngs_modulus=1.5e+4", "--set", "material.density=3100",
                   "--set", "material.damping.phi=2", "--set", "material.damping.psi=5"],
                  "a soft hanging beam, one global explicit step")
    # Issue 16 point 4: in the adaptive hierarchy the semi-implicit step stays at least twice
    # the explicit one (the interface mass keeps the filter's margin).
    limit = {(r["case"], r["integrator"]): r["limit_substeps"] for r in rows
             if not r["time_levels"]}
    explicit = limit.get(("beam_adaptive", "modified_euler"))
    semi = limit.get(("beam_adaptive", "semi_implicit"))
    check(explicit is not None and semi is not None and 2 * semi <= explicit,
          "beam_adaptive: semi_implicit runs at %s substeps, modified_euler needs %s (>= 2x)"
          % (semi, explicit))
    check_shifted_ladders(script, args.binary)
    check_refined_step(script, args.binary)
    return report()


def check_shifted_ladders(script, binary):
    """With time levels each particle's step is a power-of-two division of the frame, so one
    ladder measures the limit only within a factor 2 above the true ratio. Ladders are added
    while the smallest limit is above 2.5 (each one is above the true ratio), and the smallest
    is kept, against [1, 2.5]. liver_thesis at psi = 20, semi-implicit with time levels, whole
    run: 2.83 / 2.48 on the first two ladders (frames of 20 x 2^(k/4) ms), within the band since
    each point counts its own share of what the filter leaves explicit (2026-12-03; with the
    thesis' quarter 2.83 on all four, out of it on the cautious side: docs/stability_matrix.md).
    liver_press, which this check ran before, is within the band on its own ladder."""
    with tempfile.TemporaryDirectory() as work:
        subprocess.run(["/usr/bin/python3", script, "--binary", binary, "--work", work,
                        "--cases", "liver_thesis", "--integrators", "semi_implicit", "--psi",
                        "20", "--time-levels", "on", "--ladder-shifts", "4"],
                       capture_output=True, text=True, timeout=900)
        path = os.path.join(work, "stability.json")
        rows = json.load(open(path)) if os.path.exists(path) else []
    shifts = rows[0].get("shifts", []) if len(rows) == 1 else []
    check(len(shifts) >= 2, "more than the scenario's own ladder measured: %s" % shifts)
    if not shifts:
        return
    row, limits = rows[0], [x["limit_factor"] for x in shifts]
    check(all(abs(x["frame_dt"] - 0.02 * 2 ** (k / 4)) < 1e-12 and x["auto_exit"] == 0
              for k, x in enumerate(shifts)),
          "ladder k has frames of 20 x 2^(k/4) ms and its automatic run finishes: %s" % shifts)
    check(all(c > 2.5 for c in limits[:-1]) and (limits[-1] <= 2.5 or len(limits) == 4),
          "a ladder is added only while every limit so far is above 2.5: %s" % limits)
    check(row["limit_factor"] == min(limits) and row["band"] == [1.0, 2.5]
          and row["ok"] == (1.0 <= min(limits) <= 2.5),
          "the smallest limit, judged against [1, 2.5]: %s %s %s" % (row["limit_factor"],
                                                                    row["band"], row["ok"]))
    check(row["ok"], "liver_thesis at psi = 20, semi-implicit with time levels, within [1, 2.5]: "
          "%s (physics/patch_spectrum.hpp)" % limits)


def check_refined_step(script, binary):
    """Few substeps per frame are a coarse measure: liver_thesis' semi-implicit whole run holds 4
    substeps of its 20 ms frames and not 3, which puts its limit anywhere in 5.0-6.7 ms. Below 20
    substeps the step is refined by stretching the frame (the substeps kept), to 5 %."""
    with tempfile.TemporaryDirectory() as work:
        subprocess.run(["/usr/bin/python3", script, "--binary", binary, "--work", work,
                        "--cases", "liver_thesis", "--integrators", "semi_implicit", "--psi",
                        "given", "--time-levels", "off"],
                       capture_output=True, text=True, timeout=900)
        path = os.path.join(work, "stability.json")
        rows = json.load(open(path)) if os.path.exists(path) else []
    row = rows[0] if len(rows) == 1 else {}
    n, step = row.get("limit_substeps", 0), row.get("limit_step")
    check(0 < n < 20 and step is not None and 0.02 / n <= step < 0.02 / max(n - 1, 0.5),
          "refined between frame / n and frame / (n - 1): %s substeps, step %s" % (n, step))
    check(step is not None and abs(row["ratio"] - step / row["in_force"]) < 1e-12
          and row["auto_exit"] == 0 and row["ratio"] >= 1.0,
          "the refined step over the estimate in force, not optimistic: %s" % row.get("ratio"))
    # Cut at 0.1 s, a frame is never stretched beyond the run (an input error before).
    with tempfile.TemporaryDirectory() as work:
        r = subprocess.run(["/usr/bin/python3", script, "--binary", binary, "--work", work,
                            "--cases", "liver_thesis", "--integrators", "semi_implicit",
                            "--psi", "given", "--time-levels", "off", "--duration", "0.1"],
                           capture_output=True, text=True, timeout=900)
        path = os.path.join(work, "stability.json")
        rows = json.load(open(path)) if os.path.exists(path) else []
    step = rows[0].get("limit_step", 0.02 / rows[0]["limit_substeps"]) if len(rows) == 1 else 0
    check(0.02 / max(rows[0]["limit_substeps"], 1) <= step <= 0.1 + 1e-12 if rows else False,
          "a short run's refined step stays within its duration: %s (%s)"
          % (step, (r.stdout + r.stderr).strip()[-300:] if not rows else "ok"))


if __name__ == "__main__":
    sys.exit(main())
