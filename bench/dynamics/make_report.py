#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes docs/reports/benchmarks-dynamics.md from the JSON of dynamics_slider_crank_bench and,
when given, a `perf report` of the spatial slider-crank with its clearance joint.

    python3 bench/dynamics/make_report.py BENCH.json [PERF_REPORT.txt] OUT.md

bench/dynamics/run_bench.sh runs the benchmark (and perf) and then this script. The page is
reference text (what each row times, how to run and read it) around tables generated from one
run, with one provenance line at the top: commit, date, machine load.
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from report_provenance import provenance as page_provenance  # noqa: E402  (bench/ on the path first)

WHAT = {
    "BM_IntegratePlanarSliderCrank": "planar slider-crank, ideal joints: 1 s",
    "BM_IntegrateSpatialSliderCrank": "spatial slider-crank, ideal joints: 1 s",
    "BM_IntegrateSpatialSliderCrankWithClearance": "spatial slider-crank, clearance joint (Table 2): 1 s",
    "BM_IntegratePlanarSliderCrankWithClearance": "planar slider-crank, aligned clearance joint: 1 s",
    "BM_IntegrateLubricatedPlanarSliderCrankShortBearing":
        "planar slider-crank, lubricated clearance joint, short-bearing film: 1 s",
    "BM_IntegrateLubricatedPlanarSliderCrankTable":
        "planar slider-crank, lubricated clearance joint, finite-width film (48 x 12 grid tabulated): 1 s",
    "BM_DerivativePlanarSliderCrank": "one right-hand side, planar ideal",
    "BM_DerivativeSpatialSliderCrank": "one right-hand side, spatial ideal",
    "BM_DerivativeSpatialSliderCrankWithClearance": "one right-hand side, spatial with clearance (journal centred)",
}

# perf symbols to the parts of a right-hand-side evaluation, first match wins: (part, dso pattern,
# symbol pattern). Eigen's products and the factorisation are inlined into the constraint solve;
# a joint pair's Schur block (schur_block.hpp) may stay a function of its own.
PARTS = [
    ("contact detection (`clearjoint_geometry`)", r"libclearjoint_geometry", r""),
    ("constraint solve (Schur matrix, factorisation, solves)", r"",
     r"solve_constrained_accelerations|Eigen::|detail::add_product_block|cholesky_in_place"),
    ("constraint rows (`ConstraintSet::evaluate`, joint equations, primitives)", r"libclearjoint_dynamics",
     r"ConstraintSet::|JointEquations::|ConstraintRows::|clearjoint::dynamics::add_(?!force)"),
    ("clearance joint forces (`evaluate_forces`, force law, friction)", r"libclearjoint_dynamics",
     r"ClearanceRevoluteJoint::|normal_contact_force|regularised_friction"),
    ("kinematics, Euler-parameter rates, integrator, rest of `clearjoint_dynamics`", r"libclearjoint_dynamics", r""),
    ("libm (acos, pow, sincos, ...)", r"libm\.so", r""),
    ("libc, kernel, other", r"", r""),
]


def medians(path):
    data = json.load(open(path))
    median, cv = {}, {}
    # The repetitions ran interleaved; the table lists the rows in the program's order.
    for r in sorted(data["benchmarks"], key=lambda r: r.get("family_index", 0)):
        name = r["run_name"].split("/")[0]
        if r.get("aggregate_name") == "median":
            median[name] = r
        elif r.get("aggregate_name") == "cv":
            cv[name] = r
    return data["context"], median, cv


def time_text(seconds):
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("us", 1e-6)):
        if seconds >= scale:
            return f"{seconds / scale:.3g} {unit}"
    return f"{seconds * 1e9:.3g} ns"


def seconds(r, key):
    return r[key] * {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[r["time_unit"]]


def bench_table(median, cv):
    lines = ["| benchmark | what | median wall | median CPU | CPU cv | steps | RHS evaluations | CPU per evaluation "
             "| contact detections | impacts | detections per impact beyond the evaluations |",
             "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for name, r in median.items():
        cpu = seconds(r, "cpu_time")
        calls = r.get("derivative_calls")
        detections, impacts = r.get("detection_calls"), r.get("impacts")
        probes = (detections - calls) / impacts if detections and impacts else None
        cells = [f"`{name}`", WHAT.get(name, ""), time_text(seconds(r, "real_time")), time_text(cpu),
                 f"{100 * cv[name]['cpu_time']:.1f} %" if name in cv else "",
                 f"{r['steps']:.0f}" if "steps" in r else "", f"{calls:.0f}" if calls else "",
                 time_text(cpu / calls) if calls else "",
                 f"{detections:.0f}" if detections else "", f"{impacts:.0f}" if impacts else "",
                 f"{probes:.1f}" if probes is not None else ""]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def perf_table(path):
    """Shares of `perf report --stdio --no-children --sort dso,sym` samples per part."""
    shares = {part: 0.0 for part, _, _ in PARTS}
    for line in open(path):
        match = re.match(r"\s*([\d.]+)%\s+(\S+)\s+\[[.k]\]\s+(.*)", line)
        if not match:
            continue
        share, dso, symbol = float(match.group(1)), match.group(2), match.group(3)
        for part, dso_pattern, symbol_pattern in PARTS:
            if re.search(dso_pattern, dso) and re.search(symbol_pattern, symbol):
                shares[part] += share
                break
    lines = ["| part | share of CPU samples |", "| --- | ---: |"]
    lines += [f"| {part} | {share:.0f} % |" for part, share in shares.items()]
    return "\n".join(lines)


def provenance(context):
    return page_provenance(context, "bash bench/dynamics/run_bench.sh")


TEMPLATE = """# Dynamics benchmarks: what a simulated second costs

{provenance}

`bench/dynamics/slider_crank_bench.cpp` (Google Benchmark) integrates each slider-crank of paper
Section 6 over its 1 s at the paper's settings (Table 2: Dormand-Prince 5(4), tolerance 1e-7,
dense output at every 1e-5 s report time, an observer that does nothing: the solver alone), and
times one right-hand-side evaluation at the initial state. The models are the shipped files in
`models/` and deterministic, so every iteration of a row is the same run and there is no seed.
[dynamics.md](../dynamics.md) describes the engine; [reproduction.md](reproduction.md) the runs of
Section 6 themselves.

## Running it

    bash bench/dynamics/run_bench.sh

builds `dynamics_slider_crank_bench` (Release, `-j2`) in `./build`, runs it with
`--benchmark_repetitions=$REPETITIONS` (default 5) `--benchmark_enable_random_interleaving=true
--benchmark_report_aggregates_only=true` and JSON output (`build/dynamics_slider_crank_bench.json`),
records a CPU profile of the spatial slider-crank with its clearance joint with `perf record -e
cpu-clock` when `perf` is installed (`build/dynamics_slider_crank_bench.perf.txt`), and writes this
page with `bench/dynamics/make_report.py`. `BUILD_DIR` builds elsewhere, `REPORT` writes the page
elsewhere. To compare two builds, `bench/dynamics/compare_builds.py` runs both programs in
interleaved rounds (two programs cannot share one Google Benchmark process) and prints the ratios
of their medians.

## Figures

Medians over the repetitions. "CPU per evaluation" divides a run's CPU time by its right-hand-side
evaluations (`IntegrationStatistics::derivative_calls`: the stepper's, restarts included),
everything included: the integrator, the report interpolation, the located contact onsets.
"Detections per impact beyond the evaluations" is (contact detections - evaluations) / impacts:
mostly the probes that locate each contact onset on the dense output (dynamics.md, "Contact onset
located"; a detection at the poses of the previous one is reused, not counted).

{bench_table}

{perf_section}

## Reading the figures

* **CPU, not wall.** On a machine shared with other work the wall time of a row can be many times
  its CPU time; the CPU times and the ratios between rows of one run stay comparable.
* **A run's cost is its evaluations times their cost.** The ideal mechanisms take a few hundred to
  a thousand steps in 1 s; a clearance joint takes tens of thousands, because every impact of the
  stiff contact law (K = 1e11 N/m^1.5) is resolved by the error control. Each step costs the
  Dormand-Prince stages' evaluations, so the step count, not the evaluation's cost, decides the
  difference between ideal and clearance models.
* **Ideal mechanisms pay for their reports.** With a few hundred steps and 100 001 report times,
  a run's CPU per evaluation is above one right-hand side's (the `BM_Derivative` rows): the
  interpolation of the reports adds a cost of the order of the evaluations' own.
* **The located onsets are cheap.** Locating an impact's first instant costs the probes in the last
  column, each an interpolation on the dense output and a contact detection, no evaluation of the
  right-hand side: a small fraction of the evaluations of the steps that resolve the impact.
* **The lubricated joint never touches.** The lubricated Section 6.1 rows (the model
  `slider_crank_planar_clearance_lubricated.json` with `lubrication.method` `short` or `table`,
  [lubrication.md](../lubrication.md), "A lubricated Section 6.1") have no impacts: their steps
  are set by the squeeze film's stiffness. The finite-width film carries less load than the short
  bearing's at B/D = 1, so the journal runs closer to the wall, where the film is stiffer, and
  takes more steps. The table row's film table is built before the timing (once per process:
  `BM_TableBuild` of `bench/lubrication/film_bench.cpp`, about 0.5 s).
* **Where an evaluation goes.** The constraint solve (the Schur complement of the block-sparse
  mass matrix, its Cholesky factorisation and solves) and the contact detection take most of it.
  The solve computes the non-zero entries only (a block per pair of joints on a shared body, the
  joints' equations only; the factor's rows that can be non-zero), bit for bit the dense loops'
  answer; what is left is mostly the divisions by the pivots and the two triangular solves,
  chains of dependent operations ([dynamics.md](../dynamics.md), "Solving eq. (38)"). A run gets
  substantially cheaper only with a cheaper detection in contact or with fewer evaluations.
"""


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    context, median, cv = medians(sys.argv[1])
    perf_section = ""
    if len(sys.argv) == 4:
        perf_section = ("Where the CPU time of `BM_IntegrateSpatialSliderCrankWithClearance` goes (`perf record -e "
                        "cpu-clock`, samples grouped by library and symbol):\n\n" + perf_table(sys.argv[2]))
    page = TEMPLATE.format(provenance=provenance(context), bench_table=bench_table(median, cv),
                           perf_section=perf_section)
    with open(sys.argv[-1], "w") as f:
        f.write(page)


if __name__ == "__main__":
    main()
