"""Takes docs/img/html-demo.png, README's picture of `em703 html`: the demo
board's page in headless chromium (as the tests run it), the conductor tape
run to its 100th executed frame. Run after `make demo`, from the top of the
repository: python scripts/html_picture.py [out/LOGIC-CARD-A.html]
"""
from __future__ import annotations

import sys
from pathlib import Path

from bench.html import chromium

ROOT = Path(__file__).resolve().parents[1]


def main(argv: list[str]) -> int:
    page = Path(argv[1] if len(argv) > 1 else ROOT / "out" / "LOGIC-CARD-A.html")
    driver = chromium()
    try:
        driver.set_window_size(1400, 860)
        driver.get(page.resolve().as_uri())
        driver.execute_script("em703.select('cond'); em703.step(100);")
        driver.save_screenshot(str(ROOT / "docs" / "img" / "html-demo.png"))
    finally:
        driver.quit()
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv))
