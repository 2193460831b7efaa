# SPDX-License-Identifier: BSD-3-Clause
"""A small study on a LocalCluster: every run stored once with the values a direct simulate call
gives, the summary tables and figure written, a second call reusing every run."""
import csv
import os

import h5py

from clearjoint.study import Store, load_study, run_study
from clearjoint.study.__main__ import main
from study_fixtures import assert_store_matches, edit_run_file, run_without_faults, write_study


def test_a_local_cluster_study_stores_every_run_as_a_direct_call_computes_it(tmp_path, models_dir):
    study = load_study(write_study(tmp_path, models_dir, radial=(0.05, 0.1, 0.3), members=3))
    report = run_study(study, workers=2, progress=False)
    assert report.failed == {} and report.reused == 0 and len(report.computed) == 9 and report.workers == 2
    store = Store(study.store_path)
    assert_store_matches(store, run_without_faults(study))
    assert sorted(store.write_log()) == sorted(report.computed)

    with open(os.path.join(study.store_path, "summary", "runs.csv")) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 9 and {r["run_id"] for r in rows} == store.stored_ids()
    with open(os.path.join(study.store_path, "summary", "points.csv")) as f:
        points = [r for r in csv.DictReader(f) if r["statistic"] == "peak"]
    assert len(points) == 3 and all(r["n"] == "3" and r["complete"] == "True" for r in points)
    assert all(float(r["min"]) <= float(r["median"]) <= float(r["max"]) for r in points)
    with open(os.path.join(study.store_path, "summary", "trends.csv")) as f:
        trends = [r for r in csv.DictReader(f) if r["statistic"] == "peak"]
    assert [(r["lower"], r["upper"]) for r in trends] == [("0.05", "0.1"), ("0.1", "0.3"), ("0.05", "0.3")]
    assert all(0.0 <= float(r["p_value_greater"]) <= 1.0 for r in trends)

    with h5py.File(store.run_path(report.computed[0]), "r") as f:
        assert f.attrs["library_version"] and f.attrs["model_sha256"] and "reductions" in f

    again = run_study(study, workers=1, progress=False)
    assert again.computed == [] and again.reused == 9 and again.failed == {}

    # A run stored by another build of the library (same version string) is run again, alone.
    stale = report.computed[4]
    edit_run_file(store, stale, lambda f: f.attrs.__setitem__("library_build", "another build"))
    third = run_study(study, workers=1, progress=False)
    assert third.computed == [stale] and third.reused == 8


def test_the_plot_command_draws_the_standard_figure_from_the_store(tmp_path, models_dir):
    path = write_study(tmp_path, models_dir, radial=(0.05, 0.3), members=2)
    assert main(["run", path, "--workers", "1", "--no-progress", "--no-plot"]) == 0
    assert main(["plot", path, "--out", str(tmp_path / "figures")]) == 0
    with open(tmp_path / "figures" / "statistics.png", "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"


def test_a_run_that_fails_is_reported_and_the_others_are_stored(tmp_path, models_dir):
    path = write_study(tmp_path, models_dir, radial=(0.05, 15.0), members=1)  # 15 mm: journal radius < 0
    study = load_study(path)
    report = run_study(study, workers=1, progress=False)
    assert len(report.computed) == 1 and len(report.failed) == 1
    (error,) = report.failed.values()
    assert "radius" in error
    assert main(["run", path, "--workers", "1", "--no-progress"]) == 1


def test_the_clearjoint_program_hands_study_over_to_the_python_runner(tmp_path, models_dir, cli):
    import subprocess
    path = write_study(tmp_path, models_dir, radial=(0.1,), members=2)
    done = subprocess.run([str(cli), "study", "run", path, "--workers", "1", "--no-progress", "--no-plot"],
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    assert "2 runs stored now, 0 reused, 0 failed" in done.stderr
    assert len(Store(load_study(path).store_path).stored_ids()) == 2
    bad = subprocess.run([str(cli), "study", "run", str(tmp_path / "absent.json")], capture_output=True, text=True,
                         timeout=600)
    assert bad.returncode == 2 and "absent.json: cannot read the study file" in bad.stderr


def test_a_second_client_on_a_store_in_use_is_refused_with_a_clear_error(tmp_path, models_dir):
    import pytest
    from clearjoint.study import StudyError
    study = load_study(write_study(tmp_path, models_dir, radial=(0.1,), members=1))
    holder = Store(study.store_path)
    holder.open_for_writing({})
    try:
        with pytest.raises(StudyError, match="another client is running a study into this store"):
            run_study(study, workers=1, progress=False)
    finally:
        holder.close()


def test_local_workers_get_a_memory_limit_that_a_study_or_option_can_set(tmp_path, models_dir):
    import pytest
    from clearjoint.study import StudyError
    from clearjoint.study.runner import connect, worker_memory_limit
    from distributed.system import MEMORY_LIMIT
    from study_fixtures import edit_study
    path = write_study(tmp_path, models_dir, radial=(0.1,), members=1)
    study = load_study(path)
    share = worker_memory_limit(study)
    assert 0 < share <= MEMORY_LIMIT
    assert worker_memory_limit(study, "0") == 0 and worker_memory_limit(study, "0.25") == int(0.25 * MEMORY_LIMIT)
    edit_study(path, lambda s: s.update(worker_memory_limit="256MiB"))
    study = load_study(path)
    assert worker_memory_limit(study) == 2 ** 28 and worker_memory_limit(study, "auto") == share
    with pytest.raises(StudyError, match="--memory-limit = 'lots': not a memory size"):
        worker_memory_limit(study, "lots")
    client, cluster = connect(workers=1, memory_limit=worker_memory_limit(study), dashboard_address=None)
    try:
        (worker,) = client.scheduler_info()["workers"].values()
        assert worker["memory_limit"] == 2 ** 28
    finally:
        client.close()
        cluster.close()


def test_the_clearjoint_program_imports_its_own_package_from_a_folder_holding_another(tmp_path, cli):
    import subprocess
    (tmp_path / "clearjoint").mkdir()
    (tmp_path / "clearjoint" / "__init__.py").write_text("raise ImportError('the wrong clearjoint')\n")
    done = subprocess.run([str(cli), "study", "run", "absent.json"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 2 and "absent.json: cannot read the study file" in done.stderr, done.stderr


def test_run_help_reads_as_the_command_line(capsys):
    import pytest
    with pytest.raises(SystemExit) as exit_status:
        main(["run", "--help"])
    assert exit_status.value.code == 0
    out = capsys.readouterr().out
    assert out.startswith("usage: clearjoint study run [-h]") and "--memory-limit LIMIT" in out


def test_plot_on_a_study_without_plots_says_so_with_status_2(tmp_path, models_dir, capsys):
    from study_fixtures import edit_study
    path = edit_study(write_study(tmp_path, models_dir, radial=(0.1,), members=1),
                      lambda s: s["designs"][0].pop("x"))
    assert main(["plot", path]) == 2
    assert "no figure to draw" in capsys.readouterr().err


def test_plot_titles_and_labels_come_from_the_study(tmp_path, models_dir):
    from clearjoint.study.plot import fill, plot_title, study_fields
    from study_fixtures import TEST_END_TIME
    study = load_study(write_study(tmp_path, models_dir, radial=(0.05, 0.3), members=3))
    plot = {"file": "a.png", "designs": ["radial"], "statistics": ["peak"]}
    fields = study_fields(study, plot)
    assert plot_title(plot, fields) == "small: median and range of 3 members per point, %g s simulated" % TEST_END_TIME
    plot["title"] = "{points} points x {members} runs over {end_time} s {not a field}"
    assert plot_title(plot, fields) == "2 points x 3 runs over %g s {not a field}" % TEST_END_TIME
    assert fill("peak |a| over {end_time} s", fields) == "peak |a| over %g s" % TEST_END_TIME


def test_the_shipped_studies_draw_their_figures_beside_their_store_not_into_the_repository(models_dir):
    from clearjoint.study.plot import figure_directory, plots_of
    root = models_dir.parent
    shipped = sorted((root / "reproduction" / "studies").glob("*.json"))
    assert shipped, "no study files in reproduction/studies"
    for path in shipped:
        study = load_study(str(path))
        for plot in plots_of(study):
            directory = figure_directory(study, plot)
            assert directory == os.path.join(study.store_path, "figures"), (path.name, plot["file"], directory)
            assert figure_directory(study, plot, "elsewhere") == "elsewhere"  # `study plot --out`
