"""verify on a board too big for the old whole-layer pixel budget: 900 pads
spread over 600 x 600 mm, one to a tile, so that the tiles to evaluate hold
more than 50 000 000 pixels even at the coarsest pitch (the old check
refused it as 'coverage cannot be checked').  Timed figures for the 100 000-
pad boards are in the benchmarks, not here."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from harness import cards, raster, sim, tape, verify
from harness.deck import parse_deck
from harness.shapes import run_shapes
from harness.tape import Frame

ROOT = Path(__file__).resolve().parents[3]
SIDE = 30                   #: pads a row and a column
STEP = 2000                 #: 20 mm between rows and columns
#: The old budget: a layer needing more pixels than this was refused.
OLD_CAP = 50_000_000


def centre(i: int, j: int) -> tuple[int, int]:
    """Pad (i, j)'s centre, units: the grid shifted a little, irregularly."""
    return 500 + i * STEP + (i * 7 + j * 13) % 300, 500 + j * STEP + (i * 11 + j * 5) % 300


def spread_deck() -> str:
    lines = [cards.p_card(2000, 2000, 50, 100, 50, 200, None, "8", "D")]
    lines += [cards.d_card(*centre(i, j), 160) for j in range(SIDE) for i in range(SIDE)]
    return cards.deck([cards.CardPackage("SPREAD", lines)], envelope=False)


DECK = spread_deck()


@pytest.fixture(scope="module")
def spread(tenzor_exe, tmp_path_factory) -> Path:
    """TENZOR's tapes of the spread board."""
    base = tmp_path_factory.mktemp("spread")
    (base / "spread.crd").write_text(DECK)
    proc = subprocess.run([tenzor_exe, base / "spread.crd", "-o", base / "tapes"],
                          capture_output=True, timeout=120)
    assert proc.returncode == 0, proc.stderr.decode()
    return base / "tapes"


def test_the_board_is_over_the_old_budget(spread) -> None:
    (pkg,) = parse_deck(DECK)
    run = sim.simulate(tape.decode((spread / "SPREAD-small.ptp").read_bytes()).frames)
    pl = raster.plan(pkg.layers["small"].shapes, run_shapes(run, 50), verify.TOLERANCE,
                     pitch=4.0)
    assert pl is not None and pl.pixels > OLD_CAP


def test_a_board_over_the_old_budget_is_checked_and_passes(spread) -> None:
    v = verify.verify(DECK, spread)
    assert v.passed, v.text()


def test_a_damaged_tape_of_it_fails_naming_the_pad(spread, tmp_path) -> None:
    """Pad (17, 11) is left out of the small-pad tape: a raised move takes
    the place of its frames; the reason names its card and its (x, y)."""
    out = tmp_path / "tapes"
    out.mkdir()
    for p in spread.glob("SPREAD-*.ptp"):
        (out / p.name).write_bytes(p.read_bytes())
    path = out / "SPREAD-small.ptp"
    t = tape.decode(path.read_bytes())
    frames = list(t.frames)
    cx, cy = centre(17, 11)
    x = y = 0
    idx = []
    for n, f in enumerate(frames):
        assert not f.cyc                   # single pads: no cycles
        if f.k != 20 and abs(x - cx) <= 100 and abs(y - cy) <= 100:
            idx.append(n)
        x, y = x + f.dx, y + f.dy
    assert idx and idx == list(range(idx[0], idx[-1] + 1))
    dx = sum(frames[n].dx for n in idx)
    dy = sum(frames[n].dy for n in idx)
    frames[idx[0]:idx[-1] + 1] = [Frame(dx=dx, dy=dy, k=20)]
    path.write_bytes(tape.encode(frames, t.code))
    v = verify.verify(DECK, out)
    card = 3 + 11 * SIDE + 17
    assert [(r.kind, r.card) for r in v.reasons] == [("pad-missing", card)], v.text()
    assert (f"card {card} (D): round 1.60 mm pad at ({cx / 100:.2f}, {cy / 100:.2f}) mm: "
            "missing") in v.text()
    assert v.text().endswith("FAIL: 1 reason\n")


def test_progress_goes_to_standard_error_only(spread, tmp_path) -> None:
    """A long run shows its progress on standard error; here 'long' is made
    zero seconds (VERIFY_PROGRESS_AFTER) so that the test need not be slow.
    Standard output is the verdict alone, as without progress."""
    deck = tmp_path / "spread.crd"
    deck.write_text(DECK)
    env = dict(os.environ, VERIFY_PROGRESS_AFTER="0")
    proc = subprocess.run([sys.executable, "-m", "harness", "verify", str(deck), str(spread)],
                          cwd=ROOT, capture_output=True, text=True, timeout=300, env=env)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == verify.verify(DECK, spread, deck_name=str(deck)).text()
    lines = proc.stderr.splitlines()
    assert lines and all(line.startswith("verify: ") for line in lines), proc.stderr
    # the first line comes at once; the next at most a second later (the
    # tiles of a layer, when it takes that long)
    assert lines[0] == "verify: small pads: reading SPREAD-small.ptp (0 s)", proc.stderr
    assert all(re.fullmatch(r"verify: (small pads|large pads|conductors): (reading \S+|"
                            r"(coverage|differences), tile \d+ of \d+) \(\d+ s\)", line)
               for line in lines), proc.stderr
    quiet = subprocess.run([sys.executable, "-m", "harness", "verify", str(deck), str(spread)],
                           cwd=ROOT, capture_output=True, text=True, timeout=300,
                           env=dict(os.environ, VERIFY_PROGRESS_AFTER="1000"))
    assert quiet.stdout == proc.stdout and quiet.stderr == ""
