#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Run dynamics_slider_crank_bench from two builds side by side and print the ratio of their
median times as a Markdown table (docs/benchmarks-dynamics.md has one build's figures).

Two programs cannot share one Google Benchmark process, so the interleaving is done here: each of
`--rounds` rounds runs every benchmark once in each build (`--benchmark_repetitions=1`), the two
builds in a shuffled order (seeded, the seed is printed), so that a change of machine load falls
on both alike. Every run's JSON is kept in `--out` (one file per round and build).

  bench/dynamics/compare_builds.py --baseline OLD/build/bench/dynamics/dynamics_slider_crank_bench \\
      --candidate build/bench/dynamics/dynamics_slider_crank_bench --rounds 5 --out build/bench-dynamics
"""

import argparse
import json
import os
import random
import statistics
import subprocess
import sys


def run(program, benchmark_filter, out_path):
    subprocess.run([program, "--benchmark_filter=" + benchmark_filter, "--benchmark_repetitions=1",
                    "--benchmark_out=" + out_path, "--benchmark_out_format=json"],
                   check=True, stdout=subprocess.DEVNULL)
    with open(out_path) as f:
        return json.load(f)["benchmarks"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--baseline", required=True)
    parser.add_argument("--candidate", required=True)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--filter", default=".", help="--benchmark_filter for both builds")
    parser.add_argument("--seed", type=int, default=23)
    parser.add_argument("--out", default="build/bench-dynamics")
    args = parser.parse_args()
    if args.rounds < 1:
        raise SystemExit("--rounds %d: must be at least 1" % args.rounds)
    os.makedirs(args.out, exist_ok=True)
    order = random.Random(args.seed)
    times = {"baseline": {}, "candidate": {}}  # build -> benchmark -> [(real, cpu, counters)]
    for r in range(args.rounds):
        builds = ["baseline", "candidate"]
        order.shuffle(builds)
        for build in builds:
            program = getattr(args, build)
            for b in run(program, args.filter, os.path.join(args.out, "%s_%d.json" % (build, r))):
                times[build].setdefault(b["name"], []).append(b)
        print("round %d of %d done (%s first)" % (r + 1, args.rounds, builds[0]), file=sys.stderr)
    print("seed %d, %d interleaved rounds; medians; ratio = candidate / baseline" % (args.seed, args.rounds))
    print()
    print("| benchmark | baseline wall | candidate wall | wall ratio | baseline CPU | candidate CPU | CPU ratio | steps (baseline, candidate) |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |")
    for name, base in times["baseline"].items():
        cand = times["candidate"].get(name)
        if not cand:
            continue
        unit = base[0]["time_unit"]
        med = lambda runs, key: statistics.median(x[key] for x in runs)
        bw, cw = med(base, "real_time"), med(cand, "real_time")
        bc, cc = med(base, "cpu_time"), med(cand, "cpu_time")
        steps = ""
        if "steps" in base[0]:
            steps = "%d, %d" % (base[0]["steps"], cand[0]["steps"])
        print("| %s | %.4g %s | %.4g %s | %.3f | %.4g %s | %.4g %s | %.3f | %s |" % (
            name, bw, unit, cw, unit, cw / bw, bc, unit, cc, unit, cc / bc, steps))


if __name__ == "__main__":
    main()
