# SPDX-License-Identifier: BSD-3-Clause
"""The store: a folder the study owns, never one of the user's; run files read only when their
bytes match their checksum (a corrupted one is set aside, named and run again); runs reused only
under the same reuse key, reducing code included; folders a group shares stay writable by the
group; a store that cannot be used is one line on stderr and status 2."""
import io
import json
import os
import shutil
import stat
import subprocess
import sys
import tempfile

import h5py
import pytest

from clearjoint.study import Store, load_study, run_study
from clearjoint.study.__main__ import main
from clearjoint.study.expand import Run
from study_fixtures import (assert_store_matches, edit_run_file, edit_study, fake_result, run_without_faults,
                            study_command, write_study)

RUN_ARGUMENTS = ["--workers", "1", "--no-progress", "--no-plot"]


@pytest.fixture(scope="module")
def client():
    """One in-process worker thread: runs of a few milliseconds without starting processes."""
    from distributed import Client, LocalCluster
    cluster = LocalCluster(n_workers=1, threads_per_worker=1, processes=False, dashboard_address=None)
    with Client(cluster) as c:
        yield c
    cluster.close()


def snapshot(folder):
    """{relative path: bytes, or None for a folder} of everything under folder."""
    found = {}
    for root, folders, files in os.walk(folder):
        for name in folders:
            found[os.path.relpath(os.path.join(root, name), folder)] = None
        for name in files:
            with open(os.path.join(root, name), "rb") as f:
                found[os.path.relpath(os.path.join(root, name), folder)] = f.read()
    return found


def users_folder(tmp_path):
    home = tmp_path / "home"
    (home / "data").mkdir(parents=True)
    (home / "thesis.tex").write_text("precious\n")
    (home / "data" / "measured.csv").write_text("t,x\n0,1\n")
    return home


def one_line_error(capsys):
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err, err
    return err


# -- a folder the study owns ---------------------------------------------------------------------

@pytest.mark.parametrize("store", ["home", "home/data", "."])
def test_a_populated_folder_that_is_not_a_store_is_refused_and_left_as_it_was(tmp_path, models_dir, capsys, store):
    home = users_folder(tmp_path)
    path = edit_study(write_study(tmp_path, models_dir, radial=(0.1,), members=1), lambda s: s.update(store=store))
    before = snapshot(tmp_path)
    assert main(["run", path] + RUN_ARGUMENTS) == 2
    err = one_line_error(capsys)
    assert "store = %r" % store in err and "not a study store" in err
    assert snapshot(tmp_path) == before
    assert main(["summary", path]) == 2 and "store = %r" % store in one_line_error(capsys)
    assert (home / "thesis.tex").read_text() == "precious\n"


def test_the_root_folder_is_not_a_store(tmp_path):
    from clearjoint.study.store import StoreError
    with pytest.raises(StoreError, match="not a study store"):
        Store("/").check_folder()


def test_a_new_store_inside_a_users_folder_is_made_marked_and_reused_and_leaves_the_users_files(tmp_path, models_dir,
                                                                                               client):
    from clearjoint.study.store import MARKER
    home = users_folder(tmp_path)
    path = edit_study(write_study(tmp_path, models_dir, radial=(0.1,), members=1),
                      lambda s: s.update(store="home/results"))
    users_files = snapshot(home)
    study = load_study(path)
    assert run_study(study, client=client, progress=False).computed
    assert os.path.exists(home / "results" / MARKER)
    assert run_study(study, client=client, progress=False).reused == 1  # its own store: accepted
    after = snapshot(home)
    assert {k: v for k, v in after.items() if not k.startswith("results")} == users_files


def test_an_empty_folder_is_accepted_and_marked(tmp_path):
    from clearjoint.study.store import MARKER
    empty = tmp_path / "empty"
    empty.mkdir()
    Store(str(empty)).open_for_writing({})
    assert os.path.isfile(empty / MARKER)


LOOKALIKE_STORES = {
    "a summary and figures of the user's": {"summary/runs.csv": "point_id,mine\n1,precious\n", "figures/": None},
    "the files of a store but no marker": {"runs/": None, "study.json": "{}", "writes.log": "",
                                           "summary/runs.csv": "precious\n"},
    "a marker that is a folder": {".clearjoint-study-store/": None, "summary/runs.csv": "precious\n"},
}


@pytest.mark.parametrize("contents", LOOKALIKE_STORES.values(), ids=LOOKALIKE_STORES.keys())
def test_a_folder_that_only_looks_like_a_store_is_refused_naming_the_missing_marker(tmp_path, models_dir, capsys,
                                                                                   contents):
    from clearjoint.study.store import MARKER
    for name, text in contents.items():
        (tmp_path / "results" / name).parent.mkdir(parents=True, exist_ok=True)
        if text is None:
            (tmp_path / "results" / name).mkdir()
        else:
            (tmp_path / "results" / name).write_text(text)
    path = edit_study(write_study(tmp_path, models_dir, radial=(0.1,), members=1), lambda s: s.update(store="results"))
    before = snapshot(tmp_path)
    for command in (["run", path] + RUN_ARGUMENTS, ["summary", path], ["plot", path]):
        assert main(command) == 2, command
        err = one_line_error(capsys)
        assert "store = 'results'" in err and "not a study store" in err and "no marker %s" % MARKER in err, err
        assert str(tmp_path / "results") in err
    assert snapshot(tmp_path) == before


def test_a_store_that_is_a_file_is_one_line_and_status_2(tmp_path, models_dir, capsys):
    path = edit_study(write_study(tmp_path, models_dir, radial=(0.1,), members=1), lambda s: s.update(store="notes.txt"))
    (tmp_path / "notes.txt").write_text("mine\n")
    assert main(["run", path] + RUN_ARGUMENTS) == 2
    assert "store = 'notes.txt'" in one_line_error(capsys)
    assert (tmp_path / "notes.txt").read_text() == "mine\n"


@pytest.fixture
def shared_tmp():
    """A folder every user can enter (pytest's tmp_path is private to its user)."""
    folder = tempfile.mkdtemp(prefix="clearjoint-study-")
    os.chmod(folder, 0o755)
    yield folder
    shutil.rmtree(folder)


def _as_other_user(user):
    """subprocess arguments that run as another user when this process may switch users (root),
    else none (then the folders are made unwritable for this user instead)."""
    return {"user": user, "group": 100, "extra_groups": [100], "umask": 0o022} if os.geteuid() == 0 else {}


def test_a_store_this_user_cannot_write_is_one_line_and_status_2(models_dir, shared_tmp):
    folder = shared_tmp
    path = write_study(folder, models_dir, radial=(0.1,), members=1)
    os.chmod(path, 0o644)
    Store(load_study(path).store_path).open_for_writing({})  # another user's store, mode 0755
    if os.geteuid() != 0:
        os.chmod(load_study(path).store_path, 0o555)
    for command in (["run", path, *RUN_ARGUMENTS], ["summary", path]):
        done = subprocess.run(study_command(*command), capture_output=True, text=True, timeout=600,
                              env=dict(os.environ, HOME=folder), **_as_other_user(65534))
        assert done.returncode == 2, done.stderr
        assert done.stderr.count("\n") == 1 and "Traceback" not in done.stderr, done.stderr
        assert "store = 'store_small'" in done.stderr and "Permission denied" in done.stderr


SECOND_USER_WRITES = """
import sys
from clearjoint.study.store import Store
from clearjoint.study.expand import Run
sys.path.insert(0, sys.argv[3])
from study_fixtures import fake_result
store = Store(sys.argv[1])
store.open_for_writing({})
store.write(Run(sys.argv[2], "p", 0, {}, "m"), (), fake_result(), "o", "s")
store.close()
"""


def test_a_store_in_a_group_writable_folder_is_group_writable_whatever_the_umask(shared_tmp):
    shared = os.path.join(shared_tmp, "shared")
    os.mkdir(shared)
    os.chmod(shared, 0o2775)
    old = os.umask(0o022)
    try:
        store = Store(os.path.join(shared, "store"))
        store.open_for_writing({})
        store.write(Run("first", "p", 0, {}, "m"), (), fake_result(), "o", "s")
        store.close()
    finally:
        os.umask(old)
    for root, folders, files in os.walk(store.path):
        for name in folders + files:
            mode = os.stat(os.path.join(root, name)).st_mode
            assert mode & stat.S_IWGRP, (name, oct(mode))


@pytest.mark.skipif(os.geteuid() != 0, reason="needs two users: runs as root only")
def test_a_second_member_of_the_group_can_run_into_a_store_the_first_made(shared_tmp):
    shared = os.path.join(shared_tmp, "shared")
    os.mkdir(shared)
    os.chown(shared, 0, 100)
    os.chmod(shared, 0o2775)
    store = os.path.join(shared, "store")
    tests = os.path.dirname(os.path.abspath(__file__))
    for user, run_id in ((65534, "first"), (65533, "second")):
        done = subprocess.run([sys.executable, "-c", SECOND_USER_WRITES, store, run_id, tests], capture_output=True,
                              text=True, timeout=120, env=dict(os.environ, HOME=shared), **_as_other_user(user))
        assert done.returncode == 0, (user, done.stderr)
    assert Store(store).stored_ids() == {"first", "second"}


# -- checksums -----------------------------------------------------------------------------------

def flip_byte(path, offset):
    """The issue's corruption: 0x04 -> 0xF0 at byte 1714 of a run file (any change will do)."""
    with open(path, "r+b") as f:
        f.seek(offset)
        byte = f.read(1)[0]
        f.seek(offset)
        f.write(bytes([byte ^ 0xF4]))


def test_corrupted_run_files_are_set_aside_named_and_run_again(tmp_path, models_dir, client):
    study = load_study(write_study(tmp_path, models_dir, radial=(0.05, 0.1, 0.3), members=1))
    first = run_study(study, client=client, progress=False)
    store = Store(study.store_path)
    flipped, edited, intact = first.computed
    flip_byte(store.run_path(flipped), 1714)
    with h5py.File(store.run_path(edited), "a") as f:  # an intact file with another value in it
        f["reductions"]["peak"][()] = 1.0
    out = io.StringIO()
    second = run_study(study, client=client, progress=False, stream=out)
    assert set(second.set_aside) == {flipped, edited} and sorted(second.computed) == sorted([flipped, edited])
    for run_id, (why, where) in second.set_aside.items():
        assert "do not match its checksum" in why and os.path.exists(where)
        assert "run %s" % run_id in out.getvalue() and where in out.getvalue()
    assert second.reused == 1
    assert_store_matches(store, run_without_faults(study))


def test_study_summary_names_a_corrupted_run_file_instead_of_reading_it(tmp_path, models_dir, client):
    path = write_study(tmp_path, models_dir, radial=(0.05, 0.1), members=1)
    study = load_study(path)
    corrupted = run_study(study, client=client, progress=False).computed[0]
    flip_byte(Store(study.store_path).run_path(corrupted), 1714)
    done = subprocess.run(study_command("summary", path), capture_output=True, text=True, timeout=600)
    assert done.returncode == 1, done.stderr  # not 139 (a crash in libhdf5), not 0 (reused silently)
    assert "Traceback" not in done.stderr and corrupted + ".h5" in done.stderr
    with open(os.path.join(study.store_path, "summary", "summary.json")) as f:
        summary = json.load(f)
    assert list(summary["unreadable_runs"]) == [corrupted] and summary["stored_runs"] == 1


def _fifo(path):
    os.mkfifo(path)


def _link_to_dev_zero(path):
    os.symlink("/dev/zero", path)


def _oversized(path, limit):
    with open(path, "wb") as f:  # sparse: a hole of the limit and one byte
        f.truncate(limit + 1)


STORE_FILES_NOT_TO_READ = {
    "a run file that is a fifo": ("run", _fifo, "is not a regular file"),
    "a run file linked to /dev/zero": ("run", _link_to_dev_zero, "is a symbolic link"),
    "a checksum that is a fifo": ("checksum", _fifo, "is not a regular file"),
    "a checksum linked to /dev/zero": ("checksum", _link_to_dev_zero, "is a symbolic link"),
    # 4096: store.MAX_CHECKSUM_BYTES
    "an oversized checksum": ("checksum", lambda path: _oversized(path, 4096), "more than the 4096 bytes"),
}


@pytest.mark.parametrize("which, replace, message", STORE_FILES_NOT_TO_READ.values(),
                         ids=STORE_FILES_NOT_TO_READ.keys())
def test_a_store_file_that_is_not_a_small_regular_file_is_named_and_set_aside_not_read(tmp_path, models_dir, client,
                                                                                        which, replace, message):
    path = write_study(tmp_path, models_dir, radial=(0.1,), members=1)
    study = load_study(path)
    [run_id] = run_study(study, client=client, progress=False).computed
    store = Store(study.store_path)
    target = store.run_path(run_id) if which == "run" else store.checksum_path(run_id)
    os.remove(target)
    replace(target)
    done = subprocess.run(study_command("summary", path), capture_output=True, text=True, timeout=60)
    assert done.returncode == 1, done.stderr  # not a hang on the fifo, not /dev/zero read forever
    assert "Traceback" not in done.stderr and repr(target) in done.stderr and message in done.stderr, done.stderr
    again = run_study(study, client=client, progress=False, stream=io.StringIO())
    assert again.computed == [run_id] and message in again.set_aside[run_id][0]
    assert store.verify(run_id) is None


def test_each_stored_run_has_a_checksum_sha256sum_verifies(tmp_path):
    store = Store(str(tmp_path / "store"))
    store.open_for_writing({})
    store.write(Run("abc", "p", 0, {}, "m"), (), fake_result(), "o", "s")
    done = subprocess.run(["sha256sum", "-c", "abc.sha256"], cwd=store.runs, capture_output=True, text=True)
    assert done.returncode == 0 and "abc.h5: OK" in done.stdout


# -- the reuse key -------------------------------------------------------------------------------

def test_a_run_stored_by_another_package_or_library_build_is_run_again(tmp_path, models_dir, client):
    from clearjoint.study.execute import library_build, package_code
    study = load_study(write_study(tmp_path, models_dir, radial=(0.05, 0.1, 0.3), members=1))
    first = run_study(study, client=client, progress=False)
    store = Store(study.store_path)
    with h5py.File(store.run_path(first.computed[0]), "r") as f:
        assert f.attrs["package_sha256"] == package_code() and f.attrs["library_build"] == library_build()
    other_package, other_build, same = first.computed
    edit_run_file(store, other_package, lambda f: f.attrs.__setitem__("package_sha256", "another package"))
    edit_run_file(store, other_build, lambda f: f.attrs.__setitem__("library_build", "another build"))
    again = run_study(study, client=client, progress=False)
    assert sorted(again.computed) == sorted([other_package, other_build]) and again.reused == 1
    assert again.set_aside == {}


REUSABLE_RUNS = """
import sys
import clearjoint
from clearjoint.study import Store, expand_study, load_study
from clearjoint.study.expand import outputs_sha256
from clearjoint.study.runner import reuse_key
study = load_study(sys.argv[1])
_, runs, _ = expand_study(study)
store = Store(study.store_path)
print(clearjoint.__file__, sum(store.is_current(r.run_id, reuse_key(r, outputs_sha256(study))) for r in runs))
"""


def reusable_runs_under(package_copy, study_path):
    """How many of the study's stored runs `study run` would reuse when it imports the package at
    package_copy (a folder holding clearjoint/)."""
    done = subprocess.run([sys.executable, "-c", REUSABLE_RUNS, study_path], capture_output=True, text=True,
                          timeout=120, cwd=str(package_copy), env=dict(os.environ, PYTHONPATH=str(package_copy)))
    assert done.returncode == 0, done.stderr
    imported, count = done.stdout.split()
    assert imported.startswith(str(package_copy)), imported
    return int(count)


def test_a_copy_of_the_package_with_one_file_changed_reuses_no_stored_run(tmp_path, models_dir, client):
    import clearjoint
    path = write_study(tmp_path, models_dir, radial=(0.05, 0.1), members=1)
    assert len(run_study(load_study(path), client=client, progress=False).computed) == 2
    copy = tmp_path / "copy"
    shutil.copytree(os.path.dirname(clearjoint.__file__), copy / "clearjoint",
                    ignore=shutil.ignore_patterns("__pycache__"))
    assert reusable_runs_under(copy, path) == 2  # the same files elsewhere: the same package
    with open(copy / "clearjoint" / "_simulate.py", "a") as f:  # not the study's own code
        f.write("\n# a changed copy\n")
    assert reusable_runs_under(copy, path) == 0
