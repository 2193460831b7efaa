#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds the Debian packages of clearjoint (cmake/ClearjointPackage.cmake: clearjoint,
# python3-clearjoint, octave-clearjoint, clearjoint-engines when built), runs lintian on them (an
# error fails the check; warnings are printed), installs them with `apt-get install ./*.deb` (which
# installs their Depends), then checks them as a user would: the program, a consumer built with
# find_package and with pkg-config (run with an empty environment), the Python package
# (tests/package/python_smoke.py), Octave's `help` of each MEX gateway and calls of cj_detect and
# cj_detect_pin_in_hole_many, the files Debian expects
# (multiarch libraries, copyright, docs, examples). Removes the packages again (`apt-get purge`).
# Needs root, dpkg and apt (Debian 12).
#
# usage: bash scripts/check-deb.sh [BUILD_DIR [CMAKE_ARGS...]]   (default build-deb; kept for reruns)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-deb}
shift || true
[[ $(id -u) -eq 0 ]] || { echo "check-deb: run as root (apt-get install / remove)" >&2; exit 2; }
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
for package in clearjoint python3-clearjoint octave-clearjoint clearjoint-engines; do
  if installed "$package"; then
    echo "check-deb: the package $package is installed already; remove it first" >&2
    exit 2
  fi
done
bash scripts/install-dependencies.sh
# dpkg-shlibdeps (for the packages' Depends) is in dpkg-dev.
installed dpkg-dev || DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends dpkg-dev

# Everything but the tests and benchmarks, for the prefix /usr (multiarch libdir, no run paths).
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr \
      -DCLEARJOINT_BUILD_TESTS=OFF -DCLEARJOINT_BUILD_BENCHMARKS=OFF "$@"
cmake --build "$build" -j2
rm -f "$build"/*.deb
(cd "$build" && cpack -G DEB)
debs=()
for deb in "$build"/*.deb; do debs+=("$(realpath "$deb")"); done
for deb in "${debs[@]}"; do
  echo "== $deb"
  dpkg-deb --info "$deb" | sed -n '/Package:/,$p'
  dpkg-deb --contents "$deb" | awk '{ print $6 }' | grep -v '/include/clearjoint/.*/\|/doc/clearjoint/docs/.*/'
done

# lintian: errors fail the check; warnings and the rest are shown (the packages are built by
# CPack, not from a Debian source package; README.md, "Using the library", says which remain).
echo "== lintian"
lintian_log=$(mktemp)
lintian --no-tag-display-limit "${debs[@]}" | tee "$lintian_log" || true
if grep -q '^E: ' "$lintian_log"; then
  echo "check-deb: lintian reports errors" >&2
  exit 1
fi

removed=0
packages=()
for deb in "${debs[@]}"; do packages+=("$(dpkg-deb --field "$deb" Package)"); done
remove() {
  if ((removed == 0)); then
    removed=1
    # purge: CPack's ldconfig scripts would otherwise keep the packages in dpkg's "rc" state.
    echo "== apt-get purge -y ${packages[*]}"
    apt-get purge -y -qq "${packages[@]}"
  fi
}
trap remove EXIT
echo "== apt-get install -y ${debs[*]}"
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${debs[@]}"

fail() { echo "check-deb: $*" >&2; exit 1; }
work=$(mktemp -d)
echo "== files Debian expects"
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
[[ -f /usr/lib/$multiarch/libclearjoint_geometry.so ]] || fail "no /usr/lib/$multiarch/libclearjoint_geometry.so"
for package in "${packages[@]}"; do
  [[ -f /usr/share/doc/$package/copyright ]] || fail "no /usr/share/doc/$package/copyright"
done
for file in README.md LICENSE CHANGELOG.md docs/python.md examples/joint_detection.cpp; do
  [[ -f /usr/share/doc/clearjoint/$file ]] || fail "no /usr/share/doc/clearjoint/$file"
done
echo "multiarch libraries, copyright per package, README, docs and examples: present"

echo "== clearjoint from /usr/bin"
clearjoint --version
# Into a file, then head: a pipe into head would end the program with SIGPIPE (pipefail).
clearjoint detect examples/joints.jsonl > "$work/detect.jsonl"
head -2 "$work/detect.jsonl"
echo "== a consumer with find_package(clearjoint) (tests/package/consumer)"
cmake -S tests/package/consumer -B "$work/cmake" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log"
cmake --build "$work/cmake" -j2 > "$work/build.log"
env -i "$work/cmake/consumer"
env -i "$work/cmake/dynamics_consumer"
echo "== a consumer with pkg-config, run with an empty environment"
# shellcheck disable=SC2046 # the flags are separate words
c++ -std=c++20 -o "$work/consumer" tests/package/consumer/main.cpp $(pkg-config --cflags --libs clearjoint-geometry)
# shellcheck disable=SC2046
c++ -std=c++20 -o "$work/dynamics_consumer" tests/package/consumer/dynamics_main.cpp \
    $(pkg-config --cflags --libs clearjoint-dynamics)
env -i "$work/consumer"
env -i "$work/dynamics_consumer"
if [[ " ${packages[*]} " == *" python3-clearjoint "* ]]; then
  echo "== the Python package (tests/package/python_smoke.py)"
  version=$(sed -n 's/^project(clearjoint VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
  (cd "$work" && env -u PYTHONPATH /usr/bin/python3 "$OLDPWD/tests/package/python_smoke.py" \
     /usr/lib/python3/dist-packages "$version" "$OLDPWD/models")
fi
if [[ " ${packages[*]} " == *" octave-clearjoint "* ]]; then
  echo "== Octave: help and a call of each MEX gateway"
  help=$(cd "$work" && octave-cli --norc --no-history --quiet --eval \
         'help cj_detect; help cj_detect_many; help cj_detect_pin_in_hole; help cj_detect_pin_in_hole_many' 2>&1)
  echo "$help" | head -4
  grep -q "result = cj_detect(dims, bearing, journal)" <<< "$help" || fail "help cj_detect prints no documentation"
  grep -q "r = cj_detect_many(dims, bearings, journals)" <<< "$help" || fail "help cj_detect_many prints no documentation"
  grep -q "result = cj_detect_pin_in_hole(dims, hole, pin)" <<< "$help" ||
    fail "help cj_detect_pin_in_hole prints no documentation"
  grep -q "r = cj_detect_pin_in_hole_many(dims, holes, pins)" <<< "$help" ||
    fail "help cj_detect_pin_in_hole_many prints no documentation"
  (cd "$work" && octave-cli --norc --no-history --quiet --eval \
     "d = struct('bearing_radius', 10, 'bearing_length', 20, 'journal_radius', 9.9, 'journal_length', 19.8);
      r = cj_detect(d, [0 0 0 0 0 1], [0 0.15 0.02 0 0 1]); printf('cj_detect: scenario %s\n', r.scenario);
      assert(r.contact_count > 0)
      p = struct('hole_radius', 10, 'hole_length', 20, 'pin_radius', 9.9, 'stops', [-10.5 16; 10.5 16]);
      r = cj_detect_pin_in_hole_many(p, [0 0 0 0 0 1], [0 0.15 0 0 0 1; 0 0 0 0 0 1]);
      printf('cj_detect_pin_in_hole_many: contact counts %s\n', mat2str(r.contact_count'));
      assert(isequal(r.contact_count > 0, [true; false]))")
fi
rm -rf "$work" "$lintian_log"
remove
for package in "${packages[@]}"; do
  installed "$package" && fail "$package still installed after removal"
done
echo "check-deb: ${packages[*]}: lintian without errors; they install, build consumers, run, and are removed again"
