#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Reproduce Section 6 of Marques et al. (2017) with the study runner: build the clearjoint program
# and its Python package, run the three Section 6 studies (studies/section6_mechanisms.json: the
# planar and spatial slider-cranks and the 4 x 4 clearance study at two tolerances, 37 runs;
# studies/section6_clearance.json: ensembles of 9 runs per point of the radial, axial and diagonal
# sweeps, 153 runs; studies/section6_settling.json: 11 variants behind the page's explanations)
# on a local Dask cluster (one worker per core) or an existing one, then draw Figs. 7-11 and 13-19
# (the single runs with clearjoint.plot's panels) and the ensemble figures into
# docs/figures/section6/ and regenerate the tables of docs/reports/reproduction.md from the stores,
# with the rows that moved since the page they replace.
#
#   bash scripts/reproduce-section6.sh                 # resumes: stored runs are not redone
#   bash scripts/reproduce-section6.sh --force         # redo every run (after changing the code)
#   bash scripts/reproduce-section6.sh --scheduler tcp://host:8786
#   BUILD_DIR=build-mine JOBS=1 bash scripts/reproduce-section6.sh
#
# Stores: results/section6_mechanisms/, results/section6_clearance/, results/section6_settling/
# (docs/studies.md); the numbers quoted in docs/reports/reproduction.md also go to
# results/section6/summary.json.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
run_options=("$@")
if [[ -n ${JOBS:-} && " $* " != *" --scheduler "* ]]; then run_options+=(--workers "$JOBS"); fi

cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DCLEARJOINT_BUILD_PYTHON=ON >/dev/null
cmake --build "$BUILD_DIR" -j2 --target clearjoint clearjoint_python_core

clearjoint="$BUILD_DIR/apps/clearjoint/clearjoint"
"$clearjoint" study run studies/section6_mechanisms.json --no-plot "${run_options[@]}"
"$clearjoint" study run studies/section6_clearance.json --no-plot "${run_options[@]}"
"$clearjoint" study run studies/section6_settling.json --no-plot "${run_options[@]}"
# The figures of both studies and the page's tables, by the interpreter the package was built for.
python=$(sed -n 's/^Python3_EXECUTABLE:FILEPATH=//p' "$BUILD_DIR/CMakeCache.txt")
PYTHONPATH="$BUILD_DIR/bindings/python${PYTHONPATH:+:$PYTHONPATH}" \
  exec "${python:-/usr/bin/python3}" scripts/reproduce_section6.py --update-docs
