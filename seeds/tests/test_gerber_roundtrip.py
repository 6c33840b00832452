"""The round trip of gerber2deck on the real boards: gerber2deck -> tenzor ->
em703 gerber must give back the board (docs/GERBER.md).

Both the board's own copper layer and em703's photomask are rendered by
gerbv (Debian), an independent renderer, at 0.02 mm a pixel on the same
window, in tiles of at most 2000 pixels (gerbv's limit). Then:

* coverage: the copper a round tool of the job's finest width can reach (the
  board's copper opened by that tool: eroded, then dilated by its radius) is
  covered except for at most 0.5 % of the copper area, and no uncovered
  spot is wider than 0.1 mm (the uncovered pixels eroded by a disc of
  0.05 mm radius leave nothing);
* excess: the photomask adds no copper outside the board's copper grown by
  one pixel, beyond 0.1 % of the copper area (excess copper shorts nets).

The boards are found through $REALBOARDS only; without it the test skips,
except under CI=true, where it fails. The Altium board (203 x 124 mm) is
checked on a 40 x 40 mm window at its centre, at the same pixel, to keep the
test's time in CI down (its full conversion is timed by its own test).
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from harness.tests.em703.test_em703_gerber import read_png

GERBV = shutil.which("gerbv")
PITCH = 0.02                     # mm a pixel
DPI = 25.4 / PITCH               # 1270
TILE = 2000                      # gerbv exports at most 2000 x 2000 pixels

#: (folder, copper layer, drill file, window: None = whole board, else
#: (dx, dy, w, h) mm from the board's centre)
BOARDS = [
    ("geda-stepper-driver", "driver.top.gbr", "driver.plated-drill.cnc", None),
    ("eagle-arduino-uno", "arduino-uno.cmp", "arduino-uno.drd", None),
    ("diptrace-fd1-mainboard", "mainboard_Top.gbr", "mainboard.drl", None),
    ("kicad-chibi", "chibi_2024-F.Cu.gbr", "chibi_2024.drl", None),
    ("altium-limesdr-qpcie", "LimeSDR-QPCIe_1v2.GTL", "LimeSDR-QPCIe_1v2-RoundHoles.TXT",
     (-20.0, -20.0, 40.0, 40.0)),
]


def realboards() -> Path:
    """The folder of the real boards ($REALBOARDS), or a skip (a failure in CI)."""
    given = os.environ.get("REALBOARDS")
    if not given or not Path(given).is_dir():
        msg = ("REALBOARDS is not set to the folder of the real boards (.ci/run sets it); "
               "the round trip of gerber2deck cannot run")
        if os.environ.get("CI") == "true":
            pytest.fail(msg, pytrace=False)
        pytest.skip(msg)
    return Path(given)


def gerber2deck(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "seeds", "gerber2deck", *map(str, args)],
                          capture_output=True, text=True, timeout=300)


@dataclass(frozen=True)
class BoardRun:
    """gerber2deck and tenzor run on one real board: what gerber2deck said
    about it, how long it took, and tenzor's output folder."""
    said: str
    seconds: float
    tapes: Path


_RUNS: dict[tuple[str, str], BoardRun] = {}


def board_run(board, tenzor: Path, tmp_path_factory: pytest.TempPathFactory) -> BoardRun:
    """The board's copper layer and drill file through gerber2deck and tenzor,
    once a run and tenzor: the round trip here and test_gerber_drill.py read
    the same tapes (gerber2deck and tenzor take seconds on a real board)."""
    key = (board[0], str(tenzor))
    if key not in _RUNS:
        folder = realboards() / board[0]
        work = tmp_path_factory.mktemp(board[0])
        deck = work / "board.crd"
        t = time.monotonic()
        proc = gerber2deck(folder / board[1], "--drill", folder / board[2], "-o", deck)
        assert proc.returncode == 0, proc.stderr
        seconds = time.monotonic() - t
        out = work / "tapes"
        tz = subprocess.run([str(tenzor), str(deck), "-o", str(out)], capture_output=True,
                            timeout=300)
        assert tz.returncode == 0, tz.stderr.decode("latin-1")
        _RUNS[key] = BoardRun(proc.stderr, seconds, out)
    return _RUNS[key]


def render(gbr: Path, x0: float, y0: float, nx: int, ny: int, tmp: Path) -> np.ndarray:
    """gerbv's picture of gbr, [row from the bottom, column], pixel (0, 0)'s
    lower-left corner at x0, y0 mm; True = dark."""
    out = np.zeros((ny, nx), bool)
    for j in range(0, ny, TILE):
        for i in range(0, nx, TILE):
            w, h = min(TILE, nx - i), min(TILE, ny - j)
            png = tmp / f"tile-{i}-{j}.png"
            origin = f"{x0 + i * PITCH:.4f}x{y0 + j * PITCH:.4f}"
            proc = subprocess.run(
                [GERBV, "-x", "png", "-u", "mm", "-D", f"{DPI:g}", "-O", origin,
                 "-w", f"{w}x{h}", "-B", "0", "-b", "#000000", "-f", "#ffffffff",
                 "-o", str(png), str(gbr)], capture_output=True, timeout=300)
            assert proc.returncode == 0 and png.exists(), proc.stderr.decode("latin-1")
            img = read_png(png)
            assert img.shape == (h, w), (img.shape, w, h)
            out[j:j + h, i:i + w] = img[::-1, :] > 127
            png.unlink()
    return out


def _disc(r: float) -> list[tuple[int, int]]:
    n = int(np.floor(r))
    return [(dy, dx) for dy in range(-n, n + 1) for dx in range(-n, n + 1)
            if dx * dx + dy * dy <= r * r]


def _shifted(a: np.ndarray, dy: int, dx: int, fill: bool) -> np.ndarray:
    out = np.full_like(a, fill)
    h, w = a.shape
    out[max(dy, 0):h + min(dy, 0), max(dx, 0):w + min(dx, 0)] = \
        a[max(-dy, 0):h + min(-dy, 0), max(-dx, 0):w + min(-dx, 0)]
    return out


def erode(a: np.ndarray, r: float) -> np.ndarray:
    out = a.copy()
    for dy, dx in _disc(r):
        out &= _shifted(a, dy, dx, False)
    return out


def dilate(a: np.ndarray, r: float) -> np.ndarray:
    out = a.copy()
    for dy, dx in _disc(r):
        out |= _shifted(a, dy, dx, False)
    return out


def widest_spot(uncovered: np.ndarray) -> float:
    """About the width (mm) of the widest uncovered spot: each erosion by a
    pixel takes a pixel off both sides."""
    k = 0
    while uncovered.any() and k < 100:
        uncovered = erode(uncovered, 1.0)
        k += 1
    return max(2 * k - 1, 0) * PITCH


def round_trip(copper: Path, run: BoardRun, window, tmp: Path, em703: Path) -> dict:
    """The rest of the chain on one board, from tenzor's tapes of its copper
    layer (em703 gerber, then gerbv's pictures of both), measured; the figures
    as a dict."""
    m = re.search(r"(\S+) x (\S+) mm, start point at board (\S+), (\S+) mm; tools "
                  r"W1 (\S+), W2 (\S+), W3 (\S+) mm", run.said)
    assert m, run.said
    w, h, ox, oy, *tools = (float(v.rstrip(",")) for v in m.groups())
    job = next(p for p in run.tapes.glob("*.job") if not p.stem.endswith("-DRILL"))
    mask_gbr = tmp / "mask.gbr"
    em = subprocess.run([str(em703), "gerber", str(job), "-o", str(mask_gbr)],
                        capture_output=True, timeout=300)
    assert em.returncode == 0, em.stderr.decode("latin-1")
    if window is None:
        bx0, by0, bw, bh = ox - 0.5, oy - 0.5, w + 1.0, h + 1.0
    else:
        dx, dy, bw, bh = window
        bx0, by0 = ox + w / 2 + dx, oy + h / 2 + dy
    nx, ny = int(round(bw / PITCH)), int(round(bh / PITCH))
    orig = render(copper, bx0, by0, nx, ny, tmp)
    mask = render(mask_gbr, bx0 - ox, by0 - oy, nx, ny, tmp)
    finest = min(tools)
    rpx = finest / 2 / PITCH
    opened = dilate(erode(orig, rpx), rpx)
    # gerbv moves every coordinate to the pixel grid (harness/tests/em703/
    # test_em703_gerber.py): the edges of the two pictures may differ by a
    # pixel, so the copper's outermost pixel counts as reached either way
    uncovered = erode(opened, 1.0) & ~mask
    area = max(int(orig.sum()), 1)
    excess = mask & ~dilate(orig, 1.5)
    return {
        "board": copper.parent.name, "seconds": run.seconds, "finest_mm": finest,
        "copper_mm2": area * PITCH * PITCH,
        "uncovered_pct": 100.0 * uncovered.sum() / area,
        "widest_spot_mm": widest_spot(uncovered) if uncovered.any() else 0.0,
        "excess_pct": 100.0 * excess.sum() / area,
        # a disc of uncovered pixels wider than 0.1 mm would survive this erosion
        "spot_over_0_1mm": bool(erode(uncovered, 0.05 / PITCH + 0.01).any()),
    }


@pytest.mark.skipif(GERBV is None, reason="gerbv (Debian package) is not on PATH")
@pytest.mark.parametrize("board", BOARDS, ids=[b[0] for b in BOARDS])
def test_round_trip_gives_back_the_board(board, tenzor_exe, em703_exe, tmp_path,
                                        tmp_path_factory):
    folder = realboards() / board[0]
    t = time.monotonic()
    run = board_run(board, tenzor_exe, tmp_path_factory)
    r = round_trip(folder / board[1], run, board[3], tmp_path, em703_exe)
    r["test_seconds"] = time.monotonic() - t
    print(r)
    assert r["uncovered_pct"] <= 0.5, r
    assert not r["spot_over_0_1mm"], r
    assert r["excess_pct"] <= 0.1, r
