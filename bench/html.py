"""``python -m bench.html [--sizes 10000,100000] [--out DIR]``: how fluid the
page of ``em703 html`` is on real boards, in headless chromium.

For each uniform board of :mod:`bench.boards` it punches the tapes with the
built TENZOR, writes the page with the built em703 and measures, in a fresh
headless chromium driven by selenium:

* the page's size and the time em703 takes to write it;
* opening: from the navigation's start to the end of the page's load event
  (the browser's own Navigation Timing), when ``window.em703`` is there;
* run to the end: the small-pad tape played at x1000 (the real machine's
  speeds, a thousand times faster) from its start point to its last frame,
  wall time measured in the page (performance.now), with the machine time
  that takes at x1000 for comparison, and ``step`` of the whole tape at once.

The figures are in docs/PERFORMANCE.md. Exit status 0, or 2 when the browser
or the programs are missing.
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from harness.files import quiet_when_output_closes

from . import boards

ROOT = Path(__file__).resolve().parents[1]
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage", "--window-size=1400,1000")


def built(name: str) -> Path:
    out = subprocess.run(["fpm", "run", "--runner", "echo", name], cwd=ROOT, check=True,
                         capture_output=True, text=True).stdout.split()
    return ROOT / out[-1]


def chromium():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    os.environ.setdefault("SE_OFFLINE", "true")
    options = webdriver.ChromeOptions()
    options.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
    for flag in FLAGS:
        options.add_argument(flag)
    options.add_argument(f"--user-data-dir={tempfile.mkdtemp(prefix='em703-bench-')}")
    driver = webdriver.Chrome(options=options,
                              service=Service(shutil.which("chromedriver") or "chromedriver"))
    driver.set_script_timeout(600)
    return driver


def measure(size: int, out: Path) -> dict[str, float]:
    board = boards.make_board("uniform", size)
    deck = out / f"{board.name}.crd"
    deck.write_text(board.deck())
    subprocess.run([str(built("tenzor")), str(deck), "-o", str(out)], check=True,
                   capture_output=True)
    job, page = out / f"{board.name}.job", out / f"{board.name}.html"
    em703 = str(built("em703"))
    t0 = time.perf_counter()
    subprocess.run([em703, "html", str(job), "-o", str(page)], check=True)
    write_s = time.perf_counter() - t0
    minutes = float(dict(line.split(" = ") for line in subprocess.run(
        [em703, "sim", str(out / f"{board.name}-small.ptp")], check=True,
        capture_output=True, text=True).stdout.splitlines())["minutes"])
    driver = chromium()
    try:
        driver.get(page.resolve().as_uri())
        open_s = driver.execute_script(
            "var n = performance.getEntriesByType('navigation')[0];"
            "return typeof window.em703 === 'object' ? n.loadEventEnd / 1000 : -1;")
        run_s = driver.execute_async_script(
            "var done = arguments[0]; em703.select('small');"
            "var t0 = performance.now(); em703.play(1000);"
            "var poll = setInterval(function () {"
            "  if (em703.state().done) { clearInterval(poll);"
            "    done((performance.now() - t0) / 1000); } }, 20);")
        step_s = driver.execute_script(
            "em703.select('small'); var t0 = performance.now(); em703.step(1e12);"
            "return (performance.now() - t0) / 1000;")
        executed = driver.execute_script("return em703.state().executed")
    finally:
        driver.quit()
    return {"pads": size, "page_mb": page.stat().st_size / 1e6, "write_s": write_s,
            "open_s": open_s, "small_frames": executed, "machine_s_x1000": minutes * 60 / 1000,
            "run_s_x1000": run_s, "step_all_s": step_s}


@quiet_when_output_closes
def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m bench.html", description=__doc__.split(
        "\n\n")[0])
    parser.add_argument("--sizes", type=boards.sizes_argument, default=[10000, 100000],
                        metavar="N,N,...",
                        help="pad counts of the uniform boards (default 10000,100000)")
    parser.add_argument("--out", type=Path, default=ROOT / "out" / "bench-html")
    args = parser.parse_args(argv)
    if shutil.which("chromedriver") is None or shutil.which("fpm") is None:
        print("python -m bench.html: needs chromedriver and fpm on PATH (make setup)",
              file=sys.stderr)
        return 2
    args.out.mkdir(parents=True, exist_ok=True)
    print("pads     page MB  write s  open s  small frames  x1000 machine s  x1000 run s  "
          "step all s")
    for size in args.sizes:
        r = measure(size, args.out)
        print(f"{r['pads']:<8} {r['page_mb']:7.1f}  {r['write_s']:7.2f}  {r['open_s']:6.2f}  "
              f"{r['small_frames']:12}  {r['machine_s_x1000']:15.2f}  {r['run_s_x1000']:11.2f}  "
              f"{r['step_all_s']:10.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
