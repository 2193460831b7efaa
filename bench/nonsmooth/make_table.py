#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Rewrites the generated cost table of docs/nonsmooth.md ("Cost") from the JSON of
nonsmooth_cost_bench: CPU time per simulated second of the clearance slider-cranks, Moreau-Jean
at h = 1e-4 s and 1e-5 s beside the compliant integrator, and the ratio to the compliant run.

    python3 bench/nonsmooth/make_table.py BENCH.json docs/nonsmooth.md

bench/nonsmooth/run_bench.sh runs the benchmark and then this script. The table and its one
provenance line sit between `<!-- generated: cost -->` and `<!-- end generated: cost -->`.
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from report_provenance import provenance  # noqa: E402  (bench/ on the path first)

BEGIN, END = "<!-- generated: cost -->", "<!-- end generated: cost -->"
# Benchmark name -> (model, formulation, compliant row of the same model).
ROWS = {
    "BM_CompliantPlanar": ("planar, aligned", "compliant", "BM_CompliantPlanar"),
    "BM_MoreauJeanPlanarStep1e4": ("planar, aligned", "Moreau-Jean, h = 1e-4 s", "BM_CompliantPlanar"),
    "BM_MoreauJeanPlanarStep1e5": ("planar, aligned", "Moreau-Jean, h = 1e-5 s", "BM_CompliantPlanar"),
    "BM_CompliantSpatial": ("spatial", "compliant", "BM_CompliantSpatial"),
    "BM_MoreauJeanSpatialStep1e4": ("spatial", "Moreau-Jean, h = 1e-4 s", "BM_CompliantSpatial"),
    "BM_MoreauJeanSpatialStep1e5": ("spatial", "Moreau-Jean, h = 1e-5 s", "BM_CompliantSpatial"),
}


def cpu_model():
    """The CPU's model name (lscpu's "Model name"), for the provenance line."""
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def aggregates(path):
    data = json.load(open(path))
    median, cv = {}, {}
    for r in data["benchmarks"]:
        name = r["run_name"].split("/")[0]
        if r.get("aggregate_name") == "median":
            median[name] = r
        elif r.get("aggregate_name") == "cv":
            cv[name] = r
    return data["context"], median, cv


def cpu_seconds(r):
    return r["cpu_time"] * {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[r["time_unit"]]


def table(context, median, cv):
    lines = [provenance(context, "bash bench/nonsmooth/run_bench.sh") + f" CPU: {cpu_model()}.", "",
             "| model | formulation | CPU per simulated s (median) | CPU cv | steps | right-hand sides "
             "| contact problems | NSGS sweeps | unconverged steps | CPU / compliant CPU |",
             "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for name, (model, formulation, reference) in ROWS.items():
        if name not in median:
            continue
        r = median[name]
        cpu = cpu_seconds(r) / r["simulated_s"]
        ratio = cpu_seconds(r) / cpu_seconds(median[reference]) if reference in median else None
        if formulation == "compliant":
            formulation = f"compliant, Dormand-Prince, tolerance {r['tolerance']:g}"

        def count(key):
            return f"{r[key]:.0f}" if key in r else ""

        lines.append("| " + " | ".join([
            model, formulation, f"{cpu:.3g} s", f"{100 * cv[name]['cpu_time']:.1f} %" if name in cv else "",
            count("steps"), count("derivative_calls"), count("contact_problems"), count("nsgs_sweeps"),
            count("unconverged_steps"), "1" if name == reference else (f"{ratio:.3f}" if ratio else "")]) + " |")
    return "\n".join(lines)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    context, median, cv = aggregates(sys.argv[1])
    page = open(sys.argv[2]).read()
    pattern = re.compile(re.escape(BEGIN) + r"\n.*?" + re.escape(END), re.S)
    if not pattern.search(page):
        sys.exit(f"{sys.argv[2]}: no {BEGIN} ... {END} block to rewrite")
    block = BEGIN + "\n" + table(context, median, cv) + "\n" + END
    with open(sys.argv[2], "w") as f:
        f.write(pattern.sub(lambda _: block, page, count=1))


if __name__ == "__main__":
    main()
