# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.plot and `clearjoint plot`: the figures of a run's clearance joints, drawn from a
run folder or from what clearjoint.simulate returns, and one-sentence errors for bad runs."""
import shutil
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.colors import to_hex  # noqa: E402

import clearjoint  # noqa: E402
from clearjoint import plot  # noqa: E402
from clearjoint.plot.joint_series import CONTACT_SLOTS  # noqa: E402
from run_fixtures import short_model, write_run  # noqa: E402

JOINT_TABLE = "force_ground-crank_clearance"
JOINT_TABLE_FILE = JOINT_TABLE + ".csv"


@pytest.fixture(scope="module")
def runs(tmp_path_factory, models_dir, cli):
    base = tmp_path_factory.mktemp("runs")
    clearance = short_model(models_dir, "slider_crank_spatial_clearance.json")
    ideal = short_model(models_dir, "slider_crank_spatial_ideal.json")
    return {"clearance": write_run(cli, clearance, base / "clearance"),
            "ideal": write_run(cli, ideal, base / "ideal"),
            "model": clearance}


def orbit_axes(figure):
    return [ax for ax in figure.axes if ax.get_xlabel().startswith("u")]


def scenario_colours_of(ax):
    """The colour of every step of the scenario-coloured curve (a path per stretch of steps)."""
    collection = next(c for c in ax.collections if isinstance(c, LineCollection))
    colours = []
    for path, colour in zip(collection.get_segments(), collection.get_colors()):
        colours += [to_hex(colour)] * (len(path) - 1)
    return colours


def test_a_spatial_joint_draws_both_base_centres_in_clearance_units(runs):
    figure = plot.joint_figure(runs["clearance"])
    orbits = orbit_axes(figure)
    assert [ax.get_title() for ax in orbits] == ["journal centre at base A", "journal centre at base B"]
    assert all(ax.get_xlabel() == "u / c_r [-]" and ax.get_ylabel() == "v / c_r [-]" for ax in orbits)
    run = plot.read_run(runs["clearance"])
    series = plot.joint_series(run, JOINT_TABLE)
    radius = np.hypot(series.rim_a[:, 0], series.rim_a[:, 1]) / series.radial_clearance
    assert radius.max() > 0.9, "a 30 ms run reaches the wall"
    plt.close(figure)


def test_every_orbit_segment_has_the_colour_of_its_scenario_in_the_table(runs):
    figure = plot.joint_figure(runs["clearance"])
    scenario = plot.read_run(runs["clearance"]).table(JOINT_TABLE)["scenario"].astype(int)
    expected = [plot.scenario_colour(s) for s in scenario[1:]]
    for ax in orbit_axes(figure):
        assert scenario_colours_of(ax) == expected
    assert len(set(scenario)) > 1, "the run has free flight and contact"
    plt.close(figure)


def test_the_legend_names_each_scenario_of_the_run_in_its_colour(runs):
    figure = plot.joint_figure(runs["clearance"])
    legend = orbit_axes(figure)[1].get_legend()
    scenario = set(plot.read_run(runs["clearance"]).table(JOINT_TABLE)["scenario"].astype(int))
    entries = {text.get_text(): to_hex(handle.get_color())
               for text, handle in zip(legend.get_texts(), getattr(legend, "legend_handles", None) or legend.legendHandles)
               if not text.get_text().startswith("impact began")}
    assert entries == {plot.scenario_name(s): plot.scenario_colour(s) for s in scenario}
    plt.close(figure)


def test_impacts_are_marked_where_a_contact_slot_begins(runs):
    run = plot.read_run(runs["clearance"])
    series = plot.joint_series(run, JOINT_TABLE)
    table = run.table(JOINT_TABLE)
    touching = np.column_stack([np.isfinite(table[f"{s}.depth"]) for s in CONTACT_SLOTS])
    for row in series.impact_rows:
        assert touching[row].any() and (row == 0 or (touching[row] & ~touching[row - 1]).any())
    assert len(series.impact_rows) >= 1


def test_a_simulation_result_draws_the_same_orbit_as_its_run_folder(runs):
    result = clearjoint.simulate(runs["model"])
    from_result = plot.joint_figure(result, model=runs["model"])
    from_folder = plot.joint_figure(runs["clearance"])
    assert scenario_colours_of(orbit_axes(from_result)[0]) == scenario_colours_of(orbit_axes(from_folder)[0])
    a = orbit_axes(from_result)[0].collections[0].get_segments()
    b = orbit_axes(from_folder)[0].collections[0].get_segments()
    np.testing.assert_array_equal(np.concatenate(a), np.concatenate(b))
    plt.close("all")


def test_the_ideal_run_is_drawn_beside_the_slider_acceleration(runs):
    figure = plot.joint_figure(runs["clearance"], ideal=runs["ideal"], panels=["slider"])
    (ax,) = figure.axes
    assert [line.get_label() for line in ax.get_lines()] == ["ideal joint", "clearance joint"]
    assert ax.get_ylabel() == "slider acceleration x [m/s$^2$]"
    plt.close(figure)


def test_the_time_window_keeps_only_its_report_times(runs):
    run = plot.read_run(runs["clearance"])
    series = plot.joint_series(run, JOINT_TABLE, window=(0.01, 0.02))
    assert series.time[0] >= 0.01 and series.time[-1] <= 0.02
    figure = plot.joint_figure(run, panels=["force"], window=(0.01, 0.02), x="angle")
    (ax,) = figure.axes
    assert ax.get_xlabel() == "crank angle [deg]"
    plt.close(figure)


def test_without_the_model_lengths_are_drawn_in_metres(runs, tmp_path):
    bare = tmp_path / "bare"
    shutil.copytree(runs["clearance"], bare)
    (bare / "model.json").unlink()
    figure = plot.joint_figure(bare, panels=["orbit", "axial"])
    assert orbit_axes(figure)[0].get_xlabel() == "u [m]"
    assert figure.axes[-1].get_ylabel() == "axial position [m]"
    plt.close(figure)


def run_plot(*args):
    return subprocess.run([sys.executable, "-m", "clearjoint.plot", *map(str, args)],
                          capture_output=True, text=True)


def test_the_command_writes_png_and_svg_per_joint(runs, tmp_path):
    done = run_plot(runs["clearance"], "--out", tmp_path, "--ideal", runs["ideal"])
    assert done.returncode == 0, done.stderr
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["joint_ground-crank_clearance.png", "joint_ground-crank_clearance.svg"]
    assert (tmp_path / names[0]).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_clearjoint_program_hands_plot_over_to_python(runs, tmp_path, cli):
    done = subprocess.run([str(cli), "plot", str(runs["clearance"]), "--out", str(tmp_path),
                           "--panels", "orbit,force", "--format", "png"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "joint_ground-crank_clearance.png").is_file()


def one_sentence_error(done, *words):
    assert done.returncode == 1
    assert "Traceback" not in done.stderr
    assert done.stderr.startswith("clearjoint plot: ") and done.stderr.count("\n") == 1, done.stderr
    for word in words:
        assert word in done.stderr


def test_a_folder_that_is_not_a_run_is_refused_in_one_sentence(tmp_path):
    one_sentence_error(run_plot(tmp_path), "not a run folder")
    one_sentence_error(run_plot(tmp_path / "missing"), "no such folder")


def test_a_run_without_clearance_joints_is_refused_in_one_sentence(runs):
    one_sentence_error(run_plot(runs["ideal"]), "no clearance joint")


def test_a_truncated_table_is_refused_in_one_sentence(runs, tmp_path):
    damaged = tmp_path / "damaged"
    shutil.copytree(runs["clearance"], damaged)
    table = damaged / f"{JOINT_TABLE}.csv"
    text = table.read_text()
    table.write_text(text[: len(text) - 40])  # the last row cut in the middle
    one_sentence_error(run_plot(damaged), "truncated")


def test_a_table_with_fewer_rows_is_refused_in_one_sentence(runs, tmp_path):
    damaged = tmp_path / "short"
    shutil.copytree(runs["clearance"], damaged)
    table = damaged / "energy.csv"
    lines = table.read_text().splitlines(keepends=True)
    table.write_text("".join(lines[:-5]))
    one_sentence_error(run_plot(damaged), "truncated")


def test_an_unknown_panel_is_refused_in_one_sentence(runs):
    one_sentence_error(run_plot(runs["clearance"], "--panels", "orbit,phase"), "phase")


def test_every_scenario_of_the_library_has_a_colour_and_a_label():
    codes = [int(member) for member in clearjoint.ContactScenario]
    assert sorted(plot.SCENARIO_COLOURS) == codes
    assert len(set(plot.SCENARIO_COLOURS.values())) == len(codes)
    assert [entry["label"] for entry in plot.scenario_table()] == [
        clearjoint.scenario_label(clearjoint.ContactScenario(code)) for code in codes]


# -- what a run folder's files may be ---------------------------------------------------------

# A line of a file no table should be, with a marker that must never appear in a message.
FOREIGN_MARKER = "Zq7-foreign-marker"
FOREIGN_TEXT = f"root:x:0:0:{FOREIGN_MARKER}:/root:/bin/bash"


# The address space of a child that reads a hostile table: a reader that tried to read /dev/zero
# or a 2 GiB table whole would end in MemoryError instead of taking the machine's memory.
CHILD_ADDRESS_SPACE_BYTES = 3 << 30


def cap_memory():
    import resource
    resource.setrlimit(resource.RLIMIT_AS, (CHILD_ADDRESS_SPACE_BYTES, CHILD_ADDRESS_SPACE_BYTES))


def run_plot_capped(*args):
    return subprocess.run([sys.executable, "-m", "clearjoint.plot", *map(str, args)], capture_output=True,
                          text=True, preexec_fn=cap_memory, timeout=120)


def copy_run(runs, tmp_path, name="copy"):
    folder = tmp_path / name
    shutil.copytree(runs["clearance"], folder)
    return folder


def test_a_table_linked_to_another_file_is_refused_without_quoting_it(runs, tmp_path):
    folder = copy_run(runs, tmp_path)
    foreign = tmp_path / "passwd"
    foreign.write_text(FOREIGN_TEXT + "\n")
    (folder / "energy.csv").unlink()
    (folder / "energy.csv").symlink_to(foreign)
    done = run_plot(folder)
    one_sentence_error(done, "energy.csv", "symbolic link")
    assert FOREIGN_MARKER not in done.stderr


def test_a_table_linked_to_dev_zero_is_refused_at_once(runs, tmp_path):
    folder = copy_run(runs, tmp_path)
    (folder / JOINT_TABLE_FILE).unlink()
    (folder / JOINT_TABLE_FILE).symlink_to("/dev/zero")
    one_sentence_error(run_plot_capped(folder), JOINT_TABLE_FILE, "symbolic link")


def test_a_damaged_row_is_refused_without_quoting_its_text(runs, tmp_path):
    folder = copy_run(runs, tmp_path)
    table = folder / "energy.csv"
    lines = table.read_text().splitlines(keepends=True)
    # The marker where NumPy's parser fails first: the row's first field.
    lines[3] = f"{FOREIGN_MARKER},x,0,0,root,/root,/bin/bash\n"
    table.write_text("".join(lines))
    done = run_plot(folder)
    one_sentence_error(done, "energy.csv", "damaged")
    assert FOREIGN_MARKER not in done.stderr


# A sparse file of one byte more than the largest table read (_bounded_files.MAX_TABLE_BYTES,
# 2 GiB): refused from its size, before a byte of it is read.
TABLE_LIMIT_BYTES = 2 << 30


def test_a_table_larger_than_the_limit_is_refused_naming_the_limit(runs, tmp_path):
    folder = copy_run(runs, tmp_path)
    with open(folder / "reactions.csv", "r+b") as table:
        table.truncate(TABLE_LIMIT_BYTES + 1)
    one_sentence_error(run_plot_capped(folder), "reactions.csv", str(TABLE_LIMIT_BYTES + 1),
                       f"more than the {TABLE_LIMIT_BYTES} bytes")


def edit_time(folder, table, row, value):
    """Sets the time of data row `row` (1 = the first row after the header) of `table`."""
    path = folder / table
    lines = path.read_text().splitlines(keepends=True)
    fields = lines[row].split(",")
    fields[0] = value
    lines[row] = ",".join(fields)
    path.write_text("".join(lines))


def test_a_time_column_that_runs_backwards_is_refused_naming_the_table_row_and_value(runs, tmp_path):
    folder = copy_run(runs, tmp_path)
    edit_time(folder, "energy.csv", 7, "0.0001")  # row 7 is at 6e-4 s, row 6 at 5e-4 s
    one_sentence_error(run_plot(folder), "energy.csv row 7", "time = 0.0001", "backwards")


def test_a_time_column_holding_nan_is_refused_naming_the_table_row_and_value(runs, tmp_path):
    folder = copy_run(runs, tmp_path)
    edit_time(folder, JOINT_TABLE_FILE, 12, "nan")
    one_sentence_error(run_plot(folder), f"{JOINT_TABLE_FILE} row 12", "time = nan")


def test_a_renamed_column_of_a_body_table_is_refused_naming_it(runs, tmp_path):
    folder = copy_run(runs, tmp_path)
    table = folder / "body_slider.csv"
    text = table.read_text()
    table.write_text(text.replace(",ax,", ",acc_x,", 1))
    one_sentence_error(run_plot(folder, "--panels", "slider"), "body_slider.csv has no column ax")
