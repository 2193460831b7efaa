#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The installed package, used as a user outside this repository would use it.
#
# usage: run_package_test.sh STEP SCRATCH [ARGS...]
#   install-shared BUILD_DIR             cmake --install BUILD_DIR into SCRATCH/prefix
#   install-static SOURCE_DIR CMAKE_ARGS  configure, build and install SOURCE_DIR with static
#                                         libraries (without tests, benchmarks, programs and
#                                         bindings other than C)
#   cmake-consumer CONSUMER_SOURCE       build the consumer project with find_package(clearjoint)
#                                         against SCRATCH/prefix and run its programs
#   pkg-config-consumer CONSUMER_SOURCE  compile the consumer's sources with the flags of
#                                         clearjoint-geometry.pc / clearjoint-dynamics.pc /
#                                         clearjoint-c.pc and run
#   installed-program SOURCE_DIR BUILD_PROGRAM
#                                         run SCRATCH/prefix/bin/clearjoint with an empty
#                                         environment and compare it with the build's program
#   exported-interface                   every entry of the exported link interface is a target
#                                         (Namespace::name), never a bare library name or path
#   octave-files SOURCE_DIR OCTAVE_DIR CPACK_CONFIG OCTAVE_CLI
#                                         every MEX gateway of SOURCE_DIR/bindings/matlab (a .c
#                                         file with a mexFunction) is installed in
#                                         SCRATCH/prefix/OCTAVE_DIR with its help text, `help`
#                                         and a call of each work from there, and the Debian
#                                         package's description (CPACK_CONFIG) names each
# Environment: CXX and CC, the compilers the consumers are built with, CXXFLAGS, CFLAGS and
# LDFLAGS, their C++, C and link flags (CMake reads them itself); CLEARJOINT_VERSION, the version
# the package must report; CLEARJOINT_WITH_DYNAMICS (ON, the default, or OFF), whether it must
# hold the dynamics module (without it, its consumer is not built).
set -euo pipefail
step=$1 scratch=$2
shift 2
prefix=$scratch/prefix
cxx=${CXX:-c++}
cc=${CC:-cc}
with_dynamics=${CLEARJOINT_WITH_DYNAMICS:-ON}
[[ $with_dynamics == ON || $with_dynamics == OFF ]] ||
  { echo "CLEARJOINT_WITH_DYNAMICS=$with_dynamics: must be ON or OFF" >&2; exit 2; }
fail() { echo "FAIL: $*" >&2; exit 1; }

case $step in
install-shared)
  build_dir=$1
  rm -rf "$prefix"
  cmake --install "$build_dir" --prefix "$prefix" > "$scratch.install.log" 2>&1 ||
    { cat "$scratch.install.log"; exit 1; }
  ;;
install-static)
  source_dir=$1
  shift
  rm -rf "$prefix"
  # The build folder is kept between runs: a rerun recompiles only what changed. Not when the
  # arguments changed: CMake drops a cache whose compiler changes and configures again without
  # the other -D values (BUILD_SHARED_LIBS would go back to ON), so the folder starts afresh.
  arguments="$source_dir $*"
  if [[ ! -f "$scratch.arguments" || "$(cat "$scratch.arguments")" != "$arguments" ]]; then
    rm -rf "$scratch/build"
  fi
  printf '%s' "$arguments" > "$scratch.arguments"
  cmake -S "$source_dir" -B "$scratch/build" -DBUILD_SHARED_LIBS=OFF \
        -DCLEARJOINT_BUILD_TESTS=OFF -DCLEARJOINT_BUILD_BENCHMARKS=OFF \
        -DCLEARJOINT_BUILD_APPS=OFF -DCLEARJOINT_BUILD_PYTHON=OFF -DCLEARJOINT_BUILD_MATLAB=OFF \
        -DCLEARJOINT_BUILD_FORTRAN=OFF "$@" > "$scratch.configure.log" 2>&1 ||
    { cat "$scratch.configure.log"; exit 1; }
  cmake --build "$scratch/build" -j2 > "$scratch.build.log" 2>&1 || { tail -50 "$scratch.build.log"; exit 1; }
  cmake --install "$scratch/build" --prefix "$prefix" > "$scratch.install.log" 2>&1 ||
    { cat "$scratch.install.log"; exit 1; }
  ls "$prefix"/lib*/libclearjoint_geometry.a > /dev/null || fail "no static library installed"
  ;;
cmake-consumer)
  consumer=$1
  rm -rf "$scratch/cmake-consumer"
  cmake -S "$consumer" -B "$scratch/cmake-consumer" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_C_COMPILER="$cc" -DCMAKE_PREFIX_PATH="$prefix" \
        -DCONSUMER_WITH_DYNAMICS="$with_dynamics"
  cmake --build "$scratch/cmake-consumer" -j2
  # Shared: the libraries are found through the consumer's build RPATH, and the dynamics library
  # finds the geometry library beside it through its own RUNPATH.
  "$scratch/cmake-consumer/consumer"
  if [[ $with_dynamics == ON ]]; then "$scratch/cmake-consumer/dynamics_consumer"; fi
  "$scratch/cmake-consumer/c_consumer"
  ;;
pkg-config-consumer)
  consumer=$1
  out=$scratch/pkg-config-consumer
  rm -rf "$out" && mkdir -p "$out"
  export PKG_CONFIG_PATH
  PKG_CONFIG_PATH=$(echo "$prefix"/lib*/pkgconfig)
  static=()
  if ls "$prefix"/lib*/libclearjoint_geometry.a > /dev/null 2>&1; then static=(--static); fi
  modules=(clearjoint-geometry clearjoint-c)
  if [[ $with_dynamics == ON ]]; then modules+=(clearjoint-dynamics); fi
  for module in "${modules[@]}"; do
    pkg-config --exists --print-errors "$module"
    [[ $(pkg-config --modversion "$module") == "$CLEARJOINT_VERSION" ]] ||
      fail "$module.pc says version $(pkg-config --modversion "$module"), the project $CLEARJOINT_VERSION"
  done
  # shellcheck disable=SC2046 # the flags are separate words
  # shellcheck disable=SC2086 # CXXFLAGS holds separate words
  "$cxx" ${CXXFLAGS:-} ${LDFLAGS:-} -std=c++20 -o "$out/consumer" "$consumer/main.cpp" \
    $(pkg-config "${static[@]}" --cflags --libs clearjoint-geometry)
  if [[ $with_dynamics == ON ]]; then
    # shellcheck disable=SC2046
    # shellcheck disable=SC2086
    "$cxx" ${CXXFLAGS:-} ${LDFLAGS:-} -std=c++20 -o "$out/dynamics_consumer" "$consumer/dynamics_main.cpp" \
      $(pkg-config "${static[@]}" --cflags --libs clearjoint-dynamics)
    echo "pkg-config ${static[*]} --libs clearjoint-dynamics: $(pkg-config "${static[@]}" --libs clearjoint-dynamics)"
  elif pkg-config --exists clearjoint-dynamics; then
    fail "clearjoint-dynamics.pc installed by a build without the dynamics module"
  fi
  # The C API from C, compiled by the C compiler.
  # shellcheck disable=SC2046
  # shellcheck disable=SC2086
  "$cc" ${CFLAGS:-} ${LDFLAGS:-} -std=c99 -o "$out/c_consumer" "$consumer/c_main.c" \
    $(pkg-config "${static[@]}" --cflags --libs clearjoint-c) -lm
  echo "pkg-config ${static[*]} --libs clearjoint-c: $(pkg-config "${static[@]}" --libs clearjoint-c)"
  # Shared: the .pc files' Libs give the programs a run path to the prefix's libraries; they run
  # with an empty environment (no LD_LIBRARY_PATH).
  env -i "$out/consumer"
  if [[ $with_dynamics == ON ]]; then env -i "$out/dynamics_consumer"; fi
  env -i "$out/c_consumer"
  ;;
installed-program)
  source_dir=$1 build_program=$2
  program=$prefix/bin/clearjoint
  [[ -x $program ]] || fail "$program not installed"
  # Each clearjoint library the program loads comes from the prefix, not from the build tree.
  for lib in libclearjoint_geometry libclearjoint_dynamics; do
    resolved=$(env -i ldd "$program" | awk -v lib="$lib" 'index($1, lib) == 1 { print $3 }')
    [[ $resolved == "$prefix"/* ]] || fail "$program loads $lib from '$resolved', not from $prefix"
  done
  version=$(env -i "$program" --version)
  [[ $version == "clearjoint $CLEARJOINT_VERSION" ]] || fail "--version printed '$version'"
  echo "$version"
  for command in detect intersect; do
    example=$source_dir/examples/$([[ $command == detect ]] && echo joints || echo rims).jsonl
    env -i "$program" "$command" "$example" > "$scratch/installed-$command.jsonl"
    "$build_program" "$command" "$example" > "$scratch/build-$command.jsonl"
    cmp "$scratch/installed-$command.jsonl" "$scratch/build-$command.jsonl" ||
      fail "the installed and the built program answer $example differently"
    echo "$command $example: $(wc -l < "$scratch/installed-$command.jsonl") lines, as the build's program"
  done
  ;;
exported-interface)
  targets=$(echo "$prefix"/lib*/cmake/clearjoint/clearjointTargets.cmake)
  # INTERFACE_LINK_LIBRARIES "a;b;\$<LINK_ONLY:c>": every entry, generator expressions unwrapped.
  entries=$(sed -n 's/^ *INTERFACE_LINK_LIBRARIES "\(.*\)"$/\1/p' "$targets" | tr ';' '\n' |
            sed -e 's/^\\\$<LINK_ONLY:\(.*\)>$/\1/' | sed '/^$/d')
  [[ -n $entries ]] || fail "no INTERFACE_LINK_LIBRARIES in $targets"
  while read -r entry; do
    [[ $entry =~ ^[A-Za-z0-9_]+::[A-Za-z0-9_]+$ ]] ||
      fail "exported link interface entry '$entry' is not a Namespace::target ($targets)"
  done <<< "$entries"
  echo "exported link interface: $(echo "$entries" | sort -u | tr '\n' ' ')"
  ;;
octave-files)
  source_dir=$1 octave_dir=$2 cpack_config=$3 octave_cli=$4
  installed=$prefix/$octave_dir
  mapfile -t gateways < <(grep -l '^void mexFunction' "$source_dir"/bindings/matlab/*.c | xargs -n1 basename | sed 's/\.c$//')
  ((${#gateways[@]} > 0)) || fail "no MEX gateway found in $source_dir/bindings/matlab"
  # The description the .deb octave-clearjoint carries (cmake/ClearjointPackage.cmake).
  description=$(sed -n '/^set(CPACK_DEBIAN_OCTAVE_DESCRIPTION/,/")$/p' "$cpack_config")
  [[ -n $description ]] || fail "no CPACK_DEBIAN_OCTAVE_DESCRIPTION in $cpack_config"
  for gateway in "${gateways[@]}"; do
    for file in "$gateway.mex" "$gateway.m"; do
      [[ -f $installed/$file ]] || fail "$file not installed in $installed"
    done
    grep -qw "$gateway" <<< "$description" ||
      fail "the octave-clearjoint description does not name $gateway: $description"
  done
  # From a folder outside the sources, Octave's start-up files left out: each help text, and one
  # call of each gateway on the shipped examples' shapes (the installed MEX files find the C API
  # library through their run path).
  mkdir -p "$scratch/octave-home"
  (cd "$scratch/octave-home" && HOME=$scratch/octave-home "$octave_cli" --norc --no-history --no-gui --quiet --eval "
    addpath('$installed');
    names = {$(printf "'%s', " "${gateways[@]}" | sed 's/, $//')};
    for name = names
      text = evalc(['help ' name{1}]);
      assert(!isempty(strfind(text, [name{1} '(dims, '])), [name{1} ': ' text]);
      assert(strcmp(which(name{1}), fullfile('$installed', [name{1} '.mex'])), which(name{1}));
    end
    d = struct('bearing_radius', 10, 'bearing_length', 20, 'journal_radius', 9.9, 'journal_length', 19.8);
    assert(cj_detect(d, [0 0 0 0 0 1], [0 0.15 0.02 0 0 1]).contact_count > 0);
    assert(cj_detect_many(d, [0 0 0 0 0 1], [0 0.15 0.02 0 0 1; 0 0 0 0 0 1]).contact_count(1) > 0);
    p = struct('hole_radius', 10, 'hole_length', 20, 'pin_radius', 9.9, 'stops', [-10.5 16; 10.5 16]);
    assert(cj_detect_pin_in_hole(p, [0 0 0 0 0 1], [0 0.15 0 0 0 1]).contact_count > 0);
    r = cj_detect_pin_in_hole_many(p, [0 0 0 0 0 1], [0 0.15 0 0 0 1; 0 0 0 0 0 1]);
    assert(isequal(r.contact_count > 0, [true; false]), mat2str(r.contact_count));
    printf('%d MEX gateways installed in %s with their help; each answers\\n', numel(names), '$installed');")
  ;;
*)
  fail "unknown step $step"
  ;;
esac
