#!/usr/bin/env python3
"""Screenshots of a report (raster report) for README, in headless Chromium.

    docs/report/screenshot.py REPORT_DIR OUT.png [--at ELEMENT_ID] [--open N]

Opens REPORT_DIR/index.html at 1280x1300, opens the first N collapsible panels of the
element (the pixel-history panels are closed by default), scrolls it to the top of the
window and saves the window. Needs Debian's chromium, chromium-driver and python3-selenium,
as the report_chromium test does.
"""
import argparse
import pathlib
import sys
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("report", type=pathlib.Path)
    parser.add_argument("out", type=pathlib.Path)
    parser.add_argument("--at", help="id of the element to scroll to (default: the top of the page)")
    parser.add_argument("--open", type=int, default=3, help="collapsible panels to open inside it")
    args = parser.parse_args()
    index = (args.report / "index.html").resolve()
    if not index.is_file():
        print(f"screenshot.py: {index} is not a report (no index.html)", file=sys.stderr)
        return 2
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for argument in ("--headless=new", "--no-sandbox", "--hide-scrollbars", "--window-size=1280,1300"):
        options.add_argument(argument)
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    try:
        driver.get(index.as_uri())
        time.sleep(1)   # images decode after load
        if args.at:
            element = driver.find_element("id", args.at)
            driver.execute_script(
                "arguments[0].querySelectorAll('details').forEach((d, i) => { if (i < arguments[1]) d.open = true; });"
                "arguments[0].scrollIntoView(true); window.scrollBy(0, -10);", element, args.open)
            time.sleep(0.5)
        driver.save_screenshot(str(args.out))
    finally:
        driver.quit()
    return 0


if __name__ == "__main__":
    sys.exit(main())
