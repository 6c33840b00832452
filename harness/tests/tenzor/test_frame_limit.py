"""The P card's frame limit (columns 3-10, FMAX): long straight moves are split
as seed 004 (NC tape codes) shows for a 10000-pulse multiplier: DX = 98132,
DY = 87647 pulses in 10 frames, every intermediate point within one pulse of
the line. The table below is the document's own, typed from it by hand."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from harness import sim, tape

ROOT = Path(__file__).resolve().parents[3]

# seed 004: "1-й кадр 9813 8765 ... 10-й кадр 9813 8765"
SEED004_TABLE = [(9813, 8765), (9813, 8764), (9814, 8765), (9813, 8765), (9813, 8764),
                 (9813, 8765), (9813, 8765), (9814, 8765), (9813, 8764), (9813, 8765)]


def test_the_documents_table(run_tenzor):
    proc, out = run_tenzor(ROOT / "examples" / "seed004-split.crd")
    assert proc.returncode == 0, proc.stderr.decode()
    frames = tape.decode((out / "SPLIT-cond.ptp").read_bytes()).frames
    drawn = [(f.dx, f.dy) for f in frames if f.k == 10]
    assert drawn == SEED004_TABLE
    back = [(f.dx, f.dy) for f in frames if f.k == 20]
    assert sum(x for x, _ in back) == -98132 and sum(y for _, y in back) == -87647
    assert all(max(abs(x), abs(y)) <= 9999 for x, y in drawn + back)


@pytest.mark.parametrize("dx,dy,fmax,x0,y0", [(98132, 87647, 9999, 1000, 1000),
                                              (-12345, 678, 1000, 60000, 60000),
                                              (100, -99999, 7, 60000, 110000),
                                              (5, 5, 1, 1000, 1000)])
def test_split_points_stay_within_a_pulse_of_the_line(run_tenzor, dx, dy, fmax, x0, y0):
    def f10(v: int) -> str:
        return f"{v / 100:.2f}".rjust(10)
    deck = ("LIMIT\n" + f"P {fmax:8d}" + f10(x0) + f10(y0) + "\n"
            + "L" + " " * 9 + f10(0) + f10(0) + "\n+" + " " * 9 + f10(dx) + f10(dy) + "\nE\n")
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0, proc.stderr.decode()
    frames = tape.decode((out / "LIMIT-cond.ptp").read_bytes()).frames
    x = y = 0
    length = math.hypot(dx, dy)
    for f in sim.unroll(frames):
        if f.k != 10:
            continue
        assert max(abs(f.dx), abs(f.dy)) <= fmax
        x, y = x + f.dx, y + f.dy
        # distance of the frame's end from the line through (0,0) and (dx,dy)
        assert abs(x * dy - y * dx) / length <= 1.0
    assert (x, y) == (dx, dy)


def test_an_m_frame_beyond_the_limit_is_an_error(run_tenzor):
    deck = "LIMIT\nP     1000     10.00     10.00\n" + "M" + " " * 29 + "     20.00" + " " * 15 + "   10\nE\n"
    proc, out = run_tenzor(deck)
    assert proc.returncode == 1
    assert "LONGER THAN THE FRAME LIMIT FMAX" in proc.stderr.decode()


@pytest.mark.parametrize("fmax, m, column", [
    (1000, "M" + " " * 29 + "     20.00" + " " * 15 + "   10", 31),     # DX 20 mm
    (1000, "M" + " " * 39 + "     20.00" + " " * 5 + "   10", 41),      # DY 20 mm
    (100, "M" + " " * 9 + "     20.00" + " " * 35 + "   13", 11),      # a circle, X 20 mm
])
def test_an_m_frame_beyond_the_limit_names_its_field(run_tenzor, fmax, m, column):
    """The column of the first of X, Y, DX, DY beyond FMAX, and the limit."""
    proc, _ = run_tenzor(f"LIMIT\nP{fmax:>9}     10.00     10.00\n{m}\nE\n")
    assert proc.returncode == 1
    assert (f"CARD 3 COL {column}: THE FRAME IS LONGER THAN THE FRAME LIMIT FMAX OF THE P "
            f"CARD ({fmax} PULSES); SPLIT IT INTO M CARDS OF AT MOST {fmax} PULSES"
            in proc.stderr.decode()), proc.stderr.decode()


def test_the_arcs_of_a_pad_beyond_the_limit_are_one_error_that_gives_the_limit(run_tenzor):
    """A 1.6 mm pad drawn with a 0.5 mm tool moves 55 pulses on its arcs:
    one error for its card (not one an arc), giving the FMAX that would do;
    with that FMAX the tapes are punched."""
    pad = "D               5.00      5.00    1.60"
    proc, _ = run_tenzor(f"T\nP       54\n{pad}\nE\n")
    err = proc.stderr.decode()
    assert proc.returncode == 1 and err.count("TENZOR ERROR") == 1, err
    assert ("CARD 3 COL 11: AN ARC OF THIS CARD MOVES 55 PULSES, MORE THAN THE FRAME LIMIT "
            "FMAX OF THE P CARD (54); ARCS ARE NOT SPLIT: FMAX MUST BE 55 OR MORE") in err
    proc, out = run_tenzor(f"T\nP       55\n{pad}\nE\n")
    assert proc.returncode == 0, proc.stderr.decode()
