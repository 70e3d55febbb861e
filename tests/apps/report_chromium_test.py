#!/usr/bin/env python3
"""`raster report` opened in headless Chromium (Debian's chromium, chromium-driver and
python3-selenium): every <img> loads with the natural size of its file, the console holds
no error, and the table values equal the JSON they came from (each target's metrics against
report.json, the tradeoff tables against the tradeoff.json copied beside them). The checker
is then run on copies of the report with one image broken and one table value changed, and
must find each; and bad input must exit 2 with one line and leave nothing behind.

Usage: report_chromium_test.py RASTER_BINARY SOURCE_DIR
"""
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

raster, source = sys.argv[1], sys.argv[2]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED: " + message, file=sys.stderr)


def file_size(path):
    """The pixel size an image file declares: a PNG's IHDR, an SVG's width and height
    attributes in CSS pixels (pt are 4/3 px), or None when the file is neither."""
    with open(path, "rb") as f:
        head = f.read(4096)
    if head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR":
        return struct.unpack(">II", head[16:24])
    if path.endswith(".svg"):
        tag = re.search(rb"<svg[^>]*>", head)
        if not tag:
            return None
        scale = {b"pt": 4 / 3, b"px": 1, b"": 1}
        size = []
        for name in (b"width", b"height"):
            m = re.search(name + rb'="([0-9.]+)(pt|px|)"', tag.group(0))
            if not m:
                return None
            size.append(float(m.group(1)) * scale[m.group(2)])
        return tuple(size)
    return None


def psnr_text(value):
    return "identical" if value is None else f"{value:.2f}"


def table_rows(driver, table_id):
    """The rows of a table as lists of (text, data-value) pairs, header row first."""
    return driver.execute_script(
        "const t = document.getElementById(arguments[0]); if (!t) return null;"
        "return Array.from(t.rows).map(r => Array.from(r.cells).map(c => [c.textContent, c.getAttribute('data-value')]));",
        table_id)


def check_report(folder, profile):
    """Opens folder/index.html in headless Chromium; returns the problems found (empty: none)."""
    problems = []
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     "--user-data-dir=" + profile, "--window-size=1280,1024"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    try:
        driver.get("file://" + os.path.abspath(os.path.join(folder, "index.html")))
        # Every image: decoded, with the natural size of the file it names.
        images = driver.execute_script(
            "return Array.from(document.images).map(i => [i.getAttribute('src'), i.complete, i.naturalWidth, i.naturalHeight]);")
        if not images:
            problems.append("the page has no images")
        for src, complete, width, height in images:
            declared = file_size(os.path.join(folder, src))
            if not complete or width == 0 or height == 0:
                problems.append(f"image {src} did not load (naturalWidth {width})")
            elif declared is None:
                problems.append(f"image {src} is not a PNG or SVG with a size")
            elif abs(width - declared[0]) >= 1 or abs(height - declared[1]) >= 1:
                problems.append(f"image {src} loaded at {width}x{height}, its file says {declared[0]}x{declared[1]}")
        # The console: no errors (a failed load, a blocked resource, a script error).
        for entry in driver.get_log("browser"):
            if entry.get("level") == "SEVERE":
                problems.append("console error: " + entry.get("message", ""))

        # Each target's metrics table against report.json.
        with open(os.path.join(folder, "report.json")) as f:
            record = json.load(f)
        checked = 0
        for scene in record["scenes"]:
            for target in scene["targets"]:
                table_id = f"metrics-{scene['scene']}-{target['name']}"
                rows = table_rows(driver, table_id)
                psnr = [r for r in rows or [] if r[0][0] == "PSNR (dB)"]
                if not psnr:
                    problems.append(f"no PSNR row in table {table_id}")
                    continue
                text, value = psnr[0][1]
                if text != psnr_text(target["psnr_db"]) or json.loads(value) != target["psnr_db"]:
                    problems.append(f"{table_id}: PSNR reads {text!r} (data {value}), report.json has {target['psnr_db']}")
                checked += 1
        if checked == 0:
            problems.append("no metrics table was checked")

        # The tradeoff tables against the tradeoff.json copied beside the page.
        for chart in record["charts"]:
            if chart["kind"] != "tradeoff":
                continue
            with open(os.path.join(folder, chart["json"])) as f:
                data = json.load(f)
            for result in data if isinstance(data, list) else [data]:
                rows = table_rows(driver, f"{chart['id']}-{result['scene']}")
                if not rows:
                    problems.append(f"no table {chart['id']}-{result['scene']}")
                    continue
                header = [cell[0] for cell in rows[0]]
                column = header.index("speed-up vs llvmpipe")
                psnr_column = header.index("PSNR vs llvmpipe (dB)")
                by_name = {row[0][0]: row for row in rows[1:]}
                for point in result["points"]:
                    row = by_name.get(point["name"])
                    if row is None:
                        problems.append(f"{chart['id']}: no row for {point['name']}")
                        continue
                    if row[column][0] != f"{point['speedup_vs_llvmpipe']:.2f}x":
                        problems.append(f"{chart['id']} {point['name']}: speed-up reads {row[column][0]!r}, "
                                        f"the JSON has {point['speedup_vs_llvmpipe']}")
                    if row[psnr_column][0] != psnr_text(point["psnr_vs_llvmpipe_db"]):
                        problems.append(f"{chart['id']} {point['name']}: PSNR reads {row[psnr_column][0]!r}, "
                                        f"the JSON has {point['psnr_vs_llvmpipe_db']}")
    finally:
        driver.quit()
    return problems


def run(args):
    return subprocess.run([raster] + args, capture_output=True, text=True)


with tempfile.TemporaryDirectory(prefix="report-chromium-test-") as tmp:
    out = os.path.join(tmp, "report")
    done = run(["report", "shadow", "hdr", "--size", "160x120", "--pixels", "2", "--threads", "2",
                "--include", os.path.join(source, "docs", "tradeoff"), "--no-default-include", "--out", out, "--quiet"])
    check(done.returncode == 0, f"raster report exited {done.returncode}: {done.stderr}")
    check(not [n for n in os.listdir(tmp) if n.startswith(".")], "a temporary folder was left beside the report")

    if done.returncode == 0:
        problems = check_report(out, os.path.join(tmp, "profile-1"))
        for p in problems:
            check(False, p)
        with open(os.path.join(out, "report.json")) as f:
            record = json.load(f)
        check(any(c["kind"] == "tradeoff" for c in record["charts"]), "no tradeoff result made it into the report")
        check(os.path.exists(os.path.join(out, "hdr", "hdr_scene_ours.exr")), "no EXR data file beside a float target's preview")

        # Negative checks: the checker must see a broken image and a table value that is wrong.
        broken = os.path.join(tmp, "broken-image")
        shutil.copytree(out, broken)
        victim = os.path.join(broken, "shadow", "final_gl.png")
        with open(victim, "r+b") as f:
            f.truncate(40)
        problems = check_report(broken, os.path.join(tmp, "profile-2"))
        check(any("shadow/final_gl.png" in p for p in problems), f"a truncated image went unnoticed: {problems}")

        wrong = os.path.join(tmp, "wrong-value")
        shutil.copytree(out, wrong)
        page_path = os.path.join(wrong, "index.html")
        with open(page_path) as f:
            page = f.read()
        changed = re.sub(r'(id="metrics-hdr-final">.*?PSNR \(dB\)</td><td class="num" data-value="[^"]*">)([^<]*)<',
                         r"\g<1>12.34<", page, count=1, flags=re.S)
        check(changed != page, "could not change the PSNR cell of hdr's final image")
        with open(page_path, "w") as f:
            f.write(changed)
        problems = check_report(wrong, os.path.join(tmp, "profile-3"))
        check(any("metrics-hdr-final" in p for p in problems), f"a wrong PSNR went unnoticed: {problems}")

    # Bad input: exit 2, one line, nothing written.
    for args, what in ((["report", "nosuch", "--out", os.path.join(tmp, "bad1")], "unknown scene"),
                       (["report", "shadow", "--out", os.path.join(tmp, "no", "such", "folder")], "missing parent"),
                       (["report", "shadow", "--out", os.path.join(tmp, "profile-1")], "a folder that is not a report"),
                       (["report", "shadow", "--pixels", "99", "--out", os.path.join(tmp, "bad2")], "--pixels out of range")):
        done = run(args + ["--quiet"])
        check(done.returncode == 2, f"{what}: exit {done.returncode}, not 2 ({done.stderr.strip()})")
        check(done.stderr.count("\n") == 1 and done.stderr.startswith("raster: "), f"{what}: not one line: {done.stderr!r}")
    check(not os.path.exists(os.path.join(tmp, "bad1")) and not os.path.exists(os.path.join(tmp, "bad2")),
          "bad input left a report folder")
    check(not [n for n in os.listdir(tmp) if n.startswith(".")], "bad input left a temporary folder")

print("report_chromium_test: " + ("passed" if not failures else f"{len(failures)} failed"))
sys.exit(1 if failures else 0)
