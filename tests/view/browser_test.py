#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""design.html in a real browser: headless Chromium driven by Selenium.

Designs a shipped room with the hrspace command, opens the design.html it
wrote from file:// and checks that
  - the page loads with no console message of level warning or worse, and
    requests nothing but itself;
  - the animation advances: the chair's transform changes over time;
  - choosing another tour redraws the selected path and its cusps;
  - the accessibility overlay toggles off and on;
  - every overlay toggle and the scrubber act on the page;
  - a design with no tour found and no iteration loads without errors.

usage: browser_test.py HRSPACE SCENE [--iterations N] [--screenshot PNG]
With --screenshot the page, tour 2 selected and the route-width overlay on,
is saved as a PNG. The README's picture is made so:
  python3 tests/view/browser_test.py build/cli/hrspace scenes/bedroom.json \
      --iterations 700 --screenshot docs/images/viewer.png
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.support.ui import Select


def fail(message):
    print("browser_test: FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)


def browser():
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1280,1000",
                "--disable-dev-shm-usage", "--allow-file-access-from-files"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


def transform(driver):
    return driver.execute_script("return document.getElementById('chair').getAttribute('transform');")


def attr(driver, element_id, name):
    return driver.execute_script(
        "const e = document.getElementById(arguments[0]); return e ? e.getAttribute(arguments[1]) : null;",
        element_id, name)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("hrspace")
    parser.add_argument("scene")
    parser.add_argument("--iterations", default="150")
    parser.add_argument("--screenshot")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory() as tmp:
        out = pathlib.Path(tmp) / "design"
        subprocess.run([args.hrspace, "design", args.scene, "--out", str(out), "--seed", "1",
                        "--iterations", args.iterations], check=True, stdout=subprocess.DEVNULL)
        page = out / "design.html"
        check(page.is_file(), "hrspace design wrote no design.html")
        text = page.read_text(encoding="utf-8")
        check("http://" not in text.replace("http://www.w3.org/2000/svg", "") and "https://" not in text,
              "design.html names a network address")
        tours = json.loads((out / "tours.json").read_text())["tours"]
        found = [k for k, t in enumerate(tours) if t["found"]]
        check(len(found) >= 2, "the test needs a design with two found tours, got %d" % len(found))

        driver = browser()
        try:
            url = page.resolve().as_uri()
            driver.get(url)
            time.sleep(0.5)
            check(driver.title.startswith(json.loads((out / "layout.json").read_text())["name"]),
                  "the page's title is %r" % driver.title)

            # The animation advances.
            first = transform(driver)
            check(first is not None and first.startswith("translate("), "no chair transform: %r" % first)
            seen = {first}
            for _ in range(10):
                time.sleep(0.2)
                seen.add(transform(driver))
            check(len(seen) >= 3, "the chair did not move: %s" % sorted(seen))

            # Pausing stops it; the scrubber moves it.
            driver.find_element("id", "play").click()
            time.sleep(0.1)
            paused = transform(driver)
            time.sleep(0.5)
            check(transform(driver) == paused, "the chair moved while paused")
            driver.execute_script(
                "const s = document.getElementById('scrub'); s.value = '900';"
                "s.dispatchEvent(new Event('input'));")
            check(transform(driver) != paused, "the scrubber did not move the chair")

            # Another tour redraws the path.
            path_before = attr(driver, "sel-path", "d")
            cusps_before = driver.execute_script(
                "return document.getElementById('cusps').innerHTML;")
            Select(driver.find_element("id", "tour")).select_by_value(str(found[1]))
            path_after = attr(driver, "sel-path", "d")
            check(path_after and path_after != path_before, "selecting tour %d kept the path" % found[1])
            cusp_count = driver.execute_script("return document.querySelectorAll('#cusps circle').length;")
            data_cusps = driver.execute_script(
                "return JSON.parse(document.getElementById('hrspace-data').textContent)"
                ".tours[arguments[0]].cusps.length;", found[1])
            check(cusp_count == data_cusps,
                  "cusps drawn %d, in the data %d" % (cusp_count, data_cusps))
            gears = 0
            for leg in tours[found[1]]["legs"]:
                segs = leg["segments"]
                gears += sum(1 for a, b in zip(segs, segs[1:]) if a["gear"] != b["gear"])
            check(data_cusps == gears, "cusps in the page %d, gear changes in tours.json %d"
                  % (data_cusps, gears))
            check(cusps_before is not None, "no cusp layer")

            # The accessibility overlay toggles.
            check(attr(driver, "layer-access", "display") == "inline", "the accessibility overlay starts hidden")
            driver.find_element("id", "ov-access").click()
            check(attr(driver, "layer-access", "display") == "none", "the accessibility overlay did not hide")
            driver.find_element("id", "ov-access").click()
            check(attr(driver, "layer-access", "display") == "inline", "the accessibility overlay did not return")
            for box, layer in (("ov-goals", "layer-goals"), ("ov-width", "layer-width"),
                               ("ov-others", "layer-others")):
                before = attr(driver, layer, "display")
                driver.find_element("id", box).click()
                check(attr(driver, layer, "display") != before, "%s did not toggle %s" % (box, layer))
            goal_count = driver.execute_script("return document.querySelectorAll('#layer-goals circle').length;")
            check(goal_count > 0, "no goal poses drawn")
            trace = attr(driver, "trace-best", "d")
            check(trace and trace.count("L") >= 100, "the annealing trace is not drawn")

            if args.screenshot:
                driver.find_element("id", "ov-goals").click()   # off again
                driver.find_element("id", "ov-others").click()  # back on
                driver.execute_script(
                    "const s = document.getElementById('scrub'); s.value = '450';"
                    "s.dispatchEvent(new Event('input'));")
                driver.save_screenshot(args.screenshot)

            # No console message of level warning or worse, nothing fetched but the page.
            logs = driver.get_log("browser")
            bad = [e for e in logs if e.get("level") in ("WARNING", "SEVERE")]
            check(not bad, "console messages: %s" % bad)
            urls = []
            for entry in driver.get_log("performance"):
                message = json.loads(entry["message"])["message"]
                if message.get("method") == "Network.requestWillBeSent":
                    urls.append(message["params"]["request"]["url"])
            check(url in urls, "the page's own load was not seen in the network log: %s" % urls)
            others = [u for u in urls if u != url]
            check(not others, "the page requested %s" % others)

            # A design with no tour found and no iteration (a box behind a
            # wall-to-wall partition): the page still loads cleanly.
            walled = pathlib.Path(tmp) / "walled.json"
            walled.write_text(json.dumps({
                "format": "hrspace-scene/1", "name": "walled",
                "room": {"polygon": [[0, 0], [4, 0], [4, 3], [0, 3]]},
                "door": {"center": [0, 1.5], "width": 0.9},
                "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
                "objects": [
                    {"id": "partition", "size": [0.1, 3.0], "pose": [2.5, 1.5, 0], "fixed": True},
                    {"id": "box", "size": [0.4, 0.4], "pose": [3.5, 1.5, 0], "fixed": True}],
                "activity": {"transitions": {"door": {"box": 1.0}}, "visits": 1}}))
            empty = pathlib.Path(tmp) / "empty"
            subprocess.run([args.hrspace, "design", str(walled), "--out", str(empty),
                            "--iterations", "0"], check=True, stdout=subprocess.DEVNULL)
            check(not any(t["found"] for t in json.loads((empty / "tours.json").read_text())["tours"]),
                  "a tour was found behind the partition")
            driver.get((empty / "design.html").resolve().as_uri())
            time.sleep(0.3)
            check(attr(driver, "chair", "display") == "none", "the chair is drawn on an unfound tour")
            check("not found" in driver.find_element("id", "tour-info").text,
                  "the tour line does not say 'not found'")
            check(driver.find_element("id", "summary").text.startswith("tours found"),
                  "no summary on the empty design")
            bad = [e for e in driver.get_log("browser") if e.get("level") in ("WARNING", "SEVERE")]
            check(not bad, "console messages on the empty design: %s" % bad)
        finally:
            driver.quit()
    print("browser_test: design.html loads, animates, switches tours and toggles overlays")


if __name__ == "__main__":
    main()
