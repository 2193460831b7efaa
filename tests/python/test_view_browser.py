# SPDX-License-Identifier: BSD-3-Clause
"""The viewer page in a real browser: Debian's headless Chromium driven through Selenium and
chromium-driver (no browser download). On a short run: the page loads without console errors,
the 3-D canvas draws, moving the time slider changes the frame, and the contacts drawn at the
instant of the largest contact force have the colour of the scenario the run's table gives.
A screenshot is kept (CLEARJOINT_VIEW_ARTEFACTS, else the test's temporary folder). On a run of
1e5 report times, the time to pack it and to load the page is measured and written beside it,
not asserted (docs/viewing-runs.md quotes it)."""
import base64
import io
import os
import pathlib
import shutil
import time

import numpy as np
import pytest

from clearjoint import view
from clearjoint.plot import read_run, scenario_colour
from run_fixtures import short_model, write_run

selenium = pytest.importorskip("selenium", reason="python3-selenium (scripts/install-dependencies.sh)")
from selenium import webdriver  # noqa: E402
from selenium.webdriver.chrome.options import Options  # noqa: E402
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402
from selenium.webdriver.support.ui import WebDriverWait  # noqa: E402

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
CHROMEDRIVER = shutil.which("chromedriver") or "/usr/bin/chromedriver"
JOINT_TABLE = "force_ground-crank_clearance"
# The large run: 1e5 report times over 20 ms of the spatial slider-crank.
LARGE_END_TIME, LARGE_REPORT_STEP = 0.02, 2e-7
PAGE_TIMEOUT = 30


@pytest.fixture(scope="module")
def artefacts(tmp_path_factory):
    folder = os.environ.get("CLEARJOINT_VIEW_ARTEFACTS")
    path = pathlib.Path(folder) if folder else tmp_path_factory.mktemp("artefacts")
    path.mkdir(parents=True, exist_ok=True)
    return path


@pytest.fixture(scope="module")
def browser():
    if not (os.path.exists(CHROMIUM) and os.path.exists(CHROMEDRIVER)):
        pytest.skip("Debian's chromium and chromium-driver are needed (scripts/install-dependencies.sh)")
    options = Options()
    options.binary_location = CHROMIUM
    # WebGL without a GPU: ANGLE on SwiftShader, which Chromium allows only when asked.
    for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1280,800",
                     "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--hide-scrollbars"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    yield driver
    driver.quit()


def open_page(driver, url):
    started = time.monotonic()
    driver.get(url)
    WebDriverWait(driver, PAGE_TIMEOUT).until(
        lambda d: d.execute_script("return window.clearjointView && (window.clearjointView.ready || "
                                   "window.clearjointView.errors.length > 0)"))
    state = driver.execute_script("return window.clearjointView")
    assert state["errors"] == [], state["errors"]
    return time.monotonic() - started, state


def console_errors(driver):
    return [entry for entry in driver.get_log("browser") if entry["level"] == "SEVERE"]


def canvas_pixels(driver):
    element = driver.find_element(By.ID, "scene")
    import matplotlib.image
    return matplotlib.image.imread(io.BytesIO(base64.b64decode(element.screenshot_as_base64)), format="png")


def test_the_page_animates_a_short_run_with_the_tables_scenario_colours(browser, models_dir, cli,
                                                                          tmp_path, artefacts):
    folder = write_run(cli, short_model(models_dir, "slider_crank_spatial_clearance.json"), tmp_path / "run")
    run = read_run(folder)
    table = run.table(JOINT_TABLE)
    with view.serve(run) as server:
        _, state = open_page(browser, server.url)
        assert state["frameCount"] == len(table["time"])

        first = canvas_pixels(browser)
        colours = np.unique((first[:, :, :3] * 255).astype(np.uint8).reshape(-1, 3), axis=0)
        assert len(colours) > 50, "the 3-D canvas shows shaded shapes, not a blank area"

        slider = browser.find_element(By.ID, "time")
        slider.send_keys(Keys.END)  # a keyboard move of the range input fires its input event
        WebDriverWait(browser, 5).until(lambda d: d.execute_script("return window.clearjointView.drawnFrame") > 0)
        moved = canvas_pixels(browser)
        assert np.abs(moved - first).max() > 0.1, "the scene changes when the slider moves"
        label = browser.find_element(By.ID, "time-label").text
        assert label == f"t = {table['time'][-1]:.6f} s"

        # The instant of the largest contact force: a deep contact, the same set from the poses.
        force = sum(table[f"{s}.normal_force"] for s in ("radial_a", "radial_b", "line", "axial_a", "axial_b"))
        row = int(np.argmax(force))
        browser.execute_script("return window.clearjointView.setFrame(arguments[0])", row)
        state = browser.execute_script("return window.clearjointView")
        code = int(table["scenario"][row])
        assert state["scenario"] == code and code != 0
        assert state["contactColours"] == [scenario_colour(code)] * int(table["contact_count"][row])

        browser.save_screenshot(str(artefacts / "view-browser.png"))
        browser.find_element(By.ID, "focus").click()
        time.sleep(0.3)
        browser.save_screenshot(str(artefacts / "view-browser-joint.png"))
        assert console_errors(browser) == []


def test_a_run_without_clearance_joints_shows_its_bodies(browser, models_dir, cli, tmp_path):
    folder = write_run(cli, short_model(models_dir, "slider_crank_spatial_ideal.json"), tmp_path / "ideal")
    with view.serve(folder) as server:
        _, state = open_page(browser, server.url)
        assert state["frameCount"] == server.data.manifest["row_count"]
        pixels = canvas_pixels(browser)
        assert len(np.unique((pixels[:, :, :3] * 255).astype(np.uint8).reshape(-1, 3), axis=0)) > 50
        assert console_errors(browser) == []


def test_a_run_of_1e5_report_times_loads_and_its_load_time_is_reported(browser, models_dir, cli,
                                                                         tmp_path, artefacts):
    model = short_model(models_dir, "slider_crank_spatial_clearance.json", LARGE_END_TIME, LARGE_REPORT_STEP)
    started = time.monotonic()
    folder = write_run(cli, model, tmp_path / "large")
    simulated = time.monotonic() - started
    started = time.monotonic()
    with view.serve(folder) as server:
        packed = time.monotonic() - started
        page, state = open_page(browser, server.url)
        assert console_errors(browser) == []
        rows = server.data.manifest["row_count"]
    report = (f"{rows} report times: simulated in {simulated:.2f} s, read and packed by clearjoint view "
              f"in {packed:.2f} s, page loaded in {page:.2f} s (in-page {state['loadSeconds']:.2f} s), "
              f"{state['frameCount']} frames\n")
    (artefacts / "view-browser-timings.txt").write_text(report)
    print(report)
    assert rows >= 100_000
