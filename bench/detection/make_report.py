#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes docs/reports/benchmarks.md and its plots from the detection suite's outputs.

Inputs: the accuracy report of `detection_suite accuracy` and the Google Benchmark JSON of
`bench_detection`. Called by bench/run_detection_suite.sh; every number in the page comes from
those two files (nothing is typed in by hand).
"""

import argparse
import datetime
import json
import math
import os
import re
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

METHODS = ["paper_baseline", "uncertified", "certified"]
METHOD_TITLES = {
    "paper_baseline": "paper baseline (plain Newton)",
    "uncertified": "clearjoint, certificate off",
    "certified": "clearjoint, certified (default)",
    "certified_vs_exact_unit_axes": "clearjoint certified, scored against the joint with a/|a| normalised exactly",
}
FAMILIES = ["realistic", "near_tangent", "near_parallel", "extreme", "trajectories"]
STYLE = {
    "paper_baseline": dict(color="tab:red", marker="s"),
    "uncertified": dict(color="tab:orange", marker="^"),
    "certified": dict(color="tab:blue", marker="o"),
    "certified_vs_exact_unit_axes": dict(color="tab:cyan", marker="o", linestyle="--"),
}


def write_atomically(path, data, binary=False):
    folder = os.path.dirname(path) or "."
    os.makedirs(folder, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=folder, prefix=".tmp-")
    with os.fdopen(handle, "wb" if binary else "w") as out:
        out.write(data)
    os.replace(temporary, path)


def fmt(x, digits=3):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    if x == 0:
        return "0"
    if abs(x) >= 1e4 or abs(x) < 1e-2:
        return f"{x:.{digits - 1}e}"
    return f"{x:.{digits}g}"


def ns(x):
    if x is None:
        return "-"
    if x >= 1e6:
        return f"{x / 1e6:.3g} ms"
    if x >= 1e4:
        return f"{x / 1e3:.3g} us"
    return f"{x:.0f}"


def share(part, whole):
    return "-" if whole == 0 else f"{100.0 * part / whole:.1f}%"


# ---- inputs ---------------------------------------------------------------------------------


def load_timings(path):
    """{set name: {method: run}} with the median aggregate when there are repetitions."""
    runs = json.load(open(path))
    context = runs["context"]
    by_name = {}
    for run in runs["benchmarks"]:
        name = re.sub(r"/(iterations|repeats):\d+", "", run["run_name"])
        aggregate = run.get("aggregate_name")
        if run.get("run_type") == "aggregate" and aggregate != "median":
            continue
        if run.get("run_type") == "iteration" and name in by_name:
            continue
        by_name[name] = run
    table = {}
    for name, run in by_name.items():
        set_name, _, method = name.rpartition("/")
        table.setdefault(set_name, {})[method] = run
    return context, table


def rows_by(accuracy):
    out = {}
    for row in accuracy["results"]:
        out[(row["family"], row["group"], row["method"])] = row
    return out


# ---- plots ----------------------------------------------------------------------------------


def group_axis(family, groups):
    """x positions and tick labels for the groups of a margin family."""
    xs, labels = [], []
    for g in groups:
        if g == "parallel":
            xs.append(17)
            labels.append("0\n(parallel)")
        else:
            k = int(g.split("=")[1])
            xs.append(k)
            labels.append(f"$10^{{-{k}}}$")
    return xs, labels


def plot_family(family, accuracy_rows, timing_table, groups, path, xlabel):
    xs, labels = group_axis(family, groups)
    figure, axes = plt.subplots(1, 3, figsize=(15, 5.2))
    # Failures.
    ax = axes[0]
    for method in METHODS + ["certified_vs_exact_unit_axes"]:
        ys = []
        for g in groups:
            row = accuracy_rows.get((family, g, method))
            scored = row["inputs"] - row["reference_undecided"] if row else 0
            ys.append(100.0 * row["failed_inputs"] / scored if row and scored else float("nan"))
        ax.plot(xs, ys, label=METHOD_TITLES[method], **STYLE[method])
    ax.set_ylabel("inputs with a wrong scenario, a missed or\nspurious contact or a missed enclosure (%)")
    ax.set_title("failures")
    # Errors.
    ax = axes[1]
    for method in METHODS:
        ys = []
        for g in groups:
            row = accuracy_rows.get((family, g, method))
            value = row["point_error_m"]["p99"] if row else None
            ys.append(value if isinstance(value, (int, float)) and value > 0 else float("nan"))
        ax.plot(xs, ys, label=METHOD_TITLES[method], **STYLE[method])
    ax.set_yscale("log")
    ax.set_ylabel("contact-point error, 99th percentile (m)")
    ax.set_title("error of the contact points")
    # Cost.
    ax = axes[2]
    for method in METHODS:
        p50, p99 = [], []
        for g in groups:
            run = timing_table.get(f"{family}/{g}", {}).get(method)
            p50.append(run["input_p50_ns"] if run else float("nan"))
            p99.append(run["input_p99_ns"] if run else float("nan"))
        style = dict(STYLE[method])
        ax.plot(xs, p50, **style)
        style["linestyle"] = ":"
        style["markerfacecolor"] = "none"
        ax.plot(xs, p99, **style)
    ax.set_yscale("log")
    ax.set_ylabel("ns per full-joint query")
    ax.set_title("cost per input: median (solid), p99 (dotted)")
    for ax in axes:
        ax.set_xticks(xs)
        ax.set_xticklabels(labels, fontsize=7)
        ax.set_xlabel(xlabel)
        ax.grid(True, alpha=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    figure.legend(handles, labels, loc="lower center", ncol=4, fontsize=8, frameon=False)
    figure.tight_layout(rect=(0, 0.07, 1, 1))
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=os.path.dirname(path) or ".", prefix=".tmp-", suffix=".png")
    os.close(handle)
    figure.savefig(temporary, dpi=110)
    plt.close(figure)
    os.replace(temporary, path)


# ---- markdown -------------------------------------------------------------------------------


def accuracy_table(accuracy, rows):
    lines = [
        "| family | method | inputs | wrong scenario (within model) | missed contacts (inputs) | spurious contacts (inputs) | exact / certified / uncertain answers | enclosures checked | enclosures missing the reference | enclosure radius m: median / max |",
        "| --- | --- | ---: | ---: | ---: | ---: | --- | ---: | ---: | --- |",
    ]
    for family in FAMILIES:
        for method in METHODS + ["certified_vs_exact_unit_axes"]:
            row = rows.get((family, "", method))
            if not row:
                continue
            scored = row["inputs"] - row["reference_undecided"]
            title = "certified vs exact a/|a|" if method == "certified_vs_exact_unit_axes" else method
            lines.append(
                f"| {family} | {title} | {row['inputs']} | {row['wrong_scenarios']} ({row['wrong_scenarios_within_model']}) "
                f"| {row['missed_contacts']} ({row['inputs_with_missed']}) | {row['spurious_contacts']} ({row['inputs_with_spurious']}) "
                f"| {share(row['answers_exact'], scored)} / {share(row['answers_certified'], scored)} / {share(row['answers_uncertain'], scored)} "
                f"| {row['enclosures_checked']} | {row['enclosures_missed']} "
                f"| {fmt(row['enclosure_radius_m']['median'])} / {fmt(row['enclosure_radius_m']['max'])} |")
    return "\n".join(lines)


def error_table(rows):
    lines = [
        "| family | method | crossing error m: median / p99 / max | crossing error ulps: median / p99 / max | contact-point error m: median / p99 / max | contact-point error ulps: median / p99 / max | depth relative error: median / p99 / max |",
        "| --- | --- | --- | --- | --- | --- | --- |",
    ]
    for family in FAMILIES:
        for method in METHODS:
            row = rows.get((family, "", method))
            if not row:
                continue

            def triple(key):
                s = row[key]
                return f"{fmt(s['median'])} / {fmt(s['p99'])} / {fmt(s['max'])}"

            lines.append(f"| {family} | {method} | {triple('crossing_error_m')} | {triple('crossing_error_ulps')} "
                         f"| {triple('point_error_m')} | {triple('point_error_ulps')} | {triple('depth_relative_error')} |")
    return "\n".join(lines)


def cost_table(table):
    lines = [
        "| family | method | mean ns per query (median of repetitions) | per-input median ns | per-input p99 ns | per-input max | / paper baseline (mean) | / paper baseline (per-input median) | inputs with contact |",
        "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |",
    ]
    for family in FAMILIES:
        runs = table.get(family, {})
        base = runs.get("paper_baseline")
        for method in METHODS:
            run = runs.get(method)
            if not run:
                continue
            ratio = run["cpu_time"] / base["cpu_time"] if base else float("nan")
            ratio50 = run["input_p50_ns"] / base["input_p50_ns"] if base else float("nan")
            lines.append(f"| {family} | {method} | {ns(run['cpu_time'])} | {ns(run['input_p50_ns'])} | {ns(run['input_p99_ns'])} "
                         f"| {ns(run['input_max_ns'])} | {ratio:.2f} | {ratio50:.2f} | {100 * run['contact_share']:.0f}% |")
    return "\n".join(lines)


def group_table(family, rows, timing_table, groups, label):
    lines = [
        f"| {label} | inputs | failed inputs: baseline / uncertified / certified / certified vs exact a/\\|a\\| | certified p99 point error m | certified per-input median / p99 ns | baseline per-input median ns |",
        "| --- | ---: | --- | ---: | --- | ---: |",
    ]
    for g in groups:
        r = {m: rows.get((family, g, m)) for m in METHODS + ["certified_vs_exact_unit_axes"]}
        if not r["certified"]:
            continue
        t = timing_table.get(f"{family}/{g}", {})
        fails = " / ".join(str(r[m]["failed_inputs"]) for m in METHODS + ["certified_vs_exact_unit_axes"])
        cert = t.get("certified")
        base = t.get("paper_baseline")
        lines.append(f"| {g} | {r['certified']['inputs']} | {fails} | {fmt(r['certified']['point_error_m']['p99'])} "
                     f"| {ns(cert['input_p50_ns']) if cert else '-'} / {ns(cert['input_p99_ns']) if cert else '-'} "
                     f"| {ns(base['input_p50_ns']) if base else '-'} |")
    return "\n".join(lines)


def failure_kind(problems):
    if any(p.startswith(("scenario", "missed", "spurious")) for p in problems):
        return "wrong scenario or contacts"
    return "enclosure only"


def exact_axes_problems(f):
    return f.get("against_exact_unit_axes", {}).get("problems", [])


def failure_lines(accuracy, per_key=2, problems_of=lambda f: f["problems"]):
    """The certified pipeline's failures (against the joint as given, or with `problems_of` =
    exact_axes_problems against a/|a| normalised exactly): counts per (family, group, kind) and,
    for each, the first `per_key` inputs in full (hex floats). accuracy.json lists every one."""
    certified = [f for f in accuracy["failures"] if f["method"] == "certified" and problems_of(f)]
    counts, shown, lines = {}, {}, []
    for f in certified:
        key = (f["family"], f["group"], failure_kind(problems_of(f)))
        counts[key] = counts.get(key, 0) + 1
    summary = ["| family | group | kind | inputs |", "| --- | --- | --- | ---: |"]
    for key, count in counts.items():
        summary.append(f"| {key[0]} | {key[1] or '-'} | {key[2]} | {count} |")
    for f in certified:
        key = (f["family"], f["group"], failure_kind(problems_of(f)))
        if shown.get(key, 0) >= per_key:
            continue
        shown[key] = shown.get(key, 0) + 1
        margin = f" measured margin {f['measured_margin']:.3g} clearances;" if "measured_margin" in f else ""
        lines.append(f"- `{f['id']}`:{margin} " + "; ".join(problems_of(f)) +
                     f". Input: `{json.dumps(f['input'], separators=(',', ':'))}`")
    return certified, "\n".join(summary), lines


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--accuracy", required=True)
    parser.add_argument("--timings", required=True)
    parser.add_argument("--markdown", required=True)
    parser.add_argument("--figures", required=True)
    parser.add_argument("--mode", default="full")
    parser.add_argument("--commit", default="unknown")
    parser.add_argument("--geometry-dirty", default="0")
    parser.add_argument("--accuracy-load", default="?")
    parser.add_argument("--timing-load", default="?")
    parser.add_argument("--elapsed", default="?")
    args = parser.parse_args()

    accuracy = json.load(open(args.accuracy))
    context, timing_table = load_timings(args.timings)
    rows = rows_by(accuracy)
    families = {f["name"]: f for f in accuracy["families"]}

    figure_names = {}
    group_lists = {}
    for family, xlabel in (("near_tangent", "signed margin from touching, in clearances (both signs)"),
                           ("near_parallel", "journal tilt (rad)")):
        groups = [row["group"] for row in accuracy["results"]
                  if row["family"] == family and row["group"] and row["method"] == "certified"]
        groups.sort(key=lambda g: 17 if g == "parallel" else int(g.split("=")[1]))
        group_lists[family] = groups
        name = f"benchmarks-{family.replace('_', '-')}.png"
        figure_names[family] = name
        plot_family(family, rows, timing_table, groups, os.path.join(args.figures, name), xlabel)

    figures_rel = os.path.relpath(args.figures, os.path.dirname(args.markdown) or ".")
    realistic = timing_table.get("realistic", {})
    ratio_mean = realistic["certified"]["cpu_time"] / realistic["paper_baseline"]["cpu_time"]
    ratio_p50 = realistic["certified"]["input_p50_ns"] / realistic["paper_baseline"]["input_p50_ns"]
    ratio_uncert = realistic["uncertified"]["cpu_time"] / realistic["paper_baseline"]["cpu_time"]
    certified_failures, failure_summary, failure_text = failure_lines(accuracy)
    axes_differences, axes_summary, axes_text = failure_lines(accuracy, problems_of=exact_axes_problems)
    as_given = accuracy["certified_failures_against_joint_as_given"]
    as_exact_axes = accuracy["certified_failures_against_exact_unit_axes"]
    undecided = len(accuracy["reference_undecided"])
    if as_given == 0:
        rounding_explanation = " The certified pipeline is right on every input."
    else:
        rounding_explanation = (f" **{as_given} inputs have a certified answer that is wrong for the joint"
                                " as given: a defect of the certified pipeline.**")
    rounding_explanation += f""" Against the joint whose centres are offset along a/|a| computed
exactly (not the library's definition, which normalises the axis in double), {as_exact_axes} inputs
differ: the rounded direction moves a centre by a few ulps of L (about 1e-18 m, or 1e-14
clearances, for Table 2 in metres), which flips a topology when a margin is smaller than that and
moves a near-tangent crossing, conditioned like 1/sqrt(margin), by more than its `point_error`.
That is the one rounding left in the joint's definition (`joint_geometry.hpp`); the table below
lists what remains of the certified pipeline's failures against the joint as given, if any."""
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")

    family_lines = ["| family | seed | inputs | reference scenarios (count) | what |", "| --- | ---: | ---: | --- | --- |"]
    for name in FAMILIES:
        f = families.get(name)
        if not f:
            continue
        scen = ", ".join(f"{k} {v}" for k, v in sorted(f["reference_scenarios"].items()))
        extra = ""
        if "measured_abs_margin_range_clearances" in f:
            lo, hi = f["measured_abs_margin_range_clearances"]
            extra = f" Measured margins: {lo:.2g} to {hi:.2g} clearances."
        if "measured_nonzero_tilt_range_rad" in f:
            lo, hi = f["measured_nonzero_tilt_range_rad"]
            extra = f" Measured tilts: {lo:.2g} to {hi:.2g} rad."
        family_lines.append(f"| {name} | {f['seed']} | {f['inputs']} | {scen} | {f['description']}.{extra} |")

    # Whether the figures belong to the commit named: say so either way.
    dirty = (
        "no file under `geometry/` modified in the working tree: the figures are the commit's"
        if str(args.geometry_dirty) == "0"
        else f"{args.geometry_dirty} files under `geometry/` modified in the working tree at the time: "
        "the figures are of that working tree, not of the commit alone"
    )
    text = f"""# Detection benchmarks: cost, accuracy and robustness

Generated by `bash bench/run_detection_suite.sh` ({args.mode} run) on {now} from commit `{args.commit}`
({dirty}); {args.elapsed} s for the whole command including the build.
Load average when the accuracy pass started: {args.accuracy_load}; when the timings started:
{args.timing_load} (2 cores, shared). Do not edit by hand: rerun the command.

Three full-joint detection methods run on the same inputs, in the same process:

| method | what |
| --- | --- |
| `paper_baseline` | the paper as written (Section 3): eq. (5) tested on the unit axes in double; axial contacts by intersecting the rim with the base plane in closed form (eqs. 11-15); radial contacts by plain Newton-Raphson on eqs. (16)-(17) for x in R^3, from two fixed starting guesses a quarter turn either side of the rim point in the radial direction of the rim centre, assuming at most two crossings and a penetration only when that rim point is beyond the wall; contact points by eqs. (13)-(15), (18)-(21), depth by eq. (23). `bench/detection/paper_baseline.cpp`, not part of the library. Every answer `uncertain`. |
| `uncertified` | `clearjoint::geometry::detect_contacts` with `DetectionOptions::intersection.certify = false` (the plain double pipeline; every answer `uncertain`) |
| `certified` | `detect_contacts` with its defaults: certified kernel queries, exact (CGAL) fallback near tangencies, eq. (5) decided exactly |

They are scored against a multiprecision reference (`bench/detection/joint_reference.cpp`,
{accuracy['reference_digits']} decimal digits of MPFR) that takes the joint **as its input doubles
define it** (`joint_geometry.hpp`): base and rim centres P +- (L/2) a_hat, a_hat the axis
normalised in double by `geometry::unit_axis` (bitwise a for an axis whose a . a evaluates to 1),
never rounded to double afterwards. The library rounds the centres for speed but carries the
rounding into its bounds and decides on the exact centres in its exact tier, so its certificates
are about this joint. The row "certified vs exact a/|a|" scores the certified pipeline against the
joint with a/|a| normalised exactly in MPFR instead, to show what the one rounding in that
definition changes. The reference decided every input ({undecided} undecided).

## Running it

    bash bench/run_detection_suite.sh            # full run; rewrites this page and its plots
    bash bench/run_detection_suite.sh --quick    # a few inputs per group; report in build/detection-quick/

It installs what is missing (`scripts/install-dependencies.sh`, which has `python3-matplotlib`),
builds `detection_suite` and `bench_detection` (Release, `-j2`), and runs

1. `detection_suite accuracy --threads 2`: generates the families, scores every method against the
   reference, writes `build/detection/accuracy.json` (every tally below, per family and per group,
   and every failure of the certified pipeline with its input in hex floats);
2. `bench_detection --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true`:
   Google Benchmark, JSON in `build/detection/timings.json`;
3. `detection_suite export`: the robustness files (below) in `build/detection/robustness/`;
4. `bench/detection/make_report.py`: this page and `docs/figures/benchmarks-*.png`.

ctest runs `detection_suite accuracy --quick --check` (test `detection_suite_quick_check`, under
a minute): it fails when the certified pipeline has a wrong scenario, a missed or spurious contact,
or an enclosure missing the reference, scored against the joint as given (what its certificates
claim), or when the reference leaves an input undecided. Differences against the joint with a/|a|
normalised exactly are printed but do not fail the test.

## Input families

Metres throughout except the unit variants of `extreme` (micrometres and kilometres: lengths in the
tables are then in the input's unit). Joint of the paper's Table 2 (Ri = 10 mm, Li = 20 mm,
Rj = 9.9 mm, Lj = 19.8 mm, cr = ca = 0.1 mm) unless stated. Each family has a fixed seed
(`std::mt19937_64` with an explicit 53-bit conversion); `bench/detection/input_families.hpp`
documents each generator.

{chr(10).join(family_lines)}

Reference scenario labels are those of `clearjoint detect`: `a`..`l` (paper Fig. 2), `none`,
`beyond_model` (a rim with two penetration arcs or beyond a surface all round, or a penetration
deeper than the clearance).

## Accuracy

Wrong scenario: the answer names another scenario than the reference (in brackets: among inputs
the reference does not call `beyond_model`; the paper has no such notion, so the baseline answers
those as it finds them). Missed / spurious: contacts keyed by type and base (radial A, radial B,
axial A, axial B; aligned: line, face A, face B) present in the reference and not in the answer,
or the reverse (in brackets: inputs with at least one). Enclosures: every crossing of a certified
or exact answer with a finite `point_error` must lie within that distance of the reference
crossing; the last column says how large those promised radii are.

{accuracy_table(accuracy, rows)}

### Errors

Crossing ("root") error: distance from each crossing point of a contact present in both to the
nearest reference crossing. Contact-point error: the larger of the journal point and the bearing
point errors. Ulps: the error's largest coordinate over the ulp of the reference point's largest
coordinate. Depth relative error: |depth - reference| / reference. Contacts of a rim beyond the wall
all round have no arc middle and are not compared; those of a rim beyond a base all round (beyond
the model) are left out of these columns because their contact point, the deepest rim point, is
ill-conditioned when the rim is nearly parallel to the base (its direction is the base normal
projected into the rim plane, a vector as short as the tilt's sine); their errors are in
`accuracy.json` (`point_error_m_rim_beyond_base_all_round`).

{error_table(rows)}

## Cost

Google Benchmark, CPU time (the machine is shared; CPU time is the process's own). "mean ns per
query": the timed loop cycles through every input of the family (a whole number of passes), median
of {context.get('suite_size') == 'full' and 3 or 2} interleaved repetitions. "per-input": each input timed alone before the
benchmarks (batches of 8 calls, one call when slower than 20 us, median of 3 passes, the three
methods in turn, the clock's cost subtracted), then the median, 99th percentile and maximum over the
family. Load average when the timings started: {context.get('load_average_at_start', '?')} (1, 5, 15 min).

{cost_table(timing_table)}

**Cost target** (issue 5: certified at no more than 2x the paper baseline on the realistic family):
measured **{ratio_mean:.2f}x** on the mean cost per query and **{ratio_p50:.2f}x** on the per-input
median, in the same run ({'met' if ratio_mean <= 2.0 else 'NOT met'} on the mean,
{'met' if ratio_p50 <= 2.0 else 'NOT met'} on the median). The uncertified pipeline costs
{ratio_uncert:.2f}x the baseline on the mean. The certified pipeline's tail on the near-tangent and
extreme families is its exact fallback (CGAL rationals) near tangencies; the near-tangent table
below shows from which margin on it sets the 99th percentile.

## Near-tangent and near-parallel inputs

![near-tangent]({figures_rel}/{figure_names['near_tangent']})

{group_table('near_tangent', rows, timing_table, group_lists['near_tangent'], 'margin group (10^-k clearances, both signs)')}

![near-parallel]({figures_rel}/{figure_names['near_parallel']})

{group_table('near_parallel', rows, timing_table, group_lists['near_parallel'], 'tilt group (10^-k rad)')}

## Certified pipeline against the joint as given

Against the reference of the joint as given, {as_given} inputs have a certified failure; against
the joint with a/|a| normalised exactly, {as_exact_axes}.{rounding_explanation}

Certified failures against the joint as given:

{failure_summary if certified_failures else '(none)'}

{chr(10).join(failure_text) if failure_text else ''}

Differences against the joint with a/|a| normalised exactly ({len(axes_differences)} inputs; the
first of each line in C99 hex floats exactly as generated; all of them are in
`build/detection/accuracy.json`, key `failures`, field `against_exact_unit_axes`, which the command
regenerates from the fixed seeds):

{axes_summary if axes_differences else '(none)'}

{chr(10).join(axes_text) if axes_text else ''}

## Robustness mode: scoring another implementation

`detection_suite export [--quick] --out-dir DIR` writes, for each family,

- `DIR/<family>.jsonl`: one `clearjoint detect` input line per input (`docs/command-line.md`,
  issue 4): `{{"id", "bearing": {{"radius", "length", "center", "axis"}}, "journal": {{...}}}}`, SI
  units (except the unit variants of `extreme`), every number printed in the shortest form that
  reads back to the same double;
- `DIR/<family>.reference.jsonl`: the reference answer for each line, same `id`, same order, in
  the `clearjoint detect` output format (`scenario`, `aligned`, `contacts` with `type`, `base`,
  `depth`, `point_journal`, `point_bearing`, `normal`, `crossings`; each number the reference value
  rounded to the nearest double), with `certificate` replaced by
  `"reference": {{"digits", "decided", "why"}}`, plus `family`, `group`, `measured_margin`
  (near-tangent, in clearances) or `measured_tilt` (near-parallel, rad), and per contact
  `points_defined` (false for a rim beyond the wall all round, whose point is not comparable).

The answers sit in a second file because `clearjoint detect` rejects unknown keys in its input.
Each reference contact also says `rim_beyond_base_all_round` (its point is the deepest rim point,
ill-conditioned for a rim nearly parallel to the base; scored apart). To score a code:

    build/bench/detection/detection_suite export --out-dir robustness        # or --quick
    your_code < robustness/near_tangent.jsonl > answers.jsonl               # one answer line per input line
    /usr/bin/python3 bench/detection/score_detect_answers.py robustness/near_tangent.reference.jsonl answers.jsonl

`score_detect_answers.py` (standard library only) applies the definitions above and prints the
counts of wrong scenarios, missed and spurious contacts, the error summaries and the first failing
ids; its exit status is 1 when any answer differs from the reference. With
`clearjoint detect` as `your_code` it reproduces the certified rows of the tables above.
"""
    write_atomically(args.markdown, text)


if __name__ == "__main__":
    main()
