#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""dynamics_slider_crank_bench from two builds side by side, the ratio of their median times as a
Markdown table (docs/reports/benchmarks-dynamics.md has one build's figures):
bench/compare_builds.py with the dynamics' defaults, the output under build/bench-dynamics and the
step counts beside the times.

  bench/dynamics/compare_builds.py --baseline OLD/build/bench/dynamics/dynamics_slider_crank_bench \\
      --candidate build/bench/dynamics/dynamics_slider_crank_bench --rounds 5
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import compare_builds  # noqa: E402  (bench/compare_builds.py)

if __name__ == "__main__":
    compare_builds.main(defaults={"out": "build/bench-dynamics", "counters": ["steps"]})
