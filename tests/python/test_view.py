# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.view without a browser: the frames the page animates say what the run's tables
say, decimation keeps the force peaks, the server serves only its own files, and bad runs are
refused in one sentence."""
import json
import shutil
import subprocess
import sys
import urllib.error
import urllib.request

import numpy as np
import pytest

from clearjoint import view
from clearjoint.plot import read_run, scenario_colour
from clearjoint.view.frames import (CONTACT_FLOATS, JOINT_HEAD_FLOATS, MAX_CONTACTS,
                                    inertia_box, nice_magnification, viewer_data)
from run_fixtures import short_model, write_run

JOINT_TABLE = "force_ground-crank_clearance"


@pytest.fixture(scope="module")
def run_folder(tmp_path_factory, models_dir, cli):
    model = short_model(models_dir, "slider_crank_spatial_clearance.json")
    return write_run(cli, model, tmp_path_factory.mktemp("view") / "run")


def joint_block(data):
    joint = data.manifest["joints"][0]
    width = JOINT_HEAD_FLOATS + MAX_CONTACTS * CONTACT_FLOATS
    return data.frames[:, joint["offset"]:joint["offset"] + width].astype(float)


def test_every_frame_carries_the_scenario_and_contact_count_of_its_row(run_folder):
    run = read_run(run_folder)
    data = viewer_data(run)
    table = run.table(JOINT_TABLE)
    block = joint_block(data)
    assert data.manifest["decimation_step"] == 1
    np.testing.assert_array_equal(block[:, 0], table["scenario"])
    np.testing.assert_array_equal(block[:, 1], table["contact_count"])


def test_the_detection_on_the_recorded_poses_finds_the_contacts_of_the_table(run_folder):
    run = read_run(run_folder)
    block = joint_block(viewer_data(run))
    contacts = block[:, JOINT_HEAD_FLOATS:].reshape(len(block), MAX_CONTACTS, CONTACT_FLOATS)
    found = np.isfinite(contacts[:, :, 0]).sum(axis=1)
    table = run.table(JOINT_TABLE)
    # Away from grazing (depth above 1e-3 of the clearance) the recomputed pose gives the same set.
    depths = np.column_stack([table[f"{s}.depth"] for s in ("radial_a", "radial_b", "line", "axial_a", "axial_b")])
    clear = np.all(np.isnan(depths) | (depths > 1e-7), axis=1)
    np.testing.assert_array_equal(found[clear], table["contact_count"][clear])
    radial = np.hypot(contacts[:, :, 0], contacts[:, :, 1])
    joint = run.clearance_joints[0]
    wall = np.isfinite(radial) & (np.abs(contacts[:, :, 2]) < 0.5 * joint.bearing_length - 1e-6)
    np.testing.assert_allclose(radial[wall], joint.bearing_radius, rtol=1e-3)


def test_decimation_keeps_the_largest_force_of_each_frame(run_folder):
    run = read_run(run_folder)
    full, decimated = viewer_data(run), viewer_data(run, max_frames=37)
    step = decimated.manifest["decimation_step"]
    assert step == int(np.ceil(full.manifest["row_count"] / 37))
    force = joint_block(full)[:, 8]
    peaks = joint_block(decimated)[:, 9]
    np.testing.assert_allclose(peaks, [force[k:k + step].max() for k in range(0, len(force), step)], rtol=1e-6)
    assert peaks.max() == pytest.approx(force.max(), rel=1e-6)


def test_bodies_are_boxes_with_their_mass_and_inertia():
    a, b, c = inertia_box(0.12, [1e-4, 1e-4, 1e-5])  # the paper's crank (Table 3)
    assert c == pytest.approx(0.0975, rel=1e-3) and a == b == pytest.approx(0.0224, rel=1e-2)
    assert nice_magnification(15.0) == 10.0 and nice_magnification(0.5) == 1.0


def test_the_server_serves_the_page_the_run_and_nothing_else(run_folder):
    with view.serve(run_folder) as server:
        assert server.url.startswith("http://127.0.0.1:")
        page = urllib.request.urlopen(server.url).read().decode()
        assert "vendor/three.bundle.min.js" in page
        manifest = json.loads(urllib.request.urlopen(server.url + "run/manifest.json").read())
        frames = urllib.request.urlopen(server.url + "run/frames.f32").read()
        assert len(frames) == 4 * manifest["frame_count"] * manifest["stride"]
        assert manifest["scenarios"][1]["colour"] == scenario_colour(1)
        script = urllib.request.urlopen(server.url + "main.js")
        assert script.headers["Content-Type"].startswith("text/javascript")
        for path in ("../__init__.py", "%2e%2e/server.py", "run/../frames.py", "nothing"):
            with pytest.raises(urllib.error.HTTPError) as error:
                urllib.request.urlopen(server.url + path)
            assert error.value.code == 404


def test_the_vendored_library_ships_with_its_licence():
    import clearjoint.view.server as server
    vendor = server.WEB_DIRECTORY + "/vendor/"
    assert "MIT License" in open(vendor + "three-LICENSE.txt").read()
    assert open(vendor + "three.bundle.min.js").read(200).startswith("/* three.js ")


def run_view(*args):
    return subprocess.run([sys.executable, "-m", "clearjoint.view", "--no-browser", *map(str, args)],
                          capture_output=True, text=True, timeout=60)


def one_sentence_error(done, *words):
    assert done.returncode == 1
    assert "Traceback" not in done.stderr
    assert done.stderr.startswith("clearjoint view: ") and done.stderr.count("\n") == 1, done.stderr
    for word in words:
        assert word in done.stderr


def test_a_run_without_its_model_is_refused_in_one_sentence(run_folder, tmp_path):
    bare = tmp_path / "bare"
    shutil.copytree(run_folder, bare)
    (bare / "model.json").unlink()
    one_sentence_error(run_view(bare), "--model")


def test_a_folder_that_is_not_a_run_is_refused_in_one_sentence(tmp_path):
    one_sentence_error(run_view(tmp_path), "not a run folder")


def test_a_truncated_table_is_refused_in_one_sentence(run_folder, tmp_path):
    damaged = tmp_path / "damaged"
    shutil.copytree(run_folder, damaged)
    table = damaged / "body_crank.csv"
    table.write_text(table.read_text()[:-25])
    one_sentence_error(run_view(damaged), "truncated")


def request_with_host(server, host, path="run/manifest.json"):
    """Status of a GET whose Host header is `host` (None: no Host header at all)."""
    import http.client
    port = int(server.url.rsplit(":", 1)[1].strip("/"))
    connection = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    try:
        connection.putrequest("GET", "/" + path, skip_host=True)
        if host is not None:
            connection.putheader("Host", host)
        connection.endheaders()
        response = connection.getresponse()
        response.read()
        return response.status
    finally:
        connection.close()


def test_the_server_answers_only_requests_addressed_to_a_loopback_name_and_its_port(run_folder):
    # A page of another site that rebinds its name to 127.0.0.1 sends that name as Host.
    with view.serve(run_folder) as server:
        port = int(server.url.rsplit(":", 1)[1].strip("/"))
        for host in ("localhost", f"localhost:{port}", f"127.0.0.1:{port}", f"[::1]:{port}", "LOCALHOST"):
            assert request_with_host(server, host) == 200, host
        for host in (f"evil.example:{port}", "evil.example", f"127.0.0.1:{port + 1}", f"localhost.:{port}",
                     f"127.0.0.1.evil.example:{port}", "", None):
            assert request_with_host(server, host) == 421, host
            assert request_with_host(server, host, "") == 421, host


@pytest.mark.parametrize("option, value", [("--port", "99999"), ("--port", "-1"), ("--port", "http"),
                                           ("--max-frames", "0"), ("--magnify", "nan"), ("--magnify", "-2")])
def test_an_option_out_of_range_is_refused_naming_it_without_a_traceback(run_folder, option, value):
    done = run_view(run_folder, option, value)
    assert done.returncode == 2
    assert "Traceback" not in done.stderr
    assert f"argument {option}: '{value}'" in done.stderr, done.stderr


def test_a_port_out_of_range_is_refused_by_serve(run_folder):
    with pytest.raises(ValueError, match="port = 70000: must be a whole number from 0"):
        view.serve(run_folder, port=70000)


def test_a_renamed_column_of_the_joint_table_is_refused_naming_it(run_folder, tmp_path):
    damaged = tmp_path / "renamed"
    shutil.copytree(run_folder, damaged)
    table = damaged / f"{JOINT_TABLE}.csv"
    text = table.read_text()
    table.write_text(text.replace("rim_a_u", "rim_a_x", 1))
    one_sentence_error(run_view(damaged), f"{JOINT_TABLE}.csv has no column rim_a_u")


def test_a_table_linked_to_another_file_is_refused(run_folder, tmp_path):
    linked = tmp_path / "linked"
    shutil.copytree(run_folder, linked)
    (tmp_path / "elsewhere.csv").write_bytes((linked / "energy.csv").read_bytes())
    (linked / "energy.csv").unlink()
    (linked / "energy.csv").symlink_to(tmp_path / "elsewhere.csv")
    one_sentence_error(run_view(linked), "energy.csv", "symbolic link")


def test_an_hdf5_run_of_a_lubricated_joint_is_served_with_the_film_force_on_a_sensible_axis(tmp_path, models_dir, cli):
    folder = tmp_path / "lubricated-hdf5"
    subprocess.run([str(cli), "simulate", str(models_dir / "slider_crank_planar_clearance_lubricated.json"),
                    "--end-time", "0.01", "--format", "hdf5", "--out", str(folder)],
                   check=True, stdout=subprocess.DEVNULL)
    with view.serve(folder) as server:
        manifest = json.loads(urllib.request.urlopen(server.url + "run/manifest.json").read())
        frames = np.frombuffer(urllib.request.urlopen(server.url + "run/frames.f32").read(), dtype="<f4")
    (joint,) = manifest["joints"]
    assert joint["lubricated"] and joint["peak_force"] == 0.0, "the film holds: no dry contact"
    assert joint["peak_total_force"] > 1.0, "the film carries the rod's load"
    head = frames.reshape(manifest["frame_count"], manifest["stride"])[:, joint["offset"]:]
    # From the first report time on (at t = 0 the journal is centred, its film unloaded).
    assert np.all(head[1:, 10] > 1.0)
    film_thickness = head[:, 12].astype(float)
    assert np.all((film_thickness > 0.0) & (film_thickness <= 1.0001e-4)), "h_min within the clearance c = 0.1 mm"
