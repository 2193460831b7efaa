#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs the Debian 12 packages clearjoint needs, only those that are missing.
# Run as root (or with sudo available). Idempotent: a no-op when everything is there.
set -euo pipefail

packages=(
  cmake make g++                        # build
  libcgal-dev libgmp-dev libmpfr-dev    # exact predicates and constructions
  libeigen3-dev                         # linear algebra
  libboost-dev                          # Interval, Odeint, Multiprecision (header-only)
  libgtest-dev libbenchmark-dev         # tests and benchmarks
  nlohmann-json3-dev                    # JSON Lines and model files
  libhdf5-dev                           # simulate --format hdf5 (dynamics/run_folder)
  pkgconf                               # packaging test: a consumer built with pkg-config
  lintian                               # scripts/check-deb.sh: the Debian packages' checks
  python3 python3-matplotlib            # plots in docs/
  python3-jsonschema                    # tests: outputs and examples against docs/schema/
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest  # the Python package
  python3-pandas                        # Python: DetectionBatch tables as DataFrames
  octave octave-dev                     # MATLAB/Octave binding: octave-cli, mkoctfile (Debian 12's
                                        # liboctave-dev is only a transitional name for octave-dev)
  gfortran                              # Fortran binding
  clang-14 libclang-rt-14-dev           # run-sanitizers.sh, fuzz/: ASan, UBSan, libFuzzer
  python3-distributed python3-h5py python3-jsonschema python3-scipy python3-tqdm  # clearjoint.study
  chromium chromium-driver python3-selenium  # the viewer's browser test (docs/viewing-runs.md)
  libsimbody-dev libmujoco-dev          # the engine adapters (docs/engines.md)
  libsiconos-numerics-dev libfclib-dev  # the non-smooth integrator's contact solver (docs/nonsmooth.md)
  python3-siconos                       # tests: the non-smooth integrator against Siconos's kernel
  libsiconos-kernel-dev                 # tests: the same, in C++ (tests/nonsmooth/test_siconos_comparison.cpp)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install-dependencies: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-dependencies: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
