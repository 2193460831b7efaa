#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# usage: run_install_test.sh PYTHON BUILD_DIR SCRATCH_DIR SITE_DIR
# `cmake --install` into a scratch prefix, then import the package from there alone (not from the
# build tree): the module must find the installed clearjoint libraries through its run path.
set -euo pipefail
python=$1 build_dir=$2 scratch=$3 site=$4
rm -rf "$scratch"
cmake --install "$build_dir" --prefix "$scratch" > "$scratch.install.log" 2>&1 ||
  { cat "$scratch.install.log"; exit 1; }
cd "$scratch"
env -u PYTHONPATH PYTHONPATH="$scratch/$site" "$python" - "$scratch" <<'PY'
import sys
import clearjoint
assert clearjoint.__file__.startswith(sys.argv[1]), clearjoint.__file__
dims = clearjoint.JointDimensions(bearing_radius=10.0, bearing_length=20.0,
                                  journal_radius=9.9, journal_length=19.8)
result = clearjoint.detect(dims, [0, 0, 0], [0, 0, 1], [0, 0.15, 0.02], [0, 0, 1])
assert result.scenario == clearjoint.ContactScenario.line, result
print(f"clearjoint {clearjoint.__version__} imported from {clearjoint.__file__}: {result}")
# The viewer page loads only what its server serves from the install (docs/viewing-runs.md).
import os
import clearjoint.view.server
page = clearjoint.view.server.WEB_DIRECTORY
assert page.startswith(sys.argv[1]), page
for name in ("index.html", "main.js", "scene.js", "plots.js", "run_data.js", "viewer.css",
             "vendor/three.bundle.min.js", "vendor/three-LICENSE.txt"):
    assert os.path.isfile(os.path.join(page, name)), name
PY
