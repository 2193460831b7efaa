#!/usr/bin/env bash
# The main job: install what is missing, build, run the shipped example.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
echo "== clearjoint intersect examples/rims.jsonl"
./build/apps/clearjoint/clearjoint intersect examples/rims.jsonl
