"""Valid TENZOR cards, built column by column, and random boards.

Lengths are given as ``int`` (units of 0.01 mm) or ``Decimal`` (mm, at
most two decimals); ``None`` leaves a field blank (its default).  Real
fields are always written WITH a decimal point, right-justified, so they
read the same under every Fortran blank mode.  Layout: SPEC section 5.3.

:func:`st_package` is a hypothesis strategy for small random boards that
TENZOR must accept (see its doc for the rules that keep them valid).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from decimal import Decimal
from typing import Union

from hypothesis import strategies as st

Length = Union[int, Decimal]


# ---------------------------------------------------------------------------
# Fields and cards.
# ---------------------------------------------------------------------------
def units(v: Length) -> int:
    """A length as an integer number of 0.01 mm."""
    if isinstance(v, bool):
        raise TypeError("a length cannot be a bool")
    if isinstance(v, int):
        return v
    if isinstance(v, Decimal):
        u = v * 100
        if u != u.to_integral_value():
            raise ValueError(f"{v} mm is not a whole number of 0.01 mm")
        return int(u)
    raise TypeError(f"a length is an int (0.01 mm) or a Decimal (mm), not {type(v).__name__}")


def real_field(v: Length | None, width: int) -> str:
    """Fw.2 field: e.g. 1250 -> '     12.50' for width 10; None -> blanks."""
    if v is None:
        return " " * width
    u = units(v)
    text = f"{'-' if u < 0 else ''}{abs(u) // 100}.{abs(u) % 100:02d}"
    if len(text) > width:
        raise ValueError(f"{text} does not fit in {width} columns")
    return text.rjust(width)


def int_field(v: int | None, width: int) -> str:
    """Iw field, right-justified; None -> blanks."""
    if v is None:
        return " " * width
    text = str(int(v))
    if len(text) > width:
        raise ValueError(f"{text} does not fit in {width} columns")
    return text.rjust(width)


def _card(*parts: tuple[int, str]) -> str:
    """A card from (first column, text) parts; trailing blanks removed."""
    cols = [" "] * 72
    for col, text in parts:
        for n, ch in enumerate(text):
            if cols[col - 1 + n] != " " and ch != " ":
                raise ValueError(f"column {col + n} written twice")
            cols[col - 1 + n] = ch
    return "".join(cols).rstrip()


def name_card(name: str) -> str:
    """Package name in columns 1-18."""
    if not name.strip() or len(name) > 18 or name[0] in "*# ":
        raise ValueError(f"bad package name {name!r}")
    return _card((1, name))


def p_card(x0: Length | None = None, y0: Length | None = None,
           w1: Length | None = None, w2: Length | None = None, w3: Length | None = None,
           dmax: Length | None = None, scale: tuple[int, int] | None = None,
           code: str | None = None, order: str | None = None) -> str:
    """P card: start point, tools, Dmax, scale, code (8/K), order (O/D)."""
    if code not in (None, "8", "K") or order not in (None, "O", "D"):
        raise ValueError(f"code {code!r} / order {order!r}")
    n, d = scale if scale is not None else (None, None)
    return _card((1, "P"), (11, real_field(x0, 10)), (21, real_field(y0, 10)),
                 (31, real_field(w1, 8)), (39, real_field(w2, 8)),
                 (47, real_field(w3, 8)), (55, real_field(dmax, 8)),
                 (63, int_field(n, 3)), (66, int_field(d, 3)),
                 (70, code or " "), (71, order or " "))


def d_card(x: Length, y: Length, w: Length, h: Length | None = None, n: int | None = None,
           sx: Length | None = None, sy: Length | None = None) -> str:
    """D card: a pad (round if h is None), or a row of n pads at steps sx, sy."""
    return _card((1, "D"), (11, real_field(x, 10)), (21, real_field(y, 10)),
                 (31, real_field(w, 8)), (39, real_field(h, 8)), (47, int_field(n, 4)),
                 (51, real_field(sx, 10)), (61, real_field(sy, 10)))


def l_card(x: Length, y: Length, w: Length | None = None) -> str:
    """L card: first vertex of a conductor of width w (None = w3)."""
    return _card((1, "L"), (11, real_field(x, 10)), (21, real_field(y, 10)),
                 (31, real_field(w, 8)))


def plus_card(x: Length, y: Length) -> str:
    """+ card: next vertex of the open conductor."""
    return _card((1, "+"), (11, real_field(x, 10)), (21, real_field(y, 10)))


def o_card(direction: str, x: Length, y: Length, r: Length) -> str:
    """O card: a circle; direction '+' (clockwise) or '-'."""
    if direction not in ("+", "-"):
        raise ValueError(f"direction {direction!r}")
    return _card((1, "O"), (2, direction), (11, real_field(x, 10)),
                 (21, real_field(y, 10)), (31, real_field(r, 10)))


def a_card(direction: str, xc: Length, yc: Length, xs: Length, ys: Length,
           xe: Length, ye: Length) -> str:
    """A card: an arc about (xc, yc) from (xs, ys) to (xe, ye)."""
    if direction not in ("+", "-"):
        raise ValueError(f"direction {direction!r}")
    return _card((1, "A"), (2, direction),
                 *[(c, real_field(v, 10)) for c, v in
                   zip((11, 21, 31, 41, 51, 61), (xc, yc, xs, ys, xe, ye))])


def m_card(tape: str = "L", x: Length | None = None, y: Length | None = None,
           dx: Length | None = None, dy: Length | None = None,
           cyc: int | None = None, k: int = 10) -> str:
    """M card: one frame for tape 'S', 'B' or 'L' (or ' ', meaning L)."""
    if tape not in ("S", "B", "L", " "):
        raise ValueError(f"tape {tape!r}")
    return _card((1, "M"), (2, tape), (11, real_field(x, 10)), (21, real_field(y, 10)),
                 (31, real_field(dx, 10)), (41, real_field(dy, 10)),
                 (51, int_field(cyc, 5)), (56, int_field(k, 5)))


@dataclass
class CardPackage:
    """A package to punch: its name and its data cards (no C/E card)."""

    name: str
    cards: list[str] = field(default_factory=list)


def deck(packages: list[CardPackage], envelope: bool = True, job: str = "HARNESS") -> str:
    """A whole deck: optional job envelope, the packages separated by C
    cards, the final E, and *END FILE; one card per line."""
    lines: list[str] = []
    if envelope:
        lines += [f"*NAME {job}", "*MAIN TENZOR", "*EXECUTE"]
    for n, pkg in enumerate(packages):
        lines.append(name_card(pkg.name))
        lines += pkg.cards
        lines.append("E" if n == len(packages) - 1 else "C")
    if envelope:
        lines.append("*END FILE")
    for no, line in enumerate(lines, 1):
        if len(line) > 72:
            raise ValueError(f"card {no} is longer than 72 columns")
    return "\n".join(lines) + "\n"


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
