"""Hypothesis strategies of the test suites: random frame lists (tapes for the
decoders, simulators and translators) and random small boards (decks that
TENZOR must accept), written with the oracle's own tape and card writers."""

from __future__ import annotations

import math

from hypothesis import assume
from hypothesis import strategies as st

from harness.cards import (CardPackage, a_card, d_card, l_card, m_card, o_card, p_card,
                           plus_card)
from harness.tape import Frame, on_circle


# ---------------------------------------------------------------------------
# Random frame lists: lines, travel, dots, circles, arcs whose ends lie on
# their circle (checked with the harness's own rule), cycles of small counts,
# so that a tape stays within a few hundred mm and a few hundred frames.
# ---------------------------------------------------------------------------
steps = st.integers(-6000, 6000)


@st.composite
def circle_start(draw: st.DrawFn) -> tuple[int, int]:
    x = draw(st.integers(-3000, 3000))
    y = draw(st.integers(-3000, 3000))
    assume(x or y)
    return x, y


@st.composite
def arc_frame(draw: st.DrawFn) -> Frame:
    x, y = draw(circle_start())
    k = draw(st.sampled_from([11, 13]))
    r, a0 = math.hypot(x, y), math.atan2(y, x)
    theta = draw(st.floats(0.05, 2 * math.pi - 0.05))
    ex, ey = round(r * math.cos(a0 + theta)), round(r * math.sin(a0 + theta))
    assume((ex, ey) != (x, y) and on_circle(x, y, ex - x, ey - y))
    return Frame(x=x, y=y, dx=ex - x, dy=ey - y, k=k)


def single_frame() -> st.SearchStrategy[Frame]:
    lines = st.builds(Frame, dx=steps, dy=steps, k=st.sampled_from([10, 20]))
    circles = st.builds(lambda xy, k: Frame(x=xy[0], y=xy[1], k=k),
                        circle_start(), st.sampled_from([11, 13]))
    dots = st.just(Frame(k=10))
    return st.one_of(lines, lines, circles, arc_frame(), dots)


@st.composite
def frame_lists(draw: st.DrawFn, max_items: int = 8) -> list[Frame]:
    frames: list[Frame] = []
    for _ in range(draw(st.integers(1, max_items))):
        first = draw(single_frame())
        if draw(st.integers(0, 3)) == 0:                   # a cycle pair
            frames += [Frame(first.x, first.y, first.dx, first.dy,
                             draw(st.integers(2, 12)), first.k), draw(single_frame())]
        else:
            frames.append(first)
    return frames


# ---------------------------------------------------------------------------
# Random boards.
# ---------------------------------------------------------------------------
#: Everything lies within this many units (150 mm) of the start point.
REACH = 15000
#: Pythagorean triples (a, b, c): points (a, b)*k lie exactly on radius c*k.
TRIPLES: tuple[tuple[int, int, int], ...] = ((3, 4, 5), (5, 12, 13), (8, 15, 17),
                                             (7, 24, 25), (20, 21, 29), (0, 1, 1))


def _circle_points(a: int, b: int, c: int, k: int) -> list[tuple[int, int]]:
    """Lattice points of a triple on the circle of radius c*k (and the axis
    points), without duplicates, in a fixed order."""
    pts: list[tuple[int, int]] = []
    for p, q in ((a, b), (b, a), (c, 0), (0, c)):
        for sp in (1, -1):
            for sq in (1, -1):
                pt = (sp * p * k, sq * q * k)
                if pt not in pts:
                    pts.append(pt)
    return pts


@st.composite
def _pad(draw: st.DrawFn, w1: int, w2: int, dmax: int) -> list[str]:
    """A D card whose pads are at least as big as their tape's tool."""
    lo = max(w1, w2)
    rect = draw(st.booleans())
    dots = [t for t, ok in ((w1, w1 <= dmax), (w2, w2 > dmax)) if ok]
    if not rect and dots and draw(st.integers(0, 4)) == 0:
        w, h = draw(st.sampled_from(dots)), None        # a pad equal to its tool
    else:
        w = draw(st.integers(lo, 800))
        h = draw(st.integers(lo, 800)) if rect else None
    hh = w if h is None else h
    n = draw(st.sampled_from([1, 1, 1, 2, 3, 6]))
    sx = sy = 0
    if n > 1:
        ax, ay = draw(st.sampled_from([(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1)]))
        sx = ax * (w + draw(st.integers(10, 500)))
        sy = ay * (hh + draw(st.integers(10, 500)))
    ex, ey = (w + 1) // 2, (hh + 1) // 2
    x = draw(st.integers(-REACH + ex - min(0, (n - 1) * sx), REACH - ex - max(0, (n - 1) * sx)))
    y = draw(st.integers(-REACH + ey - min(0, (n - 1) * sy), REACH - ey - max(0, (n - 1) * sy)))
    return [d_card(x, y, w, h, n if n > 1 or draw(st.booleans()) else None,
                   sx or None, sy or None)]


@st.composite
def _conductor(draw: st.DrawFn, w3: int) -> list[str]:
    """L and + cards: 2-6 vertices, segments >= max(1 mm, width)."""
    w = draw(st.one_of(st.none(), st.integers(w3, 300)))
    width = w3 if w is None else w
    seg = max(100, width)
    box = REACH - (width + 1) // 2
    x, y = draw(st.integers(-box, box)), draw(st.integers(-box, box))
    cards = [l_card(x, y, w)]
    for _ in range(draw(st.integers(1, 5))):
        dx, dy = draw(st.integers(-3000, 3000)), draw(st.integers(-3000, 3000))
        length = math.hypot(dx, dy)
        if length < seg:
            if length == 0:
                dx, dy = seg, 0
            else:
                f = math.ceil(seg / length)
                dx, dy = dx * f, dy * f
        if not -box <= x + dx <= box:
            dx = -dx
        if not -box <= y + dy <= box:
            dy = -dy
        x, y = x + dx, y + dy
        cards.append(plus_card(x, y))
    return cards


@st.composite
def _circle(draw: st.DrawFn, w3: int) -> list[str]:
    r = draw(st.integers(50, 1000))
    box = REACH - r - w3
    return [o_card(draw(st.sampled_from("+-")), draw(st.integers(-box, box)),
                   draw(st.integers(-box, box)), r)]


@st.composite
def _arc(draw: st.DrawFn, w3: int) -> list[str]:
    a, b, c = draw(st.sampled_from(TRIPLES))
    k = draw(st.integers(math.ceil(100 / c), 2000 // c))
    pts = _circle_points(a, b, c, k)
    i = draw(st.integers(0, len(pts) - 1))
    j = draw(st.integers(0, len(pts) - 2))
    j += j >= i
    box = REACH - c * k - w3
    xc, yc = draw(st.integers(-box, box)), draw(st.integers(-box, box))
    (sx, sy), (ex, ey) = pts[i], pts[j]
    return [a_card(draw(st.sampled_from("+-")), xc, yc, xc + sx, yc + sy, xc + ex, yc + ey)]


@st.composite
def _manual(draw: st.DrawFn) -> list[str]:
    """An M card: a line, a dot, a travel or a full circle (small)."""
    tape = draw(st.sampled_from(["S", "B", "L", " "]))
    kind = draw(st.sampled_from(["line", "dot", "travel", "circle"]))
    step = st.integers(-2000, 2000).filter(bool)
    if kind == "line":
        return [m_card(tape, dx=draw(step), dy=draw(step), k=10)]
    if kind == "dot":
        return [m_card(tape, k=10)]
    if kind == "travel":
        return [m_card(tape, dx=draw(step), dy=draw(step), k=20)]
    return [m_card(tape, x=draw(st.integers(50, 1000)) * draw(st.sampled_from([1, -1])),
                   k=draw(st.sampled_from([11, 13])))]


@st.composite
def st_package(draw: st.DrawFn, name: str | None = None) -> CardPackage:
    """A random small board TENZOR must accept.

    P card: scale 1:1 (mostly), 1:2 or 2:1, start point placed so the whole
    board (within :data:`REACH` of it) stays 10 mm inside the 1200 mm field
    at that scale; tools 0.20..1.50 mm; Dmax default or 1..5 mm; code and
    order random.  0-8 pads (round or rectangular, at least max(w1, w2) and
    at most 8 mm, or exactly their tool; rows of 2..6 with gaps of 0.1..5 mm
    between pads), 0-4 conductors (2-6 vertices, width w3..3 mm, segments at
    least 1 mm and at least the width), 0-3 circles (R 0.5..10 mm), 0-3
    arcs (end points exactly on the circle by Pythagorean triples), 0-2 M
    cards.  Cards in random order (P first), now and then a blank card.
    """
    if name is None:
        name = draw(st.from_regex(r"[A-Z][A-Z0-9]{0,7}", fullmatch=True))
    num, den = draw(st.sampled_from([(1, 1), (1, 1), (1, 1), (1, 2), (2, 1)]))
    lo = math.ceil(REACH * num / den) + 1000
    x0, y0 = draw(st.integers(lo, 120000 - lo)), draw(st.integers(lo, 120000 - lo))
    tool = st.integers(20, 150)
    w1, w2, w3 = draw(tool), draw(tool), draw(tool)
    dmax = draw(st.one_of(st.none(), st.integers(100, 500)))
    code = draw(st.sampled_from([None, "8", "K"]))
    order = draw(st.sampled_from([None, "O", "D"]))
    scale = None if (num, den) == (1, 1) and draw(st.booleans()) else (num, den)
    groups: list[list[str]] = []
    groups += [draw(_pad(w1, w2, 200 if dmax is None else dmax))
               for _ in range(draw(st.integers(0, 8)))]
    groups += [draw(_conductor(w3)) for _ in range(draw(st.integers(0, 4)))]
    groups += [draw(_circle(w3)) for _ in range(draw(st.integers(0, 3)))]
    groups += [draw(_arc(w3)) for _ in range(draw(st.integers(0, 3)))]
    groups += [draw(_manual()) for _ in range(draw(st.sampled_from([0, 0, 0, 1, 2])))]
    groups = draw(st.permutations(groups))
    if groups and draw(st.integers(0, 5)) == 0:
        groups.insert(draw(st.integers(0, len(groups))), [""])
    cards = [p_card(x0, y0, w1, w2, w3, dmax, scale, code, order)]
    for g in groups:
        cards += g
    return CardPackage(name, cards)
