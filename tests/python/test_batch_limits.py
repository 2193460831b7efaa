# SPDX-License-Identifier: BSD-3-Clause
"""Batches that cannot finish: running out of memory raises MemoryError in the caller whatever
the thread that ran out, and Ctrl-C raises KeyboardInterrupt within a fraction of a second. Each
case runs in a child interpreter, which a failure here would abort or keep busy."""
import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

#: Joint of Table 2 in millimetres; a journal against the wall with its axis tilted by 1e-140:
#: both rims touch the wall at a near-tangency, decided by the exact tier (~60 us a pose).
SLOW_POSES = """
import numpy as np
import clearjoint
dims = clearjoint.JointDimensions(bearing_radius=10.0, bearing_length=20.0, journal_radius=9.9,
                                  journal_length=19.8)
def slow_batch(rows, threads):
    return clearjoint.detect(dims, [0, 0, 0], [0, 0, 1], np.tile([0.0, 0.1, 0.0], (rows, 1)),
                             [0, 1e-140, 1], threads=threads)
#: A pin against the bore with its axis tilted by 1e-140 (the tests' pin-in-hole joint): both hole
#: edges touch the pin at a near-tangency, the exact tier again (~60 us a pose).
pin_dims = clearjoint.PinInHoleDimensions(hole_radius=10.0, hole_length=20.0, pin_radius=9.9,
                                          stops=((-10.5, 16.0), (10.5, 16.0)))
def slow_pin_batch(rows, threads):
    return clearjoint.detect_pin_in_hole(pin_dims, [0, 0, 0], [0, 0, 1], np.tile([0.0, 0.1, 0.0], (rows, 1)),
                                         [0, 1e-140, 1], threads=threads)
#: A rim internally tangent to a wall (examples/rims.jsonl, wall-B-exact-tangent): the exact
#: tier again, ~20 us a pair.
def slow_kernel_batch(rows, threads):
    return clearjoint.intersect_circle_cylinder(np.tile([100.0, 0, 9900], (rows, 1)), [0, 0, 1], 9900,
                                                [0, 0, 0], [0, 0, 1], 10000, threads=threads)
"""


def child(script):
    return subprocess.Popen([sys.executable, "-c", textwrap.dedent(SLOW_POSES + script)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=dict(os.environ))


@pytest.mark.parametrize("threads", [1, 2, 3])
def test_a_batch_out_of_memory_raises_memory_error_on_any_thread_count(threads):
    # The batch: a million poses in scenario (i), four contacts each, about 1 GB of
    # results, under an address-space limit 400 MB above what the interpreter holds already.
    run = child(f"""
import resource
def address_space():
    with open("/proc/self/status") as status:
        return next(int(line.split()[1]) * 1024 for line in status if line.startswith("VmSize:"))
limit = address_space() + 400 * 2**20
resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
try:
    clearjoint.detect(dims, [0, 0, 0], [0, 0, 1], np.zeros((1000000, 3)), [0, 0.013, 1.0],
                      threads={threads})
    print("finished")
except MemoryError:
    print("MemoryError")
print(clearjoint.detect(dims, [0, 0, 0], [0, 0, 1], np.zeros((3, 3)), [0, 0.013, 1.0]).scenario[0])
""")
    out, err = run.communicate(timeout=300)
    assert run.returncode == 0, err
    assert out.split() == ["MemoryError", "9"], out  # and the interpreter carries on


@pytest.mark.parametrize("batch, rows", [("slow_batch", 100000), ("slow_pin_batch", 100000),
                                         ("slow_kernel_batch", 300000)])
@pytest.mark.parametrize("threads", [1, 2])
def test_ctrl_c_stops_a_long_batch_within_a_fraction_of_a_second(batch, rows, threads):
    # About 6 s on one thread, if nothing stops them.
    run = child(f"""
import time
{batch}(1000, {threads})  # warm up
print("ready", flush=True)
start = time.monotonic()
try:
    {batch}({rows}, {threads})
    print("finished", time.monotonic() - start)
except KeyboardInterrupt:
    print("interrupted", time.monotonic() - start)
""")
    assert run.stdout.readline().strip() == "ready"
    time.sleep(0.5)
    run.send_signal(signal.SIGINT)
    sent = time.monotonic()
    out, err = run.communicate(timeout=120)
    waited = time.monotonic() - sent
    assert out.split()[0] == "interrupted", (out, err)
    assert waited < 1.0, waited


def test_many_threads_under_an_address_space_limit_finish_or_raise_memory_error_naming_the_batch():
    # The batch: 2e6 poses with four contacts each (about 1 GB of results) on 16 threads,
    # under ulimit -v at several margins above what the interpreter holds once the package is
    # loaded, three times each. Sixteen threads on a two-core machine ended the process in glibc
    # ("cannot allocate memory for thread-local data: ABORT", exit status 127) in about one run in
    # nine at these margins; each run takes about half a second.
    probe = subprocess.run([sys.executable, "-c", textwrap.dedent(SLOW_POSES + """
slow_batch(64, 2)
with open("/proc/self/status") as status:
    print(next(int(line.split()[1]) for line in status if line.startswith("VmSize:")))
""")], capture_output=True, text=True, check=True)
    held_kb = int(probe.stdout)
    script = textwrap.dedent(SLOW_POSES + """
try:
    clearjoint.detect(dims, [0, 0, 0], [0, 0, 1], np.zeros((2000000, 3)), [0, 0.013, 1.0], threads=16)
    print("finished")
except MemoryError as error:
    print("MemoryError:", error)
""")
    outcomes = []
    for margin_mb in (150, 200, 250, 300) * 3:
        run = subprocess.run(["bash", "-c", f'ulimit -v {held_kb + margin_mb * 1024}; exec "$0" -c "$1"',
                              sys.executable, script], capture_output=True, text=True, timeout=120)
        outcomes.append((margin_mb, run.returncode, run.stdout.strip(), run.stderr.strip()[-300:]))
    for margin_mb, returncode, out, err in outcomes:
        assert returncode == 0, outcomes
        assert out == "finished" or out == (
            "MemoryError: detect: a batch of 2000000 poses does not fit in the memory available for its "
            "results; pass fewer at a time"), outcomes


@pytest.mark.parametrize("query", ["intersect_circle_plane", "intersect_circle_cylinder"])
def test_a_kernel_batch_out_of_memory_raises_memory_error_naming_the_batch(query):
    # Four million circles: the cylinder query's result columns take about 230 bytes a row (four
    # crossings of angle, error, point, multiplicity), the plane query's about 140, so either needs
    # over 500 MB, under a limit 400 MB above what the interpreter holds with the inputs made.
    run = child(f"""
import resource
centres = np.tile([100.0, 0, 9900], (4000000, 1))
def address_space():
    with open("/proc/self/status") as status:
        return next(int(line.split()[1]) * 1024 for line in status if line.startswith("VmSize:"))
limit = address_space() + 400 * 2**20
resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
try:
    if "{query}" == "intersect_circle_plane":
        clearjoint.intersect_circle_plane(centres, [0, 0, 1], 9900, [0, 0, 0], [0, 0, 1], threads=1)
    else:
        clearjoint.intersect_circle_cylinder(centres, [0, 0, 1], 9900, [0, 0, 0], [0, 0, 1], 10000,
                                             threads=1)
    print("finished")
except MemoryError as error:
    print("MemoryError:", error)
""")
    out, err = run.communicate(timeout=300)
    assert run.returncode == 0, err
    assert out.strip() == (f"MemoryError: {query}: a batch of 4000000 circles does not fit in the "
                           "memory available for its results; pass fewer at a time"), (out, err)
