"""`em703 html`: the page runs in a real browser, not only read as text.

Debian's chromium, driven headless by selenium through chromium-driver (both
installed by scripts/setup.sh), opens each page from disk. Every tape of
every example job (the report's examples, the demo board, the seeds' decks)
is stepped to its end through the page's interface `window.em703` and must
give what `em703 sim` prints for it; the frame text the page shows is `em703
list`'s, in Latin and in the report's letters; the demo page draws (a
screenshot of its field that is not blank), plays, steps back, logs no
error and makes no request but for its own file. Played on a clock the
test moves (its own requestAnimationFrame and performance.now), the
carriage stands part way round an arc where the machine is, the part drawn
on the side the arc turns. A bad tape stops the command at its row and
leaves no page.

Without a browser these tests skip, saying why; under CI (CI=true) they fail.
"""
from __future__ import annotations

import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib
from pathlib import Path

import pytest

from harness.tape import Frame, encode
from harness.tests.helpers import ROOT, keys, run, write_job

CHROMIUM = ("chromium", "chromium-browser", "google-chrome")
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage", "--window-size=1400,1000")
SIM_KEYS = ("executed", "end_x_mm", "end_y_mm", "drawn_mm", "travel_mm", "minutes",
            "tool_at_end")


def _no_browser(why: str):
    if os.environ.get("CI"):
        pytest.fail(f"{why}: CI needs the browser (scripts/setup.sh installs it)", pytrace=False)
    pytest.skip(f"{why} (scripts/setup.sh installs Debian's chromium and chromium-driver)")


@pytest.fixture(scope="module")
def browser():
    """A headless chromium with a fresh profile, its console and network logged."""
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        _no_browser("selenium is not installed")
    binary = next((shutil.which(name) for name in CHROMIUM if shutil.which(name)), None)
    driver = shutil.which("chromedriver")
    if binary is None or driver is None:
        _no_browser("no chromium or chromedriver on PATH")
    os.environ.setdefault("SE_OFFLINE", "true")   # selenium's manager downloads nothing
    profile = tempfile.mkdtemp(prefix="em703-chromium-")
    options = webdriver.ChromeOptions()
    options.binary_location = binary
    for flag in FLAGS:
        options.add_argument(flag)
    options.add_argument(f"--user-data-dir={profile}")
    options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    chrome = webdriver.Chrome(options=options, service=Service(driver))
    chrome.set_script_timeout(120)
    try:
        yield chrome
    finally:
        chrome.quit()
        shutil.rmtree(profile, ignore_errors=True)


def page_of(em703_exe, job: Path, out: Path) -> Path:
    run(em703_exe, "html", job, "-o", out, check=0)
    assert out.is_file(), out
    return out


def open_page(browser, page: Path) -> None:
    browser.get(page.resolve().as_uri())
    assert browser.execute_script("return document.readyState") == "complete"
    assert browser.execute_script("return typeof window.em703") == "object"


def sim_keys(em703_exe, tape: Path) -> dict[str, str]:
    return keys(run(em703_exe, "sim", tape).stdout.decode())   # (field = left: status 1)


def fixed(value: float, decimals: int) -> str:
    """A number as em703 prints it (base_text's fixed: half away from zero)."""
    scaled = int(abs(value) * 10 ** decimals + 0.5)
    text = f"{scaled // 10 ** decimals}.{scaled % 10 ** decimals:0{decimals}d}"
    return "-" + text if value < 0 and scaled else text


def printed(state: dict) -> dict[str, str]:
    """The page's state with em703 sim's keys and decimals."""
    return {"executed": str(state["executed"]), "end_x_mm": fixed(state["x_mm"], 2),
            "end_y_mm": fixed(state["y_mm"], 2), "drawn_mm": fixed(state["drawn_mm"], 2),
            "travel_mm": fixed(state["travel_mm"], 2), "minutes": fixed(state["minutes"], 3),
            "tool_at_end": state["tool"]}


def test_the_page_module_is_what_the_script_writes() -> None:
    """src/em703/em703_page.f90 is scripts/html_page.py's output for src/em703/page/."""
    proc = subprocess.run([sys.executable, str(ROOT / "scripts" / "html_page.py"), "--check"],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_every_example_tape_runs_to_what_em703_sim_prints(em703_exe, example_jobs, browser,
                                                          tmp_path) -> None:
    assert len(example_jobs) >= 10
    for n, job in enumerate(example_jobs):
        page = page_of(em703_exe, job, tmp_path / f"{n}.html")
        open_page(browser, page)
        sheet = keys(job.read_text())
        assert browser.execute_script("return em703.tapes()") == ["small", "large", "cond"]
        for key in ("small", "large", "cond"):
            want = sim_keys(em703_exe, job.parent / sheet[f"{key}.tape"])
            state = browser.execute_script(
                "em703.select(arguments[0]); return em703.step(1e12)", key)
            assert state["tape"] == key and state["done"] is True
            assert state == browser.execute_script("return em703.state()")
            got = printed(state)
            assert {k: got[k] for k in SIM_KEYS} == {k: want[k] for k in SIM_KEYS}, (job, key)
            assert state["total"] == state["executed"]


def test_the_frame_text_is_em703_lists_in_both_alphabets(em703_exe, example_jobs, browser,
                                                         tmp_path) -> None:
    for n, job in enumerate(example_jobs[:8]):
        page = page_of(em703_exe, job, tmp_path / f"{n}.html")
        open_page(browser, page)
        sheet = keys(job.read_text())
        for key in ("small", "large", "cond"):
            tape = job.parent / sheet[f"{key}.tape"]
            for utf8 in (False, True):
                args = ["list", "--bare", tape] + (["--utf8"] if utf8 else [])
                want = run(em703_exe, *args, check=0).stdout.decode("utf-8").splitlines()[1:-1]
                got = browser.execute_script(
                    "em703.select(arguments[0]); em703.setCyrillic(arguments[1]);"
                    "var s = em703.state(), out = [];"
                    "for (var i = 1; i <= s.frames; i++) out.push(em703.frameText(i));"
                    "em703.setCyrillic(false); return out;", key, utf8)
                assert got == want, (tape, utf8)


def test_steps_count_every_pass_of_a_cycle_and_seek_goes_back(em703_exe, tmp_path,
                                                              browser) -> None:
    """The report's Example 5 (a saw: one frame pair run 8 times) and a tape of
    arcs: step(n) runs n executed frames, in any chunks, and seek(n) reaches
    the same state going back as going forward."""
    saw = encode([Frame(dx=300, dy=400, cyc=8, k=10), Frame(dx=100, dy=-400, k=10),
                  Frame(dx=-3200, k=20)])
    arcs = encode([Frame(x=2000, dx=-2000, dy=-2000, k=13), Frame(y=-500, k=11),
                   Frame(dx=2000, dy=2000, k=20)])
    job = write_job(tmp_path, "STEPS", {"small": saw, "cond": arcs}, {"small": "0.40"})
    page = page_of(em703_exe, job, tmp_path / "steps.html")
    open_page(browser, page)
    seen = browser.execute_script(
        "em703.select('small'); var out = [];"
        "for (var i = 0; i < 17; i++) out.push(em703.step(1)); return out;")
    assert [s["executed"] for s in seen] == list(range(1, 18))
    assert [s["pass"] for s in seen[:16]] == [p for p in range(1, 9) for _ in (0, 1)]
    assert [s["passes"] for s in seen[:16]] == [8] * 16
    assert [s["frame"] for s in seen] == [1, 2] * 8 + [3]
    assert [s["tool"] for s in seen] == ["down"] * 16 + ["up"]
    assert (seen[0]["x_mm"], seen[0]["y_mm"]) == (3.0, 4.0)
    assert (seen[15]["x_mm"], seen[15]["y_mm"]) == (32.0, 0.0)
    assert seen[-1]["done"] and printed(seen[-1])["drawn_mm"] == "72.98"
    chunks = browser.execute_script(
        "em703.select('small'); em703.step(3); em703.step(0); em703.step(5);"
        "return em703.step(100);")
    assert chunks == seen[-1]
    back = browser.execute_script("return [em703.seek(5), em703.seek(16), em703.seek(5)];")
    assert back[0] == seen[4] and back[1] == seen[15] and back[2] == seen[4]
    arcs_end = browser.execute_script("em703.select('cond'); return em703.step(10);")
    want = sim_keys(em703_exe, tmp_path / "STEPS-cond.ptp")
    assert {k: printed(arcs_end)[k] for k in SIM_KEYS} == {k: want[k] for k in SIM_KEYS}
    empty = browser.execute_script("em703.select('large'); return em703.step(5);")
    assert empty["executed"] == 0 and empty["done"] and empty["tool"] == "up"


def _png_pixels(png: bytes) -> tuple[int, int, list[bytes]]:
    """Width, height and the unfiltered rows (RGB or RGBA, 8 bits) of a PNG."""
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    pos, data, width = 8, b"", 0
    while pos < len(png):
        length, kind = struct.unpack(">I4s", png[pos:pos + 8])
        body = png[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour in (2, 6), (depth, colour)
            bpp = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            data += body
        pos += 12 + length
    raw = zlib.decompress(data)
    stride = width * bpp
    rows, prev = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line[::bpp]))          # the red channel is enough
        prev = line
    return width, height, rows


def test_the_demo_page_draws_plays_and_fetches_nothing(em703_exe, example_jobs, browser,
                                                       tmp_path) -> None:
    job = next(j for j in example_jobs if j.name == "LOGIC-CARD-A.job")
    page = page_of(em703_exe, job, tmp_path / "demo.html")
    text = page.read_text(encoding="utf-8")
    assert "http://" not in text and "https://" not in text and " src=" not in text
    browser.get_log("browser")
    browser.get_log("performance")
    open_page(browser, page)
    # playing at x1000: the carriage moves on its own, frame after frame
    first = browser.execute_script("em703.select('small'); em703.play(1000); return em703.state()")
    browser.execute_async_script(
        "var done = arguments[0]; setTimeout(function () { done(); }, 1500);")
    moving = browser.execute_script("var s = em703.state(); em703.pause(); return s;")
    assert first["executed"] == 0 and 0 < moving["executed"], moving
    state = browser.execute_script("return em703.step(1e9)")
    assert state["done"]
    field = browser.find_element("id", "field")
    width, height, red = _png_pixels(field.screenshot_as_png)
    drawn = sum(1 for row in red for v in row if v < 128)
    assert drawn > 0.005 * width * height, (drawn, width, height)
    strip = browser.find_element("id", "strip").text
    assert "GM" in strip and "KK" in strip and "|o o o . o o    | 037   GM" in strip
    errors = [e for e in browser.get_log("browser") if e["level"] in ("SEVERE", "WARNING")]
    assert not errors, errors
    urls = set()
    for entry in browser.get_log("performance"):
        message = json.loads(entry["message"])["message"]
        if message["method"] == "Network.requestWillBeSent":
            urls.add(message["params"]["request"]["url"])
    assert urls == {page.resolve().as_uri()}, urls


def test_a_bad_tape_stops_at_its_row_and_leaves_no_page(em703_exe, tmp_path) -> None:
    good = encode([Frame(dx=500, k=10), Frame(dx=-500, k=20)])
    bad = bytearray(good)
    bad[25] = 0o33                            # a row outside the code
    job = write_job(tmp_path, "BAD", {"small": good, "cond": bytes(bad)}, {})
    out = tmp_path / "bad.html"
    proc = run(em703_exe, "html", job, "-o", out, check=1)
    assert proc.stderr.decode() == f"{tmp_path}/BAD-cond.ptp: row 26: code 33 (octal) is not " \
                                   "an EM-703 code\n"
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["BAD-cond.ptp", "BAD-large.ptp",
                                                          "BAD-small.ptp", "BAD.job"]


def test_names_are_escaped_in_the_page(em703_exe, tmp_path) -> None:
    job = write_job(tmp_path, "ODD", {}, {})
    text = job.read_text().replace("name = ODD", 'name = A</script><b>"\\')
    job.write_text(text + "job = X & <Y>\n")
    page = run(em703_exe, "html", job, check=0).stdout.decode()
    assert page.count("</script>") == page.count("<script")
    assert '"name":"A\\u003c/script>\\u003cb>\\"\\\\"' in page
    assert "<title>EM-703 job A&lt;/script&gt;&lt;b&gt;\"\\</title>" in page


def _view_rows(em703_exe, tape: Path) -> dict[int, str]:
    """em703 view's line of every row of a tape, by row number."""
    lines = run(em703_exe, "view", tape).stdout.decode().splitlines()
    return {int(line[:5]): line for line in lines if line[:5].strip().isdigit()}


def test_the_strip_is_em703_views_rows_with_the_frame_under_way_highlighted(
        em703_exe, tmp_path, browser) -> None:
    """At every step the strip is `em703 view` of the 33 rows around the
    reader mark, the mark on the first row of the frame executed last (the
    state's row), and exactly that frame's rows highlighted, from the row
    after the previous frame's KK (or the opening GM) to its own KK. A tape
    in the "8" code and one in the code with control (whose digits 3, 5, 6, 9
    have their own rows)."""
    saw = [Frame(dx=300, dy=400, cyc=8, k=10), Frame(dx=100, dy=-400, k=10),
           Frame(dx=-3200, k=20)]
    digits = [Frame(dx=3569, dy=-9653, k=10), Frame(dx=-3569, dy=9653, k=20)]
    for code in ("8", "K"):
        job = write_job(tmp_path, f"STRIP{code}", {"small": encode(saw, code),
                                                   "cond": encode(digits, code)}, {}, code)
        open_page(browser, page_of(em703_exe, job, tmp_path / f"strip{code}.html"))
        for key in ("small", "cond"):
            tape = tmp_path / f"STRIP{code}-{key}.ptp"
            view = _view_rows(em703_exe, tape)
            gm = [r for r, line in view.items() if line.endswith(" GM")]
            kk = [r for r, line in view.items() if line.endswith(" KK")]
            spans = list(zip([gm[0] + 1] + [r + 1 for r in kk[:-1]], kk))  # a frame's rows
            seen = browser.execute_script(
                "em703.select(arguments[0]); var out = [];"
                "for (var s = em703.state(); ; s = em703.step(1)) {"
                "  var strip = document.getElementById('strip'), lit = [];"
                "  strip.querySelectorAll('.hl').forEach(function (e) {"
                "    lit.push(e.textContent); });"
                "  out.push([s, strip.textContent, lit]);"
                "  if (s.done) return out; }", key)
            assert len(seen) == seen[-1][0]["total"] + 1
            for state, text, lit in seen:
                lines = text.split("\n")
                assert len(lines) == 2 + 33 + 1, (tape, state)
                mark = gm[0] if state["frame"] == 0 else spans[state["frame"] - 1][0]
                if state["frame"]:
                    assert state["row"] == mark, (tape, state)
                for i, line in enumerate(lines[2:-1]):
                    row = mark - 16 + i
                    assert line == ("\u25b6" if row == mark else " ") + \
                        view.get(row, "      |      .        |"), (tape, state, row)
                want = [] if state["frame"] == 0 else \
                    list(range(spans[state["frame"] - 1][0], spans[state["frame"] - 1][1] + 1))
                assert [int(line[:5]) for line in lit] == want, (tape, state)


def _ink(browser, canvas: str = "drawing") -> list[str]:
    """A canvas of the field (the drawing or the carriage) as rows of "#" (drawn
    black, the tool), "r" (the carriage's red), "b" (the start point's blue)
    and "."."""
    return browser.execute_script(
        "var c = document.getElementById(arguments[0]), w = c.width, h = c.height;"
        "var d = c.getContext('2d').getImageData(0, 0, w, h).data, rows = [];"
        "for (var y = 0; y < h; y++) { var s = '';"
        "  for (var x = 0; x < w; x++) { var p = 4 * (y * w + x), r = d[p], g = d[p + 1],"
        "      b = d[p + 2], a = d[p + 3];"
        "    s += a > 128 && r < 64 && g < 64 && b < 64 ? '#' :"
        "         a > 64 && r > 160 && g < 64 && b < 96 ? 'r' :"
        "         a > 64 && r < 64 && b > 160 ? 'b' : '.'; }"
        "  rows.push(s); } return rows;", canvas)


def _box(ink: list[str], mark: str = "#") -> tuple[int, int, int, int]:
    """Left, right, top and bottom pixel of the ink (or of another mark of _ink)."""
    cols = [x for row in ink for x, c in enumerate(row) if c == mark]
    rows = [y for y, row in enumerate(ink) if mark in row]
    assert cols, f"no {mark!r} on the canvas"
    return min(cols), max(cols), min(rows), max(rows)


def test_the_field_is_fitted_and_drawn_with_the_tools_width(em703_exe, tmp_path,
                                                            browser) -> None:
    """The field's canvas, read back pixel by pixel: the drawing is centred and
    fills the field on its longer side; a line and a dot (K10 without a move)
    are as wide as the job sheet's tool at that scale; a clockwise (K13) and a
    counter-clockwise (K11) quarter arc are drawn on their own side of the
    chord, around the centre X, Y gives, not the other three quarters."""
    small = [Frame(k=10), Frame(dx=10000, k=20), Frame(dy=5000, k=10),
             Frame(dx=-10000, dy=-5000, k=20)]
    cw = [Frame(y=5000, dx=5000, dy=-5000, k=13), Frame(dx=-5000, dy=5000, k=20)]
    ccw = [Frame(x=5000, dx=-5000, dy=5000, k=11), Frame(dx=5000, dy=-5000, k=20)]
    job = write_job(tmp_path, "FIELD", {"small": encode(small), "large": encode(ccw),
                                        "cond": encode(cw)},
                    {"small": "2.00", "large": "1.00", "cond": "1.00"})
    open_page(browser, page_of(em703_exe, job, tmp_path / "field.html"))
    size = browser.execute_script("return document.getElementById('drawing').width")
    # The line and the dot: the ink is x -1..101 mm, y -1..51 mm (the tool 2 mm).
    browser.execute_script("em703.select('small'); em703.step(10);")
    ink = _ink(browser)
    left, right, top, bottom = _box(ink)
    assert abs((left + right) / 2 - size / 2) <= 1.5 and abs((top + bottom) / 2 - size / 2) <= 1.5
    assert 0 < left and right < size - 1 and right - left + 1 >= 0.9 * size, (left, right)
    px = (right - left + 1) / 102                       # pixels a millimetre
    assert abs((bottom - top + 1) - 52 * px) <= 2, (top, bottom, px)
    dot = ink[round(bottom - 1 * px)][left:left + round(10 * px)]
    line = ink[round(bottom - 26 * px)][right - round(10 * px):right + 1]
    assert abs(dot.count("#") - 2 * px) <= 1.5, (dot, px)
    assert abs(line.count("#") - 2 * px) <= 1.5, (line, px)
    assert "#" not in ink[round(bottom - 26 * px)][:right - round(10 * px)]
    # The quarter arcs: the ink is the quarter's box and the tool's half width;
    # its middle (45 degrees from the chord's ends) is drawn, the centre is not.
    for key, (xmin, ymax), middle, centre in (("cond", (0, 0), (35.36, -14.64), (0, -50)),
                                              ("large", (-50, 50), (-14.64, 35.36), (-50, 0))):
        browser.execute_script("em703.select(arguments[0]); em703.step(10);", key)
        ink = _ink(browser)
        left, right, top, bottom = _box(ink)
        assert abs(right - left - (bottom - top)) <= 2 and right - left + 1 >= 0.9 * size
        px = (right - left + 1) / 51
        mx, my = (round(left + (middle[0] - xmin + 0.5) * px),
                  round(top + (ymax - middle[1] + 0.5) * px))
        cx, cy = (round(left + (centre[0] - xmin + 0.5) * px),
                  round(top + (ymax - centre[1] + 0.5) * px))
        assert ink[my][mx] == "#", (key, mx, my)
        assert "#" not in "".join(row[cx - 5:cx + 6] for row in ink[cy - 5:cy + 6]), key


def _panel(browser) -> dict[str, str]:
    """The machine panel's rows, name: value."""
    return dict(browser.execute_script(
        "var out = []; document.querySelectorAll('#state tr').forEach(function (tr) {"
        "  out.push([tr.cells[0].textContent, tr.cells[1].textContent]); }); return out;"))


def _panel_of(state: dict, label: str, file: str) -> dict[str, str]:
    """What the machine panel shows for a state of the page."""
    command = {10: "line / dot", 20: "travel / raise", 11: "arc counter-clockwise",
               13: "arc clockwise"}
    return {
        "tape": f"{state['tape']} ({label}), {file}",
        "X from the start point": fixed(state["x_mm"], 2) + " mm",
        "Y from the start point": fixed(state["y_mm"], 2) + " mm",
        "tool": state["tool"],
        "command": f"K{state['k']} ({command[state['k']]})" if state["k"] else "-",
        "cycle": f"pass {state['pass']} of {state['passes']}" if state["passes"] else "-",
        "frames executed": f"{state['executed']} of {state['total']}",
        "tape frame": f"{state['frame']} of {state['frames']}, row {state['row']}",
        "drawn": fixed(state["drawn_mm"], 2) + " mm",
        "travel": fixed(state["travel_mm"], 2) + " mm",
        "machine time": fixed(state["minutes"], 3) + " min",
        "": "the tape has run to its end" if state["done"] else ""}


def test_the_panel_and_the_controls(em703_exe, tmp_path, browser) -> None:
    """The heading gives the job's code, scale and start point; the machine
    panel shows the state at every step (in em703's decimals, the arcs'
    direction named); the buttons one frame forward and back and reset, and
    a click on a row of the strip, run the tape to where they say."""
    from selenium.webdriver.common.action_chains import ActionChains
    saw = encode([Frame(dx=300, dy=400, cyc=8, k=10), Frame(dx=100, dy=-400, k=10),
                  Frame(dx=-3200, k=20)])
    arcs = encode([Frame(x=2000, dx=-2000, dy=-2000, k=13), Frame(y=-500, k=11),
                   Frame(dx=2000, dy=2000, k=20)])
    job = write_job(tmp_path, "PANEL", {"small": saw, "cond": arcs}, {})
    job.write_text(job.read_text().replace("scale = 1:1", "scale = 1:2")
                   .replace("start_y_mm = 600.00", "start_y_mm = 150.00"))
    open_page(browser, page_of(em703_exe, job, tmp_path / "panel.html"))
    assert browser.find_element("id", "subtitle").text == \
        "code 8, scale 1:2, start point at 600.00, 150.00 mm on the field"
    for key, label, file in (("small", "small pads", "PANEL-small.ptp"),
                             ("cond", "conductors", "PANEL-cond.ptp")):
        seen = browser.execute_script(
            "var out = [[em703.select(arguments[0]), []]];"
            "for (var i = 0; i < 20; i++) out.push([em703.step(1), []]);"
            "out.forEach(function (s, i) { em703.seek(i); document.querySelectorAll("
            "  '#state tr').forEach(function (tr) {"
            "  s[1].push([tr.cells[0].textContent, tr.cells[1].textContent]); }); });"
            "return out;", key)
        for state, rows in seen:
            assert dict(rows) == _panel_of(state, label, file), state
    browser.execute_script("em703.setCyrillic(true); em703.seek(1);")
    assert _panel(browser)["command"] == "\u041a13 (arc clockwise)"
    browser.execute_script("em703.setCyrillic(false); em703.select('small');")

    def click(name: str) -> dict:
        browser.find_element("id", name).click()
        return browser.execute_script("return em703.state()")

    assert [click("fwd")["executed"] for _ in range(3)] == [1, 2, 3]
    assert click("back")["executed"] == 2
    assert _panel(browser)["frames executed"] == "2 of 17"
    assert browser.find_element("id", "goto").get_attribute("value") == "2"
    browser.execute_script("em703.seek(16)")
    assert click("back")["executed"] == 15 and click("fwd")["executed"] == 16
    assert click("reset")["executed"] == 0 and click("back")["executed"] == 0

    strip = browser.find_element("id", "strip")

    def click_row(row: int) -> dict:
        lines = browser.execute_script("return arguments[0].textContent", strip).split("\n")
        index = next(i for i, line in enumerate(lines) if line[1:6].strip() == str(row))
        box = browser.execute_script(
            "var e = arguments[0]; return [e.clientHeight, e.clientTop,"
            " e.getBoundingClientRect().height];", strip)
        y = (index + 0.5) * box[0] / len(lines) + box[1] - box[2] / 2
        ActionChains(browser).move_to_element_with_offset(strip, 0, round(y)).click().perform()
        return browser.execute_script("return em703.state()")

    # the saw: frame 1 rows 22-35 (run 8 times with frame 2, rows 36-49), frame 3 rows 50-59
    assert click_row(21)["executed"] == 0                # the GM: no frame
    got = click_row(36)
    assert (got["executed"], got["frame"], got["pass"]) == (2, 2, 1)
    got = click_row(52)
    assert (got["executed"], got["frame"]) == (17, 3)
    got = click_row(35)
    assert (got["executed"], got["frame"], got["pass"]) == (1, 1, 1)


def test_play_runs_at_the_machines_speeds(em703_exe, tmp_path, browser) -> None:
    """Played at x10 and x100 for a second and a half, a tape gets as far as
    the machine would in 10 or 100 times that: 5.5 m/min on lines and travel,
    1.5 m/min on arcs. Never further: the page's clock cannot run ahead of
    the browser's. How much less depends on how busy the machine is, so the
    test asks only that play got under way (how fast the page is belongs to
    bench.html, not to a test)."""
    lines = encode([Frame(dx=1000, cyc=200, k=10), Frame(dx=-1000, k=20)])
    circles = encode([Frame(x=1000, cyc=200, k=11), Frame(x=1000, k=11)])
    job = write_job(tmp_path, "PLAY", {"small": lines, "cond": circles}, {})
    open_page(browser, page_of(em703_exe, job, tmp_path / "play.html"))
    for key, speed, minutes in (("small", 10, 10 / 5500), ("cond", 100, 2 * math.pi * 10 / 1500)):
        state, ms = browser.execute_async_script(
            "var done = arguments[2]; em703.select(arguments[0]);"
            "var t0 = performance.now(); em703.play(arguments[1]);"
            "setTimeout(function () { em703.pause(); var s = em703.state();"
            "  done([s, performance.now() - t0]); }, 1500);", key, speed)
        most = ms / 60000 * speed / minutes            # frames the machine runs in that time
        assert 1 <= state["executed"] <= most + 1e-6, (key, state["executed"], most)
        assert not state["done"] and not browser.execute_script("return em703.playing()")


FRAME_CLOCK = """(function () {
  var now = 1000, waiting = [];
  Object.defineProperty(performance, 'now', { configurable: true,
                                              value: function () { return now; } });
  window.requestAnimationFrame = function (f) { waiting.push(f); return waiting.length; };
  window.em703Clock = function (ms) {
    now += ms;
    var run = waiting;
    waiting = [];
    run.forEach(function (f) { f(now); });
    return run.length;
  };
})();"""


@pytest.fixture
def frame_clock(browser):
    """Pages opened while it lasts run on the test's clock: performance.now()
    stands still and the animation's frames wait until em703Clock(ms) moves
    the clock ms on and runs them at the new time."""
    script = browser.execute_cdp_cmd("Page.addScriptToEvaluateOnNewDocument",
                                      {"source": FRAME_CLOCK})
    try:
        yield
    finally:
        browser.execute_cdp_cmd("Page.removeScriptToEvaluateOnNewDocument",
                                {"identifier": script["identifier"]})


def _cross(ink: list[str], mark: str) -> tuple[float, float, int, int]:
    """The centre, width and height of a cross (the pixels of one mark)."""
    left, right, top, bottom = _box(ink, mark)
    return (left + right) / 2, (top + bottom) / 2, right - left + 1, bottom - top + 1


def test_playing_the_carriage_runs_round_arcs_and_circles_the_way_they_turn(
        em703_exe, tmp_path, browser, frame_clock) -> None:
    """Played on the test's clock and stopped part of the way through an arc,
    the carriage (a red cross of two bars) stands where the machine is on the
    arc, and the part of the arc it has drawn is black from the arc's start
    the way the arc turns, and nowhere else on its circle: a full circle
    (K11 or K13 without DX and DY) a quarter of the way, counter-clockwise
    and clockwise, and a clockwise quarter arc a third of the way."""
    cond = encode([Frame(x=1000, k=11), Frame(x=1000, k=13),
                   Frame(y=-1000, dx=-1000, dy=1000, k=13), Frame(dx=1000, dy=-1000, k=20)])
    job = write_job(tmp_path, "TURN", {"cond": cond}, {})
    open_page(browser, page_of(em703_exe, job, tmp_path / "turn.html"))
    # Millimetres to pixels: the carriage at rest at the start point and at
    # the end of frame 3, (-10, 10) mm.
    browser.execute_script("em703.select('cond')")
    x0, y0, *size = _cross(_ink(browser, "carriage"), "r")
    assert 19 <= min(size) and max(size) <= 24, size
    browser.execute_script("em703.seek(3)")
    x3, y3, *size = _cross(_ink(browser, "carriage"), "r")
    assert 19 <= min(size) and max(size) <= 24, size
    assert x3 < x0 - 200 and y3 < y0 - 200, (x0, y0, x3, y3)

    def pixel(x_mm: float, y_mm: float) -> tuple[int, int]:
        return round(x0 + x_mm / -10 * (x3 - x0)), round(y0 + y_mm / 10 * (y3 - y0))

    def on(cx: float, cy: float, degrees: float) -> tuple[int, int]:   # on a 10 mm circle
        return pixel(cx + 10 * math.cos(math.radians(degrees)),
                     cy + 10 * math.sin(math.radians(degrees)))

    circle = 2 * math.pi * 10 / 1500                        # minutes at 1.5 m/min
    # executed before, minutes of the arc, the part run, the centre, degrees
    # from the centre at the start, and after the part run (signed)
    for before, minutes, part, (cx, cy), start, turn in (
            (0, circle, 1 / 4, (-10, 0), 0, 90), (1, circle, 1 / 4, (-10, 0), 0, -90),
            (2, circle / 4, 1 / 3, (0, 10), -90, -30)):
        ms = part * minutes * 60000 / 10                    # at x10
        ran = browser.execute_script(
            "em703.seek(arguments[0]); em703.play(10); return em703Clock(arguments[1]);",
            before, ms)
        state = browser.execute_script("return em703.state()")
        assert ran >= 1 and state["executed"] == before, (before, ran, state)
        assert browser.execute_script("return em703.playing()")
        ink = _ink(browser, "carriage")
        browser.execute_script("em703.pause()")
        x, y, *size = _cross(ink, "r")
        want = on(cx, cy, start + turn)
        assert abs(x - want[0]) <= 1.5 and abs(y - want[1]) <= 1.5, (before, (x, y), want)
        assert 19 <= min(size) and max(size) <= 24, (before, size)
        mx, my = on(cx, cy, start + turn / 2)
        assert ink[my][mx] == "#", (before, "not drawn half way", mx, my)
        for degrees in range(start + turn + (20 if turn > 0 else -20),
                             start + (340 if turn > 0 else -340), 20 if turn > 0 else -20):
            px, py = on(cx, cy, degrees)
            if 3 <= px < len(ink) - 3 and 3 <= py < len(ink) - 3:
                near = "".join(row[px - 3:px + 4] for row in ink[py - 3:py + 4])
                assert "#" not in near, (before, "drawn at", degrees)


def test_the_start_point_is_a_blue_cross_of_two_bars_where_the_carriage_starts(
        em703_exe, tmp_path, browser) -> None:
    """The field shows the start point as a blue cross, a bar across and a
    bar up, 17 pixels each, centred where the carriage stands before the
    first frame, and again when the tape has run and gone back to the
    start."""
    small = encode([Frame(dx=2000, dy=1000, k=20), Frame(dx=-2000, dy=-1000, k=10)])
    job = write_job(tmp_path, "START", {"small": small}, {})
    open_page(browser, page_of(em703_exe, job, tmp_path / "start.html"))
    x, y, *size = _cross(_ink(browser, "carriage"), "r")
    for run in ("em703.select('small')", "em703.step(2); em703.seek(0)"):
        browser.execute_script(run)
        bx, by, *bsize = _cross(_ink(browser), "b")
        assert abs(bx - x) <= 1 and abs(by - y) <= 1, (run, (bx, by), (x, y))
        assert 16 <= min(bsize) and max(bsize) <= 19, (run, bsize)


def test_the_go_button_runs_to_the_executed_frame_typed(em703_exe, tmp_path, browser) -> None:
    """The frame box and go: the tape runs (forward or back) to the number
    typed, not to where it already is."""
    saw = encode([Frame(dx=300, dy=400, cyc=8, k=10), Frame(dx=100, dy=-400, k=10),
                  Frame(dx=-3200, k=20)])
    job = write_job(tmp_path, "GO", {"small": saw}, {})
    open_page(browser, page_of(em703_exe, job, tmp_path / "go.html"))
    goto = browser.find_element("id", "goto")
    for n in (16, 3, 17, 0):
        goto.clear()
        goto.send_keys(str(n))
        browser.find_element("id", "go").click()
        assert browser.execute_script("return em703.state()")["executed"] == n
        assert goto.get_attribute("value") == str(n)
