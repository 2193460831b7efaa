#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes docs/reports/benchmarks-kernel.md from the JSON of bench_intersections and
bench_detect_contacts.

    python3 bench/make_kernel_report.py INTERSECTIONS.json DETECTION.json OUT.md

bench/run_kernel_bench.sh runs both benchmarks and then this script. The page is reference text
(how the benchmarks are built, run and read) around tables generated from the two runs, with one
provenance line at the top: commit, date, compiler options, machine load.
"""
import json
import sys

from report_provenance import provenance as page_provenance


def medians(path):
    data = json.load(open(path))
    runs = sorted(data["benchmarks"], key=lambda r: (r.get("family_index", 0), r.get("per_family_instance_index", 0)))
    median = {}
    cv = {}
    for r in runs:
        if r.get("aggregate_name") == "median":
            median[r["run_name"]] = r
        elif r.get("aggregate_name") == "cv":
            cv[r["run_name"]] = r
    return data["context"], median, cv


COUNTER_SKIP = {"iterations", "real_time", "cpu_time", "time_unit", "repetitions", "threads", "name", "run_name",
                "run_type", "aggregate_name", "aggregate_unit", "family_index", "per_family_instance_index",
                "repetition_index", "rims_per_s", "items_per_second", "poses_per_s", "detections_per_s"}


def shares(r):
    parts = []
    for key, value in r.items():
        if key in COUNTER_SKIP or not isinstance(value, (int, float)) or value == 0:
            continue
        parts.append(f"{key} {value:.3g}")
    return ", ".join(parts)


def time_table(median, cv):
    lines = ["| benchmark | median CPU ns | CPU cv | counters (shares of the inputs) |", "| --- | ---: | ---: | --- |"]
    for name, r in median.items():
        spread = f"{100 * cv[name]['cpu_time']:.1f}%" if name in cv else ""
        lines.append(f"| `{name}` | {r['cpu_time']:.1f} | {spread} | {shares(r)} |")
    return "\n".join(lines)


def ratio_table(median, pairs):
    lines = ["| ratio of median CPU times (same run) | value |", "| --- | ---: |"]
    for name, r in median.items():
        stem, _, variant = name.rpartition("/")
        for mine, other in pairs:
            base = f"{stem}/{other}"
            if variant == mine and base in median:
                lines.append(f"| `{stem}`: {mine} / {other} | {r['cpu_time'] / median[base]['cpu_time']:.2f} |")
    return "\n".join(lines)


def provenance(context):
    return page_provenance(context, "bash bench/run_kernel_bench.sh")


TEMPLATE = """# Kernel benchmarks: what a rim query and a detection cost

{provenance}

`bench/geometry/bench_intersections.cpp` (Google Benchmark) times the two queries of the geometry
kernel, `intersect_circle_cylinder` and `intersect_circle_plane`, on the joint of the paper's Table
2, with the certificate on (the default), off (`certify = false`, the plain double pipeline), and
with the exact fallback off. `bench/geometry/bench_detect_contacts.cpp` times the full-joint
`detect_contacts` on Table 2 poses. Each binary runs all its rows in one run, their repetitions
interleaved, so the ratios below compare like with like. [benchmarks.md](benchmarks.md) holds the
detection suite (accuracy against an MPFR reference, and the paper's method beside it).

## Running it

    bash bench/run_kernel_bench.sh

builds both benchmarks (Release, `-j2`) in `./build`, runs each with
`--benchmark_repetitions=$REPETITIONS` (default 10) `--benchmark_enable_random_interleaving=true
--benchmark_report_aggregates_only=true` and JSON output (`build/bench_intersections.json`,
`build/bench_detect_contacts.json`: every aggregate and the context, seed included), and writes
this page with `bench/make_kernel_report.py`. `BUILD_DIR` builds elsewhere, `CMAKE_ARGS` adds
configure options (e.g. `-DCLEARJOINT_X86_64_V2=ON`), `REPORT` writes the page elsewhere. Keep the
machine otherwise idle while it runs. To compare two builds, run both binaries in one shell loop
with interleaved repetitions and compare ratios, never figures from different runs: absolute
times on a shared VM drift by 15-30 % over an hour while instruction counts do not.

Google Benchmark's console says `***WARNING*** Library was built as DEBUG`: that refers to
Debian's `libbenchmark` package itself, not to clearjoint, which is built Release (`-O3`, no
`-ffast-math`).

## Compilers and build options

The kernel is built with Debian's GCC 12 at `-O3`, without link-time or profile-guided
optimisation: neither made detection faster. Each variant below built `libclearjoint_geometry.so`
alone and was loaded (`LD_LIBRARY_PATH`) by the default GCC build's `bench_detection` (realistic
family) and `bench_detect_contacts` (`detect/in_contact` rows), so the paper's method, which is
compiled into those programs, is the same code on both sides; only the Clang row rebuilt the
programs too. `bench/compare_builds.py` ran each variant against the default build in 9 or 11
interleaved rounds (CPU time, medians; a 2-core AMD EPYC shared with other builds, where single
rounds moved by up to 10-30 %, so differences of a few per cent are noise). `dump_answers`
(192,000 answers, every field in `%a`) gave the same output bit for bit for every variant.

| build of the kernel | realistic: certified / default build | realistic: certified / paper | in contact: certified / default build | in contact: certified / paper |
| --- | ---: | ---: | ---: | ---: |
| GCC 12 `-O3` (default) | 1.00 | 1.23-1.30 | 1.00 | 1.19-1.26 |
| + LTO (`-flto`) | 1.01 | 1.29 | 1.11 | 1.35 |
| + LTO, `-fno-semantic-interposition` | 1.09 | 1.34 | 1.12 | 1.33 |
| + PGO | 0.98 | 1.22 | 1.00 | 1.25 |
| + LTO + PGO | 1.00 | 1.29 | 1.00 | 1.17 |
| + `-fno-trapping-math` | 0.98 | 1.24 | 1.00 | 1.28 |
| Clang 14 kernel, GCC programs | 0.94 | 1.21 | 0.96 | 1.21 |
| Clang 14, kernel and programs | 0.98 | 1.11 | 0.97 | 1.12 |

PGO was trained on `bench_detection --suite=quick` (the detection suite's five families) and the
certified rows of `bench_detect_contacts`. It would also tie the Debian and pip builds either to a
training run inside the build or to committed profiles, which are specific to one compiler
version and go stale with every change to the kernel. The Clang build's lower ratios are mostly
the paper's method running 8-9 % slower under Clang (its certified detection is 3-5 % faster):
the gap to the paper's method is in the algorithms, not in the code generation.

## Inputs

Metres, the bearing frame is the world frame: bearing axis +z through the origin, wall radius
Ri = 10 mm, base B the plane z = +Li/2 = 10 mm with its normal pointing out of the bearing. A
journal pose is a centre P_j and an axis a_j; the rim at base B is the circle of centre
P_j + (Lj/2) a_j, normal a_j, radius Rj = 9.9 mm (paper Fig. 5). Random sets hold 4096 inputs drawn
from `std::mt19937_64` (seed 20170823 for the queries, 20170824 for detection, each set seed + its
index, with an explicit 53-bit conversion so that any standard library gives the same inputs); the
timed loop cycles through them. Outcome shares are counted before timing, one call per input.

| benchmark | inputs |
| --- | --- |
| `circle_cylinder/random_pose` | offset of P_j off the bearing axis uniform in [0, 1.5 cr], tilt of a_j uniform in [0, 2 cr/Lj], both azimuths uniform |
| `circle_cylinder/well_inside` | offset up to 0.25 cr, tilt up to 0.25 (2 cr/Lj): the rim stays half a clearance inside the wall |
| `circle_cylinder/aligned_journal` | as `random_pose` with tilt 0 (the planar mechanism of paper Section 6.1) |
| `circle_plane/random_pose` | P_j moved axially by [0, 2 ca], radially up to 1.5 cr, tilt as above: about half the rims cross the base |
| `circle_plane/aligned_journal` | as above with tilt 0: rims parallel to the base |
| `circle_cylinder/exact_tangency` | 11 exactly tangent configurations with small integer coordinates (wall radius 2 about z, rim centre (1, 0, 0), normal z, radius 1, and variations) |
| `circle_cylinder/near_tangency_1e-15cr` | Table 2 rims perpendicular to the axis whose farthest point is 1e-15 cr inside or beyond the wall |
| `circle_plane/exact_tangency` | 5 exact tangencies: integer rims perpendicular to the plane, a 3-4-5 tilt, Table 2 in micrometres |
| `circle_plane/near_tangency_1ulp` | the micrometre Table 2 tangency with the rim centre moved by one ulp either way |
| `detect/in_contact` | Table 2 poses (centre up to 1.5 cr off the axis and 1.5 ca along it, tilt up to 2 cr/Lj) with at least one contact |
| `detect/free_flight` | the same poses with no contact |
| `detect/aligned_*` | the same with the journal aligned (tilt 0) |

Variants: `certified` = default options; `uncertified` = `{{.certify = false}}`;
`no_exact_fallback` = `{{.exact_fallback = false}}` (the cost of the floating-point attempt alone,
before it hands over to exact arithmetic; those answers are `uncertain`); `certified_reused_result`
= the overload of `detect_contacts` that writes into the caller's `JointContacts` (a simulation
step's use).

Counters: `inside`, `outside`, `crossing`, `roots4` (four roots with multiplicity), `tangent` (a
crossing of multiplicity >= 2), `on_surface`, `disjoint`, `in_plane`: share of the inputs with that
outcome; `cert_exact`, `cert_certified`, `cert_uncertain`: share per certificate level.

## Kernel queries

{query_table}

{query_ratios}

## Full-joint detection

{detect_table}

{detect_ratios}

`build/bench/geometry/bench_detection_parts` times the parts of the in-contact detection alone on
the same poses (the circle-cylinder query of each rim that crosses the wall, its rim distance
polynomial and certified roots, the circle-plane query of each rim that crosses a base plane), with
`per_pose` the average count of each per detection. Its rows are throughput figures: a part can
get faster there and the detection not, so judge a change by `bench_detect_contacts` and use the
parts to see where it acts.

## Reading the figures

* **Certifying costs little, because the plain pipeline is not much cheaper.** `certify = false`
  runs the same root search without the proofs, and the proofs are cheap: tier 1 of the
  circle-cylinder roots proves with an a priori bound in plain double, and the circle-plane
  quantities too. The cost is the root isolation itself: the first-harmonic proof, Halley's
  iteration by angle addition, the polynomial's coefficients, the input checks and magnitude
  guards. Uncertified aligned-journal rims can even be slower than certified ones: their iteration
  calls libm's sine and cosine each step, where the certified path reuses one sine-cosine per root
  by angle addition.
* **The quick rejection works:** a rim well inside the wall costs a fraction of a random pose, and
  free flight a fraction of a detection in contact: the candidate prefilters prove all four
  candidates clear at once, straight from the poses.
* **The exact fallback is the expensive path,** hundreds of times a random wall query. At an
  exact tangency the subdivision tier stops as soon as the exact roots prove the tangency it
  could never certify (docs/circle-cylinder.md, section 3.1), so most of a `certified` row is the
  exact tier itself. A `no_exact_fallback` row instead runs the failing search to its end, and
  then the uncertified search for its best guess. On inputs far from the paper's scale the exact
  tier is slower still, because its integers grow with the inputs' binary exponents (the
  `extreme` family of [benchmarks.md](benchmarks.md)).
* **Why the first harmonic starts tier 1.** On realistic poses the rim distance polynomial is
  dominated by its first harmonic (offset term) next to the second (tilt term), so the roots of
  k0 + A cos(theta - phi) are within about 1e-3 rad of the true ones; two Halley steps from there
  settle each root, and one proof by the slope encloses it (docs/circle-cylinder.md, section 2).
* **Why not CGAL's Interval_nt or Boost.Interval** for the filters: both switch the FPU's rounding
  mode around each operation, which costs more than the whole a priori filter and keeps the
  compiler from vectorising; running-error bounds in round-to-nearest (error_bounded.hpp) give
  the same guarantees at a fraction of the cost.
* The coefficient of variation is large for the short, allocation-heavy exact rows: compare their
  ratios, not their digits.
"""


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    context, query_median, query_cv = medians(sys.argv[1])
    _, detect_median, detect_cv = medians(sys.argv[2])
    page = TEMPLATE.format(
        provenance=provenance(context),
        query_table=time_table(query_median, query_cv),
        query_ratios=ratio_table(query_median, [("certified", "uncertified"), ("certified", "no_exact_fallback")]),
        detect_table=time_table(detect_median, detect_cv),
        detect_ratios=ratio_table(detect_median, [("certified", "uncertified"),
                                                  ("certified_reused_result", "certified")]),
    )
    with open(sys.argv[3], "w") as out:
        out.write(page)


if __name__ == "__main__":
    main()
