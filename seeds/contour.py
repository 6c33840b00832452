"""Contours of lines and arcs, shared by the neighbouring systems.

A contour is a chain of elements, :class:`Seg` (a straight line) and
:class:`ArcEl` (an arc with its centre), in millimetres.  Here: the
cutter-centre equidistant of a closed contour (seed 002's flange, whose
paper computed it on the Ural-1), chords of an arc within a tolerance,
distances, and the TENZOR cards that draw a contour (L/+ conductors and A
arcs) and the contour read back from a deck's cards.  Seed 002 builds its
flange with them; seed 001 turns DXF polylines and arcs into them.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Union

from harness import cards

Point = tuple[float, float]

# ---------------------------------------------------------------------------
# Contours of lines and arcs, and their equidistants.
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Seg:
    """A straight element from (x0, y0) to (x1, y1)."""

    x0: float
    y0: float
    x1: float
    y1: float

    def start_dir(self) -> Point:
        d = math.hypot(self.x1 - self.x0, self.y1 - self.y0)
        return (self.x1 - self.x0) / d, (self.y1 - self.y0) / d

    end_dir = start_dir

    def with_ends(self, p0: Point, p1: Point) -> Seg:
        return Seg(p0[0], p0[1], p1[0], p1[1])


@dataclass(frozen=True)
class ArcEl:
    """An arc about (cx, cy) from (x0, y0) to (x1, y1); ``cw`` clockwise.
    Both ends are on the circle (radius from the start)."""

    cx: float
    cy: float
    x0: float
    y0: float
    x1: float
    y1: float
    cw: bool

    @property
    def r(self) -> float:
        return math.hypot(self.x0 - self.cx, self.y0 - self.cy)

    def _tangent(self, x: float, y: float) -> Point:
        rx, ry = (x - self.cx) / self.r, (y - self.cy) / self.r
        return (ry, -rx) if self.cw else (-ry, rx)

    def start_dir(self) -> Point:
        return self._tangent(self.x0, self.y0)

    def end_dir(self) -> Point:
        return self._tangent(self.x1, self.y1)

    @property
    def sweep(self) -> float:
        """Swept angle in radians, positive, (0, 2 pi]."""
        a0 = math.atan2(self.y0 - self.cy, self.x0 - self.cx)
        a1 = math.atan2(self.y1 - self.cy, self.x1 - self.cx)
        s = (a0 - a1) if self.cw else (a1 - a0)
        s %= 2 * math.pi
        return s if s > 1e-12 else 2 * math.pi

    def with_ends(self, p0: Point, p1: Point) -> ArcEl:
        return replace(self, x0=p0[0], y0=p0[1], x1=p1[0], y1=p1[1])


Element = Union[Seg, ArcEl]


def _start(e: Element) -> Point:
    return e.x0, e.y0


def _end(e: Element) -> Point:
    return e.x1, e.y1


def signed_area(contour: Sequence[Element]) -> float:
    """Signed area of a closed contour (positive = counter-clockwise): the
    shoelace sum over the elements plus each arc's circular segment."""
    area = 0.0
    for e in contour:
        area += (e.x0 * e.y1 - e.x1 * e.y0) / 2
        if isinstance(e, ArcEl):
            t = e.sweep
            seg = e.r ** 2 * (t - math.sin(t)) / 2
            area += -seg if e.cw else seg
    return area


def check_closed(contour: Sequence[Element], eps: float = 1e-6) -> None:
    """Raise ValueError unless each element starts where the last ended."""
    if not contour:
        raise ValueError("an empty contour")
    for n, (a, b) in enumerate(zip(contour, list(contour[1:]) + [contour[0]])):
        if math.dist(_end(a), _start(b)) > eps:
            raise ValueError(f"element {n + 1} ends at {_end(a)}, element "
                             f"{(n + 1) % len(contour) + 1} starts at {_start(b)}")


def _offset(e: Element, d: float) -> Element:
    """The element moved by d to its left (d < 0: to its right)."""
    if isinstance(e, Seg):
        ux, uy = e.start_dir()
        nx, ny = -uy * d, ux * d
        return Seg(e.x0 + nx, e.y0 + ny, e.x1 + nx, e.y1 + ny)
    # the left of a counter-clockwise arc is its centre: the radius shrinks
    r1 = e.r + (d if e.cw else -d)
    if r1 <= 1e-9:
        raise ValueError(f"its radius {e.r:.3f} mm about ({e.cx:g}, {e.cy:g}) is tighter "
                         f"than the cutter's radius {abs(d):g} mm (this arc allows a cutter of "
                         f"less than {2 * e.r:.3f} mm)")
    k = r1 / e.r
    return replace(e, x0=e.cx + (e.x0 - e.cx) * k, y0=e.cy + (e.y0 - e.cy) * k,
                   x1=e.cx + (e.x1 - e.cx) * k, y1=e.cy + (e.y1 - e.cy) * k)


def _circle_of(e: Element) -> tuple[Point, float] | None:
    return None if isinstance(e, Seg) else ((e.cx, e.cy), e.r)


def _intersections(a: Element, b: Element) -> list[Point]:
    """Intersections of the full lines / circles carrying a and b."""
    ca, cb = _circle_of(a), _circle_of(b)
    if ca is None and cb is None:
        (ux, uy), (vx, vy) = a.start_dir(), b.start_dir()
        den = ux * vy - uy * vx
        if abs(den) < 1e-12:
            return []
        t = ((b.x0 - a.x0) * vy - (b.y0 - a.y0) * vx) / den
        return [(a.x0 + t * ux, a.y0 + t * uy)]
    if ca is None or cb is None:
        line, ((cx, cy), r) = (a, cb) if ca is None else (b, ca)
        ux, uy = line.start_dir()
        fx, fy = line.x0 - cx, line.y0 - cy
        pb = fx * ux + fy * uy
        disc = pb * pb - (fx * fx + fy * fy - r * r)
        if disc < 0:
            return []
        s = math.sqrt(disc)
        return [(line.x0 + t * ux, line.y0 + t * uy) for t in (-pb - s, -pb + s)]
    ((x0, y0), r0), ((x1, y1), r1) = ca, cb
    d = math.hypot(x1 - x0, y1 - y0)
    if d < 1e-12 or d > r0 + r1 or d < abs(r0 - r1):
        return []
    al = (r0 * r0 - r1 * r1 + d * d) / (2 * d)
    h = math.sqrt(max(r0 * r0 - al * al, 0.0))
    mx, my = x0 + al * (x1 - x0) / d, y0 + al * (y1 - y0) / d
    return [(mx + h * (y1 - y0) / d, my - h * (x1 - x0) / d),
            (mx - h * (y1 - y0) / d, my + h * (x1 - x0) / d)]


#: A gap at a corner shorter than this (mm) is closed by meeting in its
#: middle rather than by an arc that the cards' 0.01 mm could not carry.
SNAP_MM = 0.02
#: the coordinatograph's field, mm: no coordinate relative to the origin, no
#: size and no cutter is larger
FIELD_MM = 1200.0
#: the most chords one arc or one profile is cut into: a tolerance far
#: below the cards' 0.01 mm (1e-9 mm, or 1e-320, where the step angle is
#: 0) would ask for millions, billions or an endless number
MAX_CHORDS = 1_000_000


def _name(labels: Sequence[str] | None, i: int) -> str:
    """Element i (0-based) of a contour in a message: its label when the
    contour was read from cards (:func:`contour_and_cards`)."""
    return labels[i] if labels else f"element {i + 1}"


def equidistant(contour: Sequence[Element], radius: float, outside: bool = True,
                labels: Sequence[str] | None = None) -> list[Element]:
    """The path of the centre of a cutter of ``radius`` running along a
    closed contour of lines and arcs, outside it (or inside).

    Each element is moved by the radius along its normal (an arc keeps its
    centre and changes its radius); where two moved elements leave a gap (a
    convex corner, seen from the cutter) the cutter turns about the corner on
    an arc of its radius; where they overlap (a concave corner) both are cut
    at their intersection nearest the corner.  Tangent joins stay joined,
    and so do near-tangent ones whose gap is under :data:`SNAP_MM`.
    A concave arc tighter than the cutter, or an element that vanishes
    between two overlapping neighbours, is a ValueError (the paper's flange
    has neither).  ``labels`` name the elements in those messages (the
    cards that drew them; default "element N").
    """
    check_closed(contour)
    ccw = signed_area(contour) > 0
    d = radius if (ccw != outside) else -radius  # + = to the left
    moved: list[Element] = []
    for i, e in enumerate(contour):
        try:
            moved.append(_offset(e, d))
        except ValueError as exc:
            raise ValueError(f"{_name(labels, i)}: {exc}") from None
    n = len(contour)
    starts = [_start(m) for m in moved]
    ends = [_end(m) for m in moved]
    corners: list[Element | None] = [None] * n
    for i in range(n):
        j = (i + 1) % n
        vx, vy = _end(contour[i])
        ta, tb = contour[i].end_dir(), contour[j].start_dir()
        cross = ta[0] * tb[1] - ta[1] * tb[0]
        dot = ta[0] * tb[0] + ta[1] * tb[1]
        gap = math.dist(ends[i], starts[j])
        if dot > 0 and (abs(cross) < 1e-9 or gap < SNAP_MM):
            mid = ((ends[i][0] + starts[j][0]) / 2, (ends[i][1] + starts[j][1]) / 2)
            ends[i] = starts[j] = mid
        elif cross * d < 0:          # turning away from the cutter: a gap
            corners[i] = ArcEl(vx, vy, ends[i][0], ends[i][1], starts[j][0],
                               starts[j][1], cw=d > 0)
        else:                        # turning toward it: the moved elements overlap
            cands = _intersections(moved[i], moved[j])
            if not cands:
                raise ValueError(f"{_name(labels, i)} and {_name(labels, j)}, moved by the "
                                 f"cutter's radius, do not meet")
            x = min(cands, key=lambda p: math.dist(p, (vx, vy)))
            ends[i] = starts[j] = x
    out: list[Element] = []
    for i, m in enumerate(moved):
        new = m.with_ends(starts[i], ends[i])
        if isinstance(new, Seg):
            (ux, uy), (wx, wy) = m.start_dir(), (new.x1 - new.x0, new.y1 - new.y0)
            if ux * wx + uy * wy <= 1e-9:
                raise ValueError(f"{_name(labels, i)} vanishes in the equidistant "
                             f"(the cutter is too large for it)")
        elif isinstance(m, ArcEl) and new.sweep > m.sweep + 0.5:   # wrapped round
            raise ValueError(f"{_name(labels, i)} vanishes in the equidistant "
                             f"(the cutter is too large for it)")
        out.append(new)
        if corners[i] is not None:
            out.append(corners[i])
    return out


def chord_step(radius: float, tol: float) -> float:
    """The step angle (radians) of chords on an arc of ``radius`` that stray
    at most ``tol`` from it: Δφ = 2 arccos(1 - y/R0), the paper's formula."""
    if not 0 < tol < radius:
        raise ValueError(f"chord tolerance {tol} must be positive and below the radius {radius}")
    return 2.0 * math.acos(1.0 - tol / radius)


def distance_to(e: Element, p: Point) -> float:
    """Distance from p to the element (a segment or an arc)."""
    if isinstance(e, Seg):
        ex, ey = e.x1 - e.x0, e.y1 - e.y0
        t = max(0.0, min(1.0, ((p[0] - e.x0) * ex + (p[1] - e.y0) * ey) / (ex * ex + ey * ey)))
        return math.hypot(p[0] - e.x0 - t * ex, p[1] - e.y0 - t * ey)
    a = math.atan2(p[1] - e.cy, p[0] - e.cx)
    a0 = math.atan2(e.y0 - e.cy, e.x0 - e.cx)
    t = ((a0 - a) if e.cw else (a - a0)) % (2 * math.pi)
    if t <= e.sweep:
        return abs(math.hypot(p[0] - e.cx, p[1] - e.cy) - e.r)
    return min(math.dist(p, _start(e)), math.dist(p, _end(e)))


def sample(e: Element, step: float = 0.5) -> list[Point]:
    """Points along an element about ``step`` apart, both ends included."""
    if isinstance(e, Seg):
        k = max(1, math.ceil(math.hypot(e.x1 - e.x0, e.y1 - e.y0) / step))
        return [(e.x0 + (e.x1 - e.x0) * s / k, e.y0 + (e.y1 - e.y0) * s / k) for s in range(k + 1)]
    k = max(1, math.ceil(e.r * e.sweep / step))
    a0 = math.atan2(e.y0 - e.cy, e.x0 - e.cx)
    sgn = -1 if e.cw else 1
    return [(e.cx + e.r * math.cos(a0 + sgn * e.sweep * s / k),
             e.cy + e.r * math.sin(a0 + sgn * e.sweep * s / k)) for s in range(k + 1)]


def arc_chords(e: ArcEl, tol: float) -> list[Point]:
    """An arc as chords within ``tol`` of it (step angle :func:`chord_step`),
    from its start to its end."""
    step = chord_step(e.r, tol)
    if not (step > 0 and e.sweep / step <= MAX_CHORDS):
        raise ValueError(f"an arc of radius {e.r:g} mm within {tol:g} mm needs more than "
                         f"{MAX_CHORDS} chords: give a larger chord tolerance")
    k = max(1, math.ceil(e.sweep / step - 1e-9))
    a0 = math.atan2(e.y0 - e.cy, e.x0 - e.cx)
    sgn = -1 if e.cw else 1
    pts = [(e.cx + e.r * math.cos(a0 + sgn * e.sweep * s / k),
            e.cy + e.r * math.sin(a0 + sgn * e.sweep * s / k)) for s in range(k)]
    return pts + [_end(e)]


# ---------------------------------------------------------------------------
# Contours as card decks (and back).
# ---------------------------------------------------------------------------
def units(v: float) -> int:
    """Millimetres to the cards' units of 0.01 mm, rounded half up."""
    return int(math.floor(v * 100 + 0.5))


def _card_arc(e: ArcEl, p0: tuple[int, int], p1: tuple[int, int]) -> tuple[int, int]:
    """A centre in units near e's centre for which p0 and p1 (units) are on
    one circle within 1 unit, as TENZOR's A card needs."""
    c0 = (units(e.cx), units(e.cy))
    best = None
    for ddx in (0, -1, 1, -2, 2):
        for ddy in (0, -1, 1, -2, 2):
            c = (c0[0] + ddx, c0[1] + ddy)
            gap = abs(math.dist(c, p0) - math.dist(c, p1))
            key = (gap > 1, abs(ddx) + abs(ddy), gap)
            if best is None or key < best[0]:
                best = (key, c)
    assert best is not None
    if best[0][0]:
        raise ValueError(f"no centre near ({e.cx:.3f}, {e.cy:.3f}) puts both ends on one circle")
    return best[1]


def contour_cards(contour: Sequence[Element], chord_tol: float | None = None,
                  width: int | None = None) -> list[str]:
    """Cards drawing a chain of elements: runs of lines as one L/+ conductor
    (of ``width`` units, blank = the tape's tool), arcs as A cards, or as
    chords within ``chord_tol`` mm when given (for a line-only machine)."""
    out: list[str] = []
    run: list[tuple[int, int]] = []

    def flush() -> None:
        if len(run) >= 2:
            out.append(cards.l_card(run[0][0], run[0][1], width))
            out.extend(cards.plus_card(x, y) for x, y in run[1:])
        run.clear()

    for e in contour:
        p0 = (units(e.x0), units(e.y0))
        p1 = (units(e.x1), units(e.y1))
        if isinstance(e, ArcEl) and chord_tol is None:
            flush()
            c = _card_arc(e, p0, p1)
            out.append(cards.a_card("+" if e.cw else "-", c[0], c[1], *p0, *p1))
            continue
        pts = [p1] if isinstance(e, Seg) else [(units(x), units(y)) for x, y in arc_chords(e, chord_tol)[1:]]
        if not run:
            run.append(p0)
        for p in pts:
            if p != run[-1]:
                run.append(p)
    flush()
    return out


def contour_from_package(pkg) -> list[Element]:
    """The conductors (L/+) and arcs (A) of a parsed deck package
    (:class:`harness.deck.Package`), in card order, as one chain of
    elements in mm.  Circles, pads and M cards are not part of a contour."""
    return contour_and_cards(pkg)[0]


def contour_and_cards(pkg) -> tuple[list[Element], list[str]]:
    """:func:`contour_from_package`, and for each element the card that draws
    it, for messages: "the line to card 7" (the L or + card where a straight
    element ends) or "the arc of card 8"."""
    items = [(c.card, c) for c in pkg.conductors] + [(a.card, a) for a in pkg.arcs]
    out: list[Element] = []
    labels: list[str] = []
    for _, item in sorted(items, key=lambda t: t[0]):
        if hasattr(item, "points"):
            pts = [(x / 100, y / 100) for x, y in item.points]
            for p, q, no in zip(pts, pts[1:], item.point_cards[1:]):
                if p != q:
                    out.append(Seg(*p, *q))
                    labels.append(f"the line to card {no}")
        else:
            out.append(ArcEl(item.xc / 100, item.yc / 100, item.xs / 100, item.ys / 100,
                             item.xe / 100, item.ye / 100, item.clockwise))
            labels.append(f"the arc of card {item.card}")
    return out, labels


def package_contour(pkg) -> tuple[list[Element], list[str]]:
    """The closed contour of a package's L/+ and A cards (:func:`close_chain`)
    and the label of each element, for :func:`equidistant`'s messages."""
    elements, labels = contour_and_cards(pkg)
    return close_chain(elements, labels=labels), labels


def close_chain(elements: Sequence[Element], eps: float = 0.015,
                labels: Sequence[str] | None = None) -> list[Element]:
    """Snap a chain read from cards so that it closes exactly (each element
    ends where the next starts); ValueError if two ends are more than
    ``eps`` mm apart: then it is not one closed contour.  ``labels`` name
    the elements in that message (:func:`contour_and_cards`)."""
    out = list(elements)
    if not out:
        raise ValueError("no lines or arcs (L/+ or A cards): no contour")
    for i, e in enumerate(out):
        j = (i + 1) % len(out)
        nxt = out[j]
        if math.dist(_end(e), _start(nxt)) > eps:
            raise ValueError(f"{_name(labels, i)} ends at ({e.x1:.2f}, {e.y1:.2f}) but "
                             f"{_name(labels, j)} starts at ({nxt.x0:.2f}, {nxt.y0:.2f}): "
                             f"not a closed contour (each line or arc, in card order, must "
                             f"start within {eps:g} mm of where the one before it ends, "
                             f"and the last end where the first starts)")
    return [e.with_ends(_start(e), _start(out[(i + 1) % len(out)])) for i, e in enumerate(out)]
