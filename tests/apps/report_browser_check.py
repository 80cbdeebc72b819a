"""Opens a report's index.html in headless Chromium (through Selenium and
Debian's chromium-driver) and fails when an image is missing or broken or
the browser logged a console error.
Usage: /usr/bin/python3 report_browser_check.py REPORT_DIR"""
import pathlib
import sys

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

index = pathlib.Path(sys.argv[1]).resolve() / "index.html"
if not index.is_file():
    sys.exit(f"report_browser_check: {index} does not exist")

options = webdriver.ChromeOptions()
options.binary_location = "/usr/bin/chromium"
for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--allow-file-access-from-files"):
    options.add_argument(argument)
options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
try:
    driver.set_page_load_timeout(60)
    driver.get(index.as_uri())
    images = driver.execute_script(
        "return Array.from(document.images).map(i => [i.getAttribute('src'), i.complete, i.naturalWidth]);")
    sections = driver.execute_script("return Array.from(document.querySelectorAll('section')).map(s => s.id);")
    log = driver.get_log("browser")
finally:
    driver.quit()

broken = [src for src, complete, width in images if not complete or width == 0]
errors = [entry["message"] for entry in log if entry["level"] in ("SEVERE", "ERROR")]
print(f"{len(sections)} sections, {len(images)} images, {len(broken)} broken, {len(errors)} console errors")
for src in broken:
    print(f"broken image: {src}")
for message in errors:
    print(f"console error: {message}")
if not images:
    print("no image on the page")
sys.exit(1 if broken or errors or not images else 0)
