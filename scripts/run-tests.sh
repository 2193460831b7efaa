#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The whole test suite: install what is missing, build, run ctest. Ends with ctest's summary.
#
# Before the main suite it runs the reduced sanitizer suite (scripts/run-sanitizers.sh --reduced:
# the joint-detection and command-line tests, the SIGKILL loop of `simulate` included, built with
# ASan+UBSan by Clang 14, and each libFuzzer target for FUZZ_SECONDS on its committed corpus), so
# that the main suite's summary stays the last line. A sanitizer report or a fuzz finding stops
# the run with a non-zero status. Then scripts/check-deb.sh builds, checks, installs and removes
# the Debian packages (as root).
#   FUZZ_SECONDS  seconds per fuzz target (default 30)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
# install-dependencies.sh (run by build.sh) installs clang-14; without it the sanitizer script
# would fall back to g++ and leave the fuzz targets out.
command -v clang++-14 >/dev/null ||
  { echo "run-tests: clang++-14 is missing (scripts/install-dependencies.sh installs it)" >&2; exit 1; }
bash scripts/run-sanitizers.sh --reduced --fuzz-seconds "${FUZZ_SECONDS:-30}"
# The Debian packages as a user installs them (lintian, install, consumers, the Python smoke
# script, Octave's help, purge): a second build, for /usr, in build-deb.
bash scripts/check-deb.sh build-deb
cd build
ctest --output-on-failure -j2
