# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.plot.compare and `clearjoint plot RUN RUN ... --out FIG`: runs of both engines and
both formats overlaid in one figure, looked at through the matplotlib Figure (panels with data,
a legend entry per run, axes with units), and one-sentence errors for runs that cannot be
compared."""
import pathlib
import shutil
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import clearjoint  # noqa: E402
from clearjoint import plot  # noqa: E402
from clearjoint.plot.compare import TRANSIENT_SHARE  # noqa: E402

END_TIME = 0.02
JOINT = "rod-slider_clearance"
LUBRICATED = "slider_crank_planar_clearance_lubricated.json"
DRY = "slider_crank_planar_clearance_aligned.json"
IDEAL = "slider_crank_planar_ideal.json"


def simulate(cli, models_dir, model, folder, *options):
    subprocess.run([str(cli), "simulate", str(models_dir / model), "--end-time", str(END_TIME),
                    "--out", str(folder), *options], check=True, stdout=subprocess.DEVNULL)
    return folder


@pytest.fixture(scope="module")
def runs(tmp_path_factory, models_dir, cli):
    base = tmp_path_factory.mktemp("compare")
    folders = {"lubricated csv": simulate(cli, models_dir, LUBRICATED, base / "lubricated-csv"),
               "dry hdf5": simulate(cli, models_dir, DRY, base / "dry-hdf5", "--format", "hdf5"),
               "ideal": simulate(cli, models_dir, IDEAL, base / "ideal")}
    if "simbody" in clearjoint._core.engines():
        folders["lubricated simbody"] = simulate(cli, models_dir, LUBRICATED, base / "lubricated-simbody",
                                                 "--engine", "simbody")
    return folders


def compared(runs):
    return [k for k in ("dry hdf5", "lubricated csv", "lubricated simbody") if k in runs]


def test_runs_of_both_engines_and_formats_are_overlaid_with_a_legend_entry_per_run_and_units(runs):
    labels = compared(runs)
    result = plot.compare([runs[k] for k in labels], labels=labels, ideal=runs["ideal"])
    figure = result.figure
    y_labels = [ax.get_ylabel() for ax in figure.axes]
    assert y_labels == ["v / c_r [-]", "joint force |F| [N]", "film force [N]", "h_min [µm]",
                        "eccentricity ratio ε [-]", "peak pressure [MPa]", "slider acceleration x [m/s²]",
                        "total energy [J]"]
    assert figure.axes[0].get_xlabel() == "u / c_r [-]" and figure.axes[-1].get_xlabel() == "time [s]"
    for ax in figure.axes:
        assert "[" in ax.get_ylabel() and "]" in ax.get_ylabel(), ax.get_ylabel()
        data = [line for line in ax.get_lines() if len(line.get_xdata()) > 1 and np.isfinite(line.get_ydata()).any()]
        assert data, f"panel {ax.get_ylabel()} has no curve"
    legend = figure.axes[0].get_legend()
    assert [t.get_text() for t in legend.get_texts()] == labels + ["ideal joint"]
    # A curve per run on the panels every run has, one per lubricated run on the film panels.
    assert len(figure.axes[1].get_lines()) == len(labels)
    assert len(figure.axes[3].get_lines()) == len(labels) - 1
    assert len(figure.axes[6].get_lines()) == len(labels) + 1  # and the ideal joint's
    plt.close(figure)


def test_a_lubricated_joint_carries_its_load_through_the_film_not_a_flat_zero(runs):
    result = plot.compare([runs["lubricated csv"]], labels=["lubricated"])
    force = result.figure.axes[1].get_lines()[0].get_ydata()
    film = result.figure.axes[2].get_lines()[0].get_ydata()
    assert np.nanmin(force) > 1.0, "the film holds the rod's load at every report time"
    np.testing.assert_allclose(film[np.isfinite(film)], force[np.isfinite(film)])
    plt.close(result.figure)
    figure = plot.joint_figure(runs["lubricated csv"], panels=["force", "film"])
    force_axes, film_axes = figure.axes
    assert force_axes.get_ylabel() == "joint force [N]" and film_axes.get_ylabel() == "h_min [µm]"
    assert max(np.max(line.get_ydata()) for line in force_axes.get_lines()) > 1.0
    plt.close(figure)


def test_the_automatic_window_leaves_out_the_start_up_transient(runs):
    result = plot.compare([runs["dry hdf5"], runs["lubricated csv"]])
    assert result.window[0] == pytest.approx(TRANSIENT_SHARE * END_TIME)
    assert result.window[1] == pytest.approx(END_TIME)
    assert [t.get_text() for t in result.figure.axes[0].get_legend().get_texts()] == ["dry-hdf5", "lubricated-csv"]
    plt.close(result.figure)
    result = plot.compare([runs["dry hdf5"], runs["lubricated csv"]], window=(0.005, 0.01))
    time = result.figure.axes[1].get_lines()[0].get_xdata()
    assert time[0] >= 0.005 and time[-1] <= 0.01
    plt.close(result.figure)


def test_a_run_without_energy_or_bodies_leaves_those_panels_out_with_a_note(runs, tmp_path):
    # What clearjoint-mujoco writes: the joint's force table only, no model.
    forces_only = tmp_path / "forces-only"
    forces_only.mkdir()
    shutil.copy(runs["lubricated csv"] / f"force_{JOINT}.csv", forces_only)
    result = plot.compare([runs["lubricated csv"], forces_only], labels=["full", "forces only"])
    assert any("energy: no energy table in forces only" in note for note in result.notes)
    assert any("orbit in metres" in note for note in result.notes)
    assert result.figure.axes[0].get_xlabel() == "u [m]"
    energy = [ax for ax in result.figure.axes if ax.get_ylabel() == "total energy [J]"]
    assert len(energy) == 1 and len(energy[0].get_lines()) == 1
    plt.close(result.figure)


def run_plot(*args):
    return subprocess.run([sys.executable, "-m", "clearjoint.plot", *map(str, args)],
                          capture_output=True, text=True)


def one_sentence_error(done, *words):
    assert done.returncode == 1
    assert "Traceback" not in done.stderr
    assert done.stderr.startswith("clearjoint plot: ") and done.stderr.count("\n") == 1, done.stderr
    for word in words:
        assert word in done.stderr, done.stderr


def test_the_clearjoint_program_writes_the_comparison_figure_where_out_says(runs, tmp_path, cli):
    figure = tmp_path / "runs.png"
    done = subprocess.run([str(cli), "plot", str(runs["dry hdf5"]), str(runs["lubricated csv"]),
                           "--label", "dry", "lubricated", "--ideal", str(runs["ideal"]), "--out", str(figure)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == str(figure)
    assert figure.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["runs.png"]


def test_one_hdf5_run_still_gives_the_figure_of_each_joint(runs, tmp_path):
    done = run_plot(runs["dry hdf5"], "--out", tmp_path, "--format", "png")
    assert done.returncode == 0, done.stderr
    assert (tmp_path / f"joint_{JOINT}.png").is_file()


def test_runs_with_no_clearance_joint_in_common_are_refused_naming_them(runs, tmp_path):
    one_sentence_error(run_plot(runs["dry hdf5"], runs["ideal"], "--out", tmp_path / "x.png"),
                       "dry-hdf5", "ideal", "no clearance joint of the same name", JOINT)
    assert not (tmp_path / "x.png").exists()


def test_a_folder_that_is_no_run_is_refused_naming_it(runs, tmp_path):
    empty = tmp_path / "empty"
    empty.mkdir()
    one_sentence_error(run_plot(runs["dry hdf5"], empty, "--out", tmp_path / "x.png"),
                       "not a run folder", str(empty))


def test_a_comparison_needs_out_and_a_known_file_format(runs, tmp_path):
    one_sentence_error(run_plot(runs["dry hdf5"], runs["lubricated csv"]), "--out")
    one_sentence_error(run_plot(runs["dry hdf5"], runs["lubricated csv"], "--out", tmp_path / "fig.nope"),
                       "extension")
    one_sentence_error(run_plot(runs["dry hdf5"], runs["lubricated csv"], "--out", tmp_path / "x.png",
                                "--label", "only one"), "labels: 1 given for 2 runs")


def test_the_notes_under_the_figure_overlap_no_axis_or_its_labels(runs, tmp_path):
    # The tutorial's four runs carry two long notes; drawn over the time axis's label they hid it.
    forces_only = tmp_path / "forces-only"
    forces_only.mkdir()
    shutil.copy(runs["lubricated csv"] / f"force_{JOINT}.csv", forces_only)
    result = plot.compare([runs["lubricated csv"], runs["dry hdf5"], forces_only],
                          labels=["lubricated with a long label", "dry with a long label", "forces only"])
    assert result.notes
    result.figure.canvas.draw()
    renderer = result.figure.canvas.get_renderer()
    texts = {id(t): t for t in result.figure.texts + [getattr(result.figure, "_supxlabel", None)] if t is not None}
    notes = [t for t in texts.values() if result.notes[0] in t.get_text().replace("\n", " ")]
    assert len(notes) == 1
    box = notes[0].get_window_extent(renderer)
    for ax in result.figure.axes:
        assert not box.overlaps(ax.get_tightbbox(renderer)), ax.get_ylabel()
    assert box.y0 >= 0.0
    plt.close(result.figure)
