"""The pages of `kontakt serve` in a real browser (issue 32): Debian's chromium driven by
Selenium through chromedriver, headless, at 1280 x 800.

It starts `kontakt serve --port 0` (the debug binary `cargo test --workspace` built), fills
the Hertz form and compares the numbers the page shows with `kontakt solve --json` on the
same case, checks that an input error is shown beside its field with the CLI's message,
runs the roller end / rib page, the bearing page (and cancels a long solve) and the
traction page, and fails on any JavaScript error in the browser's console (level SEVERE).
Screenshots for a person to look at go to `<target>/browser/` (target: $CARGO_TARGET_DIR or
./target).

Run by tools/test after the Python package's tests; .ci/run installs chromium and
chromium-driver. Without them the test FAILS (it is never skipped): set
KONTAKT_CHROMIUM and KONTAKT_CHROMEDRIVER to use others.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import threading
import time
import urllib.request
from pathlib import Path

import pytest
from selenium import webdriver
from selenium.common.exceptions import TimeoutException
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.support import expected_conditions as ec
from selenium.webdriver.support.ui import Select, WebDriverWait

ROOT = Path(__file__).resolve().parents[4]
TARGET = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
KONTAKT = TARGET / "debug" / "kontakt"
SHOTS = TARGET / "browser"
DOWNLOADS = SHOTS / "downloads"
CHROMIUM = os.environ.get("KONTAKT_CHROMIUM", "/usr/bin/chromium")
CHROMEDRIVER = os.environ.get("KONTAKT_CHROMEDRIVER", "/usr/bin/chromedriver")


@pytest.fixture(scope="module")
def server():
    """`kontakt serve --port 0`; yields its URL, stops it afterwards."""
    if not KONTAKT.is_file():
        pytest.fail(f"{KONTAKT} not built: run cargo build --workspace --bins first")
    proc = subprocess.Popen(
        [str(KONTAKT), "serve", "--port", "0"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    url: list[str] = []
    ready = threading.Event()

    def read() -> None:
        for line in proc.stdout:  # type: ignore[union-attr]
            m = re.search(r"(http://\S+)", line)
            if m and not url:
                url.append(m.group(1).rstrip("/"))
                ready.set()

    threading.Thread(target=read, daemon=True).start()
    try:
        if not ready.wait(60):
            proc.kill()
            pytest.fail(f"kontakt serve printed no URL within 60 s: {proc.stderr.read() if proc.stderr else ''}")
        yield url[0]
    finally:
        proc.terminate()
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()


@pytest.fixture(scope="module")
def browser():
    """Headless chromium at 1280 x 800 with its console log readable."""
    missing = [p for p in (CHROMIUM, CHROMEDRIVER) if not shutil.which(p) and not Path(p).is_file()]
    if missing:
        pytest.fail(
            f"{', '.join(missing)} not found: install Debian's chromium and chromium-driver "
            "(.ci/run does) or set KONTAKT_CHROMIUM / KONTAKT_CHROMEDRIVER"
        )
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=1280,800"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    DOWNLOADS.mkdir(parents=True, exist_ok=True)
    options.add_experimental_option(
        "prefs", {"download.default_directory": str(DOWNLOADS), "download.prompt_for_download": False}
    )
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    driver.set_window_size(1280, 800)
    SHOTS.mkdir(parents=True, exist_ok=True)
    try:
        yield driver
    finally:
        driver.quit()


def console_errors(driver, expected: str | None = None) -> list[str]:
    """The browser console's SEVERE entries since the last call; `expected` (a regular
    expression) lets through the one failed request a test provokes on purpose (Chrome
    logs a 4xx answer as a failed resource load)."""
    return [
        e["message"]
        for e in driver.get_log("browser")
        if e.get("level") == "SEVERE" and not (expected and re.search(expected, e["message"]))
    ]


def open_page(driver, url: str, page: str, ready_css: str) -> None:
    driver.get(f"{url}/{page}")
    WebDriverWait(driver, 30).until(ec.presence_of_element_located((By.CSS_SELECTOR, ready_css)))


def wait_status(driver, pattern: str, timeout: float) -> str:
    """Waits until the status line matches `pattern` (or shows an error: then fails)."""
    status = driver.find_element(By.ID, "status")
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        text = status.text
        if re.search(pattern, text):
            return text
        if "error" in (status.get_attribute("class") or ""):
            pytest.fail(f"the page reports an error: {text}")
        time.sleep(0.2)
    raise TimeoutException(f"status {status.text!r} did not match {pattern!r} in {timeout} s")


def fill(driver, values: dict[str, str]) -> None:
    for id_, value in values.items():
        el = driver.find_element(By.ID, id_)
        if el.tag_name == "select":
            Select(el).select_by_value(value)
        else:
            el.clear()
            el.send_keys(value)


def shown(driver, key: str) -> str:
    return driver.find_element(By.CSS_SELECTOR, f'td[data-key="{key}"]').text


def check_layout(driver) -> None:
    """The page fits 1280 px (no horizontal scrolling), every numeric field has its unit
    beside it, and printed (print media) the page drops its buttons and keeps the form."""
    width = driver.execute_script("return document.documentElement.scrollWidth")
    assert width <= 1280, f"the page is {width} px wide"
    missing = driver.execute_script(
        """return [...document.querySelectorAll('form.case [data-key]')]
             .filter(el => el.type !== 'hidden' && !['str', 'strlist', 'bool'].includes(el.dataset.type))
             .filter(el => !(el.closest('label')?.querySelector('.unit')?.textContent.trim()))
             .map(el => el.dataset.key)"""
    )
    assert missing == [], f"fields without a unit: {missing}"
    driver.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": "print"})
    try:
        assert not driver.find_element(By.ID, "filebar").is_displayed()
        assert not driver.find_element(By.ID, "run").is_displayed()
        assert driver.find_element(By.ID, "form").is_displayed()
        name = driver.execute_script("return location.pathname.replace(/\\W/g, '')") or "index"
        driver.save_screenshot(str(SHOTS / f"{name}_print.png"))
    finally:
        driver.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": ""})


def shot(driver, name: str) -> None:
    """The page at 1280 x 800 as a person sees it (`name.png`), and the whole page
    (`name_page.png`, the window made as tall as the page)."""
    driver.save_screenshot(str(SHOTS / f"{name}.png"))
    height = driver.execute_script("return document.documentElement.scrollHeight")
    driver.set_window_size(1280, min(max(int(height) + 140, 800), 4000))
    driver.execute_script("window.scrollTo(0, 0)")
    driver.save_screenshot(str(SHOTS / f"{name}_page.png"))
    driver.set_window_size(1280, 800)


# The Hertz case the test types into the form, and the same case for the CLI.
HERTZ_FORM = {
    "kind": "point",
    "angle": "0",
    "r1x": "10",
    "r1y": "12.5",
    "r2x": "inf",
    "r2y": "-40",
    "e1": "210000",
    "nu1": "0.3",
    "e2": "200000",
    "nu2": "0.29",
    "force": "750",
    "approach": "",
    "lineload": "",
    "yield": "1800",
}
HERTZ_TOML = """
name = "browser test"
method = "hertz"
[contact]
kind = "point"
angle_deg = 0.0
[body1]
radii_mm = [10.0, 12.5]
e_mpa = 210000.0
nu = 0.3
[body2]
radii_mm = [inf, -40.0]
e_mpa = 200000.0
nu = 0.29
[load]
force_n = 750.0
[yield]
stress_mpa = 1800.0
criterion = "von_mises"
"""


def cli_json(case: str, tmp_path: Path) -> dict:
    path = tmp_path / "case.toml"
    path.write_text(case)
    out = subprocess.run([str(KONTAKT), "solve", str(path), "--json"], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def test_hertz_page_matches_the_cli(server, browser, tmp_path):
    open_page(browser, server, "hertz.html", "#form")
    fill(browser, HERTZ_FORM)
    Select(browser.find_element(By.ID, "criterion")).select_by_value("von_mises")
    browser.find_element(By.ID, "run").click()
    wait_status(browser, r"^solved", 30)
    cli = cli_json(HERTZ_TOML, tmp_path)
    for key in (
        "max_pressure_mpa",
        "mean_pressure_mpa",
        "approach_mm",
        "contact_area_mm2",
        "stiffness_n_per_mm",
        "max_von_mises_stress_mpa",
        "max_shear_depth_mm",
        "first_yield_load_n",
    ):
        page = float(shown(browser, key))
        assert page == pytest.approx(cli[key], rel=1e-5), key
    a, b = (float(x) for x in shown(browser, "semi_axes_mm").split(","))
    assert [a, b] == pytest.approx(cli["semi_axes_mm"], rel=1e-5)
    # the pressure profile and the stresses along the axis are drawn (uPlot canvases)
    assert browser.find_elements(By.CSS_SELECTOR, "#plot-pressure canvas")
    assert browser.find_elements(By.CSS_SELECTOR, "#plot-stress canvas")
    shot(browser, "hertz")
    check_layout(browser)
    assert console_errors(browser) == []


def test_hertz_input_error_beside_its_field(server, browser, tmp_path):
    open_page(browser, server, "hertz.html", "#form")
    fill(browser, {**HERTZ_FORM, "nu2": "0.7"})
    browser.find_element(By.ID, "run").click()
    err = WebDriverWait(browser, 30).until(ec.visibility_of_element_located((By.CSS_SELECTOR, ".field-error")))
    # beside the Poisson's ratio of body 2, with the CLI's one-line message
    assert "invalid" in (browser.find_element(By.ID, "nu2").get_attribute("class") or "")
    label = browser.find_element(By.ID, "nu2").find_element(By.XPATH, "./ancestor::label")
    assert label.find_element(By.XPATH, "following-sibling::*[1]") == err
    path = tmp_path / "bad.toml"
    path.write_text(HERTZ_TOML.replace("nu = 0.29", "nu = 0.7"))
    cli = subprocess.run([str(KONTAKT), "solve", str(path), "--json"], capture_output=True, text=True)
    assert cli.returncode == 2
    assert "body2.nu" in err.text
    assert err.text in cli.stderr, (err.text, cli.stderr)
    shot(browser, "hertz_error")
    assert console_errors(browser, r"/api/run - Failed to load resource: .* 422 ") == []


def test_rib_page_runs_every_pressure_model(server, browser):
    open_page(browser, server, "rib.html", "#form")
    WebDriverWait(browser, 30).until(
        lambda d: d.find_element(By.ID, "pairing").get_attribute("value") == "sphere-torus-57"
    )
    browser.find_element(By.ID, "run").click()
    wait_status(browser, r"^solved", 300)
    # friction against speed, and the PimP and half-space maps beside Hertz
    assert len(browser.find_elements(By.CSS_SELECTOR, "#plot-torque canvas")) >= 1
    assert len(browser.find_elements(By.CSS_SELECTOR, "#maps .js-plotly-plot")) == 2
    hertz = float(browser.find_element(By.CSS_SELECTOR, 'td[data-key="Hertz.max_pressure_mpa"]').text)
    pimp = float(browser.find_element(By.CSS_SELECTOR, 'td[data-key="PimP.max_pressure_mpa"]').text)
    bem = float(browser.find_element(By.CSS_SELECTOR, 'td[data-key="half-space.max_pressure_mpa"]').text)
    # sphere-torus-57 is nearly elliptic: the three agree within 5 % (docs/VALIDATION.md)
    assert pimp == pytest.approx(hertz, rel=0.05) and bem == pytest.approx(hertz, rel=0.05)
    shot(browser, "rib")
    check_layout(browser)
    # the same pair entered as one's own face and rib (sphere r_R = 57 mm on a torus rib
    # r_B = 30 mm at h = 2.75 mm, Wirsching et al. 2020 Table 1) gives the same pressures
    approach = browser.find_element(By.CSS_SELECTOR, 'td[data-key="Hertz.approach_mm"]').text
    Select(browser.find_element(By.ID, "pairing")).select_by_value("")
    Select(browser.find_element(By.ID, "face_shape")).select_by_value("sphere")
    Select(browser.find_element(By.ID, "rib_shape")).select_by_value("torus")
    fill(browser, {"face_r": "57", "face_e": "", "rib_r": "30", "height": "2.75"})
    browser.find_element(By.ID, "run").click()
    wait_status(browser, r"^solved", 300)
    for model, before in (("Hertz", hertz), ("PimP", pimp), ("half-space", bem)):
        now = float(browser.find_element(By.CSS_SELECTOR, f'td[data-key="{model}.max_pressure_mpa"]').text)
        assert now == pytest.approx(before, rel=1e-5), model
    assert browser.find_element(By.CSS_SELECTOR, 'td[data-key="Hertz.approach_mm"]').text == approach
    assert console_errors(browser) == []


def test_bearing_page_runs_and_cancels(server, browser):
    open_page(browser, server, "bearing.html", "#form")
    WebDriverWait(browser, 30).until(lambda d: d.find_element(By.ID, "dm").get_attribute("value") != "")
    fill(browser, {"fx": "4000"})  # a radial load beside the example's axial one: a load zone
    browser.find_element(By.ID, "run").click()
    wait_status(browser, r"^solved", 120)
    assert browser.find_elements(By.CSS_SELECTOR, "#plot-loads .js-plotly-plot")
    assert browser.find_elements(By.CSS_SELECTOR, "#plot-slices canvas")
    assert browser.find_elements(By.CSS_SELECTOR, "#plot-torque .js-plotly-plot")
    assert float(shown(browser, "friction.total_nmm")) > 0
    shot(browser, "bearing")  # bearing_page.png: docs/img/serve_bearing.png is its top
    check_layout(browser)
    # a ball bearing: the ball loads, every ball's pressures, the torque beside SKF
    Select(browser.find_element(By.ID, "examples")).select_by_value("bearing_6205_friction")
    WebDriverWait(browser, 30).until(lambda d: d.find_element(By.ID, "balls").get_attribute("value") == "9")
    assert not browser.find_element(By.ID, "rollers").is_displayed()
    browser.find_element(By.ID, "run").click()
    wait_status(browser, r"^solved", 120)
    assert browser.find_elements(By.CSS_SELECTOR, "#plot-slices .js-plotly-plot")
    assert float(shown(browser, "max_ball_load_n")) == pytest.approx(1060.39, rel=1e-5)
    assert float(shown(browser, "friction.total_nmm")) > 0
    shot(browser, "bearing_ball")
    # a long solve (the coupled slices, through /api/jobs: about 10 s here) shows a Cancel
    # button that stops it
    # (on the ISO roller model: the example without a rib contact)
    Select(browser.find_element(By.ID, "examples")).select_by_value("bearing_32008x_friction")
    WebDriverWait(browser, 30).until(lambda d: "rib" not in d.find_element(By.ID, "name").get_attribute("value"))
    fill(browser, {"slice_model": "coupled", "slices": "201"})
    browser.find_element(By.ID, "run").click()
    cancel = WebDriverWait(browser, 30).until(ec.element_to_be_clickable((By.CSS_SELECTOR, "#status button.cancel")))
    cancel.click()
    wait_status_class = WebDriverWait(browser, 30)
    wait_status_class.until(lambda d: "cancelled" in d.find_element(By.ID, "status").text)
    assert console_errors(browser) == []


def test_traction_page_draws_every_model(server, browser):
    open_page(browser, server, "traction.html", "#form")
    WebDriverWait(browser, 30).until(lambda d: d.find_element(By.ID, "models").get_attribute("value") != "")
    browser.find_element(By.ID, "run").click()
    wait_status(browser, r"^solved: 5 curves", 300)
    assert browser.find_elements(By.CSS_SELECTOR, "#plot-traction canvas")
    shot(browser, "traction")
    check_layout(browser)
    assert console_errors(browser) == []


def test_index_page_links_every_page(server, browser):
    open_page(browser, server, "", "nav.topnav")
    hrefs = {a.get_attribute("href").rsplit("/", 1)[-1] for a in browser.find_elements(By.CSS_SELECTOR, ".cards a")}
    assert hrefs == {"hertz.html", "rib.html", "bearing.html", "traction.html"}
    shot(browser, "index")
    assert console_errors(browser) == []


def downloaded(name: str, timeout: float = 20) -> Path:
    path = DOWNLOADS / name
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if path.is_file() and path.stat().st_size > 0:
            return path
        time.sleep(0.2)
    pytest.fail(f"{name} was not downloaded into {DOWNLOADS}")


def parsed(server: str, text: str) -> dict:
    """A case file's tables as the server's case parser reads them (`POST /api/case/parse`)."""
    request = urllib.request.Request(
        f"{server}/api/case/parse",
        data=json.dumps({"toml": text}).encode(),
        headers={"content-type": "application/json"},
    )
    with urllib.request.urlopen(request, timeout=30) as answer:
        return json.load(answer)["case"]


def test_toml_load_save_and_downloads(server, browser):
    """Load TOML (an upload) fills the form, flat radii as inf; Save TOML writes the same
    case back; JSON and CSV download the result."""
    for old in DOWNLOADS.glob("*"):
        old.unlink()
    open_page(browser, server, "hertz.html", "#form")
    upload = browser.find_element(By.CSS_SELECTOR, "#filebar input[type=file]")
    upload.send_keys(str(ROOT / "examples" / "ball_on_flat.toml"))
    WebDriverWait(browser, 30).until(lambda d: "loaded" in d.find_element(By.ID, "status").text)
    assert browser.find_element(By.ID, "r2x").get_attribute("value") == "inf"
    assert browser.find_element(By.ID, "force").get_attribute("value") == "100"
    browser.find_element(By.CSS_SELECTOR, "#filebar .save-toml").click()
    saved = parsed(server, downloaded("ball_on_flat.toml").read_text())
    assert saved == parsed(server, (ROOT / "examples" / "ball_on_flat.toml").read_text())
    browser.find_element(By.ID, "run").click()
    wait_status(browser, r"^solved", 30)
    browser.find_element(By.CSS_SELECTOR, "#filebar .save-json").click()
    report = json.loads(downloaded("ball_on_flat.json").read_text())
    assert report["max_pressure_mpa"] == pytest.approx(1855.5955901395419, rel=1e-12)
    browser.find_element(By.CSS_SELECTOR, "#filebar .save-csv").click()
    assert downloaded("ball_on_flat.csv").read_text().startswith("position_mm,")
    browser.find_element(By.CSS_SELECTOR, "#plot-pressure .plot-export button").click()
    assert downloaded("contact_pressure.png").read_bytes()[:4] == b"\x89PNG"
    assert console_errors(browser) == []
