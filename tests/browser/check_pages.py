#!/usr/bin/python3
"""The pages of `fsweep report` and `fsweep compare` in a real headless browser.

Builds small real result directories with the built fsweep (one sweep with a closest-frontier
entry, a weight grid and an exact weight search, run whole into `new` and as two shards merged
into `base`; a strategy label with HTML in it), writes base/report.html, new/report.html and
new/compare/compare.html, opens each in Debian's chromium through chromedriver (Selenium) and
checks, per page:

- it loads with no severe console message (errors, failed loads) and asks for no resource
  (everything is inline);
- every <img> is complete with naturalWidth > 0 and a data: URI;
- report.html: every figure its contents list links is on the page with a loaded picture, its
  plots are exactly the PNGs `fsweep plot` draws for the directory (progress, metrics, a weight
  heat map, an exact-search heat map), it has the trajectories of the best and worst runs and
  behaviours, each re-simulated to the recorded outcome, and the label's HTML is text (no
  element made of it, no script);
- compare.html: the plots of both sides are embedded, one image per PNG;

The report pages of the shipped sweeps a user meets first, sweeps/default.json and
sweeps/examples/strategies_planners.json, run here: besides the checks above, a ranking table per
map class whose numbers are rounded for reading (no number cell with more than 6 digits), and
the paired comparisons against the baseline with one row per strategy, metric and table.

It saves a screenshot of each (--screenshots DIR). Exit 0 when every check passes, 1 when one
fails, 77 (ctest SKIP_RETURN_CODE) only when chromium cannot start.

  check_pages.py FSWEEP [--work DIR] [--screenshots DIR] [--width 1280] [--height 900]
"""

import argparse
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SKIP = 77
CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
# A label with markup: the pages must show it as text.
HOSTILE_LABEL = "EA <b id=injected>grid</b> & 'q'"

SWEEP = {
    "schema_version": 1,
    "name": "browser_check",
    "description": "Checked by tests/browser/check_pages.py <script>document.title='injected'</script>",
    "maps": [{"generator": "rooms", "w": 24, "h": 20, "door": 2, "seed": 2, "label": "rooms <i>24</i>"}],
    "strategies": [
        {"name": "closest_frontier", "label": "cf"},
        {"name": "energy_aware", "label": HOSTILE_LABEL, "params": {"w1": [0, 5, 10], "w3": [0, 9, 20]}},
        {"name": "energy_aware", "label": "exact", "search": {"method": "exact", "mode": "all"},
         "params": {"w1": [1, 10], "w2": [0], "w3": [0, 9], "w4": [0, 20]}},
    ],
    "robot": {"sensor": {"range_m": 4}},
    "repetitions": 2,
    "seed": 3,
}


class CheckFailed(Exception):
    pass


def fsweep(binary, *args):
    """Runs `fsweep ARGS`; raises CheckFailed with its output when it exits non-zero."""
    r = subprocess.run([binary, *args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        raise CheckFailed(f"fsweep {' '.join(args)} exited {r.returncode}:\n{r.stdout}")
    return r.stdout


def make_results(binary, work):
    """base (two shards, merged) and new (whole) of SWEEP, both plotted; the pages."""
    sweep = os.path.join(work, "sweep.json")
    with open(sweep, "w", encoding="utf-8") as f:
        json.dump(SWEEP, f)
    base, new = os.path.join(work, "base"), os.path.join(work, "new")
    for i in range(2):
        fsweep(binary, "run", sweep, "--quiet", "--threads", "1", "--shard", f"{i}/2", "--out", base)
    fsweep(binary, "merge", base)
    fsweep(binary, "run", sweep, "--quiet", "--threads", "1", "--out", new)
    for d in (base, new):
        fsweep(binary, "plot", d)
        fsweep(binary, "report", d)
    # compare exits 0 (no regression): the same sweep, deterministic planner.
    fsweep(binary, "compare", new, base)
    shipped = {}
    for name, file in (("default", "sweeps/default.json"),
                       ("strategies_planners", "sweeps/examples/strategies_planners.json")):
        out = os.path.join(work, name)
        fsweep(binary, "run", os.path.join(SOURCE, file), "--quiet", "--out", out)
        fsweep(binary, "report", out)
        shipped[name] = out
    return {"shipped": shipped,
            "report_merged": os.path.join(base, "report.html"), "report": os.path.join(new, "report.html"),
            "compare": os.path.join(new, "compare", "compare.html"),
            "plots": {os.path.join(base, "report.html"): os.path.join(base, "plots"),
                      os.path.join(new, "report.html"): os.path.join(new, "plots")}}


def start_browser(work, width, height):
    """(driver, process group id); exits SKIP when chromium cannot start."""
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError as e:
        raise CheckFailed(f"python3-selenium is missing ({e}): scripts/bootstrap installs it")
    for path in (CHROMIUM, CHROMEDRIVER):
        if not os.path.exists(path):
            print(f"SKIP: {path} not found (scripts/bootstrap installs chromium and chromium-driver)")
            sys.exit(SKIP)
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
              f"--window-size={width},{height}", "--hide-scrollbars", "--no-first-run",
              f"--user-data-dir={os.path.join(work, 'chromium-profile')}"):
        options.add_argument(a)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    # Its own session, so that chromedriver and every chromium process it starts are one process
    # group, killed by its id whatever happens.
    service = Service(CHROMEDRIVER, popen_kw={"start_new_session": True})
    try:
        driver = webdriver.Chrome(service=service, options=options)
    except Exception as e:  # noqa: BLE001 - any failure to start the browser is a skip
        if service.process is not None:
            kill_group(service.process.pid)
        print(f"SKIP: chromium cannot start headless: {str(e).splitlines()[0] if str(e) else e!r}")
        sys.exit(SKIP)
    return driver, service.process.pid


def kill_group(pgid):
    try:
        os.killpg(pgid, signal.SIGKILL)
    except ProcessLookupError:
        pass


IMAGES_JS = """
return Array.from(document.images).map(i => ({alt: i.alt, complete: i.complete, width: i.naturalWidth,
  data: i.getAttribute('src').startsWith('data:image/png;base64,')}));
"""

FIGURES_JS = """
return Array.from(document.querySelectorAll('a.figure-link')).map(a => {
  const id = a.getAttribute('href').slice(1);
  const f = document.getElementById(id);
  const img = f ? f.querySelector('img') : null;
  return {id: id, found: f !== null && f.tagName === 'FIGURE',
          loaded: img !== null && img.complete && img.naturalWidth > 0};
});
"""


def check_page(driver, path, screenshot, width):
    """Loads `path`, checks what every page must hold, saves `screenshot`; the problems found."""
    problems = []
    driver.get_log("browser")  # drop anything logged before
    driver.get("file://" + os.path.abspath(path))
    deadline = time.time() + 20
    while driver.execute_script("return document.readyState") != "complete":
        if time.time() > deadline:
            return [f"{path}: did not finish loading in 20 s"]
        time.sleep(0.05)
    for entry in driver.get_log("browser"):
        if entry.get("level") == "SEVERE":
            problems.append(f"{path}: console: {entry.get('message')}")
    resources = driver.execute_script("return performance.getEntriesByType('resource').map(e => e.name)")
    if resources:
        problems.append(f"{path}: asks for resources {resources[:5]} (the page must be self-contained)")
    images = driver.execute_script(IMAGES_JS)
    if not images:
        problems.append(f"{path}: no image")
    for img in images:
        if not (img["complete"] and img["width"] > 0):
            problems.append(f"{path}: image '{img['alt']}' did not load (complete {img['complete']}, "
                            f"naturalWidth {img['width']})")
        if not img["data"]:
            problems.append(f"{path}: image '{img['alt']}' is not an embedded PNG")
    if screenshot:
        height = driver.execute_script("return document.documentElement.scrollHeight")
        driver.set_window_size(width, min(max(height, 600), 2400))
        driver.save_screenshot(screenshot)
    return problems


def check_report(driver, path, plots_dir):
    """report.html's own claims."""
    problems = []
    figures = driver.execute_script(FIGURES_JS)
    for f in figures:
        if not (f["found"] and f["loaded"]):
            problems.append(f"{path}: the contents list figure '{f['id']}', not on the page with a loaded picture")
    ids = {f["id"] for f in figures}
    drawn = {"plot-" + n[:-4] for n in os.listdir(plots_dir) if n.endswith(".png")}
    plots = {i for i in ids if i.startswith("plot-")}
    if plots != drawn:
        problems.append(f"{path}: plots {sorted(plots)}, fsweep plot draws {sorted(drawn)}")
    for want in ("plot-progress", "plot-metrics"):
        if want not in ids:
            problems.append(f"{path}: no {want}")
    if not any(i.startswith("plot-heatmap_") for i in ids):
        problems.append(f"{path}: no weight heat map")
    if not any(i.startswith("plot-search") for i in ids):
        problems.append(f"{path}: no exact-search heat map")
    trajectories = [i for i in ids if i.startswith("trajectory-")]
    if len(trajectories) != 4:  # best and worst configuration, best and worst behaviour
        problems.append(f"{path}: {len(trajectories)} trajectories, expected 4")
    for i in trajectories:
        caption = driver.execute_script(f"return document.querySelector('#{i} figcaption').innerText")
        if "recorded outcome cells" not in caption or "are equal" not in caption:
            problems.append(f"{path}: {i}: the re-simulation did not reproduce the recorded run: {caption}")
    injected = driver.execute_script(
        "return [document.querySelectorAll('script, #injected').length, document.title]")
    if injected[0] != 0 or "injected" in injected[1]:
        problems.append(f"{path}: markup from the sweep file became elements: {injected}")
    text = driver.execute_script("return document.body.innerText")
    if HOSTILE_LABEL not in text:
        problems.append(f"{path}: the strategy label is not shown as text")
    return problems


READABLE_JS = """
const cells = Array.from(document.querySelectorAll('#ranking ~ div table.readable td.num, table.readable td.num'));
return {
  classes: Array.from(document.querySelectorAll('h3')).filter(h => {
    let e = h.previousElementSibling;
    while (e && e.tagName !== 'H2') e = e.previousElementSibling;
    return e && e.id === 'ranking' && h.innerText.startsWith('map class');
  }).length,
  long: cells.map(c => c.innerText).filter(t => /[0-9]{7,}/.test(t.replace(/[,.]/g, ''))).slice(0, 5),
  paired_rows: document.querySelectorAll('#paired ~ div table.readable tr').length,
  paired: document.getElementById('paired') !== null,
};
"""


def check_shipped(driver, name, out):
    """A shipped sweep's page: rankings per map class, rounded numbers, the paired comparisons as
    paired.csv has them."""
    problems = []
    path = os.path.join(out, "report.html")
    got = driver.execute_script(READABLE_JS)
    with open(os.path.join(out, "summary.csv"), encoding="utf-8") as f:
        classes = {line.split(",")[1] for line in f.readlines()[1:]}
    if got["classes"] != len(classes):
        problems.append(f"{path}: {got['classes']} ranking tables, the sweep has {len(classes)} map classes")
    if got["long"]:
        problems.append(f"{path}: numbers not rounded for reading: {got['long']}")
    if not got["paired"]:
        problems.append(f"{path}: no paired comparisons")
    # paired.csv's rows for the same comparison: one table row each, plus a header row per table.
    fsweep_binary = os.environ.get("FSWEEP_BINARY")
    if fsweep_binary:
        fsweep(fsweep_binary, "paired", out)
        with open(os.path.join(out, "paired.csv"), encoding="utf-8") as f:
            rows = len(f.readlines()) - 1
        if got["paired_rows"] < rows:
            problems.append(f"{path}: {got['paired_rows']} rows in the paired tables, paired.csv has {rows}")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("fsweep", help="the built fsweep executable")
    parser.add_argument("--work", help="directory for the results (default: a temporary one, removed)")
    parser.add_argument("--screenshots", help="directory for report.png and compare.png (default: --work)")
    parser.add_argument("--width", type=int, default=1280)
    parser.add_argument("--height", type=int, default=900)
    args = parser.parse_args()
    start = time.time()
    work = args.work or tempfile.mkdtemp(prefix="fsweep-browser-")
    if args.work:
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
    shots = args.screenshots or work
    os.makedirs(shots, exist_ok=True)
    driver = None
    pgid = None
    try:
        pages = make_results(args.fsweep, work)
        made = time.time()
        driver, pgid = start_browser(work, args.width, args.height)
        problems = []
        for key, shot in (("report", "report.png"), ("report_merged", None), ("compare", "compare.png")):
            path = pages[key]
            driver.set_window_size(args.width, args.height)
            problems += check_page(driver, path, os.path.join(shots, shot) if shot else None, args.width)
            if key.startswith("report"):
                problems += check_report(driver, path, pages["plots"][path])
            else:
                drawn = sum(len([n for n in os.listdir(d) if n.endswith(".png")]) for d in pages["plots"].values())
                shown = driver.execute_script("return document.images.length")
                if shown != drawn:
                    problems.append(f"{path}: {shown} images, the two plots directories have {drawn} PNGs")
        os.environ["FSWEEP_BINARY"] = args.fsweep
        for name, out in pages["shipped"].items():
            path = os.path.join(out, "report.html")
            driver.set_window_size(args.width, args.height)
            problems += check_page(driver, path, os.path.join(shots, f"report_{name}.png"), args.width)
            problems += check_shipped(driver, name, out)
            figures = driver.execute_script(FIGURES_JS)
            problems += [f"{path}: figure '{f['id']}' not loaded" for f in figures if not (f["found"] and f["loaded"])]
        if problems:
            raise CheckFailed("\n".join(problems))
        print(f"5 pages checked in chromium: results {made - start:.1f} s, browser {time.time() - made:.1f} s; "
              f"screenshots in {shots}")
        return 0
    except CheckFailed as e:
        print(f"FAIL: {e}")
        return 1
    finally:
        if driver is not None:
            try:
                driver.quit()
            except Exception:  # noqa: BLE001 - the group is killed below anyway
                pass
        if pgid is not None:
            kill_group(pgid)
        if not args.work:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
