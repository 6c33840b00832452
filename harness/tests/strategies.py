"""Hypothesis strategies of the test suites: random frame lists (tapes for the
decoders, simulators and translators), random small boards (decks that
TENZOR must accept), written with the oracle's own tape and card writers,
and hostile decks (for the fuzz suites and the comparison of builds)."""

from __future__ import annotations

import math

from hypothesis import assume
from hypothesis import strategies as st

from harness import cards
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
        # (a bare C or E is the end of a package, never a name: docs/CARDS.md)
        name = draw(st.from_regex(r"[A-Z][A-Z0-9]{0,7}", fullmatch=True)
                    .filter(lambda n: n not in ("C", "E")))
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


# ---------------------------------------------------------------------------
# Hostile decks.
# ---------------------------------------------------------------------------
GOOD_M = cards.m_card("L", dx=100, k=10)

#: Numbers at and past the limits, as field text (None: blank).
F10 = ["9999999.99", "-9999999.99", "      0.01", "     -0.01", "      0.00", "  120000.00",
       " -120000.00", "  119999.99", "   1200.00", "    600.00", "  10000.00", "  10000.01",
       "9999999999", "-999999999", " 999999999", "        .5", "         .", "         -",
       "     1.5E2", "    1 2.50", "1250      ", "   0.001  ", "+000000.01", "     -0.  "]
F8 = ["99999.99", "-9999.99", "    0.01", "    0.02", "   20.00", "   20.01", "    0.00",
      "99999999", "   -0.50", "    1.60", "  1200.0", "     .  "]
INT = ["999", "-99", "  0", "  1", "100", "9999", "99999", "-9999", " 1 ", "1.0", "  2",
       "1000000", "-0"]
#: (first column, width, pool) of each card type's fields.
FIELDS: dict[str, list[tuple[int, int, list[str]]]] = {
    "P": [(11, 10, F10), (21, 10, F10), (31, 8, F8), (39, 8, F8), (47, 8, F8), (55, 8, F8),
          (63, 3, INT), (66, 3, INT), (70, 1, list("8K9 ")), (71, 1, list("OD? "))],
    "D": [(11, 10, F10), (21, 10, F10), (31, 8, F8), (39, 8, F8), (47, 4, INT),
          (51, 10, F10), (61, 10, F10)],
    "L": [(11, 10, F10), (21, 10, F10), (31, 8, F8)],
    "+": [(11, 10, F10), (21, 10, F10)],
    "O": [(2, 1, list("+- ")), (11, 10, F10), (21, 10, F10), (31, 10, F10)],
    "A": [(2, 1, list("+- ")), (11, 10, F10), (21, 10, F10), (31, 10, F10), (41, 10, F10),
          (51, 10, F10), (61, 10, F10)],
    "M": [(2, 1, list("SBL Q")), (11, 10, F10), (21, 10, F10), (31, 10, F10), (41, 10, F10),
          (51, 5, INT), (56, 5, INT + ["   10", "   20", "   11", "   13"])],
}


@st.composite
def st_extreme_card(draw: st.DrawFn) -> str:
    """A card of a known type whose fields are blank, sane or extreme."""
    kind = draw(st.sampled_from(sorted(FIELDS)))
    cols = [" "] * 72
    cols[0] = kind
    for col, width, pool in FIELDS[kind]:
        if draw(st.integers(0, 3)) == 0:
            continue
        text = draw(st.sampled_from(pool))[-width:].rjust(width)
        cols[col - 1:col - 1 + width] = list(text)
    return "".join(cols).rstrip()


@st.composite
def st_extreme_deck(draw: st.DrawFn) -> bytes:
    """One or two packages of extreme cards, otherwise well formed."""
    pkgs = []
    for n in range(draw(st.integers(1, 2))):
        body = draw(st.lists(st_extreme_card(), min_size=1, max_size=8))
        if draw(st.booleans()):
            body.insert(0, draw(st_extreme_card().filter(lambda c: c[0] == "P")))
        pkgs.append(cards.CardPackage(f"X{n}", body))
    return cards.deck(pkgs, envelope=draw(st.booleans())).encode("ascii")


#: Lengths in units near the limits: the 120000 mm reach, the 10 m radius.
BIG = [11_999_999, 12_000_000, 12_000_001, 999_999, 1_000_000, 1_000_001, 120_000, 60_000,
       99_999_999]


@st.composite
def st_length(draw: st.DrawFn, lo: int = -99_999_999, hi: int = 99_999_999) -> int:
    v = draw(st.one_of(st.sampled_from(BIG + [0, 1, 2, 3]), st.integers(lo, hi)))
    if lo < 0 and draw(st.booleans()):
        v = -v
    return max(lo, min(hi, v))


@st.composite
def st_stress_deck(draw: st.DrawFn) -> bytes:
    """Well-formed cards whose values are huge, tiny or at a limit, at the
    machine's scales, so that they reach the generators (M703T, M703L),
    the tour and the field check, not only the card reader."""
    scale = draw(st.sampled_from([(1, 100), (1, 10), (1, 1), (100, 1), (1, 2)]))
    tool = st.integers(1, 2000)
    w1, w2, w3 = draw(tool), draw(tool), draw(tool)
    body = [cards.p_card(draw(st.integers(0, 120000)), draw(st.integers(0, 120000)), w1, w2, w3,
                         draw(st.integers(1, 120000)), scale,
                         draw(st.sampled_from(["8", "K"])), draw(st.sampled_from(["O", "D"])))]
    size = st.integers(1, 99_999)
    for _ in range(draw(st.integers(1, 6))):
        kind = draw(st.sampled_from("DDLOAM"))
        if kind == "D":
            body.append(cards.d_card(draw(st_length()), draw(st_length()), draw(size),
                                     draw(st.one_of(st.none(), size)),
                                     draw(st.sampled_from([None, 2, 9999, 500])),
                                     draw(st_length(-99_999_999, 99_999_999)),
                                     draw(st_length(-99_999_999, 99_999_999))))
        elif kind == "L":
            body.append(cards.l_card(draw(st_length()), draw(st_length()),
                                     draw(st.one_of(st.none(), size))))
            for _ in range(draw(st.integers(1, 4))):
                body.append(cards.plus_card(draw(st_length()), draw(st_length())))
        elif kind == "O":
            body.append(cards.o_card(draw(st.sampled_from("+-")), draw(st_length()),
                                     draw(st_length()), draw(st_length(1))))
        elif kind == "A":
            r = draw(st.sampled_from([1_000_000, 999_999, 600_000, 1]))
            body.append(cards.a_card(draw(st.sampled_from("+-")), 0, 0, r, 0,
                                     draw(st.sampled_from([0, -r, r])),
                                     draw(st.sampled_from([r, -r, 0]))))
        else:
            body.append(cards.m_card(draw(st.sampled_from("SBL")), draw(st_length()),
                                     draw(st_length()), draw(st_length()), draw(st_length()),
                                     draw(st.sampled_from([None, 2, 99999])),
                                     draw(st.sampled_from([10, 20, 11, 13]))))
    return cards.deck([cards.CardPackage("STRESS", body)], envelope=False).encode("ascii")


@st.composite
def st_valid_deck(draw: st.DrawFn) -> str:
    pkgs = draw(st.lists(st_package(), min_size=1, max_size=3))
    for n, p in enumerate(pkgs):
        p.name = f"{p.name[:8]}N{n}"
    return cards.deck(pkgs, envelope=draw(st.booleans()))


MUTATIONS = ("cut", "shift", "unshift", "shift-all", "delete", "duplicate", "swap", "field",
             "byte", "crlf", "cr-only", "long", "nul", "truncate-file", "drop-e")


@st.composite
def st_mutated_deck(draw: st.DrawFn) -> bytes:
    """A deck TENZOR accepts, broken by 1-4 mutations (see MUTATIONS)."""
    lines = draw(st_valid_deck()).split("\n")[:-1]
    raw: bytes | None = None
    for _ in range(draw(st.integers(1, 4))):
        what = draw(st.sampled_from(MUTATIONS))
        i = draw(st.integers(0, max(0, len(lines) - 1))) if lines else 0
        if not lines:
            lines = [""]
        if what == "cut":
            lines[i] = lines[i][:draw(st.integers(0, 80))]
        elif what == "shift":
            lines[i] = " " * draw(st.integers(1, 10)) + lines[i]
        elif what == "unshift":
            lines[i] = lines[i][draw(st.integers(1, 10)):]
        elif what == "shift-all":
            k = draw(st.integers(-2, 2))
            lines = [(" " * k + ln) if k > 0 else ln[-k:] for ln in lines]
        elif what == "delete":
            del lines[i]
        elif what == "duplicate":
            lines.insert(i, lines[i])
        elif what == "swap":
            j = draw(st.integers(0, len(lines) - 1))
            lines[i], lines[j] = lines[j], lines[i]
        elif what == "field":
            pool = draw(st.sampled_from([F10, F8, INT]))
            text = draw(st.sampled_from(pool))
            col = draw(st.integers(2, 72))
            ln = lines[i].ljust(col - 1 + len(text))
            lines[i] = ln[:col - 1] + text + ln[col - 1 + len(text):]
        elif what == "byte":
            col = draw(st.integers(0, 90))
            ch = chr(draw(st.integers(0, 255)))
            lines[i] = lines[i][:col] + ch + lines[i][col + 1:]
        elif what == "long":
            lines.insert(i, draw(st.sampled_from(["M", "D", " ", "*"])) * 100000)
        elif what == "nul":
            lines[i] = lines[i] + "\x00" * draw(st.integers(1, 3))
        elif what == "drop-e":
            lines = [ln for ln in lines if not ln.startswith("E")]
        elif what in ("crlf", "cr-only", "truncate-file"):
            pass
        raw = None
        if what == "crlf":
            raw = "\r\n".join(lines).encode("latin-1") + b"\r\n"
        elif what == "cr-only":
            raw = "\r".join(lines).encode("latin-1") + b"\r"
        elif what == "truncate-file":
            full = "\n".join(lines).encode("latin-1")
            raw = full[:draw(st.integers(0, len(full)))]
    if raw is None:
        raw = ("\n".join(lines) + "\n").encode("latin-1")
    return raw


@st.composite
def st_card_soup(draw: st.DrawFn) -> bytes:
    """Lines of characters TENZOR cares about, in no order."""
    alphabet = st.sampled_from(list(" 0123456789.-+PDLOAMCEK8*#_") + ["\r", "\t", "\x00"])
    lines = draw(st.lists(st.text(alphabet, max_size=90), max_size=30))
    return "\n".join(lines).encode("latin-1")
