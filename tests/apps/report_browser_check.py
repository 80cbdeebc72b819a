"""Opens a report's index.html in headless Chromium (through Selenium and
Debian's chromium-driver) and fails when an image is missing or broken, the
browser logged a console error, the page overflows a 420 px window
sideways, a link inside the page points to no element, an image is not a link to its own full-size file, a figure's
smallest font is under 10 px as displayed at the page's full width (the
font size each PNG records, scaled by its displayed width), or the prose
(paragraphs, captions, table cells, headings, list items) shows a registry
id (`random:none`) or a "(s)" plural outside code tags.
Usage: /usr/bin/python3 report_browser_check.py REPORT_DIR"""
import pathlib
import re
import struct
import sys

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

index = pathlib.Path(sys.argv[1]).resolve() / "index.html"
if not index.is_file():
    sys.exit(f"report_browser_check: {index} does not exist")



def png_text(path):
    """The tEXt chunks of a PNG as a dict."""
    data, chunks, at = path.read_bytes(), {}, 8
    while at + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        if kind == b"tEXt":
            key, _, value = data[at + 8:at + 8 + length].partition(b"\0")
            chunks[key.decode("latin-1")] = value.decode("latin-1")
        at += 12 + length
    return chunks


options = webdriver.ChromeOptions()
options.binary_location = "/usr/bin/chromium"
for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--allow-file-access-from-files"):
    options.add_argument(argument)
options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
failures = []
try:
    driver.set_page_load_timeout(60)
    driver.set_window_size(1280, 1000)
    driver.get(index.as_uri())
    images = driver.execute_script(
        "return Array.from(document.images).map(i => [i.getAttribute('src'), i.complete, i.naturalWidth,"
        " i.getBoundingClientRect().width, i.closest('a') ? i.closest('a').getAttribute('href') : null]);")
    sections = driver.execute_script("return Array.from(document.querySelectorAll('section')).map(s => s.id);")
    prose = driver.execute_script(
        "return Array.from(document.querySelectorAll('p, figcaption, caption, td, th, h1, h2, h3, h4, li, summary, dt, dd')).map(p => {"
        " const c = p.cloneNode(true); c.querySelectorAll('code').forEach(e => e.remove()); return c.textContent; });")
    # Links inside the page whose target is missing (the index's slide links).
    dangling = driver.execute_script(
        "return Array.from(document.querySelectorAll('a[href^=\"#\"]')).map(a => a.getAttribute('href'))"
        ".filter(h => !document.getElementById(h.slice(1)));")
    log = driver.get_log("browser")
    driver.set_window_size(420, 900)
    overflow = driver.execute_script(
        "return [document.scrollingElement.scrollWidth, window.innerWidth];")
finally:
    driver.quit()

for href in dangling:
    failures.append(f"a link to {href}, which is not on the page")
if overflow[0] > overflow[1]:
    failures.append(f"the page is {overflow[0]} px wide in a {overflow[1]} px window")
for src, _, natural, shown, href in images:
    if href != src:
        failures.append(f"image {src} is not a link to itself (link: {href})")
    elif not (index.parent / src).is_file():
        failures.append(f"image {src}: no such file")
        continue
    recorded = png_text(index.parent / src).get("stratum:min-font-px")
    if recorded is None:
        failures.append(f"image {src} records no font size")
    elif natural and float(recorded) * shown / natural < 10 - 1e-6:
        failures.append(f"image {src}: smallest font {float(recorded) * shown / natural:.1f} px as shown "
                        f"({recorded} px in a {natural} px image shown {shown:.0f} px wide)")
registry_id = re.compile(r"\b[a-z0-9-]+:(none|owen|owen-hash|xor|lms|permute|cp)\b")
for text in prose:
    if "(s)" in text:
        failures.append(f"a \"(s)\" plural: {text[:120]}")
    if registry_id.search(text):
        failures.append(f"a registry id in the prose: {registry_id.search(text).group(0)} in {text[:120]}")
    # A zero duration is "0.0 s" or "0 ms" standing alone, not the tail of "40.0 s".
    miscount = (re.search(r"\b1 (points|samples|threads|rays|runs|realizations)\b", text)
                or re.search(r"(?<![\d.])0(\.0+)? m?s\b", text))
    if miscount:
        failures.append(f"a miscounted noun or a zero duration: \"{miscount.group(0)}\" in {text[:120]}")

broken = [src for src, complete, width, *_ in images if not complete or width == 0]
errors = [entry["message"] for entry in log if entry["level"] in ("SEVERE", "ERROR")]
print(f"{len(sections)} sections, {len(images)} images, {len(broken)} broken, {len(errors)} console errors, "
      f"{len(failures)} layout or wording failures")
for failure in failures:
    print(failure)
for src in broken:
    print(f"broken image: {src}")
for message in errors:
    print(f"console error: {message}")
if not images:
    print("no image on the page")
sys.exit(1 if broken or errors or failures or not images else 0)
