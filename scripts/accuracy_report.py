#!/usr/bin/env python3
"""Writes docs/ACCURACY.md: work-precision tables and diagrams of the paper scene and the hard
cases, the trust fields against the true error (presets and random scenes), what the check costs,
the differential tests at scale, long runs, and the limits of the extremes.

Usage: python3 scripts/accuracy_report.py [--vibro build/vibro] [--scan N] [--trust-scan N]
  --scan N        random scenes for the differential scan (build/tests/differential/differential_scan)
  --trust-scan N  random scenes for the trust scan (build/tests/differential/trust_scan)
Every number in the page comes from this script's runs of `vibro` and of those two programs.
"""
import argparse
import json
import math
import os
import platform
import re
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ARGS = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ARGS.add_argument("--vibro", default=os.path.join(ROOT, "build", "vibro"))
ARGS.add_argument("--scan", type=int, default=100000)
ARGS.add_argument("--trust-scan", type=int, default=1000)
OPTIONS = ARGS.parse_args()
VIBRO = OPTIONS.vibro
DIFFERENTIAL = os.path.join(ROOT, "build", "tests", "differential")
IMAGES = os.path.join(ROOT, "docs", "images")
METHODS = ["dopri5", "dop853", "radau5", "taylor", "auto"]
DIAGRAMS = ["paper", "frictionless-elastic", "stiff-friction", "chatter"]
SWEPT = ["paper", "frictionless-elastic", "chatter", "stiff-friction", "tiny-radius",
         "high-frequency", "mass-ratio", "grazing", "loop", "plastic-limiter", "rest-in-cone"]


def run(args, stdin=None):
    out = subprocess.run([VIBRO] + args, input=stdin, capture_output=True, text=True, timeout=600)
    return out.returncode, out.stdout, out.stderr


def preset(name):
    return json.loads(run(["preset", name])[1])


def fmt(x, digits=2):
    if x is None:
        return "—"
    if x == 0:
        return "0"
    return f"{x:.{digits}e}"


def work_precision(name):
    args = ["work-precision", "--preset", name, "--repeats", "3"]
    if name not in DIAGRAMS:
        code, out, err = run(args)
        if code != 0:
            raise SystemExit(f"work-precision {name} failed: {err}")
        return json.loads(out)
    # The diagram and the table from one timing.
    table = os.path.join(IMAGES, f".wp-{name}.json")
    code, out, err = run(args + ["-o", os.path.join(IMAGES, f"wp-{name}.png"), "-o", table])
    if code != 0:
        raise SystemExit(f"work-precision {name} failed: {err}")
    with open(table) as f:
        report = json.load(f)
    os.remove(table)
    return report


def wp_table(report):
    rows = {}
    for p in report["points"]:
        rows.setdefault(p["rtol"], {})[p["method"]] = p
    lines = ["| rtol | " + " | ".join(f"{m}: error / ms" for m in METHODS) + " |",
             "|---|" + "---|" * len(METHODS)]
    for rtol in sorted(rows, reverse=True):
        cells = []
        for m in METHODS:
            p = rows[rtol].get(m)
            if not p:
                cells.append("—")
                continue
            mark = "" if p["events_match"] else " ‡"
            cells.append(f"{fmt(p['error'])} / {p['median_ms']:.2f}{mark}")
        lines.append(f"| {rtol:.0e} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def estimate_table(reports):
    lines = ["| scene | reference | rtol | true error | estimate | ratio |", "|---|---|---|---|---|---|"]
    for name, report in reports.items():
        for p in report["points"]:
            if p["method"] != "auto" or p["rtol"] not in (1e-4, 1e-8, 1e-12):
                continue
            ratio = p["estimate"] / p["error"] if p["error"] and p["estimate"] else None
            lines.append(f"| {name} | {report['error_reference']} | {p['rtol']:.0e} | {fmt(p['error'])} | "
                         f"{fmt(p['estimate'])} | {fmt(ratio, 1) if ratio else '—'} |")
    return "\n".join(lines)


def best_methods(reports):
    lines = ["| scene | cheapest method reaching error ≤ 1e-6 | cheapest reaching ≤ 1e-9 |", "|---|---|---|"]
    for name, report in reports.items():
        cells = []
        for target in (1e-6, 1e-9):
            ok = [p for p in report["points"] if p["error"] is not None and p["error"] <= target and p["completed"]]
            if not ok:
                cells.append("none")
                continue
            best = min(ok, key=lambda p: p["median_ms"])
            auto = min((p for p in ok if p["method"] == "auto"), key=lambda p: p["median_ms"], default=None)
            ratio = f", auto {auto['median_ms'] / best['median_ms']:.2f}×" if auto else ", auto never"
            cells.append(f"{best['method']} ({best['median_ms']:.2f} ms{ratio})")
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def simulate(scene, extra=()):
    code, out, err = run(["simulate", "-", *extra], stdin=json.dumps(scene))
    if code == 2:
        return {"error": json.loads(err)}
    return json.loads(out)


def preset_run(name, extra=()):
    code, out, err = run(["simulate", "--preset", name, *extra])
    if code != 0:
        raise SystemExit(f"simulate {name} failed: {err}")
    return json.loads(out)


def trust_presets():
    """The event-time estimate of `auto` against the true error, per preset and tolerance."""
    lines = ["| scene | rtol | events | trusted until / t_end | estimate (s) | true error (s) | ratio |",
             "|---|---|---:|---|---:|---:|---:|"]
    for name in SWEPT:
        ref = preset_run(name, ["--method", "dop853", "--rtol", "1e-13", "--atol", "1e-15", "--no-check"])
        confirm = preset_run(name, ["--method", "dopri5", "--rtol", "1e-13", "--atol", "1e-15", "--no-check"])
        key = lambda e: (e["kind"], tuple(e["pellets"]), e.get("limiter"))
        ref_until = ref["stats"]["t_reached"]
        for a, b in zip(ref["events"], confirm["events"]):
            if key(a) != key(b):
                ref_until = min(a["t"], b["t"])
                break
        for rtol in (1e-6, 1e-8, 1e-10):
            r = preset_run(name, ["--rtol", str(rtol), "--atol", str(rtol * 1e-3)])
            st = r["stats"]
            window = min(st["trusted_until"], ref_until)
            truth, count = 0.0, 0
            for e, f in zip(r["events"], ref["events"]):
                if e["t"] >= window and f["t"] >= window:
                    break
                if key(e) != key(f):
                    truth = None
                    break
                truth = max(truth, abs(e["t"] - f["t"]))
                count += 1
            ratio = "—" if not truth else f"{st['event_time_error'] / truth:.2g}"
            shown = "missed" if truth is None else fmt(truth)
            lines.append(f"| {name} | {rtol:.0e} | {count} | {st['trusted_until']:.4g} / {st['t_reached']:.4g} | "
                         f"{fmt(st['event_time_error'])} | {shown} | {ratio} |")
    return "\n".join(lines)


def check_cost():
    """Median wall time of each preset's default run without and with the trust check."""
    lines = ["| preset | events | without (ms) | with (ms) | with / without |", "|---|---:|---:|---:|---:|"]
    ratios = []
    for name in SWEPT:
        alone, both, events = [], [], 0
        for _ in range(5):
            st = preset_run(name)["stats"]
            alone.append(st["wall_ms"] - st["check_wall_ms"])
            both.append(st["wall_ms"])
            events = st["events"]
        a, b = statistics.median(alone), statistics.median(both)
        ratios.append(b / a)
        lines.append(f"| {name} | {events} | {a:.2f} | {b:.2f} | {b / a:.2f} |")
    lines.append(f"\nMedian {statistics.median(ratios):.2f}×, largest {max(ratios):.2f}×.")
    return "\n".join(lines)


def tool(name, args):
    path = os.path.join(DIFFERENTIAL, name)
    out = subprocess.run([path] + args, capture_output=True, text=True)
    if out.returncode != 0:
        raise SystemExit(f"{name} failed: {out.stderr}")
    return out.stdout


def scan_summary(text):
    """The scan's counts and percentiles, and of its signatures only the unexplained ones (a bug);
    the ill-conditioned classes are listed by the command itself."""
    lines = []
    for line in text.strip().splitlines():
        if line.startswith("by signature"):
            lines.append("unexplained signatures (scenes, first scene); the ill-conditioned ones are omitted:")
        elif not re.match(r"\s+\d+\s", line) or "unexplained" in line:
            lines.append(line)
    return "\n".join(lines)


def long_runs():
    scene = {"model": {"R": 0.5, "alpha0": 0.05,
                       "pellets": [{"m": 0.2, "phi0": 0.0, "dphi0": 2.0, "F0": 1.2, "Omega": 3.3}],
                       "limiters": [{"angle": 0.35, "k": 0.6}, {"angle": -0.35, "k": 0.6}]},
             "t_end": 1000.0}
    lines = ["| rtol | events | limiter impacts | steps | wall ms | error estimate |", "|---|---|---|---|---|---|"]
    for rtol in (1e-6, 1e-8, 1e-10, 1e-12):
        r = simulate(scene, ["--rtol", str(rtol), "--atol", str(rtol * 1e-2)])
        s = r["stats"]
        lines.append(f"| {rtol:.0e} | {s['events']} | {r['summary']['limiter_impacts']} | {s['steps']} | "
                     f"{s['wall_ms']:.1f} | {fmt(s['error_estimate'])} |")
    return json.dumps(scene), "\n".join(lines)


def one_pellet(R=0.5, alpha0=0.05, dphi0=5.0, F0=0.0, Omega=0.0, m=0.2, limiters=None):
    return {"model": {"R": R, "alpha0": alpha0,
                      "pellets": [{"m": m, "phi0": 0.0, "dphi0": dphi0, "F0": F0, "Omega": Omega}],
                      "limiters": limiters if limiters is not None else [{"angle": 0.6, "k": 0.7}, {"angle": -0.6, "k": 0.7}]},
            "t_end": 2.0}


def extremes():
    cases = []
    for R in (1e-3, 1e-4, 1e-5, 1e-6):
        cases.append((f"R = {R:g} m", one_pellet(R=R, dphi0=5.0 / math.sqrt(R / 0.5))))
    for a in (1.0, 1.3, 1.5):
        cases.append((f"alpha0 = {a}", one_pellet(alpha0=a, dphi0=200.0)))
    for v in (1e3, 1e4, 1e5):
        cases.append((f"dphi0 = {v:g} rad/s (no limiters)", one_pellet(dphi0=v, limiters=[])))
        cases.append((f"dphi0 = {v:g} rad/s (limiters ±0.6)", one_pellet(dphi0=v)))
    for ratio in (1e4, 1e6, 1e8):
        sc = one_pellet()
        sc["model"]["pellets"] = [{"m": 1.0, "phi0": -0.3, "dphi0": 3.0},
                                  {"m": 1.0 / ratio, "phi0": 0.2, "dphi0": 0.0}]
        sc["model"]["limiters"] = [{"angle": 0.5, "k": 0.9}, {"angle": -1.0, "k": 0.9}]
        cases.append((f"mass ratio {ratio:g}", sc))
    for Om in (1e3, 1e4, 1e5, 1e6):
        sc = one_pellet(dphi0=0.0, F0=20.0, Omega=Om)
        sc["t_end"] = 0.5
        cases.append((f"Omega = {Om:g} rad/s, F0 = 20 N", sc))
    lines = ["| case | outcome | events | steps | wall ms | error estimate |", "|---|---|---|---|---|---|"]
    for label, scene in cases:
        r = simulate(scene, ["--deadline-ms", "60000"])
        if "error" in r:
            lines.append(f"| {label} | refused: `{r['error']['field']}` {r['error']['error']} | | | | |")
            continue
        s = r["stats"]
        outcome = s["termination"] + (f": {s['message']}" if s.get("message") else "")
        lines.append(f"| {label} | {outcome} | {s['events']} | {s['steps']} | {s['wall_ms']:.1f} | "
                     f"{fmt(s['error_estimate'])} |")
    return "\n".join(lines)


TRUST_TEXT = """\
Every run is checked against a *shadow*: the same scene at a hundredth of both tolerances, with
its longest step halved, and with another method where one method errs alike at any tolerance.
Taylor checks DOPRI5, DOP853 and itself, `auto` (explicit unless the scene is stiff) checks
Radau IIA, and `auto` is checked by `auto` on DOP853. Why each choice:

- **Another method for Radau IIA**: checked by itself it agreed with itself through a cascade of
  collisions where the explicit methods put an impact 1 ms away.
- **Taylor for DOP853**: a flight cut short by events, shorter than the run's and the shadow's
  steps, is one DOP853 step of the flight's length at any tolerance, and errs alike in both. On a
  light pellet's elastic ping-pong between a stop and a heavy pellet (ctest
  `trust_scene.dop853_shared_its_short_flights_error`), which amplifies a few ulps of an angle at
  t = 0.5 s 1e5 times, DOP853 erred 4.5e-10 s at rtol 1e-9 and 4.6e-10 s at 1e-11 (and
  2e-10 to 1e-9 s down to 1e-13), and its own shadow's estimate was 35 times short. A Taylor
  flight is one step of a series whose length follows the tolerance (Taylor at 1e-11 erred
  5e-12 s there).
- **Taylor for DOPRI5**: DOP853's error on such flights is the same at any tolerance, so as
  DOPRI5's shadow it erred as much as the run there: DOPRI5 at rtol 1e-11 and 1e-13 erred
  1.05e-9 and 4.5e-10 s on that scene and DOP853 estimated 0.48 and 0.29 of it (ctest
  `Trust.Dopri5CheckedByDop853SharedItsShortFlightsFloor`); Taylor, 1.00. Over `trust_scan`
  seeds 1–4 the worst DOPRI5 estimate went from 0.69 to 0.98 of its true error, at a median
  check cost of 1.6–2.7× where a DOP853 shadow cost 2.0–3.1×.
- **A hundredth of the tolerance**: the shadow must be well ahead of the run whatever luck the
  run has (at a tenth Radau IIA's shadow erred as much as the run on a chaotic scene, at a
  thirtieth DOP853's shared a lucky run's error). A tolerance divided by `q` costs `q^(1/(p+1))`
  times the steps of a method of order p (1.67× for DOP853), events cost the same in both, and the
  estimate errs by a few percent where the error constants are alike.
- **The longest step halved**: steps capped by the swing or the forcing (no step spans more than a
  radian of either) are the same at any tolerance, so a shadow capped alike shares them and their
  error. Halved, a capped step of DOP853 errs 2⁹ times less (2⁶ for DOPRI5).

The two event lists are compared instant by instant: the collisions of one instant as one
collision of all the pellets they involve, the impacts on one limiter as one (how a cascade is
listed depends on which gaps its instant found closed; its outcome does not):

- `stats.event_time_error` is the largest time difference of the events listed alike (kind,
  pellets, limiter; the shadow's time less what its start moved it, below), and never below the
  errors the two runs share and the shadow cannot see: the round-off of event times
  (`1e3·ε·(T0 + t)`, `T0 = sqrt(R/g)`, or `100·ε·(1 + |φ|)` over an impact's approach speed, or
  the start's round-off as a chain amplifies it, below), a summed chatter's own error (`1e-8·T0`,
  docs/MODEL.md), and a hundredth of what the tolerance asks, `1e-2·rtol·(T0 + t)` (a run and its
  shadow of one method that agree far better than asked may share a bias);
- `stats.state_error` is the largest difference of the final states (φ, and φ̇ times `T0`);
- `stats.trusted_until` ends before the two first list different events; where the times of an
  event differ by more than a tenth of the time to its neighbours and more than
  `1e3·rtol·(T0 + t)` (sensitive dynamics amplified them); where the two put an event and the one
  before it apart by times that differ by more than a tenth (their order is not resolved); or
  where the shadow stopped. It ends ten times the event-time error before the earlier of the two
  events (the true sequence may part earlier than either run), but not before the last event both
  list alike less ten times the event-time error. A `not_trusted` warning names both events.
- A *sensitive turn* ends `stats.trusted_until` ten times the event-time error before a
  collision both list alike that leaves a pellet at a speed within ten times the run's and the
  shadow's difference of zero (and that difference above `1e3·ε` of the largest speed the instant meets
  or leaves, its round-off): whether the pellet turns soon after, or not at all, follows the sign
  of that speed, which the tolerance does not resolve. DOP853 at rtol 1e-9 and its shadow left a
  pellet at −1.8e-4 and −8.3e-5 rad/s and listed no turn; every reference left it at +7.6e-5 to
  +3.4e-4 rad/s and turned it 2.6e-7 s later (trust_scan seed 7, scene 534). An impact on a
  limiter does not count: the limiter sets the sign of the speed it leaves, and the times of the
  events after it measure that speed's error. The warning names the pellet and both speeds.
- A *near miss* ends `stats.trusted_until` too, where the shadow is blind to it: a body's speed, a
  gap or the way to a limiter that comes within ten times its tolerance's error of zero and turns
  away, or strikes so slowly that it would have turned within that error past it (docs/MODEL.md).
  So does a *near-simultaneous impact*: a pellet that two impacts close on at one instant, whose
  order (and with it their outcome) is decided below the contact radius.

Why this mechanism: the shadow's error is several times smaller than the run's, so the difference
estimates the run's error through impacts, sticking and chatter, and sees a sequence that changes
(a grazing impact, a stick test at its threshold), which no propagation of errors along one path
can. Where a single shadow is blind, the variational equations with saltation (the machinery of
the Floquet multipliers, docs/ORBITS.md) see along its path at a small cost: the shadow starts
64 ulps ahead (its speeds, and the angles of the pellets that move), so that the two never round
alike, and `instant_shifts` (core/analysis/monodromy.h) says how far that start, and a few ulps of
every angle, move each instant (within a few percent of central differences of plain runs). A
chain that amplifies errors amplifies the shadow's start as it amplifies the run's own error, so
each shadow time is taken as it is and less its start's shift; and where nothing moves, the
estimate is never below the start's round-off as the chain amplifies it. Where every pellet
starts at rest the shadow starts where the run does: a pellet may rest where its force balances
gravity to round-off, and a few ulps on it turns at once. Where the shadow's path holds pellets moving
together (which the saltations do not cover), and past its first 20,000 instants, the shadow is
taken as it is. The remaining blind spot is an error the run and its shadow share there: the
same method's bias on an ill-conditioned decision; the differential tests below count how often
that happens. `"solver": {"check": false}` turns the check off: the trust fields then come from
the consistency checks alone and `stats.check` is false."""


DIFFERENTIAL_TEXT = """\
`tests/differential/` generates random scenes over the whole space a user can reach (1–4 pellets,
both friction laws, forced and unforced with Ω from 0.1 to 1e4 rad/s, at rest inside and outside
the friction cone or moving, pellets touching, limiters fixed and mobile and acting on some
pellets, k and k_c from 0 to 1, R from 1e-3 to 10 m) with RapidCheck, and checks three properties:
(a) every method at rtol 1e-11 and 1e-12 lists the same events at times within
`1e3·rtol·(T0 + t)` (looser by `v/w` for an impact at approach speed `w` below the speed scale
`v = 1/T0`); (b) each method at rtol 1e-9 and 1e-10 lists the same events as at a tenth of it;
(c) every run keeps the physics (momentum and restitution at every impact, the energy balance and
first integral, pellets never passing each other or a fixed limiter that acts on them, resting
pellets at their limiter's angle, events in order within the run). A mismatch is classified by
the conditioning of the events involved (`conditioning.h`): a grazing impact, a stick test at its
threshold, a tangent release, near-simultaneous events and differences amplified by such an earlier
event are ill-conditioned; what no conditioning explains is a bug.

An independent reference simulator (`tests/reference/vibro_ref.py`, Python and SciPy, written from
MODEL.md alone without reading the engine) checks the engine on the presets and random scenes.
Every scene either found wrong is kept, named for what went wrong, in a regression corpus
(`tests/differential/corpus/`, `tests/reference/corpus/`, run under every method by `corpus_test`
and `reference_corpus_test`). The rules of the engine that those scenes hold in place, most of them
stated in docs/MODEL.md:

- an event's root is corrected on a precise state (one step of the method from the step's start:
  a dense output is of lower order than the step), by the root of the watch's quadratic there;
- watches of the motion are followed between samples (a quadratic prediction from their rates),
  so that collisions and turns that come and go inside one step are found; watches starting on
  their root are deflated; release and separation are scanned by steps their bounds prove safe;
- an interval keeps one side of the normal force's zero, so its equations stay smooth; no step
  spans more than a radian of a swing or a forcing; after a rejection the error estimate is no
  lower than the error model predicts from it;
- an angle is held to rtol times its distance from the bottom (φ mod 2π), never closer than ten
  ulps of φ, and one angle scale serves every pellet of a state;
- at an instant: a limiter contact goes to the pellet that meets it, on the side it lies on, and
  the frontmost pellet touching on that side; pellets across a limiter never touch; pellets on the
  angle of a limiter that holds them stay put when others meet them; pellets that would part by
  less than the gap's round-off move on together; impacts below round-off speed are resting
  contacts; a sliding pellet at zero speed within v_eps at another's reversal, not going on its
  way, reverses there too;
- a chatter series is summed exactly when r < 1, a body's as a lone pellet's with the fraction of
  its speed its cascade returns; chatter past t_end is listed at t_end.

The trust check is judged by `trust_scan` (a scene generator's runs under every method at
rtol 1e-6 … 1e-10 against a reference and its alternates, as in the table above). Over seeds 1–32
(31,998 scenes × 20 runs, the Taylor method not among them: `build/tests/differential/trust_scan
--count 1000 --seed S --jobs 2 --out runs-S.csv --dump DIR` for S = 1…32, which writes each
flagged scene as scene JSON, pooled by `python3 scripts/trust_summary.py runs-*.csv`;
`trust_scan --seed S --show I:METHOD:RTOL` prints one run beside its shadow, the reference and its
alternates, event by event): no estimate fell more than ten times short of a true error above 1 %
of what the tolerance asks, no run vouched for events that the references list otherwise, 98.58 %
of the runs were trusted to their end, and the median estimate / true error was 2.91 (DOP853 at
rtol 1e-6 over-estimates by a median 77×, held up by the floor of a hundredth of what the
tolerance asks). 6,471 runs had a true error within their trust above what their tolerance asks.
The check costs a median 2.09× the bare run for DOP853, 2.79× for `auto`, 2.03× for DOPRI5, 1.29×
for Radau IIA (two scenes at a time on two cores).

The scan counts a true error net of the spread of the reference's alternates, each as valid as
the reference: DOPRI5 at rtol 1e-13, and DOP853 with the moving pellets, then every pellet, an ulp
on. An error below that spread is not known: a chain of a thousand collisions 4e-5 s apart walks
its round-off to 1.3e-7 s from the reference, where DOPRI5 stays within 1.7e-8 s.

Not landed, with the scan's reasons: a shadow perturbed by as much as the run's error (8 or 256
ulps ahead, 64 behind, a thousandth of the tolerance ahead) moved the coincidence elsewhere or
cost runs their trust; moving the forcing's phase or the resting pellets' angles in the shadow
broke equilibria and stick decisions, even where every pellet rests (over seeds 1–4, 4 ulps of
their angles took 50 of those scenes' 7,400 runs their trust to the end and 64 ulps 300, while
unmoved no estimate of theirs fell below 0.79 of its true error); a shadow of a model perturbed by a tenth of the tolerance
cancelled runs' errors of the same size. The start's shifts move nothing: the shadow's sequence
is the run's, and only the estimate learns what the start does.

Two speed rules were chosen by `trust_scan` over seeds 1–8 (160,000 runs) and hold no wrong event
vouched for. *Calm steps*: a watch that stays farther from its root, at both ends of a step, than
it moves in the step is searched at the step's end alone (`CrossingFinder::calm`, `kCalm` = 1 in
core/events/crossing_finder.cpp, chosen against references that search inside every step,
`SimOptions::sample_every_step`); every preset lists the same events with and without it
(`EveryPreset.CalmStepsFindTheSameEvents`). *A reversal keeps the step size*: at an instant of
reversals alone the explicit methods go on with the step their controller proposed
(`Stepper::continue_smoothly`); after an impact HINIT's guess still bounds the first step, since
trusting the previous step there raised the runs above what their tolerance asks. What they save
is in docs/PERFORMANCE.md."""


def main():
    os.makedirs(IMAGES, exist_ok=True)
    reports = {name: work_precision(name) for name in SWEPT}
    long_scene, long_table = long_runs()
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
    out = [
        "# Accuracy: error against run time",
        "",
        "Made by `python3 scripts/accuracy_report.py` (after `bash scripts/setup.sh`); every number",
        f"below comes from that run, on {os.cpu_count()} cores of an {cpu} ({platform.system()}).",
        "Times are medians of 3 runs on a shared machine: read them as ratios, not absolutes.",
        "",
        "## What the error numbers mean",
        "",
        "- **The trust fields** (`stats.event_time_error`, `stats.state_error`, `stats.trusted_until`, in",
        "  every result) come from a shadow run of the same scene at a hundredth of the tolerance,",
        "  compared event by event (below, *The trust check*).",
        "- **The consistency checks**: the energy-balance defect `|E(t) − E(0) − W_force − W_friction −",
        "  impact losses|` over the energy scale, and the residual of the exact first integral of MODEL.md",
        "  on unforced paper-law intervals. Both vanish for the exact solution; both are measured at every",
        "  event and at the end. `stats.error_estimate` is the largest of all four in one unit.",
        "- **The true error** of the work-precision sweeps (`vibro work-precision`) is measured against",
        "  what is exact where it applies — the first integral (unforced, paper law), the energy (no",
        "  friction, no forcing) — and otherwise against a reference run with another method at",
        "  rtol 1e-13: the largest of |Δt|/√(R/g) over the events, |Δφ| and √(R/g)|Δφ̇| at the end.",
        "  ‡ marks runs whose events part ways with the reference (their error is over the shared part).",
        "",
        "## Work-precision diagrams",
        "",
    ]
    for name in DIAGRAMS:
        out += [f"`vibro work-precision --preset {name} -o docs/images/wp-{name}.png`", "",
                f"![work-precision, {name}](images/wp-{name}.png)", ""]
    out += ["## Tables", ""]
    for name, report in reports.items():
        out += [f"### {name}", "", f"Error reference: {report['reference']}.", "", wp_table(report), ""]
    out += ["## Which method, and how close `auto` is", "", best_methods(reports), "",
            "## The trust check", "",
            TRUST_TEXT, "",
            "### The estimate against the true error, presets (method auto)", "",
            "The true error is the largest time difference of the events against DOP853 at rtol 1e-13,",
            "over the events both before the run's `trusted_until` and before DOPRI5 at rtol 1e-13 parts",
            "ways with that reference; \"missed\" would mean the run vouched for a wrong event.", "",
            trust_presets(), "",
            "### The estimate against the true error, random scenes", "",
            f"`build/tests/differential/trust_scan --count {OPTIONS.trust_scan} --seed 3 --jobs 2 --taylor 1`: random",
            "scenes of the differential generator (below), every method at rtol 1e-6 … 1e-10, against the",
            "reference and its alternates (DOPRI5 at rtol 1e-13, DOP853 with the moving pellets and with every",
            "pellet an ulp on), the true error net of their spread. *Missed* counts runs that listed another",
            "event than the reference before their own `trusted_until`; *below 1/10* the runs whose estimate fell more than ten times",
            "short of the true error (over runs with a true error above 1e-14 s), and how many of those had a",
            "true error that matters: above 1 % of what the tolerance asks, `rtol·(T0 + t)`.", "",
            tool("trust_scan", ["--count", str(OPTIONS.trust_scan), "--seed", "3", "--jobs", "2", "--taylor", "1"]), "",
            "### What the check costs", "",
            "Each preset's default run (method auto, its own tolerances), median of 5, wall time of the",
            "run alone and with its shadow (`stats.wall_ms`, `stats.check_wall_ms`).", "",
            check_cost(), "",
            "## Differential testing at scale", "",
            DIFFERENTIAL_TEXT, "",
            f"`build/tests/differential/differential_scan --count {OPTIONS.scan} --seed 1 --jobs 2`:",
            "every run compared raw (all its events, trusted or not):", "",
            "```", scan_summary(tool("differential_scan", ["--count", str(OPTIONS.scan), "--seed", "1", "--jobs", "2"])), "```", "",
            f"The same scenes' first {OPTIONS.scan // 10} compared as the CI property tests do, over what",
            "each run vouches for (`--trust`):", "",
            "```", scan_summary(tool("differential_scan", ["--count", str(OPTIONS.scan // 10), "--seed", "1", "--jobs", "2", "--trust"])), "```", "",
            "## A long forced run", "",
            "One forced pellet between two limiters for t_end = 1000 s: the event count must not drift",
            "as the tolerance shrinks. Memory stays bounded: the run keeps events, not samples, unless",
            "asked.", "", "```json", long_scene, "```", "", long_table, "",
            "## The extremes", "",
            "One pellet (0.2 kg, R = 0.5 m, alpha0 = 0.05, limiters at ±0.6 rad, k = 0.7, t_end = 2 s)",
            "unless the row says otherwise; each run has a 10 s deadline. A case beyond what the engine",
            "can do ends with a clear termination and message, never NaN or a hang.", "",
            extremes(), ""]
    with open(os.path.join(ROOT, "docs", "ACCURACY.md"), "w") as f:
        f.write("\n".join(out))
    print("accuracy: docs/ACCURACY.md written")


if __name__ == "__main__":
    main()
