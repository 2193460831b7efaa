#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Reproduce Section 6 of Marques et al. (2017): build the clearjoint program, run the slider-crank
# models (planar and spatial, ideal and with the clearance joint, the 4 x 4 clearance study and
# ensembles of 9 slightly perturbed runs per point of its three sweeps (and of the radial and axial
# sweeps at tolerance 1e-8), in parallel on all cores)
# and draw Figs. 7-11 and 13-19 and the ensemble statistics into docs/figures/section6/.
#
#   bash scripts/reproduce-section6.sh            # resumes: finished runs are not redone
#   bash scripts/reproduce-section6.sh --force    # redo every run (after changing the code)
#   BUILD_DIR=build-mine JOBS=1 bash scripts/reproduce-section6.sh
#
# Results (reduced time series, one .npz per run, written atomically) go to results/section6/,
# the numbers quoted in docs/reproduction.md to results/section6/summary.json. Measured at af1c323:
# 1.8-7.8 s per run on one core of a 2-core machine, about 6 min for all 190 runs with 2 jobs.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-$(nproc)}

cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD_DIR" -j2 --target clearjoint

# numpy and matplotlib come from Debian (python3-matplotlib); another python3 earlier on PATH
# (pyenv, a virtualenv) may not have them.
PYTHON=${PYTHON:-python3}
if ! "$PYTHON" -c "import matplotlib, numpy" 2>/dev/null; then
  PYTHON=/usr/bin/python3
fi
exec "$PYTHON" scripts/reproduce_section6.py --clearjoint "$BUILD_DIR/apps/clearjoint/clearjoint" \
  --jobs "$JOBS" "$@"
