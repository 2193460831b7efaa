#!/usr/bin/env bash
# The main job: install what is missing, build, run the shipped example.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
echo "== clearjoint intersect examples/rims.jsonl (certified rim/base and rim/wall intersections)"
./build/apps/clearjoint/clearjoint intersect examples/rims.jsonl
echo "== clearjoint simulate models/slider_crank_spatial_ideal.json (paper section 6.2, ideal joints)"
./build/apps/clearjoint/clearjoint simulate models/slider_crank_spatial_ideal.json --out build/results/spatial_ideal
echo "results: build/results/spatial_ideal/ (body_*.csv, energy.csv, reactions.csv)"
tail -n 1 build/results/spatial_ideal/energy.csv
