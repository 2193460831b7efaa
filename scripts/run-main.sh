#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The main job: install what is missing, build, run the shipped examples and the paper's spatial
# slider-crank (Section 6.2) with its clearance joint.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
clearjoint=./build/apps/clearjoint/clearjoint
echo "== clearjoint intersect examples/rims.jsonl (certified rim/base and rim/wall intersections)"
"$clearjoint" intersect examples/rims.jsonl
echo "== clearjoint detect examples/joints.jsonl (contact scenarios of the paper's Fig. 2)"
"$clearjoint" detect examples/joints.jsonl
echo "== clearjoint simulate models/slider_crank_spatial_clearance.json (paper section 6.2, clearance joint)"
"$clearjoint" simulate models/slider_crank_spatial_clearance.json --out build/results/spatial_clearance --force --plot
echo "== the run's folder: the tables (CSV), model.json, summary.json, and its figures (clearjoint plot)"
ls build/results/spatial_clearance build/results/spatial_clearance/figures
