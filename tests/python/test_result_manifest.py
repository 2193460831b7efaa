# SPDX-License-Identifier: BSD-3-Clause
"""A run folder's manifest (.clearjoint-result, dynamics/output_folder.hpp): what `clearjoint plot`
writes into a run folder is listed there, so that `simulate --force` replaces it with the run and
still refuses the files a user added."""
import json
import subprocess

import pytest

from clearjoint.plot.result_manifest import HEADER, MARKER, register_written
from run_fixtures import short_model

MANIFEST_END_TIME = 0.005  # [s]: a run of some tenths of a second


@pytest.fixture
def model_file(tmp_path, models_dir):
    path = tmp_path / "model.json"
    path.write_text(json.dumps(short_model(models_dir, "slider_crank_spatial_clearance.json",
                                           end_time=MANIFEST_END_TIME)))
    return path


def simulate(cli, model_file, out, *options):
    return subprocess.run([str(cli), "simulate", str(model_file), "--out", str(out), *options],
                          capture_output=True, text=True)


def entries(folder):
    lines = (folder / MARKER).read_text().split("\n")
    assert lines[0].startswith(HEADER)
    return lines[1:-1]


def test_simulate_force_plot_runs_twice_in_a_row(cli, model_file, tmp_path):
    # scripts/run-main.sh does this: the second run found figures/ unlisted and was refused.
    out = tmp_path / "res"
    for attempt in range(2):
        done = simulate(cli, model_file, out, "--force", "--plot")
        assert done.returncode == 0, f"run {attempt + 1}: {done.stderr}"
    listed = entries(out)
    assert "figures/joint_ground-crank_clearance.png" in listed
    assert "figures/joint_ground-crank_clearance.svg" in listed
    assert len(listed) == len(set(listed))


def test_plot_lists_its_figures_once_however_often_it_runs(cli, model_file, tmp_path):
    out = tmp_path / "res"
    assert simulate(cli, model_file, out).returncode == 0
    for _ in range(2):
        done = subprocess.run([str(cli), "plot", str(out), "--format", "png"], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
    assert entries(out).count("figures/joint_ground-crank_clearance.png") == 1


def test_force_still_refuses_a_file_the_user_added_beside_the_figures(cli, model_file, tmp_path):
    out = tmp_path / "res"
    assert simulate(cli, model_file, out, "--plot").returncode == 0
    (out / "figures" / "annotated.png").write_bytes(b"mine")
    done = simulate(cli, model_file, out, "--force")
    assert done.returncode == 1
    assert "holds files no clearjoint run wrote (figures/annotated.png)" in done.stderr
    assert (out / "figures" / "annotated.png").read_bytes() == b"mine"


def test_register_written_leaves_paths_outside_the_folder_and_foreign_folders_alone(tmp_path):
    run = tmp_path / "run"
    run.mkdir()
    (run / MARKER).write_text(HEADER + ": test\nenergy.csv\n")
    register_written(run, [tmp_path / "elsewhere.png", run / ".." / "up.png", run / "figures" / "a.png"])
    assert entries(run) == ["energy.csv", "figures/a.png"]
    foreign = tmp_path / "foreign"
    foreign.mkdir()
    (foreign / MARKER).write_text("not a manifest\n")
    register_written(foreign, [foreign / "a.png"])
    assert (foreign / MARKER).read_text() == "not a manifest\n"
    plain = tmp_path / "plain"
    plain.mkdir()
    register_written(plain, [plain / "a.png"])
    assert not (plain / MARKER).exists()


def test_register_written_does_not_follow_a_linked_manifest(tmp_path):
    run = tmp_path / "run"
    run.mkdir()
    target = tmp_path / "target.txt"
    target.write_text(HEADER + "\n")
    (run / MARKER).symlink_to(target)
    register_written(run, [run / "a.png"])
    assert target.read_text() == HEADER + "\n"
