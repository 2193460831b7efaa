# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.read_run's tables: pandas DataFrames (when pandas is installed) whose code columns
have the dtypes of detection batches, the same numbers in CSV and HDF5 folders, and
clearjoint.plot.read_run reading the same folders (HDF5 included) with the same reader."""
import subprocess

import numpy as np
import pytest

import clearjoint
from clearjoint import plot

END_TIME = 0.01
TABLE = "force_rod-slider_clearance"


@pytest.fixture(scope="module")
def folders(tmp_path_factory, models_dir, cli):
    base = tmp_path_factory.mktemp("read-run")
    out = {}
    for format in ("csv", "hdf5"):
        out[format] = base / format
        subprocess.run([str(cli), "simulate", str(models_dir / "slider_crank_planar_clearance_lubricated.json"),
                        "--end-time", str(END_TIME), "--format", format, "--out", str(out[format])],
                       check=True, stdout=subprocess.DEVNULL)
    return out


def test_tables_are_dataframes_with_the_code_dtypes_of_detection_batches(folders):
    pandas = pytest.importorskip("pandas")
    run = clearjoint.read_run(folders["csv"])
    joint = run.tables[TABLE]
    assert isinstance(joint, pandas.DataFrame)
    batch = clearjoint.detect(clearjoint.JointDimensions(bearing_radius=0.01, bearing_length=0.02,
                                                         journal_radius=0.0099, journal_length=0.0198),
                              [[0, 0, 0]], [[0, 0, 1]], [[0, 0, 0]], [[0, 0, 1]]).poses()
    for column, batch_column in (("scenario", "scenario"), ("certainty", "certificate"),
                                 ("contact_count", "contact_count"), ("aligned", "aligned")):
        assert joint[column].dtype == batch[batch_column].dtype, column
    assert joint["film.regime"].dtype == np.int8
    assert joint["fx"].dtype == np.float64 and run.tables["energy"]["total"].dtype == np.float64


def test_csv_and_hdf5_folders_read_back_the_same_tables(folders):
    csv, hdf5 = clearjoint.read_run(folders["csv"]), clearjoint.read_run(folders["hdf5"])
    assert sorted(csv.tables) == sorted(hdf5.tables)
    for name, columns in csv.tables.items():
        assert list(columns) == list(hdf5.tables[name])
        for column in columns:
            np.testing.assert_array_equal(np.asarray(columns[column]), np.asarray(hdf5.tables[name][column]))


def test_the_figures_read_an_hdf5_folder_and_a_read_run_result_in_metres(folders):
    from_folder = plot.read_run(folders["hdf5"])
    assert from_folder.model is not None and from_folder.clearance_tables() == [TABLE]
    from_result = plot.read_run(clearjoint.read_run(folders["hdf5"]))
    assert from_result.model is not None, "the result's folder holds model.json"
    for column in ("scenario", "rim_a_u", "film.min_thickness"):
        assert from_result.tables[TABLE][column].dtype == np.float64
        np.testing.assert_array_equal(from_result.tables[TABLE][column], from_folder.tables[TABLE][column])
    series = plot.joint_series(from_folder, TABLE)
    assert np.max(np.abs(series.rim_a[:, :2])) < 2 * series.radial_clearance, "rims in metres"
