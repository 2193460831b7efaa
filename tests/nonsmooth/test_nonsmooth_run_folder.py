# SPDX-License-Identifier: BSD-3-Clause
"""A solver.method "moreau_jean" model run from the front-ends (docs/nonsmooth.md, "Run folder"):
the program's simulate and Python's simulate write the compliant run's tables and columns, the
clearance joint's with its percussion columns after them, and plot reads the folder."""
import csv
import json
import os
import subprocess

import clearjoint
import pytest

CLI = os.environ.get("CLEARJOINT_CLI")
STEP = 1e-5

# A journal (0.5 kg) moving sideways and down in a bearing on the ground (0.1 mm clearance):
# its first impact comes after about 0.2 ms.
MODEL = {
    "name": "journal in bearing", "gravity": [0, -9.81, 0],
    "bodies": [{"name": "journal", "mass": 0.5, "inertia": [1e-4, 1e-4, 2e-5],
                "position": [0, 0, 0], "velocity": [0.3, -0.5, 0]}],
    "forces": [{"type": "clearance_revolute", "name": "joint",
                "bearing": {"body": "ground", "point": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.01, "length": 0.02},
                "journal": {"body": "journal", "point": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.0099,
                            "length": 0.0198},
                "normal_force": {"model": "hertz", "stiffness": 1e11, "exponent": 1.5, "restitution": 0.9},
                "friction": {"coefficient": 0.1}}],
    "solver": {"end_time": 2e-3, "report_step": STEP},
}


def model_file(tmp_path, method):
    model = json.loads(json.dumps(MODEL))
    if method == "moreau_jean":
        model["solver"].update({"method": "moreau_jean", "step": STEP})
    path = tmp_path / f"{method}.json"
    path.write_text(json.dumps(model))
    return path


def header(path):
    with open(path, newline="") as f:
        return next(csv.reader(f))


def rows(path):
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        return [{k: float(v) for k, v in row.items()} for row in reader]


@pytest.mark.skipif(not CLI, reason="needs the clearjoint program (CLEARJOINT_CLI)")
def test_simulate_writes_a_moreau_jean_run_with_the_compliant_runs_tables_and_plot_reads_it(tmp_path):
    for method in ("dormand_prince", "moreau_jean"):
        subprocess.run([CLI, "simulate", str(model_file(tmp_path, method)), "--out", str(tmp_path / method)],
                       check=True, capture_output=True, text=True)
    compliant, rigid = tmp_path / "dormand_prince", tmp_path / "moreau_jean"
    tables = sorted(p.name for p in compliant.glob("*.csv"))
    assert tables == sorted(p.name for p in rigid.glob("*.csv"))
    for name in tables:
        if name != "force_joint.csv":
            assert header(rigid / name) == header(compliant / name), name
    extra = [f"{slot}.{q}" for slot in ("radial_a", "radial_b", "line", "axial_a", "axial_b")
             for q in ("normal_percussion", "friction_percussion", "rebound_speed")]
    assert header(rigid / "force_joint.csv") == header(compliant / "force_joint.csv") + extra

    # The force columns are the step's mean contact force: percussion / h.
    impacts = [r for r in rows(rigid / "force_joint.csv") if r["line.normal_percussion"] > 0]
    assert impacts, "no impact in 2 ms"
    for r in impacts:
        assert r["line.normal_force"] == pytest.approx(r["line.normal_percussion"] / STEP, rel=1e-12)
        assert r["contact_count"] >= 1
        assert (r["fx"] ** 2 + r["fy"] ** 2) ** 0.5 >= r["line.normal_force"] * (1 - 1e-12)
    summary = json.loads((rigid / "summary.json").read_text())
    assert summary["element_statistics"][0].startswith("moreau_jean: 200 steps")

    figures = tmp_path / "figures"
    done = subprocess.run([CLI, "plot", str(rigid), "--out", str(figures)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert list(figures.glob("*.png"))


def test_python_simulate_runs_a_moreau_jean_model_in_memory(tmp_path):
    result = clearjoint.simulate(str(model_file(tmp_path, "moreau_jean")))
    assert "force_joint" in result.tables and "energy" in result.tables
    assert result.summary["element_statistics"][0].startswith("moreau_jean: 200 steps")
    folder = clearjoint.simulate(str(model_file(tmp_path, "moreau_jean")), out=tmp_path / "run")
    assert clearjoint.read_run(tmp_path / "run") is not None
    assert folder is not None


def test_another_engine_refuses_a_moreau_jean_model_naming_solver_method(tmp_path):
    from clearjoint import _core
    if "simbody" not in _core.engines():
        pytest.skip("this build has no second engine")
    with pytest.raises(ValueError, match="solver.method"):
        clearjoint.simulate(str(model_file(tmp_path, "moreau_jean")), engine="simbody")


@pytest.mark.skipif(not CLI, reason="needs the clearjoint program (CLEARJOINT_CLI)")
def test_simulate_write_fclib_writes_the_first_contact_problems_as_fclib_files(tmp_path):
    h5py = pytest.importorskip("h5py")
    done = subprocess.run([CLI, "simulate", str(model_file(tmp_path, "moreau_jean")), "--out", str(tmp_path / "run"),
                           "--write-fclib", str(tmp_path / "fclib"), "--fclib-count", "2"],
                          check=True, capture_output=True, text=True)
    assert "2 contact problems written as FCLIB files" in done.stdout
    files = sorted((tmp_path / "fclib").glob("step_*.hdf5"))
    assert len(files) == 2
    for path in files:
        with h5py.File(path, "r") as f:
            assert int(f["fclib_local/spacedim"][()]) == 3
            n = len(f["fclib_local/vectors/q"][()])
            assert n % 3 == 0 and len(f["solution/r"][()]) == n


@pytest.mark.skipif(not CLI, reason="needs the clearjoint program (CLEARJOINT_CLI)")
def test_simulate_refuses_a_write_fclib_path_that_is_a_file_naming_the_option(tmp_path):
    (tmp_path / "file").write_text("not a folder")
    done = subprocess.run([CLI, "simulate", str(model_file(tmp_path, "moreau_jean")), "--out", str(tmp_path / "run"),
                           "--write-fclib", str(tmp_path / "file")], capture_output=True, text=True)
    assert done.returncode != 0
    assert f"--write-fclib = '{tmp_path / 'file'}': not a folder" in done.stderr
    assert "Traceback" not in done.stderr and not (tmp_path / "run").exists()


@pytest.mark.skipif(not CLI, reason="needs the clearjoint program (CLEARJOINT_CLI)")
def test_simulate_refuses_write_fclib_for_a_compliant_model(tmp_path):
    done = subprocess.run([CLI, "simulate", str(model_file(tmp_path, "dormand_prince")), "--out",
                           str(tmp_path / "run"), "--write-fclib", str(tmp_path / "fclib")],
                          capture_output=True, text=True)
    assert done.returncode != 0
    assert "--write-fclib" in done.stderr and "moreau_jean" in done.stderr
    assert not (tmp_path / "fclib").exists()


def test_impacts_by_scenario_counts_each_slots_onsets_and_the_energy_lost(tmp_path):
    """nonsmooth/scripts/impacts_by_scenario.py, which produces docs/nonsmooth.md's spatial table."""
    import sys
    slots = ("radial_a", "radial_b", "line", "axial_a", "axial_b")
    (tmp_path / "energy.csv").write_text("time,total\n0,1.0\n1,0.75\n")
    header = ["time", "scenario"] + [f"{s}.{c}" for s in slots for c in ("normal_force", "approach_speed")]
    # radial_a: pressed at rows 1-2 (one onset, scenario 1 = (a), 0.5 m/s), again at row 4 (0.001 m/s);
    # axial_b at row 4 (scenario 5 = (e), 0.2 m/s).
    table = [[0, 0] + [0, 0] * 5, [1, 1, 5, 0.5] + [0, 0] * 4, [2, 1, 5, 0.4] + [0, 0] * 4,
             [3, 0] + [0, 0] * 5, [4, 5, 5, 0.001] + [0, 0] * 3 + [5, 0.2]]
    (tmp_path / "force_joint.csv").write_text(
        ",".join(header) + "\n" + "\n".join(",".join(str(v) for v in row) for row in table) + "\n")
    script = os.path.join(os.path.dirname(__file__), "..", "..", "nonsmooth", "scripts", "impacts_by_scenario.py")
    every = subprocess.run([sys.executable, script, str(tmp_path)], check=True, capture_output=True, text=True)
    assert "lost 0.25 J (25.0 %), 3 onsets; by scenario: (e) 2, (a) 1;" in every.stdout
    assert "radial_a 2, radial_b 0, line 0, axial_a 0, axial_b 1" in every.stdout
    fast = subprocess.run([sys.executable, script, "--min-speed", "0.01", str(tmp_path)], check=True,
                          capture_output=True, text=True)
    assert "2 onsets; by scenario: (a) 1, (e) 1;" in fast.stdout


def fclib_files(folder):
    return sorted(folder.glob("step_*.hdf5"))


@pytest.mark.parametrize("into_folder", [False, True])
def test_python_simulate_write_fclib_writes_the_first_contact_problems_as_fclib_files(tmp_path, into_folder):
    h5py = pytest.importorskip("h5py")
    out = tmp_path / "run" if into_folder else None
    result = clearjoint.simulate(str(model_file(tmp_path, "moreau_jean")), out=out,
                                 write_fclib=tmp_path / "fclib", fclib_count=2)
    assert "moreau_jean: 2 contact problems written as FCLIB files (--write-fclib)" in \
        result.summary["element_statistics"]
    files = fclib_files(tmp_path / "fclib")
    assert len(files) == 2
    for path in files:
        with h5py.File(path, "r") as f:
            assert int(f["fclib_local/spacedim"][()]) == 3
            n = len(f["fclib_local/vectors/q"][()])
            assert n % 3 == 0 and len(f["solution/r"][()]) == n


@pytest.mark.skipif(not CLI, reason="needs the clearjoint program (CLEARJOINT_CLI)")
def test_python_write_fclib_writes_the_programs_files(tmp_path):
    h5py = pytest.importorskip("h5py")
    numpy = pytest.importorskip("numpy")
    model = str(model_file(tmp_path, "moreau_jean"))
    subprocess.run([CLI, "simulate", model, "--out", str(tmp_path / "run"), "--write-fclib", str(tmp_path / "cli"),
                    "--fclib-count", "3"], check=True, capture_output=True, text=True)
    clearjoint.simulate(model, write_fclib=tmp_path / "python", fclib_count=3)
    names = [p.name for p in fclib_files(tmp_path / "cli")]
    assert names == [p.name for p in fclib_files(tmp_path / "python")] and len(names) == 3
    for name in names:
        with h5py.File(tmp_path / "cli" / name, "r") as a, h5py.File(tmp_path / "python" / name, "r") as b:
            for key in ("fclib_local/vectors/q", "fclib_local/vectors/mu", "solution/r", "solution/u"):
                assert numpy.array_equal(a[key][()], b[key][()]), (name, key)


def test_python_simulate_refuses_a_write_fclib_path_that_is_a_file_naming_the_keyword(tmp_path):
    (tmp_path / "file").write_text("not a folder")
    with pytest.raises(ValueError, match=f"write_fclib = '{tmp_path / 'file'}': not a folder"):
        clearjoint.simulate(str(model_file(tmp_path, "moreau_jean")), out=tmp_path / "run",
                            write_fclib=tmp_path / "file")
    assert not (tmp_path / "run").exists()


def test_python_simulate_refuses_write_fclib_for_a_compliant_model(tmp_path):
    with pytest.raises(ValueError, match=r"write_fclib = '.*': needs solver.method = \"moreau_jean\""):
        clearjoint.simulate(str(model_file(tmp_path, "dormand_prince")), write_fclib=tmp_path / "fclib")
    assert not (tmp_path / "fclib").exists()


@pytest.mark.parametrize("count, error, message", [
    (0, ValueError, r"fclib_count = 0: must be a whole number in \[1, 1000000\]"),
    (10**6 + 1, ValueError, r"fclib_count = 1000001: must be"),
    (2.5, TypeError, r"fclib_count = 2.5: must be a whole number or None"),
    (True, TypeError, r"fclib_count = True: must be a whole number or None"),
])
def test_python_simulate_refuses_a_bad_fclib_count_naming_it(tmp_path, count, error, message):
    with pytest.raises(error, match=message):
        clearjoint.simulate(str(model_file(tmp_path, "moreau_jean")), write_fclib=tmp_path / "fclib",
                            fclib_count=count)
    assert not (tmp_path / "fclib").exists()


def test_python_simulate_refuses_fclib_count_without_write_fclib(tmp_path):
    with pytest.raises(ValueError, match="fclib_count needs write_fclib=DIR"):
        clearjoint.simulate(str(model_file(tmp_path, "moreau_jean")), fclib_count=2)


def test_spatial_comparison_writes_the_table_and_the_figure_from_the_run_folders(tmp_path):
    """nonsmooth/scripts/spatial_comparison.py, which produces docs/nonsmooth.md's spatial table
    and figure, on three small run folders (--reuse: nothing is run)."""
    pytest.importorskip("matplotlib")
    import sys
    slots = ("radial_a", "radial_b", "line", "axial_a", "axial_b")
    header = ["time", "scenario"] + [f"{s}.{c}" for s in slots for c in ("normal_force", "approach_speed")]
    for name, statistics in (("compliant", ["clearance joint: 1 impact"]),
                             ("moreau_jean_1e-4", ["moreau_jean: 4 steps of 1e-04 s, 3 contact problems, 5 fc3d "
                                                   "NSGS sweeps, largest residual 0, 2 unconverged steps"]),
                             ("moreau_jean_1e-5", [])):
        run = tmp_path / "runs" / name
        run.mkdir(parents=True)
        (run / "energy.csv").write_text("time,total\n0,1.0\n1,0.75\n")
        # radial_a pressed from row 1 at 0.5 m/s in scenario (a); axial_b at row 3 at 0.001 m/s.
        table = [[0, 0] + [0, 0] * 5, [1, 1, 5, 0.5] + [0, 0] * 4, [2, 1, 5, 0.4] + [0, 0] * 4,
                 [3, 5, 0, 0] + [0, 0] * 3 + [5, 0.001]]
        (run / "force_joint.csv").write_text(
            ",".join(header) + "\n" + "\n".join(",".join(str(v) for v in row) for row in table) + "\n")
        (run / "summary.json").write_text(json.dumps({"steps": 4, "element_statistics": statistics}))
    page = tmp_path / "page.md"
    page.write_text("before\n<!-- generated: spatial -->\nold\n<!-- end generated: spatial -->\nafter\n")
    script = os.path.join(os.path.dirname(__file__), "..", "..", "nonsmooth", "scripts", "spatial_comparison.py")
    subprocess.run([sys.executable, script, "--runs", str(tmp_path / "runs"), "--reuse", "--page", str(page),
                    "--figure", str(tmp_path / "figure.png")], check=True, capture_output=True, text=True)
    text = page.read_text()
    assert text.startswith("before\n<!-- generated: spatial -->\nGenerated by") and text.endswith("after\n")
    assert "old" not in text
    assert ("| Moreau-Jean, h = 1e-4 s | 0.250 J (25.0 % of E0 = 1.000 J) | 2 | 1 | 1, 0, 0, 0, 0 | (a) 1 | "
            "4 steps, 3 contact problems, 2 unconverged |") in text
    assert (tmp_path / "figure.png").stat().st_size > 0
