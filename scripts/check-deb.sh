#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds the Debian package of clearjoint and checks it on this system: installs it with
# `apt-get install ./clearjoint_*.deb` (which installs its Depends), builds the packaging test's
# consumer against it with find_package and with pkg-config, runs the installed program, then
# removes the package again (`apt-get remove`). Needs root, dpkg and apt (Debian 12).
#
# usage: bash scripts/check-deb.sh [BUILD_DIR]     (default build-deb; kept for reruns)
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$PWD
build=${1:-build-deb}
[[ $(id -u) -eq 0 ]] || { echo "check-deb: run as root (apt-get install / remove)" >&2; exit 2; }
if dpkg-query -W -f='${Status}' clearjoint 2>/dev/null | grep -q "install ok installed"; then
  echo "check-deb: a clearjoint package is installed already; remove it first" >&2
  exit 2
fi
bash scripts/install-dependencies.sh
# dpkg-shlibdeps (for the package's Depends) is in dpkg-dev.
dpkg-query -W -f='${Status}' dpkg-dev 2>/dev/null | grep -q "install ok installed" ||
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends dpkg-dev

# The libraries and the program alone, for the prefix /usr (multiarch libdir).
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr \
      -DCLEARJOINT_BUILD_TESTS=OFF -DCLEARJOINT_BUILD_BENCHMARKS=OFF \
      -DCLEARJOINT_BUILD_PYTHON=OFF -DCLEARJOINT_BUILD_MATLAB=OFF -DCLEARJOINT_BUILD_FORTRAN=OFF
cmake --build "$build" -j2
rm -f "$build"/clearjoint_*.deb
(cd "$build" && cpack -G DEB)
deb=$(ls "$build"/clearjoint_*.deb)
echo "== $deb"
dpkg-deb --info "$deb" | sed -n '/Package:/,$p'
dpkg-deb --contents "$deb" | awk '{ print $6 }' | grep -v '/include/clearjoint/.*/' 

removed=0
remove() { if ((removed == 0)); then removed=1; echo "== apt-get remove -y clearjoint"; apt-get remove -y -qq clearjoint; fi; }
trap remove EXIT
echo "== apt-get install -y $deb"
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$PWD/$deb"

work=$(mktemp -d)
echo "== clearjoint from /usr/bin"
clearjoint --version
clearjoint detect examples/joints.jsonl | head -2
echo "== a consumer with find_package(clearjoint) (tests/package/consumer)"
cmake -S tests/package/consumer -B "$work/cmake" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log"
cmake --build "$work/cmake" -j2 > "$work/build.log"
"$work/cmake/consumer"
"$work/cmake/dynamics_consumer"
echo "== a consumer with pkg-config"
c++ -std=c++20 -o "$work/consumer" tests/package/consumer/main.cpp $(pkg-config --cflags --libs clearjoint-geometry)
c++ -std=c++20 -o "$work/dynamics_consumer" tests/package/consumer/dynamics_main.cpp \
    $(pkg-config --cflags --libs clearjoint-dynamics)
"$work/consumer"
"$work/dynamics_consumer"
rm -rf "$work"
remove
dpkg-query -W -f='${Status}' clearjoint 2>/dev/null | grep -q "install ok installed" &&
  { echo "check-deb: clearjoint still installed after removal" >&2; exit 1; }
echo "check-deb: $deb installs, builds consumers and runs, and is removed again"
