# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.simulate against `clearjoint simulate`, and its inputs, progress and interrupts."""
import json
import os
import pickle
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import clearjoint

# A short run of the paper's spatial slider-crank with a clearance joint: contact outputs with
# NaN slots, impacts, all four kinds of tables, in about a tenth of a second.
SHORT_RUN_END_TIME = 0.02
SHORT_RUN_REPORT_STEP = 1e-3


@pytest.fixture
def short_model(models_dir):
    with open(models_dir / "slider_crank_spatial_clearance.json") as f:
        model = json.load(f)
    model["solver"]["end_time"] = SHORT_RUN_END_TIME
    model["solver"]["report_step"] = SHORT_RUN_REPORT_STEP
    return model


def read_csv(path):
    """Header and columns of a CSV file of `clearjoint simulate`; float() reads the shortest
    round-trip form back to the exact double."""
    with open(path) as f:
        header = f.readline().strip().split(",")
        rows = [[float(v) for v in line.split(",")] for line in f]
    values = np.array(rows, dtype=np.float64).reshape(len(rows), len(header))
    return header, values.T


def same_bits(a, b):
    """Equal bit patterns, NaN matching NaN (a contact slot not in use)."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    both_nan = np.isnan(a) & np.isnan(b)
    return a.shape == b.shape and bool(np.all((a.view(np.int64) == b.view(np.int64)) | both_nan))


def test_the_arrays_equal_the_csv_files_of_the_command_line_bit_for_bit(short_model, cli, tmp_path):
    model_file = tmp_path / "model.json"
    model_file.write_text(json.dumps(short_model))
    out = tmp_path / "csv"
    subprocess.run([str(cli), "simulate", str(model_file), "--out", str(out)], check=True,
                   capture_output=True)
    result = clearjoint.simulate(model_file)

    files = sorted(p.stem for p in out.glob("*.csv"))
    assert sorted(result.tables) == files
    assert {"energy", "reactions", "body_slider", "force_ground-crank_clearance"} <= set(files)
    for name in files:
        header, columns = read_csv(out / f"{name}.csv")
        assert list(result[name]) == header, name
        for column, values in zip(header, columns):
            assert same_bits(result[name][column], values), f"{name}.{column}"
    rows = round(SHORT_RUN_END_TIME / SHORT_RUN_REPORT_STEP) + 1
    assert result["energy"]["time"].shape == (rows,)


def test_a_dict_and_the_file_it_was_written_to_give_the_same_arrays(short_model, tmp_path):
    model_file = tmp_path / "model.json"
    model_file.write_text(json.dumps(short_model))
    from_dict = clearjoint.simulate(short_model)
    from_file = clearjoint.simulate(str(model_file))
    assert from_dict.tables.keys() == from_file.tables.keys()
    for name, columns in from_dict.tables.items():
        for column, values in columns.items():
            assert same_bits(values, from_file[name][column]), f"{name}.{column}"
    assert from_dict.summary == from_file.summary


def test_numpy_values_in_a_dict_are_read_as_numbers_and_lists(short_model):
    from_numpy = json.loads(json.dumps(short_model))
    from_numpy["solver"]["end_time"] = np.float64(SHORT_RUN_END_TIME)
    from_numpy["gravity"] = np.array(short_model["gravity"])
    a, b = clearjoint.simulate(short_model), clearjoint.simulate(from_numpy)
    assert same_bits(a["energy"]["total"], b["energy"]["total"])


def test_a_value_json_cannot_hold_raises_type_error(short_model):
    short_model["solver"]["end_time"] = object()
    with pytest.raises(TypeError, match="model: a value of type object is not a JSON value"):
        clearjoint.simulate(short_model)


def test_the_summary_reports_the_run(short_model):
    summary = clearjoint.simulate(short_model).summary
    assert summary["steps"] > 0
    assert summary["derivative_calls"] >= 6 * summary["steps"]  # Dormand-Prince: 6 stages a step
    assert 0.0 < summary["smallest_step"] <= summary["largest_step"]
    assert summary["initial_energy"] != 0.0
    assert any("contact detections" in line for line in summary["element_statistics"])


def test_the_result_pickles_with_its_arrays(short_model):
    result = clearjoint.simulate(short_model)
    copy = pickle.loads(pickle.dumps(result))
    assert same_bits(copy["energy"]["total"], result["energy"]["total"])
    assert copy.summary == result.summary
    assert "energy: 7 columns x 21 rows" in repr(result)


def test_a_bad_model_raises_value_error_naming_the_field(short_model):
    short_model["bodies"][1]["mass"] = -1.0
    with pytest.raises(ValueError, match=r"<dict>: bodies\[1\]\.mass = -1: must be positive"):
        clearjoint.simulate(short_model)


def test_a_missing_model_file_raises_file_not_found_error_naming_the_path(tmp_path):
    missing = tmp_path / "no-such-model.json"
    with pytest.raises(FileNotFoundError, match="model file not found") as raised:
        clearjoint.simulate(missing)
    assert raised.value.filename == str(missing)


def test_a_folder_as_model_raises_is_a_directory_error(tmp_path):
    with pytest.raises(IsADirectoryError):
        clearjoint.simulate(tmp_path)


def test_a_path_with_a_nul_character_is_refused_not_cut_at_it(models_dir):
    # The C++ reader saw 'ball.json' and ran it.
    path = str(models_dir / "slider_crank_spatial_clearance.json") + "\0/etc/passwd"
    with pytest.raises(ValueError, match="cannot contain a NUL character"):
        clearjoint.simulate(path)


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf"), np.float64("nan")])
def test_a_non_finite_number_in_a_dict_names_its_field(short_model, bad):
    # json.dumps wrote NaN as a bare word and the reader reported a parse error at a column.
    short_model["bodies"][1]["mass"] = bad
    with pytest.raises(ValueError, match=r"^bodies\[1\]\.mass = .*: must be finite$"):
        clearjoint.simulate(short_model)


def test_a_non_finite_number_in_an_array_of_a_dict_names_its_field(short_model):
    short_model["gravity"] = np.array([0.0, np.nan, -9.81])
    with pytest.raises(ValueError, match=r"^gravity = \[0\.0, nan, -9\.81\]: every value must be finite$"):
        clearjoint.simulate(short_model)


def test_a_run_beyond_the_size_guard_is_refused_unless_allowed(short_model):
    # Python had no guard: end_time 1e9 with report_step 1 grew until the OOM killer.
    short_model["solver"]["end_time"] = 1e9
    short_model["solver"]["report_step"] = 1.0
    with pytest.raises(ValueError, match=r"solver\.end_time - solver\.start_time = 1000000000 s: longer than 1000 s"):
        clearjoint.simulate(short_model)


def test_allow_large_runs_past_the_size_guard(short_model):
    model = {"bodies": [{"name": "ball", "mass": 1, "inertia": [1, 1, 1], "position": [0, 0, 0]}],
             "gravity": [0, 0, -9.81], "solver": {"end_time": 2000, "report_step": 100}}
    with pytest.raises(ValueError, match="longer than 1000 s"):
        clearjoint.simulate(model)
    result = clearjoint.simulate(model, allow_large=True)
    assert len(result["energy"]["time"]) == 21


def test_allow_large_must_be_a_bool(short_model):
    with pytest.raises(TypeError, match="allow_large = 1: must be True or False"):
        clearjoint.simulate(short_model, allow_large=1)


def test_a_model_that_is_neither_path_nor_dict_raises_type_error():
    with pytest.raises(TypeError, match="model = list: must be a path or a dict"):
        clearjoint.simulate([1, 2, 3])


def test_a_progress_callable_sees_the_simulated_fraction_grow_from_zero_to_one(short_model):
    # At every report time, and between them every 0.1 s of wall time (a slow machine adds calls).
    fractions = []
    clearjoint.simulate(short_model, progress=fractions.append)
    reports = round(SHORT_RUN_END_TIME / SHORT_RUN_REPORT_STEP) + 1
    assert len(fractions) >= reports
    for k in range(reports):
        assert any(f == pytest.approx(k / (reports - 1)) for f in fractions), k
    assert fractions[0] == 0.0 and fractions[-1] == pytest.approx(1.0)
    assert all(b >= a for a, b in zip(fractions, fractions[1:]))


def test_progress_true_draws_a_bar_on_standard_error(short_model, capsys):
    clearjoint.simulate(short_model, progress=True)
    assert "100%" in capsys.readouterr().err


def test_progress_true_without_tqdm_draws_a_text_bar(short_model, capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "tqdm", None)  # import tqdm now raises ImportError
    clearjoint.simulate(short_model, progress=True)
    err = capsys.readouterr().err
    assert err.endswith("] 100%\n") and err.startswith("\r[")


def test_progress_of_another_kind_raises_type_error(short_model):
    with pytest.raises(TypeError, match="progress = 'yes': must be True, False, None or a callable"):
        clearjoint.simulate(short_model, progress="yes")


def test_an_exception_in_the_progress_callable_stops_the_run_and_propagates(short_model):
    calls = []

    def stop_at_the_fourth_report(fraction):
        calls.append(fraction)
        if len(calls) == 4:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        clearjoint.simulate(short_model, progress=stop_at_the_fourth_report)
    assert len(calls) == 4  # nothing ran after the interrupt


def test_ctrl_c_during_a_run_raises_keyboard_interrupt_promptly(models_dir):
    # The full one-second run takes seconds; SIGINT arrives after a fraction of that, while the
    # integration runs without the GIL and without a progress callable.
    with open(models_dir / "slider_crank_spatial_clearance.json") as f:
        model = json.load(f)
    delay = 0.3
    timer = threading.Timer(delay, os.kill, args=(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            clearjoint.simulate(model)
    finally:
        timer.cancel()
    full_run = 1.5  # seconds: the run alone on an idle machine takes ~2 s (CPU time)
    assert time.monotonic() - start < full_run


def test_ctrl_c_is_honoured_between_report_times_within_a_fraction_of_a_second(models_dir):
    # With one report time at the end, the interrupt waited for the whole run (9.3 s observed):
    # progress is now checked every 0.1 s of wall time between report times as well.
    with open(models_dir / "slider_crank_spatial_clearance.json") as f:
        model = json.load(f)
    model["solver"]["report_step"] = model["solver"]["end_time"] - model["solver"].get("start_time", 0.0)
    delay = 0.3
    timer = threading.Timer(delay, os.kill, args=(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            clearjoint.simulate(model)
    finally:
        timer.cancel()
    assert time.monotonic() - start < delay + 1.0


def test_the_version_is_the_command_line_programs(cli):
    printed = subprocess.run([str(cli), "--version"], check=True, capture_output=True,
                             text=True).stdout.split()
    assert printed == ["clearjoint", clearjoint.__version__]


@pytest.mark.parametrize("format", ["csv", "hdf5"])
def test_a_run_written_to_a_folder_reads_back_bit_for_bit(short_model, tmp_path, format):
    # The same folder `clearjoint simulate --out` writes: tables, model.json, summary.json.
    folder = tmp_path / "run"
    written = clearjoint.simulate(short_model, out=folder, format=format)
    assert written.folder == str(folder) and written.tables == {}
    assert written.summary["steps"] > 0
    assert (folder / ("run.h5" if format == "hdf5" else "energy.csv")).exists()
    assert json.loads((folder / "model.json").read_text())["solver"]["end_time"] == SHORT_RUN_END_TIME
    back = clearjoint.read_run(folder)
    in_memory = clearjoint.simulate(short_model)
    assert back.summary == written.summary == in_memory.summary
    assert back.tables.keys() == in_memory.tables.keys()
    for table, columns in in_memory.tables.items():
        assert list(back[table]) == list(columns)
        for name, values in columns.items():
            assert same_bits(back[table][name], values), (table, name)


def test_the_summary_has_the_keys_of_summary_json(short_model, tmp_path):
    clearjoint.simulate(short_model, out=tmp_path / "run")
    on_disk = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert clearjoint.simulate(short_model).summary.keys() == on_disk.keys()


def test_an_earlier_result_is_replaced_only_with_force(short_model, tmp_path):
    folder = tmp_path / "run"
    clearjoint.simulate(short_model, out=folder)
    with pytest.raises(RuntimeError, match="use --force to replace it"):
        clearjoint.simulate(short_model, out=folder)
    clearjoint.simulate(short_model, out=folder, force=True)
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "thesis.tex").write_text("precious")
    with pytest.raises(RuntimeError, match="not a clearjoint result"):
        clearjoint.simulate(short_model, out=tmp_path / "mine", force=True)
    assert (tmp_path / "mine" / "thesis.tex").read_text() == "precious"


def test_report_step_and_decimation_set_the_rows(short_model):
    result = clearjoint.simulate(short_model, report_step=SHORT_RUN_REPORT_STEP / 2, decimation=4)
    # 41 report times, rows at indices 0, 4, .., 40: 11 rows.
    assert len(result["energy"]["time"]) == 11
    assert result["energy"]["time"][-1] == SHORT_RUN_END_TIME


@pytest.mark.parametrize("options, error", [
    (dict(format="hdf5"), ValueError), (dict(force=True), ValueError), (dict(out="x", format="xml"), ValueError),
    (dict(decimation=2.5), TypeError), (dict(report_step="1ms"), TypeError), (dict(force=1, out="x"), TypeError)])
def test_folder_options_are_checked_before_the_run(short_model, options, error):
    with pytest.raises(error):
        clearjoint.simulate(short_model, **options)


@pytest.mark.parametrize("options, message", [
    (dict(decimation=2**70), r"decimation = 1180591620717411303424: must be in \[1, 1e9\]"),
    (dict(decimation=0), r"decimation = 0: must be in \[1, 1e9\]"),
    (dict(report_step=2**1100), r"report_step = \d+: too large for a double")])
def test_numbers_beyond_a_double_or_a_long_are_refused_naming_the_argument(short_model, options, message):
    with pytest.raises(ValueError, match=message):
        clearjoint.simulate(short_model, **options)


def test_read_run_names_a_missing_folder(tmp_path):
    with pytest.raises(FileNotFoundError):
        clearjoint.read_run(tmp_path / "absent")
    with pytest.raises(ValueError, match="no run tables"):
        clearjoint.read_run(tmp_path)


def test_out_with_a_nul_character_is_refused_naming_the_argument(short_model, tmp_path):
    # A NUL ends the path where the C++ side reads it: 'nul/newdir\0/../../x' must not write x.
    target = tmp_path / "nul" / "newdir\0" / ".." / ".." / "x"
    with pytest.raises(ValueError, match=r"out = .*a path cannot contain a NUL character"):
        clearjoint.simulate(short_model, out=str(target))
    with pytest.raises(ValueError, match="out = "):
        clearjoint.simulate(short_model, out=os.fsencode(str(target)))
    assert list(tmp_path.iterdir()) == []


# -- run.h5 and its checksum ------------------------------------------------------------------


@pytest.fixture
def hdf5_run(short_model, tmp_path):
    folder = tmp_path / "run"
    clearjoint.simulate(short_model, out=folder, format="hdf5")
    return folder


def test_an_hdf5_run_has_a_checksum_that_sha256sum_verifies(hdf5_run):
    done = subprocess.run(["sha256sum", "-c", "run.h5.sha256"], cwd=hdf5_run, capture_output=True, text=True)
    assert done.returncode == 0 and done.stdout == "run.h5: OK\n", done.stdout + done.stderr


# Offsets of run.h5 whose byte set to 0xff made h5py crash the process (segmentation fault) in a
# run of the spatial slider-crank; the sweep below covers the rest of the file.
CRASHING_OFFSETS = (8272, 12303)
SWEEP_FLIPS = 116

FLIP_AND_READ = r"""
import shutil, sys, clearjoint
source, scratch = sys.argv[1], sys.argv[2]
size = len(open(source + "/run.h5", "rb").read())
offsets = [o for o in (8272, 12303) if o < size] + [k * size // %d for k in range(%d)]
for offset in offsets:
    shutil.rmtree(scratch, ignore_errors=True)
    shutil.copytree(source, scratch)
    with open(scratch + "/run.h5", "r+b") as f:
        f.seek(offset)
        byte = f.read(1)
        f.seek(offset)
        f.write(b"\xfe" if byte == b"\xff" else b"\xff")
    try:
        clearjoint.read_run(scratch)
        print(offset, "read without an error")
    except ValueError as error:
        print(offset, error)
""" % (SWEEP_FLIPS, SWEEP_FLIPS)


def test_a_flipped_byte_anywhere_in_run_h5_gives_the_damaged_file_error_never_a_crash(hdf5_run, tmp_path):
    # In a child process: a crash in libhdf5 ends it with a signal instead of ending the tests.
    done = subprocess.run([sys.executable, "-c", FLIP_AND_READ, str(hdf5_run), str(tmp_path / "flipped")],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, f"status {done.returncode}: {done.stderr[-2000:]}"
    lines = done.stdout.splitlines()
    assert len(lines) >= SWEEP_FLIPS + 1, "the sweep and at least one of the crashing offsets ran"
    for line in lines:
        offset, message = line.split(" ", 1)
        assert message.startswith(f"run.h5 in {tmp_path / 'flipped'} does not match its checksum: "
                                  "the file is damaged"), line


def test_a_run_h5_without_its_checksum_is_refused_saying_how_to_add_one(hdf5_run):
    (hdf5_run / "run.h5.sha256").unlink()
    with pytest.raises(ValueError, match=r"has no checksum beside it \(run.h5.sha256\).*sha256sum run.h5"):
        clearjoint.read_run(hdf5_run)
    # The way out the message gives: the checksum of a file the user trusts.
    subprocess.run("sha256sum run.h5 > run.h5.sha256", shell=True, cwd=hdf5_run, check=True)
    assert "energy" in clearjoint.read_run(hdf5_run).tables


def test_a_checksum_file_that_is_not_sha256sums_line_is_refused(hdf5_run):
    (hdf5_run / "run.h5.sha256").write_text("not a checksum\n")
    with pytest.raises(ValueError, match="not one SHA-256 line for run.h5"):
        clearjoint.read_run(hdf5_run)


def test_a_symbolic_link_as_run_h5_is_refused(hdf5_run, tmp_path):
    elsewhere = tmp_path / "elsewhere.h5"
    (hdf5_run / "run.h5").rename(elsewhere)
    (hdf5_run / "run.h5").symlink_to(elsewhere)
    with pytest.raises(ValueError, match="symbolic link"):
        clearjoint.read_run(hdf5_run)


def test_a_matching_file_hdf5_cannot_read_as_a_run_is_refused_in_one_sentence(hdf5_run):
    # Bytes that match a checksum written for them, but are not an HDF5 run file.
    (hdf5_run / "run.h5").write_bytes(b"\x89HDF\r\n\x1a\n" + bytes(4000))
    subprocess.run("sha256sum run.h5 > run.h5.sha256", shell=True, cwd=hdf5_run, check=True)
    with pytest.raises(ValueError, match=r"cannot be read as a run: the file is damaged or was not "
                                         r"written by clearjoint simulate \(HDF5 cannot read it"):
        clearjoint.read_run(hdf5_run)


def test_read_run_refuses_a_table_linked_to_another_file(short_model, tmp_path):
    folder = tmp_path / "run"
    clearjoint.simulate(short_model, out=folder)
    (tmp_path / "elsewhere.csv").write_bytes((folder / "energy.csv").read_bytes())
    (folder / "energy.csv").unlink()
    (folder / "energy.csv").symlink_to(tmp_path / "elsewhere.csv")
    with pytest.raises(ValueError, match="energy.csv' is a symbolic link"):
        clearjoint.read_run(folder)
