#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Configure and build clearjoint (Release) in ./build with 2 parallel jobs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build -j2
