# SPDX-License-Identifier: BSD-3-Clause
"""A short tour of an installed clearjoint Python package, as a new user would take it: import,
detect on one pose and on a batch, the pin-in-hole joint on a batch, the two kernel queries, a short simulation of a shipped model,
and the study runner, figures and viewer that come with the package.

usage: python python_smoke.py INSTALL_ROOT VERSION MODELS_DIR

INSTALL_ROOT is where the package must be imported from (a virtual environment, a prefix): not
the source tree or a build tree. Run it from a folder outside the repository.
"""
import json
import os
import sys

import numpy as np

install_root, version, models_dir = sys.argv[1], sys.argv[2], sys.argv[3]
install_root = os.path.realpath(install_root)

import clearjoint  # noqa: E402
import clearjoint._core  # noqa: E402


def check(condition, what):
    if not condition:
        sys.exit(f"python_smoke: {what}")


for module in (clearjoint, clearjoint._core):
    where = os.path.realpath(module.__file__)
    check(where.startswith(install_root + os.sep), f"{module.__name__} imported from {where}, not from {install_root}")
check(clearjoint.__version__ == version, f"clearjoint.__version__ = {clearjoint.__version__}, the project {version}")

# One pose: the journal off-centre by 0.15 in a bearing of radial clearance 0.1, axes parallel.
dims = clearjoint.JointDimensions(bearing_radius=10.0, bearing_length=20.0,
                                  journal_radius=9.9, journal_length=19.8)
one = clearjoint.detect(dims, [0, 0, 0], [0, 0, 1], [0, 0.15, 0.02], [0, 0, 1])
check(one.scenario == clearjoint.ContactScenario.line, f"one pose: {one}")
check(one.certificate.level == clearjoint.Certainty.certified, f"one pose: {one.certificate}")

# A batch of poses on two threads.
rng = np.random.default_rng(20261128)
centres = rng.uniform(-0.2, 0.2, (1000, 3))
batch = clearjoint.detect(dims, [0, 0, 0], [0, 0, 1], centres, [0, 0, 1], threads=2)
check(len(batch) == 1000, f"batch of {len(batch)} poses")
table = batch.as_dict()
check(len(table["scenario"]) == 1000, f"batch fields {sorted(table)}")

# The pin-in-hole joint on a batch: the pin off-centre by 0.15 in a hole of radial clearance 0.1
# (a line contact along the bore) and centred (none), packed as PinInHoleBatch; row by row the
# single calls' answers.
pin_dims = clearjoint.PinInHoleDimensions(hole_radius=10.0, hole_length=20.0, pin_radius=9.9,
                                          stops=((-10.5, 16.0), (10.5, 16.0)))
pins = np.array([[0, 0.15, 0], [0, 0, 0]], dtype=float)
pin_batch = clearjoint.detect_pin_in_hole(pin_dims, [0, 0, 0], [0, 0, 1], pins, [0, 0, 1], threads=2)
check(isinstance(pin_batch, clearjoint.PinInHoleBatch) and len(pin_batch) == 2, f"pin-in-hole batch: {pin_batch!r}")
check(pin_batch.scenarios() == [clearjoint.PinInHoleScenario.line, clearjoint.PinInHoleScenario.none],
      f"pin-in-hole batch scenarios: {pin_batch.scenarios()}")
for n, pin in enumerate(pins):
    single = clearjoint.detect_pin_in_hole(pin_dims, [0, 0, 0], [0, 0, 1], pin, [0, 0, 1])
    check(pin_batch[n].as_dict() == single.as_dict(), f"pin-in-hole pose {n}: {pin_batch[n]} != {single}")

# The kernel: a unit circle against the plane z = 0.5 and a cylinder of radius 1.5.
plane = clearjoint.intersect_circle_plane([0, 0, 0], [1, 0, 0], 1.0, [0, 0, 0.5], [0, 0, 1])
check(len(plane.crossings) == 2, f"circle-plane: {plane}")
cylinder = clearjoint.intersect_circle_cylinder([0.8, 0, 0], [0, 0, 1], 1.0, [0, 0, 0], [0, 0, 1], 1.5)
check(len(cylinder.crossings) == 2, f"circle-cylinder: {cylinder}")

# A shipped model, simulated for 2 ms.
with open(os.path.join(models_dir, "slider_crank_spatial_clearance.json")) as f:
    model = json.load(f)
model["solver"]["end_time"] = 2e-3
model["solver"]["report_step"] = 1e-4
run = clearjoint.simulate(model)
check(len(run.tables) > 0 and all(len(next(iter(t.values()))) > 0 for t in run.tables.values()),
      f"simulate: tables {sorted(run.tables)}")

# The same run written as one HDF5 file and read back, and the model stepped by hand with a load.
import tempfile  # noqa: E402

with tempfile.TemporaryDirectory() as scratch:
    folder = os.path.join(scratch, "run")
    written = clearjoint.simulate(model, out=folder, format="hdf5")
    check(os.path.isfile(os.path.join(folder, "run.h5")), f"simulate to HDF5: {os.listdir(folder)}")
    back = clearjoint.read_run(folder)
    check(all(np.array_equal(back[t][c], run[t][c], equal_nan=True) for t in run.tables for c in run[t]),
          "read_run gives other numbers than simulate")
sim = clearjoint.Simulator(model)
sim.apply_load("crank", moment=[0.0, 0.01, 0.0])
sim.advance_to(1e-3)
check(abs(sim.time - 1e-3) < 1e-15, f"Simulator.advance_to(1e-3) ended at {sim.time}")

# What else the package holds: the study runner with its schema, figures, the viewer's page.
import clearjoint.plot  # noqa: E402
import clearjoint.study  # noqa: E402
import clearjoint.view.server  # noqa: E402

study_schema = os.path.join(os.path.dirname(clearjoint.study.__file__), "study-v1.schema.json")
check(os.path.isfile(study_schema), f"no {study_schema}")
page = os.path.realpath(clearjoint.view.server.WEB_DIRECTORY)
for name in ("index.html", "main.js", "scene.js", "plots.js", "run_data.js", "viewer.css",
             "vendor/three.bundle.min.js", "vendor/three-LICENSE.txt"):
    check(os.path.isfile(os.path.join(page, name)), f"the viewer's {name} is not in {page}")
check(os.path.isfile(os.path.join(os.path.dirname(clearjoint.__file__), "py.typed")), "no py.typed")

# The `clearjoint` command pip installs into a virtual environment: plot, view and study run from
# the package; the C++ program's subcommands are refused with a line saying how to get the program
# (none is on PATH). A Debian install has the C++ program itself as /usr/bin/clearjoint, from the
# clearjoint package, and no Python command (scripts/check-deb.sh runs that program).
import subprocess  # noqa: E402

pip_install = os.path.isfile(os.path.join(install_root, "pyvenv.cfg"))
command = os.path.join(install_root, "bin", "clearjoint")
if pip_install:
    check(os.path.isfile(command) and os.access(command, os.X_OK), f"pip installed no clearjoint command in {command}")
bare = dict(os.environ, PATH=os.path.dirname(command) + os.pathsep + "/usr/bin:/bin")
bare.pop("CLEARJOINT_PROGRAM", None)


def clearjoint_command(*args):
    return subprocess.run([command, *args], capture_output=True, text=True, env=bare, timeout=120)


if pip_install:
    done = clearjoint_command("--version")
    check(done.returncode == 0 and version in done.stdout, f"clearjoint --version: {done}")
    for sub in ("study", "plot", "view"):
        done = clearjoint_command(sub, "--help")
        check(done.returncode == 0 and f"usage: clearjoint {sub}" in done.stdout, f"clearjoint {sub} --help: {done}")
    done = clearjoint_command("simulate", os.path.join(models_dir, "slider_crank_spatial_clearance.json"))
    check(done.returncode == 2 and "C++ program `clearjoint`, which pip does not install" in done.stderr
          and "Traceback" not in done.stderr, f"clearjoint simulate without the C++ program: {done}")

print(f"python_smoke: clearjoint {clearjoint.__version__} from {os.path.dirname(clearjoint.__file__)}: "
      f"detect (1 pose, {len(batch)} poses), detect_pin_in_hole ({len(pin_batch)} poses), kernel, simulate ({', '.join(sorted(run.tables))}), "
      "simulate to HDF5, Simulator, "
      "study, plot, view" + (", the clearjoint command" if pip_install else ""))
