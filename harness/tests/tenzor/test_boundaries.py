"""Every rule of the drawing at its boundary: the value where the rule just
holds and the value where it just does not, so that a change of `.LT.` to
`.LE.` or of a count by one anywhere in legacy/ changes a test's verdict.

Found by a mutation run (each mutant a small realistic change to legacy/):
these are the boundaries no other test reached. The rules are docs/FILLING.md's
and docs/CARDS.md's:

* a pair of frames repeated N >= 2 times in a row is one cycle (CYC N): two
  is the least, so a saw of two teeth folds and a saw of one does not;
* the circles of a round pad step inwards by at most T - OVL (OVL = T/4, at
  least 0.01 mm and at most 0.10 mm), with the fewest circles that allows;
* a conductor whose width exceeds its tool by less than 0.02 mm (R1 < 1 unit)
  is one pass on its centre line; from 0.02 mm on it is drawn in loops;
* a straight move longer than FMAX is cut into ceil(max(|DX|,|DY|) / FMAX)
  frames: exactly k FMAX is k frames, one pulse more is k + 1.
"""
from __future__ import annotations

import math

import pytest

from harness import cards, sim, tape


def _tape(run_tenzor, body: list[str], layer: str, name: str = "EDGE") -> list[tape.Frame]:
    deck = cards.deck([cards.CardPackage(name, body)], envelope=False)
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0, proc.stderr.decode()
    return list(tape.decode((out / f"{name}-{layer}.ptp").read_bytes()).frames)


# ---------------------------------------------------------------------------
# Cycles: the least repeat that folds.
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("teeth", [1, 2, 3])
def test_a_saw_folds_from_two_teeth_on(run_tenzor, teeth):
    body = [cards.p_card(1000, 1000, order="D"), cards.l_card(0, 0)]
    for t in range(teeth):
        body += [cards.plus_card(400 * t + 300, 400), cards.plus_card(400 * t + 400, 0)]
    frames = _tape(run_tenzor, body, "cond")
    drawn = [f for f in frames if f.k == 10]
    if teeth == 1:
        assert [(f.dx, f.dy, f.cyc) for f in drawn] == [(300, 400, 0), (100, -400, 0)]
    else:
        assert [(f.dx, f.dy, f.cyc) for f in drawn] == [(300, 400, teeth), (100, -400, 0)]


# ---------------------------------------------------------------------------
# Round pads: the circles' step and their number.
# ---------------------------------------------------------------------------
def _ovl(t: int) -> int:
    return max(1, min(10, t // 4))


def _rings(frames: list[tape.Frame]) -> list[int]:
    """The radii of the circles (K13 frames: X is the radius), in order, and a
    0 for the dot that may end them (a K10 frame that does not move)."""
    return [f.x if f.k == 13 else 0 for f in frames
            if f.k == 13 or (f.k == 10 and f.dx == 0 and f.dy == 0)]


# A pad of diameter over 200 goes to the large pads' tape, by the same rule.
@pytest.mark.parametrize("tool", [20, 40, 50, 100])
@pytest.mark.parametrize("extra", range(0, 130, 7))
def test_round_pad_circles_step_by_at_most_t_minus_ovl_and_are_fewest(run_tenzor, tool, extra):
    d = tool + 2 + extra
    frames = _tape(run_tenzor, [cards.p_card(1000, 1000, w1=tool, w2=tool, order="D"),
                                cards.d_card(500, 500, d)], "small" if d <= 200 else "large")
    rings = _rings(frames)
    r1 = (d - tool) // 2
    smax = max(1, tool - _ovl(tool))
    if r1 == 0:
        assert rings == [0], "a pad as big as its tool is a dot"
        return
    assert rings[0] == r1, "the first circle runs the tool's edge along the rim"
    steps = [a - b for a, b in zip(rings, rings[1:])]
    assert all(0 < s <= smax for s in steps), (rings, smax)
    assert 2 * rings[-1] <= tool, "the last circle (or the dot) covers the centre"
    # the fewest: with one circle fewer some step would exceed T - OVL
    n = len(rings)
    if n > 1:
        assert 2 * r1 - tool > 2 * smax * (n - 2), (rings, smax)


@pytest.mark.parametrize("tool", [4, 39, 40, 41, 43, 44, 48, 50, 100, 400])
@pytest.mark.parametrize("span", [0, 1])
def test_round_pad_overlap_is_a_quarter_of_the_tool_within_its_limits(run_tenzor, tool, span):
    """Where the last circle is exactly T - OVL (span 0) or one unit more
    (span 1) inside the first, for tools on both sides of OVL's limits (0.01
    mm below 0.08 mm tools, T/4 between, 0.10 mm from 0.40 mm on): one step
    suffices exactly when the span is at most T - OVL."""
    smax = max(1, tool - _ovl(tool))
    r1 = tool // 2 + smax + span
    d = tool + 2 * r1
    frames = _tape(run_tenzor, [cards.p_card(1000, 1000, w1=tool, dmax=d, order="D"),
                                cards.d_card(5000, 5000, d)], "small")
    rings = _rings(frames)
    assert rings[0] == r1
    steps = [a - b for a, b in zip(rings, rings[1:])]
    assert all(0 < s <= smax for s in steps), (rings, smax)
    assert 2 * rings[-1] <= tool
    assert len(steps) == (1 if span == 0 else 2), (rings, smax)


# ---------------------------------------------------------------------------
# Conductors: one pass or loops.
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("over,passes", [(0, "one"), (1, "one"), (2, "loops"), (3, "loops")])
def test_a_conductor_wider_than_its_tool_by_two_hundredths_is_drawn_in_loops(
        run_tenzor, over, passes):
    tool = 50
    body = [cards.p_card(1000, 1000, w3=tool, order="D"),
            cards.l_card(0, 0, tool + over), cards.plus_card(1000, 0)]
    drawn = [f for f in _tape(run_tenzor, body, "cond") if f.k in (10, 11, 12)]
    if passes == "one":
        assert [(f.dx, f.dy) for f in drawn] == [(1000, 0)]
    else:
        assert len(drawn) > 1
        ys = set()
        x = y = 0
        for f in sim.unroll(_tape(run_tenzor, body, "cond", "EDGE2")):
            x, y = x + f.dx, y + f.dy
            if f.k == 10:
                ys.add(y)
        assert len(ys) >= 2, "loops run on both sides of the centre line"


@pytest.mark.parametrize("tool", [20, 50, 100])
@pytest.mark.parametrize("extra", [2, 3, 9, 40, 41, 80, 81, 150, 237, 300])
def test_conductor_loops_step_by_at_most_t_minus_ovl_and_are_fewest(run_tenzor, tool, extra):
    """A straight conductor of width W: loops at offsets R1 = (W - T)/2 inwards
    by at most T - OVL, the last within T/2 - 0.01 mm of the centre line (or
    a pass on it), the fewest loops that allow it. On a horizontal conductor
    each loop's end arcs (K11 or K13) have the loop's offset as their Y."""
    w = tool + extra
    body = [cards.p_card(1000, 1000, w3=tool, order="D"),
            cards.l_card(0, 0, w), cards.plus_card(2000, 0)]
    frames = _tape(run_tenzor, body, "cond")
    offsets = sorted({abs(f.y) for f in frames if f.k in (11, 13)}, reverse=True)
    # each loop has two straight runs the conductor's length; one more is a
    # pass on the centre line
    runs = [f for f in frames if f.k == 10 and f.dy == 0 and abs(f.dx) == 2000]
    rings = offsets + ([0] if len(runs) > 2 * len(offsets) else [])
    r1 = (w - tool) / 2
    smax = max(1, tool - _ovl(tool))
    assert abs(rings[0] - r1) <= 0.5, (rings, r1)
    steps = [a - b for a, b in zip(rings, rings[1:])]
    assert all(0 < s <= smax for s in steps), (rings, smax)
    assert rings[-1] <= (tool - 2) / 2 + 0.5, "the last loop covers the centre line"
    n = len(rings)
    if n > 1:
        assert 2 * r1 - (tool - 2) > 2 * smax * (n - 2), (rings, smax)


# ---------------------------------------------------------------------------
# The frame limit: exactly k FMAX is k frames.
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("length,frames", [(2999, 3), (3000, 3), (3001, 4), (1000, 1),
                                           (1001, 2)])
def test_a_move_of_exactly_k_fmax_is_k_frames(run_tenzor, length, frames):
    fmax = 1000

    def f10(v: int) -> str:
        return f"{v / 100:.2f}".rjust(10)
    deck = ("LIMIT\n" + f"P {fmax:8d}" + f10(10000) + f10(10000) + "\n"
            + "L" + " " * 9 + f10(0) + f10(0) + "\n+" + " " * 9 + f10(length) + f10(0)
            + "\nE\n")
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0, proc.stderr.decode()
    got = tape.decode((out / "LIMIT-cond.ptp").read_bytes()).frames
    drawn = [f for f in sim.unroll(list(got)) if f.k == 10]
    assert len(drawn) == frames, drawn
    assert sum(f.dx for f in drawn) == length
    assert max(f.dx for f in drawn) - min(f.dx for f in drawn) <= 1
    assert math.ceil(length / fmax) == frames


# ---------------------------------------------------------------------------
# The reach of a row of pads: its last pad at most 120000 mm out.
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("axis", ["x", "y"])
@pytest.mark.parametrize("past", [0, 1])
def test_the_last_pad_of_a_row_may_reach_exactly_120000_mm(run_tenzor, axis, past):
    """A row whose last pad lies exactly 120000 mm from the start point is
    within TENZOR's reach (it is still off the field: another error); one
    hundredth further is refused at the step's column."""
    step = 12_000_000 + past
    sx, sy = (step, 0) if axis == "x" else (0, step)
    deck = cards.deck([cards.CardPackage("REACH", [cards.d_card(0, 0, 100, n=2, sx=sx, sy=sy)])],
                      envelope=False)
    proc, _ = run_tenzor(deck)
    err = proc.stderr.decode()
    assert proc.returncode == 1
    col = 51 if axis == "x" else 61
    said = f"CARD 2 COL {col}: THE LAST PAD OF THE ROW IS MORE THAN 120000.00 MM" in err
    assert said == bool(past), err


# ---------------------------------------------------------------------------
# The P card's ranges: each limit is a value the card takes.
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("field,col,limit,fragment", [
    ("x0", 11, 120_000, "X0 IS OFF THE 1200 X 1200 MM FIELD; EXPECTED 0 TO 1200.00"),
    ("y0", 21, 120_000, "Y0 IS OFF THE 1200 X 1200 MM FIELD; EXPECTED 0 TO 1200.00"),
    ("w1", 31, 2_000, "TOOL W1 OUT OF RANGE; A TOOL IS 0.01 TO 20.00 MM WIDE"),
    ("w2", 39, 2_000, "TOOL W2 OUT OF RANGE; A TOOL IS 0.01 TO 20.00 MM WIDE"),
    ("w3", 47, 2_000, "TOOL W3 OUT OF RANGE; A TOOL IS 0.01 TO 20.00 MM WIDE"),
    ("dmax", 55, 120_000, "DMAX OUT OF RANGE; THE SMALL-PAD LIMIT IS 0.01 TO 1200.00 MM"),
])
@pytest.mark.parametrize("past", [0, 1])
def test_the_p_cards_fields_may_reach_their_limits(run_tenzor, field, col, limit, fragment, past):
    """A start point on the field's edge (1200.00 mm), a tool of 20.00 mm and
    a DMAX of 1200.00 mm are taken; one hundredth more is refused at the
    field's first column (docs/CARDS.md, "P")."""
    # the one frame goes back from the start point when it stands on the edge
    back = -100 if field in ("x0", "y0") else 100
    frame = cards.m_card(dx=back if field != "y0" else None, dy=back if field == "y0" else None)
    body = [cards.p_card(**{field: limit + past}), frame]
    deck = cards.deck([cards.CardPackage("LIMIT", body)], envelope=False)
    proc, out = run_tenzor(deck)
    err = proc.stderr.decode()
    if past:
        assert proc.returncode == 1
        assert f"TENZOR ERROR CARD 2 COL {col}: {fragment}" in err, err
        assert not list(out.glob("*.ptp"))
    else:
        assert proc.returncode == 0, err
        assert err == ""
        assert (out / "LIMIT-cond.ptp").exists()


MACHINE_SCALES = [(1, 100), (1, 10), (1, 5), (1, 2), (1, 1), (2, 1), (5, 1), (50, 1), (100, 1)]


@pytest.mark.parametrize("scale", MACHINE_SCALES + [(20, 1), (10, 1), (1, 50), (1, 20), (3, 1),
                                                    (100, 100), (2, 2)])
def test_the_scale_is_one_of_the_machines_nine(run_tenzor, scale):
    """The scale is one of 1:100, 1:10, 1:5, 1:2, 1:1, 2:1, 5:1, 50:1, 100:1
    (docs/CARDS.md, "P"), written as the machine's: 2:2 is not 1:1."""
    body = [cards.p_card(scale=scale), cards.m_card(dx=100)]
    deck = cards.deck([cards.CardPackage("SCALE", body)], envelope=False)
    proc, _ = run_tenzor(deck)
    err = proc.stderr.decode()
    if scale in MACHINE_SCALES:
        assert proc.returncode == 0, err
    else:
        assert proc.returncode == 1
        assert "TENZOR ERROR CARD 2 COL 63: SCALE IS NOT ONE OF THE MACHINE'S: 1:100 1:10 1:5 " \
               "1:2 1:1 2:1 5:1 50:1 100:1" in err, err


# ---------------------------------------------------------------------------
# Pads: a side as wide as its tool is drawn; a row's N has four digits.
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("w,h,col", [(200, 50, 0), (200, 49, 39), (50, 200, 0), (49, 200, 31)])
def test_a_rectangular_pad_may_be_as_narrow_as_its_tool(run_tenzor, w, h, col):
    """A 2.00 x 0.50 mm pad drawn with a 0.50 mm tool is one stroke; 0.49 mm
    is smaller than the tool, an error at the side's column."""
    body = [cards.p_card(), cards.d_card(1000, 1000, w, h)]
    deck = cards.deck([cards.CardPackage("THIN", body)], envelope=False)
    proc, out = run_tenzor(deck)
    err = proc.stderr.decode()
    if col:
        assert proc.returncode == 1
        assert f"TENZOR ERROR CARD 3 COL {col}: PAD SIZE 0.49 MM IS SMALLER THAN TOOL W1 " \
               "0.50 MM OF THE SMALL-PAD TAPE" in err, err
    else:
        assert proc.returncode == 0, err
        frames = list(tape.decode((out / "THIN-small.ptp").read_bytes()).frames)
        drawn = [(f.dx, f.dy) for f in frames if f.k == 10]
        assert drawn == ([(150, 0)] if h == 50 else [(0, 150)]), frames


@pytest.mark.parametrize("n", [2, 3, 4, 1234])
def test_a_row_of_pads_is_one_cycle_from_three_pads_on(run_tenzor, n):
    """A row of N dots is the dot, then the step and the dot run N - 1 times:
    a cycle from N - 1 = 2 on (CYC 1 is not a cycle), so a row of three is
    three dots, not two. N is I4 in cols 47-50: all four digits count."""
    body = [cards.p_card(), cards.d_card(100, 100, 50, n=n, sx=50)]
    deck = cards.deck([cards.CardPackage("ROW", body)], envelope=False)
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0, proc.stderr.decode()
    frames = list(tape.decode((out / "ROW-small.ptp").read_bytes()).frames)
    dot = tape.Frame(0, 0, 0, 0, 0, 10)
    assert frames == [tape.Frame(0, 0, 100, 100, 0, 20), dot,
                      tape.Frame(0, 0, 50, 0, n - 1 if n >= 3 else 0, 20), dot,
                      tape.Frame(0, 0, -100 - 50 * (n - 1), -100, 0, 20)]


# ---------------------------------------------------------------------------
# Arcs: the largest radius of the machine is 10 m, itself included.
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("kind", ["O", "A", "M"])
@pytest.mark.parametrize("past", [0, 1])
def test_an_arc_of_exactly_ten_metres_is_drawn(run_tenzor, kind, past):
    """Radius 10000.00 mm is the machine's largest arc (drawn here at 1:100,
    100 mm about a start point in the middle of the field); 10000.01 mm is
    refused (docs/CARDS.md, "O", "M")."""
    r = 1_000_000 + past
    if kind == "O":
        card, col = cards.o_card("+", 0, 0, r), 31
    elif kind == "A":
        card, col = cards.a_card("+", 0, 0, 0, r, r, 0), 31
    else:
        card, col = cards.m_card(x=-r, dx=r, dy=r, k=13), 11
    body = [cards.p_card(60_000, 60_000, scale=(1, 100)), card]
    deck = cards.deck([cards.CardPackage("BIG", body)], envelope=False)
    proc, out = run_tenzor(deck)
    err = proc.stderr.decode()
    if past:
        assert proc.returncode == 1
        assert f"TENZOR ERROR CARD 3 COL {col}: RADIUS OVER 10 M, THE LARGEST ARC OF THE " \
               "MACHINE" in err, err
    else:
        assert proc.returncode == 0, err
        frames = list(tape.decode((out / "BIG-cond.ptp").read_bytes()).frames)
        assert [math.hypot(f.x, f.y) for f in frames if f.k in (11, 13)] == [r], frames
