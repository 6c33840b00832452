"""Seed 001: a DXF drawing to a TENZOR card deck.

Source: seed 001 (docs/SOURCES.md): Xiong Mudi, Xie Zhao,
Xiao Wenli, Xing Zhongbao, "利用 CAD 图形交换文件实现激光直写设备的运动控制"
(motion control of a laser direct-writing device from CAD drawing exchange
files; Changchun Institute of Optics).  Its section 3 says what a drawing
must carry besides the path (the start and end segments, the order of the
segments, macros, hints, all as TEXT placed near the path); its section 4
how the interpreter uses it: read FIRST's insertion point, compute its
distance to every line (start and end point) and arc (centre and radius),
take the nearest segment; then the text "1", its nearest segment, then "2",
and so on up to the largest number.  Item 5 of section 3: a path walked
again gets the later numbers too.

What is built (docs/SEED001-DXF.md says why):

* CIRCLE -> ``D`` pad of its diameter (on a layer named ``RING...``: an
  ``O`` circle drawn with the conductor tool instead);
* LWPOLYLINE, POLYLINE (2D) and LINE -> ``L``/``+`` conductors; the width
  is the polyline's constant width, else the layer's ``_W<mm>`` suffix
  (``SIGNAL_W0.8``), else blank (the conductor tool).  A closed
  axis-parallel rectangle on a layer named ``PAD...`` is a rectangular pad.
  Bulges are cut into chords within 0.005 mm;
* ARC -> ``A`` card (DXF arcs run counter-clockwise: direction ``-``);
* SPLINE -> a conductor of chords, flattened by ezdxf within a stated
  tolerance (``SPLINE_TOL``, 0.005 mm; the paper's fitting module for
  higher-order curves); the report says how many were flattened;
* INSERT -> its block's entities, exploded (blocks within blocks too; a
  block that inserts itself is reported, and a drawing that expands to more
  than ``ENTITY_BUDGET`` entities is refused: a few kilobytes of nested
  INSERTs can stand for millions of circles);
* TEXT / MTEXT: ``FIRST``, ``LAST`` and whole numbers 1, 2, 3 ... attach to
  the nearest item (pads by their disc, the rest by their line) and fix the
  drawing order: FIRST, then the numbers in order, then the items without a
  label in drawing order, then LAST; the deck's P card then asks for deck
  order (``D``).  Without any label TENZOR's optimiser orders the deck.
* everything else (and the rest of a macro text such as ``FIRST OUT 1``) is
  reported with its handle and layer and left out.

The drawing is in mm; its origin becomes the start point unless ``origin``
says which drawing point does; coordinates are rounded to 0.01 mm.  An
entity with a coordinate that is not a finite number, or that lies farther
than ``FIELD_MM`` from the origin (no board on the EM-703's field can), is
reported and left out.  Labels find their nearest item through a spatial
index (shapely's STRtree), with the same answer as trying every item.
"""

from __future__ import annotations

import argparse
import io
import math
import re
import sys
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass, field
from decimal import Decimal
from pathlib import Path
from typing import Any

import ezdxf
import shapely

from harness import cards
from harness.files import quiet_when_output_closes, write_whole

from .contour import FIELD_MM, ArcEl, Seg, arc_chords, contour_cards, distance_to
from .options import Parser, mm_list

#: Chord tolerance (mm) for polyline bulges.
BULGE_TOL = 0.005
#: The most entities a drawing may expand to, blocks exploded.
ENTITY_BUDGET = 200_000
#: Default tolerance (mm) within which a SPLINE is flattened into chords
#: (the paper's "fitting module for higher-order curves", section 2).
SPLINE_TOL = 0.005
#: The most chord points one SPLINE may flatten into.
SPLINE_POINTS = 100_000


class _LeftOut(ValueError):
    """An entity that cannot be used: the reason, for its problem line."""


class TooBig(ValueError):
    """The drawing expands to more entities than ENTITY_BUDGET."""


def _check_points(pts: Iterable[Sequence[float]], origin: Point) -> None:
    for p in pts:
        for axis, v, o in zip("xy", (p[0], p[1]), origin):
            v = float(v)
            if not math.isfinite(v):
                raise _LeftOut(f"a coordinate is {v}, not a number")
            if abs(v - o) > FIELD_MM:
                if not o:
                    raise _LeftOut(f"coordinate {v:.6g} mm is off the {FIELD_MM:.0f} mm "
                                   f"field around the origin")
                raise _LeftOut(f"{axis} coordinate {v:.6g} mm is {v - o:.6g} mm from the "
                               f"origin's {axis} ({o:g} mm, --origin): off the "
                               f"{FIELD_MM:.0f} mm field around the origin")


def _check_size(v: float, what: str) -> float:
    v = float(v)
    if not math.isfinite(v) or abs(v) > FIELD_MM:
        raise _LeftOut(f"{what} {v:.6g} mm is not a size on the {FIELD_MM:.0f} mm field")
    return v
#: The drawing's lower-left corner lands this far inside the field (mm)
#: when no start point position is given.
MARGIN_MM = 10
_WIDTH = re.compile(r"_W(\d+(?:\.\d+)?)$", re.IGNORECASE)

Point = tuple[float, float]


@dataclass
class Item:
    """One deck item made from one entity: its cards, the geometry used for
    the nearest-item rule, and where it came from."""

    kind: str                   # pad, conductor, arc, circle
    cards: list[str]
    handle: str
    layer: str
    segments: list[Seg | ArcEl] = field(default_factory=list)
    disc: tuple[float, float, float] | None = None     # a pad: x, y, r
    rect: tuple[float, float, float, float] | None = None  # a pad: x0, y0, x1, y1

    def distance(self, p: Point) -> float:
        """The paper's distance from a label's insertion point."""
        if self.disc is not None:
            x, y, r = self.disc
            return max(0.0, math.hypot(p[0] - x, p[1] - y) - r)
        if self.rect is not None:
            x0, y0, x1, y1 = self.rect
            return math.hypot(max(x0 - p[0], 0.0, p[0] - x1), max(y0 - p[1], 0.0, p[1] - y1))
        return min(distance_to(s, p) for s in self.segments)


@dataclass
class Label:
    text: str
    handle: str
    layer: str
    at: Point
    kind: str = "TEXT"          # or MTEXT

    @property
    def where(self) -> str:
        """Its type, handle and layer, for a problem line."""
        return f"{self.kind} #{self.handle} on layer {self.layer}"


@dataclass
class Conversion:
    """The result: the items in deck order, the problems (one line each,
    naming the entity's handle and layer) and whether labels fixed the
    order."""

    items: list[Item]
    problems: list[str]
    ordered: bool
    bbox: tuple[float, float, float, float] | None
    splines: int = 0
    tolerance: float = SPLINE_TOL


def _u(v: float) -> int:
    """mm -> units of 0.01 mm, rounded."""
    return int(math.floor(v * 100 + 0.5))


def _where(e: Any) -> str:
    """The entity's type, handle and layer, for a problem line; never raises
    (some entity types have no layer attribute, a malformed one no handle)."""
    try:
        handle, layer = e.dxf.get("handle", "?"), e.dxf.get("layer", "?")
    except (AttributeError, ezdxf.DXFError):
        handle = layer = "?"
    return f"{e.dxftype()} #{handle} on layer {layer}"


def _layer_width(layer: str) -> int | None:
    m = _WIDTH.search(layer)
    return _u(float(m.group(1))) if m else None


def _wcs(e: Any, pts: Iterable[Sequence[float]]) -> list[Point]:
    """OCS points of a 2D entity in the drawing's coordinates."""
    ocs = e.ocs()
    return [(float(q[0]), float(q[1])) for q in ocs.points_to_wcs([(p[0], p[1], 0) for p in pts])] \
        if ocs.transform else [(float(p[0]), float(p[1])) for p in pts]


def _flat(e: Any) -> bool:
    ex = getattr(e.dxf, "extrusion", (0, 0, 1))
    return abs(ex[0]) < 1e-9 and abs(ex[1]) < 1e-9


def _bulge_arc(p: Point, q: Point, bulge: float) -> ArcEl:
    """The arc from p to q of a polyline vertex's bulge (tan of a quarter of
    its angle; positive = counter-clockwise)."""
    chord = math.dist(p, q)
    theta = 4 * math.atan(bulge)
    r = chord / (2 * math.sin(abs(theta) / 2))
    mx, my = (p[0] + q[0]) / 2, (p[1] + q[1]) / 2
    h = r * math.cos(theta / 2)
    ux, uy = (q[0] - p[0]) / chord, (q[1] - p[1]) / chord
    side = 1 if bulge > 0 else -1
    cx, cy = mx - side * uy * h, my + side * ux * h
    return ArcEl(cx, cy, p[0], p[1], q[0], q[1], cw=bulge < 0)


def _polyline_item(e: Any, verts: list[tuple[Point, float]], closed: bool,
                   width_mm: float, origin: Point, problems: list[str]) -> Item | None:
    """A conductor (or a PAD-layer rectangle) from vertices with bulges."""
    layer = e.dxf.layer
    if closed and verts:
        verts = verts + [(verts[0][0], 0.0)]
    pts = [(x - origin[0], y - origin[1]) for (x, y), _ in verts]
    if layer.upper().startswith("PAD") and closed:
        xs, ys = sorted({round(p[0], 6) for p in pts}), sorted({round(p[1], 6) for p in pts})
        # four axis-parallel edges: each edge changes x or y, never both
        # (a self-crossing "bow-tie" of the same four corners is no rectangle)
        edges_ok = all((round(p[0], 6) == round(q[0], 6)) != (round(p[1], 6) == round(q[1], 6))
                       for p, q in zip(pts, pts[1:]))
        if len(pts) == 5 and len(xs) == 2 and len(ys) == 2 and edges_ok \
                and all(b == 0 for _, b in verts):
            w, h = _u(xs[1]) - _u(xs[0]), _u(ys[1]) - _u(ys[0])
            cx2, cy2 = _u(xs[0]) + _u(xs[1]), _u(ys[0]) + _u(ys[1])
            if cx2 % 2 or cy2 % 2:
                problems.append(f"{_where(e)}: rectangle's centre is off the 0.01 mm grid; left out")
                return None
            card = cards.d_card(cx2 // 2, cy2 // 2, w, h)
            return Item("pad", [card], e.dxf.handle, layer, rect=(xs[0], ys[0], xs[1], ys[1]))
        problems.append(f"{_where(e)}: a closed polyline on a PAD layer that is not an "
                        f"axis-parallel rectangle; drawn as a conductor")
    segs: list[Seg | ArcEl] = []
    for k in range(len(pts) - 1):
        p, q, bulge = pts[k], pts[k + 1], verts[k][1]
        if p == q:
            continue
        segs.append(_bulge_arc(p, q, bulge) if abs(bulge) > 1e-12 else Seg(*p, *q))
    if not segs:
        problems.append(f"{_where(e)}: a polyline of zero length; left out")
        return None
    width = _u(width_mm) if width_mm > 0 else _layer_width(layer)
    run: list[tuple[int, int]] = []
    for s in segs:
        pts_s = [(s.x0, s.y0)] + (arc_chords(s, BULGE_TOL)[1:] if isinstance(s, ArcEl)
                                  else [(s.x1, s.y1)])
        for x, y in pts_s:
            u = (_u(x), _u(y))
            if not run or u != run[-1]:
                run.append(u)
    if len(run) < 2:
        problems.append(f"{_where(e)}: shorter than 0.01 mm; left out")
        return None
    body = [cards.l_card(*run[0], width)] + [cards.plus_card(*u) for u in run[1:]]
    return Item("conductor", body, e.dxf.handle, layer, segments=segs)


@dataclass
class _Budget:
    """The reading's state: entities left to expand (ENTITY_BUDGET at the
    start, read when the reading starts, so that the limit and the message
    that names it are one number), the tolerance splines are flattened
    within and how many were."""

    left: int = field(default_factory=lambda: ENTITY_BUDGET)
    tol: float = SPLINE_TOL
    splines: int = 0

    def take(self) -> None:
        self.left -= 1
        if self.left < 0:
            raise self.refusal()

    @staticmethod
    def refusal() -> TooBig:
        return TooBig(f"the drawing expands to more than {ENTITY_BUDGET} entities "
                      f"(blocks inserted into blocks); split it, or explode fewer blocks")


def _entity_items(e: Any, origin: Point, problems: list[str], labels: list[Label],
                  budget: _Budget | None = None, blocks: tuple[str, ...] = ()) -> list[Item]:
    """Items (or labels) of one entity; problems for what cannot be used.
    An entity that cannot be read is one problem line, never a traceback."""
    budget = budget or _Budget()
    budget.take()
    try:
        return _entity_items_of(e, origin, problems, labels, budget, blocks)
    except TooBig:
        raise
    except _LeftOut as exc:
        problems.append(f"{_where(e)}: {exc}; left out")
    except (ValueError, ArithmeticError, TypeError, AttributeError, KeyError,
            IndexError, ezdxf.DXFError) as exc:
        problems.append(f"{_where(e)}: cannot be read ({type(exc).__name__}: {exc}); left out")
    return []


def _entity_items_of(e: Any, origin: Point, problems: list[str], labels: list[Label],
                     budget: _Budget, blocks: tuple[str, ...]) -> list[Item]:
    kind = e.dxftype()
    layer = e.dxf.layer
    if kind in ("TEXT", "MTEXT"):
        text = e.plain_text() if kind == "MTEXT" else e.dxf.text
        ins = e.dxf.insert
        _check_points([ins], origin)
        labels.append(Label(" ".join(text.split()), e.dxf.handle, layer,
                            (float(ins[0]) - origin[0], float(ins[1]) - origin[1]), kind))
        return []
    if kind in ("CIRCLE", "ARC", "LWPOLYLINE") and not _flat(e):
        problems.append(f"{_where(e)}: drawn in a tilted plane; left out")
        return []
    if kind == "CIRCLE":
        (c,) = _wcs(e, [e.dxf.center])
        _check_points([c], origin)
        x, y, r = c[0] - origin[0], c[1] - origin[1], _check_size(e.dxf.radius, "radius")
        if layer.upper().startswith("RING"):
            card = cards.o_card("-", _u(x), _u(y), _u(r))
            return [Item("circle", [card], e.dxf.handle, layer,
                         segments=[ArcEl(x, y, x + r, y, x + r, y, cw=False)])]
        return [Item("pad", [cards.d_card(_u(x), _u(y), _u(2 * r))], e.dxf.handle, layer,
                     disc=(x, y, r))]
    if kind == "ARC":
        _check_size(e.dxf.radius, "radius")
        (c,) = _wcs(e, [e.dxf.center])
        _check_points([c], origin)
        p0, p1 = ((float(v[0]), float(v[1])) for v in (e.start_point, e.end_point))  # WCS
        _check_points([p0, p1], origin)
        cw = e.dxf.extrusion[2] < 0
        arc = ArcEl(c[0] - origin[0], c[1] - origin[1], p0[0] - origin[0], p0[1] - origin[1],
                    p1[0] - origin[0], p1[1] - origin[1], cw=cw)
        try:
            body = contour_cards([arc])
        except ValueError as exc:
            problems.append(f"{_where(e)}: {exc}; left out")
            return []
        return [Item("arc", body, e.dxf.handle, layer, segments=[arc])]
    if kind == "LINE":
        p, q = e.dxf.start, e.dxf.end
        _check_points([p, q], origin)
        verts = [((float(p[0]), float(p[1])), 0.0), ((float(q[0]), float(q[1])), 0.0)]
        item = _polyline_item(e, verts, False, 0.0, origin, problems)
        return [item] if item else []
    if kind == "LWPOLYLINE":
        raw = e.get_points("xyseb")
        widths = {(float(s), float(w)) for _, _, s, w, _ in raw}
        const = float(e.dxf.const_width) if e.dxf.hasattr("const_width") else 0.0
        if const == 0 and widths != {(0.0, 0.0)}:
            ws = {v for pair in widths for v in pair}
            if len(ws) != 1:
                problems.append(f"{_where(e)}: varying width; left out")
                return []
            const = ws.pop()
        _check_size(const, "width")
        pts = _wcs(e, [(x, y) for x, y, *_ in raw])
        _check_points(pts, origin)
        verts = [(p, float(v[4])) for p, v in zip(pts, raw)]
        item = _polyline_item(e, verts, bool(e.closed), const, origin, problems)
        return [item] if item else []
    if kind == "POLYLINE":
        if not e.is_2d_polyline:
            problems.append(f"{_where(e)}: a 3D polyline or mesh; left out")
            return []
        own = {float(v.dxf.start_width) for v in e.vertices} | \
            {float(v.dxf.end_width) for v in e.vertices}
        widths = own if own != {0.0} else {float(e.dxf.default_start_width),
                                           float(e.dxf.default_end_width)}
        if len(widths) != 1:
            problems.append(f"{_where(e)}: varying width; left out")
            return []
        sw = _check_size(widths.pop(), "width")
        pts = _wcs(e, [v.dxf.location for v in e.vertices])
        _check_points(pts, origin)
        verts = [(p, float(v.dxf.bulge)) for p, v in zip(pts, e.vertices)]
        item = _polyline_item(e, verts, bool(e.is_closed), sw, origin, problems)
        return [item] if item else []
    if kind == "SPLINE":
        item = _spline_item(e, origin, budget.tol, problems)
        if item is None:
            return []
        budget.splines += 1
        return [item]
    if kind == "INSERT":
        name = e.dxf.name
        if name in blocks:
            chain = " -> ".join(blocks + (name,))
            raise _LeftOut(f"block {name} inserts itself ({chain})")
        for v in (*e.dxf.insert, *(e.dxf.get(k, 1.0) for k in ("xscale", "yscale"))):
            if not math.isfinite(float(v)):
                raise _LeftOut(f"a coordinate or scale is {float(v)}, not a number")
        out: list[Item] = []
        for ve in e.virtual_entities():
            if ve.dxf.handle is None:
                ve.dxf.handle = e.dxf.handle
            out += _entity_items(ve, origin, problems, labels, budget, blocks + (name,))
        return out
    article = "an" if kind and kind[0] in "AEIOU" else "a"
    problems.append(f"{_where(e)}: cannot map {article} {kind}; left out")
    return []


def _spline_item(e: Any, origin: Point, tol: float, problems: list[str]) -> Item | None:
    """A SPLINE flattened by ezdxf into chords within ``tol`` mm, as a
    conductor (the width: the layer rule, else the tool).  Its control and
    fit points are checked first (finite, on the field): ezdxf's flattening
    recurses without end on a point that is not a number."""
    ctrl = [tuple(v) for v in e.control_points] + [tuple(v) for v in e.fit_points]
    _check_points(ctrl, origin)
    extra = [float(w) for w in e.weights] + [float(k) for k in e.knots]
    if not all(math.isfinite(v) for v in extra):
        raise _LeftOut("a weight or knot is not a number")
    pts: list[Point] = []
    try:
        for v in e.flattening(tol):
            pts.append((float(v[0]), float(v[1])))
            if len(pts) > SPLINE_POINTS:
                raise _LeftOut(f"cannot be flattened within {tol:g} mm in at most "
                               f"{SPLINE_POINTS} chords")
    except _LeftOut:
        raise
    except (ValueError, ArithmeticError, IndexError, RecursionError, ezdxf.DXFError) as exc:
        raise _LeftOut(f"cannot be flattened ({type(exc).__name__}: {exc})") from None
    _check_points(pts, origin)
    if len(pts) < 2:
        raise _LeftOut("cannot be flattened (fewer than two points)")
    verts = [(p, 0.0) for p in pts]
    return _polyline_item(e, verts, False, 0.0, origin, problems)


class _Nearest:
    """The nearest item to a point, by the paper's distance (Item.distance),
    ties to the earlier item: the answer of trying every item, found through
    an STRtree of the items' bounding boxes.  A box is never farther from a
    point than its item, so the exact distance d of the item with the nearest
    box bounds the answer, and only items whose box lies within d (plus a
    rounding margin) need their exact distance."""

    def __init__(self, items: list[Item]) -> None:
        self.items = items
        boxes = [_item_box(it) for it in items]
        self.tree = shapely.STRtree([shapely.box(*b) for b in boxes]) if items else None

    def __call__(self, at: Point) -> int:
        p = shapely.Point(at)
        first = int(self.tree.nearest(p))
        bound = self.items[first].distance(at)
        cands = self.tree.query(p, predicate="dwithin", distance=bound + 1e-6 * (1 + bound))
        return min((self.items[i].distance(at), i) for i in set(map(int, cands)) | {first})[1]


def _item_box(it: Item) -> tuple[float, float, float, float]:
    """The bounding box of an item's geometry (an arc's: its full circle's)."""
    if it.disc:
        x, y, r = it.disc
        return (x - r, y - r, x + r, y + r)
    if it.rect:
        return it.rect
    boxes = []
    for s in it.segments:
        if isinstance(s, ArcEl):
            boxes.append((s.cx - s.r, s.cy - s.r, s.cx + s.r, s.cy + s.r))
        else:
            boxes.append((min(s.x0, s.x1), min(s.y0, s.y1), max(s.x0, s.x1), max(s.y0, s.y1)))
    return (min(b[0] for b in boxes), min(b[1] for b in boxes),
            max(b[2] for b in boxes), max(b[3] for b in boxes))


def _order(items: list[Item], labels: list[Label], problems: list[str]) -> tuple[list[Item], bool]:
    """Attach FIRST, LAST and numbers to the nearest items and order them
    (section 4 of the paper); texts that are not labels are reported."""
    first: list[int] = []
    last: list[int] = []
    numbered: dict[int, int] = {}
    last_where = "LAST"
    nearest = _Nearest(items)
    for lab in labels:
        words = lab.text.split()
        where = lab.where
        if not words:
            continue
        key = words[0].upper()
        if key in ("FIRST", "LAST") or words[0].isdigit():
            if len(words) > 1:
                problems.append(f"{where}: macro {' '.join(words[1:])!r} after {words[0]} "
                                f"cannot be mapped; left out")
            if not items:
                problems.append(f"{where}: label {words[0]} has no item to attach to")
                continue
            if key in ("FIRST", "LAST") and (first if key == "FIRST" else last):
                problems.append(f"{where}: {key} given again; the first in the drawing is "
                                f"used, this one ignored")
                continue
            near = nearest(lab.at)
            if key == "FIRST":
                first.append(near)
            elif key == "LAST":
                last.append(near)
                last_where = where
            else:
                n = int(words[0])
                if n in numbered:
                    problems.append(f"{where}: order number {n} given twice; this one ignored")
                    continue
                numbered[n] = near
        else:
            problems.append(f"{where}: text {lab.text!r} is not a label (FIRST, LAST, "
                            f"1, 2, ...); left out")
    seq = sequence(len(items), first, numbered, last, problems, last_where)
    if seq is None:
        return items, False
    return [items[i] for i in seq], True


def sequence(n: int, first: list[int], numbered: dict[int, int], last: list[int],
             problems: list[str], last_where: str = "LAST") -> list[int] | None:
    """The drawing order of n items (indices) from the items FIRST, the
    numbers and LAST are attached to (section 4 of the paper): FIRST, the
    numbers in order (an item may carry several), the unlabelled items in
    drawing order, LAST.  None when there is no label at all.  The callers
    take one FIRST and one LAST, and report any other by its text;
    ``last_where`` names the LAST text for a problem line."""
    if not (first or last or numbered):
        return None
    seq = first + [numbered[k] for k in sorted(numbered)]
    seen = set(seq) | set(last)
    seq += [i for i in range(n) if i not in seen] + last
    if last and last[0] in first + list(numbered.values()):
        problems.append(f"{last_where}: LAST is attached to an item that also has an "
                        f"earlier label")
    return seq


@dataclass
class Reading:
    """What one reading of a drawing's model space gives, for dxf2deck and
    dxf2dmc alike: the items in drawing order, the texts (labels, macros,
    hints), the problems so far (one line each, naming the entity's handle
    and layer), how many SPLINEs were flattened and within what tolerance."""

    items: list[Item]
    labels: list[Label]
    problems: list[str]
    splines: int
    tolerance: float

    @property
    def bbox(self) -> tuple[float, float, float, float] | None:
        boxes = [_item_box(it) for it in self.items]
        return (min(b[0] for b in boxes), min(b[1] for b in boxes),
                max(b[2] for b in boxes), max(b[3] for b in boxes)) if boxes else None

    def spline_note(self) -> str | None:
        """The report's line on flattened splines (None when there were none)."""
        if not self.splines:
            return None
        return (f"{self.splines} SPLINE{'s' if self.splines > 1 else ''} flattened into "
                f"chords within {self.tolerance:g} mm")


def check_tolerance(tol: float) -> float:
    """A spline tolerance (mm) that can be met: finite, 0.0001 to 1 mm."""
    tol = float(tol)
    if not (math.isfinite(tol) and 0.0001 <= tol <= 1.0):
        raise ValueError(f"tolerance {tol:g} mm is not between 0.0001 and 1 mm")
    return tol


def expanded_count(doc: Any) -> int | None:
    """How many entities the model space expands to, blocks exploded, counted
    from the blocks' contents before anything is exploded (a block's count is
    worked out once, so 24 nested levels of two INSERTs each take 48 steps,
    not 2^24); ATTDEFs, which an INSERT does not explode, are not counted.
    None when a block inserts itself: the reading reports that, and counts
    as it goes."""
    counts: dict[str, int] = {}
    open_: set[str] = set()

    class Cycle(Exception):
        pass

    def of(entities: Iterable[Any]) -> int:
        n = 0
        for e in entities:
            kind = e.dxftype()
            if kind == "ATTDEF":
                continue
            n += 1
            if kind == "INSERT":
                n += block(e.dxf.get("name", ""))
        return n

    def block(name: str) -> int:
        if name in counts:
            return counts[name]
        if name in open_:
            raise Cycle
        layout = doc.blocks.get(name)
        if layout is None:
            return 0
        open_.add(name)
        counts[name] = of(layout)
        open_.discard(name)
        return counts[name]

    try:
        return of(doc.modelspace())
    except (Cycle, RecursionError):
        return None


def read_drawing(doc: Any, origin: Point = (0.0, 0.0), tolerance: float = SPLINE_TOL) -> Reading:
    """Read an ezdxf document's model space: every entity becomes items, a
    label, or a problem line (TooBig: the drawing expands past ENTITY_BUDGET,
    found by counting before any block is exploded, or while reading)."""
    problems: list[str] = []
    labels: list[Label] = []
    items: list[Item] = []
    budget = _Budget(tol=check_tolerance(tolerance))
    if (expanded_count(doc) or 0) > budget.left:
        raise budget.refusal()
    for e in doc.modelspace():
        items += _entity_items(e, origin, problems, labels, budget)
    return Reading(items, labels, problems, budget.splines, budget.tol)


def convert(doc: Any, origin: Point = (0.0, 0.0), tolerance: float = SPLINE_TOL) -> Conversion:
    """Items and problems of an ezdxf document's model space."""
    reading = read_drawing(doc, origin, tolerance)
    problems = reading.problems
    ordered_items, ordered = _order(reading.items, reading.labels, problems)
    return Conversion(ordered_items, problems, ordered, reading.bbox, reading.splines,
                      reading.tolerance)


def package_name(path: str | Path) -> str:
    """A package name from a file name: upper case, at most 18 characters."""
    stem = re.sub(r"[^A-Za-z0-9_-]", "_", Path(path).stem).upper() or "DXF"
    return stem[:18] + ("_" if stem in ("C", "E") else "")    # a bare C or E ends a package


def deck_text(conv: Conversion, name: str, start_mm: Point | None = None,
              tools: tuple[Decimal, Decimal, Decimal] | None = None, job: str = "DXF2DECK") -> str:
    """The card deck of a conversion: one package with a P card (the start
    point's place on the field, the tools, deck order when labelled)."""
    if start_mm is None:
        x0, y0 = (MARGIN_MM - conv.bbox[0], MARGIN_MM - conv.bbox[1]) if conv.bbox else (0, 0)
        start_mm = (max(x0, 0.0), max(y0, 0.0))
    sx, sy = _u(start_mm[0]), _u(start_mm[1])
    w = tools or (None, None, None)
    body = [cards.p_card(sx, sy, *w, order="D" if conv.ordered else None)]
    for it in conv.items:
        body += it.cards
    return cards.deck([cards.CardPackage(name, body)], job=job)


class Unreadable(Exception):
    """A file that is not a DXF drawing ezdxf can read: the message names it."""


def open_drawing(path: str) -> Any:
    """The drawing of a DXF file, with its model space, or Unreadable."""
    try:
        doc = ezdxf.readfile(path)
        doc.modelspace()
    except OSError as exc:
        raise Unreadable(f"{path}: {exc.strerror or exc}") from None
    except ezdxf.DXFError as exc:
        raise Unreadable(f"{path}: not a DXF drawing: {exc}") from None
    except (ValueError, TypeError, LookupError, StopIteration, EOFError,
            ArithmeticError) as exc:
        # ezdxf's tag loader raises these on a malformed file (a value that
        # is not a number, or inf where an integer belongs; a group code
        # without its value at the end, a file without the model space's
        # layout)
        raise Unreadable(f"{path}: not a DXF drawing: {type(exc).__name__} "
                         f"{exc}".rstrip()) from None
    return doc


def _run(args: argparse.Namespace) -> int:
    try:
        origin = mm_list(args.origin, "--origin", 2) if args.origin else (0.0, 0.0)
        start = mm_list(args.start, "--start", 2) if args.start else None
        tools = (tuple(Decimal(str(t)) for t in mm_list(args.tools, "--tools", 3))
                 if args.tools else None)
        if tools is not None and not all(Decimal("0.01") <= t <= 20
                                         and t == t.quantize(Decimal("0.01")) for t in tools):
            raise ValueError(f"--tools {args.tools}: each tool is 0.01 to 20.00 mm, in whole "
                             f"0.01 mm")
        if start is not None and not all(0 <= v <= FIELD_MM for v in start):
            raise ValueError(f"--start {args.start}: the start point's place on the field is "
                             f"X,Y, each 0 to {FIELD_MM:g} mm")
        tol = check_tolerance(args.tolerance)
        if args.name is not None and (not re.fullmatch(r"[A-Za-z0-9_-]{1,18}", args.name)
                                      or args.name in ("C", "E")):
            raise ValueError(f"--name {args.name!r}: 1 to 18 letters, digits, - or _ (the "
                             f"name card's columns 1-18, and the stem of TENZOR's files), "
                             f"not a bare C or E (they end a package)")
    except (ValueError, ArithmeticError) as exc:
        print(f"dxf2deck: {exc}", file=sys.stderr)
        return 2
    try:
        doc = open_drawing(args.drawing)
    except Unreadable as exc:
        print(f"dxf2deck: {exc}", file=sys.stderr)
        return 2
    try:
        conv = convert(doc, origin, tol)
    except TooBig as exc:
        print(f"dxf2deck: {args.drawing}: {exc}", file=sys.stderr)
        return 1
    for line in conv.problems:
        print(f"dxf2deck: {args.drawing}: {line}", file=sys.stderr)
    if conv.splines:
        print(f"dxf2deck: {args.drawing}: {conv.splines} SPLINE{'s' if conv.splines > 1 else ''} "
              f"flattened into chords within {conv.tolerance:g} mm", file=sys.stderr)
    if not conv.items:
        print(f"dxf2deck: {args.drawing}: nothing to draw", file=sys.stderr)
        return 1
    text = deck_text(conv, args.name or package_name(args.drawing), start, tools,
                     job=f"DXF2DECK {Path(args.drawing).name}"[:60])
    if args.output:
        try:
            write_whole(args.output, text, inputs=[args.drawing])
        except OSError as exc:
            print(f"dxf2deck: {args.output}: {exc.strerror or exc}", file=sys.stderr)
            return 2
    else:
        sys.stdout.write(text)
    unmapped = [p for p in conv.problems if "is not a label" not in p]
    return 1 if unmapped else 0


DXF2DECK_HELP = (
    "Turn a DXF drawing (mm) into a card deck: CIRCLE -> pad (layer RING*: "
    "circle), LWPOLYLINE/POLYLINE/LINE -> conductor (constant width, else "
    "a layer name ending _W<mm>, else the tool; closed rectangles on a PAD* "
    "layer -> rectangular pads), SPLINE -> conductor of chords within "
    "--tolerance, ARC -> arc, INSERT exploded; TEXT labels "
    "FIRST, LAST, 1, 2, 3 ... attach to the nearest item and fix the order.  "
    "Whatever cannot be mapped is reported with its handle and layer (exit "
    "status 1; the deck is still written).")


def _dxf2deck_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("drawing", metavar="DRAWING.dxf")
    p.add_argument("-o", "--output", metavar="DECK", help="output deck (default stdout)")
    p.add_argument("--origin", metavar="X,Y",
                   help="the drawing point (mm) that becomes the start point (default 0,0)")
    p.add_argument("--start", metavar="X0,Y0",
                   help="the start point's place on the field, mm (default: the drawing's "
                        f"lower-left corner {MARGIN_MM} mm inside the field)")
    p.add_argument("--tools", metavar="W1,W2,W3", help="tools of the P card, mm")
    p.add_argument("--name", help="package name (default: from the file name)")
    p.add_argument("--tolerance", metavar="MM", type=float, default=SPLINE_TOL,
                   help=f"SPLINEs are flattened into chords within this (default {SPLINE_TOL} mm)")
    p.set_defaults(func=_run)


def add_dxf2deck(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("dxf2deck", help="a DXF drawing to a TENZOR card deck (seed 001)",
                       description=DXF2DECK_HELP)
    _dxf2deck_arguments(p)


@quiet_when_output_closes
def main(argv: Sequence[str] | None = None) -> int:
    """The console script ``dxf2deck``: ``python -m seeds dxf2deck`` alone."""
    parser = Parser(prog="dxf2deck", description=DXF2DECK_HELP)
    _dxf2deck_arguments(parser)
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:          # argparse: --help (0) or usage error (2)
        return int(exc.code or 0)
    return int(args.func(args))


def iter_problem_handles(problems: Sequence[str]) -> Iterator[str]:
    """The handles named in problem lines (for tests and tools)."""
    for line in problems:
        m = re.search(r"#([0-9A-Fa-f]+)", line)
        if m:
            yield m.group(1)


# ---------------------------------------------------------------------------
# The known board of the round trip.
# ---------------------------------------------------------------------------
D = Decimal  # the board's figures are exact decimals, written short

# The known board of the DXF round trip (seed 001), as a card deck and as
# a DXF drawing written with ezdxf.
#
#     python -m seeds dxfboard examples/dxf
#
# writes ``board.dxf`` (the drawing, with the paper's ordering labels, a
# macro, a hint and two entities dxf2deck cannot map: an ELLIPSE and a POINT)
# and ``board-known.crd``
# (the same board as cards, written directly).  ``python -m seeds dxf2deck
# examples/dxf/board.dxf -o examples/dxf/board.crd`` must give a deck whose
# tapes draw exactly the known board: seeds/tests/test_seed001_dxf.py runs
# TENZOR on it and checks every tape against ``board-known.crd``'s ideal
# layers.  The files are byte-identical from run to run (ezdxf's fixed
# metadata: no clock, no random GUID).
#
# Board (mm, start point at the drawing's origin): a DIP-8 footprint of 1.6 mm
# pads, four 3.5 mm mounting holes (large-pad tape), five 2 x 5 mm connector
# fingers (closed rectangles on layer PAD), a 1.5 mm supply conductor
# (constant width), a signal on layer 0 (the tool's width), a LINE on layer
# SIGNAL_W0.8 (the layer rule), an ARC and a circle on layer RING.
BOARD_NAME = "BOARD"
#: Where dxf2deck puts the start point by default: the lower-left corner of
#: the board (x: a mounting hole's edge at 2.25 mm; y: the fingers' at 2 mm)
#: 10 mm inside the field.
START_MM = (D("7.75"), D("8.00"))

DIP = [(D("20.00"), D("20.00") + D("2.54") * i) for i in range(4)] + \
      [(D("27.62"), D("20.00") + D("2.54") * i) for i in range(4)]
HOLES = [(D(4), D(4)), (D(56), D(4)), (D(4), D(46)), (D(56), D(46))]
FINGERS = [(D("30.00") + D("2.54") * i, D("4.50")) for i in range(5)]
SUPPLY = [(D(8), D(10)), (D(50), D(10)), (D(50), D(40))]
SIGNAL1 = [(D("20.00"), D("27.62")), (D(14), D(34)), (D(14), D(42))]
SIGNAL2 = [(D("27.62"), D("20.00")), (D(36), D(20))]
ARC = ((D(44), D(28)), D(4))                        # 0 to 90 degrees, counter-clockwise
RING = ((D(10), D(30)), D(3))

#: Labels: text -> insertion point.  The order they give: FIRST the supply,
#: 1 the LINE, 2 the arc, 3 the signal on layer 0, 4 the LINE again (the
#: paper's "later numbers" for a path walked twice), LAST the ring.
LABELS = [("FIRST OUT 1", (30, 11.5)), ("1", (32, 21)), ("2", (47, 31)), ("3", (15, 38)),
          ("4", (33, 19)), ("LAST", (10, 34))]


def known_cards() -> list[str]:
    """The board as cards, in the order the labels ask for."""
    p = cards.p_card(*START_MM, order="D")
    pads = [cards.d_card(x, y, D("1.6")) for x, y in DIP]
    pads += [cards.d_card(x, y, D("3.5")) for x, y in HOLES]
    pads += [cards.d_card(x, y, D(2), D(5)) for x, y in FINGERS]

    def cond(pts: list, w: D | None) -> list[str]:
        return [cards.l_card(*pts[0], w)] + [cards.plus_card(*q) for q in pts[1:]]

    (cx, cy), r = ARC
    arc = [cards.a_card("-", cx, cy, cx + r, cy, cx, cy + r)]
    ring = [cards.o_card("-", *RING[0], RING[1])]
    sig2 = cond(SIGNAL2, D("0.8"))
    # deck order: FIRST, 1, 2, 3, 4, then the unlabelled items in drawing
    # order (as write_dxf draws them), then LAST
    return [p] + cond(SUPPLY, D("1.5")) + sig2 + arc + cond(SIGNAL1, None) + sig2 + pads + ring


def known_deck() -> str:
    return cards.deck([cards.CardPackage(BOARD_NAME, known_cards())], job="DXF ROUND TRIP, KNOWN BOARD")


def write_dxf(path: str | Path, offset: tuple[float, float] = (0.0, 0.0)) -> None:
    """The board as a DXF drawing (R2000), every point moved by ``offset``
    mm (so ``dxf2deck --origin`` can be tested)."""

    ox, oy = offset

    def pt(p: tuple) -> tuple[float, float]:
        return float(p[0]) + ox, float(p[1]) + oy

    saved = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        doc = ezdxf.new("R2000")
        for name in ("PAD", "SIGNAL_W0.8", "RING", "OUTLINE", "NOTES"):
            doc.layers.add(name)
        msp = doc.modelspace()
        # drawing order: conductors, arc, pads, ring (the unlabelled pads
        # follow the labelled items in this order)
        msp.add_lwpolyline([pt(p) for p in SUPPLY], dxfattribs={"const_width": 1.5})
        msp.add_line(pt(SIGNAL2[0]), pt(SIGNAL2[1]), dxfattribs={"layer": "SIGNAL_W0.8"})
        (cx, cy), r = ARC
        msp.add_arc(pt((cx, cy)), float(r), 0, 90)
        msp.add_lwpolyline([pt(p) for p in SIGNAL1])
        for x, y in DIP:
            msp.add_circle(pt((x, y)), 0.8)
        for x, y in HOLES:
            msp.add_circle(pt((x, y)), 1.75)
        for x, y in FINGERS:
            x0, x1, y0, y1 = float(x) - 1, float(x) + 1, float(y) - 2.5, float(y) + 2.5
            msp.add_lwpolyline([pt((x0, y0)), pt((x1, y0)), pt((x1, y1)), pt((x0, y1))],
                               close=True, dxfattribs={"layer": "PAD"})
        msp.add_circle(pt(RING[0]), float(RING[1]), dxfattribs={"layer": "RING"})
        for text, at in LABELS:
            msp.add_text(text, height=1.0, dxfattribs={"insert": pt(at), "layer": "NOTES"})
        # what dxf2deck reports and leaves out: a hint, an ellipse, a point
        # (a SPLINE would be flattened into a conductor of chords)
        msp.add_text("DRILL 0.8 MM", height=1.0, dxfattribs={"insert": pt((40, 46)),
                                                             "layer": "NOTES"})
        msp.add_ellipse(pt((30, -2)), (30, 0), 0.1, dxfattribs={"layer": "OUTLINE"})
        msp.add_point(pt((30, 25)), dxfattribs={"layer": "OUTLINE"})
        buf = io.StringIO()
        doc.write(buf)
        write_whole(path, buf.getvalue().encode(doc.output_encoding, errors="dxfreplace"))
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = saved


def _run_board(args: argparse.Namespace) -> int:

    out = Path(args.dir)
    try:
        out.mkdir(parents=True, exist_ok=True)
        write_dxf(out / "board.dxf")
        write_whole(out / "board-known.crd", known_deck())
    except OSError as exc:
        print(f"dxfboard: {out}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    return 0


def add_dxfboard(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("dxfboard", help="write the DXF round trip's known board (seed 001)",
                       description="Write DIR/board.dxf (with ezdxf) and DIR/board-known.crd: "
                                   "the same board as a drawing and as cards.")
    p.add_argument("dir", nargs="?", default="examples/dxf", metavar="DIR",
                   help="where to write them (default examples/dxf, the project's own "
                        "copies, when run in the project's folder)")
    p.set_defaults(func=_run_board)
