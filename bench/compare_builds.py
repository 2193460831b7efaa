#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Run one Google Benchmark program from two builds side by side and print the ratio of their
median times per benchmark, as a Markdown table.

Two programs cannot share one Google Benchmark process, so the interleaving is done here: each of
`--rounds` rounds runs the selected benchmarks once in each build (`--benchmark_repetitions=1`),
the two builds in a shuffled order (seeded, the seed is printed), so that a change of machine load
falls on both alike. Every run's JSON is kept in `--out` (one file per round and build). The
ratio column is candidate / baseline of the medians over the rounds; "round ratios" is the range
of the per-round ratios (how much the load moved the figure).

  bench/compare_builds.py --baseline OLD/build/bench/geometry/bench_intersections \\
      --candidate build/bench/geometry/bench_intersections --filter 'BM_Plane' --rounds 9 \\
      --out build/compare-intersections

Arguments after `--` go to both programs (e.g. `-- --benchmark_min_time=0.2`). `--counter NAME`
(repeatable) adds a column with a user counter's value in each build (first round).
"""

import argparse
import json
import os
import random
import re
import statistics
import subprocess
import sys


def row_key(name):
    """A benchmark's name without Google Benchmark's "/iterations:N": programs that fix a row's
    iterations from a measured cost (bench_detection) name the same row differently in each build."""
    return re.sub(r"/iterations:\d+", "", name)


def run(program, benchmark_filter, extra, out_path):
    subprocess.run([program, "--benchmark_filter=" + benchmark_filter, "--benchmark_repetitions=1",
                    "--benchmark_out=" + out_path, "--benchmark_out_format=json"] + extra,
                   check=True, stdout=subprocess.DEVNULL)
    with open(out_path) as f:
        return [b for b in json.load(f)["benchmarks"] if b.get("run_type", "iteration") == "iteration"]


def parse(argv, defaults):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--baseline", required=True, help="the benchmark program of the old build")
    parser.add_argument("--candidate", required=True, help="the same program of the new build")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--filter", default=".", help="--benchmark_filter for both builds")
    parser.add_argument("--seed", type=int, default=23)
    parser.add_argument("--out", default=defaults.get("out", "build/compare-builds"))
    parser.add_argument("--counter", action="append", default=list(defaults.get("counters", [])),
                        help="a user counter to show beside the times (repeatable)")
    parser.add_argument("extra", nargs="*", help="after --: arguments for both programs")
    args = parser.parse_args(argv)
    if args.rounds < 1:
        raise SystemExit("--rounds %d: must be at least 1" % args.rounds)
    for build in ("baseline", "candidate"):
        program = getattr(args, build)
        if not (os.path.isfile(program) and os.access(program, os.X_OK)):
            raise SystemExit("--%s %s: not an executable file" % (build, program))
    return args


def format_counter(value):
    return "%d" % value if float(value).is_integer() else "%.4g" % value


def compare(args):
    os.makedirs(args.out, exist_ok=True)
    order = random.Random(args.seed)
    times = {"baseline": {}, "candidate": {}}  # build -> benchmark -> [run per round]
    for r in range(args.rounds):
        builds = ["baseline", "candidate"]
        order.shuffle(builds)
        for build in builds:
            program = getattr(args, build)
            for b in run(program, args.filter, args.extra, os.path.join(args.out, "%s_%d.json" % (build, r))):
                times[build].setdefault(row_key(b["name"]), []).append(b)
        print("round %d of %d done (%s first)" % (r + 1, args.rounds, builds[0]), file=sys.stderr)
    print("seed %d, %d interleaved rounds; medians; ratio = candidate / baseline" % (args.seed, args.rounds))
    print()
    counters = "".join(" | %s (baseline, candidate)" % c for c in args.counter)
    print("| benchmark | baseline wall | candidate wall | wall ratio | baseline CPU | candidate CPU | CPU ratio"
          " | CPU round ratios%s |" % counters)
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |" + " --- |" * len(args.counter))
    for name, base in times["baseline"].items():
        cand = times["candidate"].get(name)
        if not cand:
            continue
        unit = base[0]["time_unit"]
        med = lambda runs, key: statistics.median(x[key] for x in runs)
        bw, cw = med(base, "real_time"), med(cand, "real_time")
        bc, cc = med(base, "cpu_time"), med(cand, "cpu_time")
        per_round = [c["cpu_time"] / b["cpu_time"] for b, c in zip(base, cand)]
        cells = "".join(" | %s, %s" % (format_counter(base[0].get(c, float("nan"))),
                                       format_counter(cand[0].get(c, float("nan")))) for c in args.counter)
        print("| %s | %.4g %s | %.4g %s | %.3f | %.4g %s | %.4g %s | %.3f | %.3f-%.3f%s |" % (
            name, bw, unit, cw, unit, cw / bw, bc, unit, cc, unit, cc / bc, min(per_round), max(per_round), cells))


def main(argv=None, defaults=None):
    compare(parse(sys.argv[1:] if argv is None else argv, defaults or {}))


if __name__ == "__main__":
    main()
