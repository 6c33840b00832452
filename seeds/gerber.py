"""gerber2deck: a board's copper layer (RS-274X) and drill file (Excellon) to
a TENZOR card deck whose three tapes draw that copper (docs/GERBER.md).

gerbonara reads the files (RS-274X and Excellon, with their odd headers and
implicit number formats); shapely does the geometry. Nothing here parses
Gerber or Excellon text itself.

What becomes what:

* round and axis-aligned rectangular flashes: ``D`` cards, in rows of equal
  pads where they line up (N, SX, SY); any flash whose outline is an
  axis-aligned rectangle (a ROTATEDRECT macro turned by 0 or 90 degrees, say)
  counts as one;
* obround flashes: a short conductor of the obround's width;
* tracks (lines of a round aperture): ``L``/``+`` conductors of their width,
  chained where one ends where the next begins; a zero-length track is a
  round pad;
* arcs of the conductor tool's width: ``A`` cards (``O`` for a full circle);
  wider arcs: conductors along chords within ``CHORD_TOL`` of the arc;
* everything else (rounded, rotated, octagonal and other macro pads,
  regions, features cut by a later clear-polarity object): strokes of the
  conductor tool that fill the outline within the tool's reach (``fill``).

Coordinates: the start point is the lower-left corner of the copper (and the
holes), in whole 0.01 mm; the P card places it at ``--start`` (default
10, 10 mm) on the field.
"""
from __future__ import annotations

import argparse
import math
import re
import sys
import time
import warnings
from collections import Counter, defaultdict
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from decimal import Decimal
from pathlib import Path

import shapely
import shapely.affinity
import shapely.errors
from shapely.geometry import LineString, Point, Polygon, box
from shapely.geometry.base import BaseGeometry

from harness import cards
from harness.files import quiet_when_output_closes, write_whole

from .contour import FIELD_MM
from .options import Parser, mm_list

#: where the start point goes on the field by default (mm)
START_MM = (10.0, 10.0)
#: how far an arc's chords may stray from it (mm)
CHORD_TOL = 0.005
#: how far a filled outline's strokes may be simplified (mm)
SIMPLIFY_MM = 0.004
#: the narrowest feature the deck can hold (one unit of 0.01 mm)
MIN_FEATURE_MM = 0.01
#: pads up to this size go on the small-pad tape (TENZOR's default DMAX)
DMAX_MM = 2.0
#: the tool when the board has no tracks and its pads allow it
DEFAULT_TOOL_MM = 0.25
#: the widest tool a P card may name (TENZOR's limit): wider copper is
#: drawn in several passes of it
MAX_TOOL_MM = 20.0
#: package names: the stem cut to this many characters, so NAME-DRILL fits 18
NAME_LEN = 12


class Refused(Exception):
    """A board the deck cannot hold (exit 1, no deck)."""


class Unreadable(Exception):
    """A file that cannot be read (exit 2)."""


def progress(msg: str) -> None:
    """A progress line on standard error."""
    print(f"gerber2deck: {msg}", file=sys.stderr, flush=True)


def _u(v: float) -> int:
    return int(round(v * 100.0))


def _floor_u(v: float) -> int:
    return int(math.floor(v * 100.0 + 1e-6))


# ---------------------------------------------------------------------------
# Reading.
# ---------------------------------------------------------------------------
def read_gerber(path: str | Path):
    """The GerberFile of a copper layer (Unreadable with one line)."""
    from gerbonara import GerberFile
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            g = GerberFile.open(path)
    except OSError as exc:
        raise Unreadable(f"{path}: {exc.strerror or exc}") from None
    except Exception as exc:                       # gerbonara's own errors
        raise Unreadable(f"{path}: not an RS-274X Gerber file gerbonara can read "
                         f"({type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''})"
                         ) from None
    if not g.objects:
        raise Unreadable(f"{path}: no copper in it (is it a Gerber file of a copper layer? "
                         f"an Excellon drill file goes after --drill)")
    return g


#: the end of a Gerber file, M02 (or the deprecated M00), as a command of its own
END_OF_FILE = re.compile(r"(?:^|[*%])\s*M0*[02]\*")


def ends_without_m02(path: str | Path) -> bool:
    """Whether a Gerber file lacks its end-of-file command (M02): gerbonara
    reads what there is without a word, and a file cut short in a copy or a
    download then loses its last objects silently."""
    try:
        text = Path(path).read_bytes().decode("latin-1")
    except OSError:
        return False                   # read_gerber has said so already
    return END_OF_FILE.search(text) is None


@dataclass
class Hole:
    x: float          # mm, the board's coordinates
    y: float
    dia: float


#: gerbonara's warnings for drill hits it leaves out, and what they mean.
DROPPED_HITS = {
    "Routing command found before first tool definition.":
        "a hit before any tool is selected (a T line with the tool's number)",
    "Bare coordinate after end of file": "a hit after the end of the program (M30)",
}


#: an Excellon canned slot, ``XaYbG85XcYd`` (KiCad writes its oval holes so):
#: gerbonara knows no G85 and refuses the whole file at that line.
G85_SLOT = re.compile(r"^[^;(]*G85")


#: a line's coordinates, in the file's own notation: what comes before them
#: (a G code, say), X, Y, and what follows
_HIT = re.compile(r"^(?P<pre>[^XY;(]*)(?:X(?P<x>[+-]?[0-9.]+))?(?:Y(?P<y>[+-]?[0-9.]+))?"
                  r"(?P<rest>.*)$")


def _without_slots(lines: list[str], slots: set[int]) -> list[str]:
    """The file's lines with each G85 slot (line numbers ``slots``, from 1)
    blanked.  A slot leaves the drill at its end, and coordinates are modal:
    a later line that leaves out X or Y means the slot end's.  Since
    gerbonara no longer sees the slot, such a line is given that coordinate,
    as the slot wrote it (the file's own number format), until a line gives
    it again."""
    out, carried = [], {}
    for k, line in enumerate(lines, start=1):
        if k in slots:
            start, _, end = line.strip().partition("G85")
            for part in (start, end):
                m = _HIT.match(part)
                carried.update({axis: m[axis] for axis in "xy" if m[axis] is not None})
            out.append("")
            continue
        m = _HIT.match(line.strip())
        if carried and (m["x"] is not None or m["y"] is not None):
            x, y = m["x"] or carried.get("x"), m["y"] or carried.get("y")
            line = (m["pre"] + ("" if x is None else "X" + x) + ("" if y is None else "Y" + y)
                    + m["rest"])
            carried = {}
        out.append(line)
    return out


def _excellon_open(path: str | Path, text: str):
    """gerbonara's ExcellonFile.open (which also reads the format files some
    CAD tools write beside a drill file) on ``text`` instead of the file's
    own text."""
    from gerbonara import ExcellonFile

    class Given(ExcellonFile):
        @classmethod
        def from_string(kls, data, **kwargs):
            return ExcellonFile.from_string(text, **kwargs)
    return Given.open(path)


def read_drill(path: str | Path) -> tuple[list[Hole], int, list[int]]:
    """The holes of an Excellon file in file order, how many slots routed
    with M15/M16 it has, and the numbers of its lines that are G85 slots;
    the slots are left out.  A G85 line is blanked before gerbonara reads
    the file, so that its line numbers stay the file's (``_without_slots``)."""
    from gerbonara.graphic_objects import Flash
    from gerbonara.utils import MM
    try:
        text = Path(path).read_text(encoding="latin-1")
        lines = text.splitlines()
        g85 = [k for k, line in enumerate(lines, start=1) if G85_SLOT.match(line.strip())]
        if g85:
            text = "\n".join(_without_slots(lines, set(g85))) + "\n"
        with warnings.catch_warnings(record=True) as said:
            warnings.simplefilter("always")
            x = _excellon_open(path, text)
    except OSError as exc:
        raise Unreadable(f"{path}: {exc.strerror or exc}") from None
    except Exception as exc:
        raise Unreadable(f"{path}: not an Excellon drill file gerbonara can read "
                         f"({type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''})"
                         ) from None
    # gerbonara reads on past a hit it cannot place, with only a warning
    # ("FILE:LINE "TEXT": what"); the hole would be missing from the tour
    for w in said:
        text = str(w.message)
        for what, why in DROPPED_HITS.items():
            if text.endswith(what):
                where = text[:-len(what)].rstrip(": ")
                lost = sum(str(v.message).endswith(what) for v in said)
                raise Unreadable(f"{where}: {why}; gerbonara leaves such hits out ({lost} in "
                                 f"this file), and their holes would be missing from the deck")
    holes, slots = [], 0
    for o in x.objects:
        if isinstance(o, Flash):
            if o.unit is None:
                raise Unreadable(f"{path}: no unit: its header says neither METRIC nor INCH")
            o = o.converted(MM)
            dia = o.aperture.equivalent_width(MM)
            holes.append(Hole(float(o.x), float(o.y), float(dia)))
        else:
            slots += 1
    if not holes and not slots and not g85:
        raise Unreadable(f"{path}: no drill hits in it (is it an Excellon drill file?)")
    return holes, slots, g85


# ---------------------------------------------------------------------------
# Geometry of gerbonara's primitives (mm).
# ---------------------------------------------------------------------------
def _arc_points(x1, y1, x2, y2, cx, cy, clockwise, tol=CHORD_TOL):
    """Points along an arc (full circle when the ends meet), chords within tol."""
    r = math.hypot(x1 - cx, y1 - cy)
    a0 = math.atan2(y1 - cy, x1 - cx)
    a1 = math.atan2(y2 - cy, x2 - cx)
    sweep = a1 - a0
    if clockwise:
        while sweep >= -1e-12:
            sweep -= 2 * math.pi
    else:
        while sweep <= 1e-12:
            sweep += 2 * math.pi
    if math.hypot(x2 - x1, y2 - y1) > 1e-9 and abs(abs(sweep) - 2 * math.pi) < 1e-9:
        sweep = 0.0
    step = 2 * math.acos(max(-1.0, 1 - tol / r)) if r > tol else math.pi / 2
    n = max(2, int(math.ceil(abs(sweep) / max(step, 1e-6))) + 1)
    return [(cx + r * math.cos(a0 + sweep * i / (n - 1)),
             cy + r * math.sin(a0 + sweep * i / (n - 1))) for i in range(n)], r, sweep


def prim_geom(p) -> BaseGeometry:
    """A gerbonara graphic primitive (in mm) as a shapely area."""
    from gerbonara import graphic_primitives as gp
    if isinstance(p, gp.Circle):
        return Point(p.x, p.y).buffer(p.r, quad_segs=16)
    if isinstance(p, gp.Line):
        if math.hypot(p.x2 - p.x1, p.y2 - p.y1) < 1e-9:
            return Point(p.x1, p.y1).buffer(p.width / 2, quad_segs=16)
        return LineString([(p.x1, p.y1), (p.x2, p.y2)]).buffer(p.width / 2, quad_segs=16)
    if isinstance(p, gp.Arc):
        pts, _, _ = _arc_points(p.x1, p.y1, p.x2, p.y2, p.cx, p.cy, p.clockwise, tol=0.001)
        return LineString(pts).buffer(p.width / 2, quad_segs=16)
    if isinstance(p, gp.Rectangle):
        poly = p.to_arc_poly()
        return Polygon(poly.outline).buffer(0)
    if isinstance(p, gp.ArcPoly):
        pts: list[tuple[float, float]] = []
        for (x1, y1), (x2, y2), (clockwise, (cx, cy)) in p.segments:
            if clockwise is None:
                pts.append((x1, y1))
            else:
                pts += _arc_points(x1, y1, x2, y2, cx, cy, clockwise, tol=0.001)[0][:-1]
        if len(pts) < 3:
            return Polygon()
        return Polygon(pts).buffer(0)
    raise ValueError(f"unknown primitive {type(p).__name__}")


def object_geom(o) -> BaseGeometry:
    """A graphic object's area in mm (its clear primitives taken away)."""
    from gerbonara.utils import MM
    from gerbonara.graphic_objects import Flash
    geom: BaseGeometry = Polygon()
    dark_first = o.polarity_dark
    if isinstance(o, Flash):
        # a flash is its aperture drawn at 0, 0 and moved: gerbonara 1.5.0 leaves
        # the outline primitives of some macros (OC8's polygon) at 0, 0 when it
        # flashes them elsewhere
        x, y = o.unit.convert_to(MM, o.x), o.unit.convert_to(MM, o.y)
        for p in o.aperture.flash(0, 0, unit=MM, polarity_dark=o.polarity_dark):
            g = shapely.affinity.translate(prim_geom(p), x, y)
            geom = geom.union(g) if p.polarity_dark == dark_first else geom.difference(g)
        return geom
    for p in o.to_primitives(MM):
        g = prim_geom(p)
        # a primitive's polarity is relative to its object's
        if p.polarity_dark == dark_first:
            geom = geom.union(g)
        else:
            geom = geom.difference(g)
    return geom


# ---------------------------------------------------------------------------
# The conversion.
# ---------------------------------------------------------------------------
@dataclass
class Pad:
    x: int
    y: int
    w: int
    h: int | None       # None: round


@dataclass
class Conversion:
    """The items of one copper layer, in 0.01 mm relative to the start point."""

    pads: list[Pad] = field(default_factory=list)
    tracks: list[tuple[int, list[tuple[int, int]]]] = field(default_factory=list)  # (w, pts)
    arcs: list[str] = field(default_factory=list)          # A/O cards (tool W3)
    fills: list[list[tuple[int, int]]] = field(default_factory=list)   # closed rings, tool W3
    tools: tuple[int, int, int] = (0, 0, 0)
    origin: tuple[float, float] = (0.0, 0.0)               # mm, the start point
    size: tuple[float, float] = (0.0, 0.0)                 # mm
    notes: list[str] = field(default_factory=list)
    copper: object = None            # STRtree of the dark objects' outlines, board mm


def _components(g: BaseGeometry) -> list[Polygon]:
    if g.is_empty:
        return []
    if isinstance(g, Polygon):
        return [g]
    return [c for c in getattr(g, "geoms", []) if isinstance(c, Polygon) and not c.is_empty] + \
        [p for c in getattr(g, "geoms", []) if not isinstance(c, Polygon)
         for p in _components(c)]


def _rings_of(g: BaseGeometry) -> list[list[tuple[float, float]]]:
    out = []
    for poly in _components(g):
        for ring in [poly.exterior, *poly.interiors]:
            line = LineString(ring.coords).simplify(SIMPLIFY_MM, preserve_topology=False)
            out.append(list(line.coords))
    return out


#: big outlines are hatched band by band (mm): each band's intersections stay small
BAND_MM = 4.0


def fill_rings(poly: BaseGeometry, tool_mm: float) -> list[list[tuple[float, float]]]:
    """Centre lines of a tool of tool_mm that fill poly within its reach.

    E, the outline eroded by the tool's radius r, is where the tool's centre
    may go without drawing outside. Its boundary (every ring) is drawn, and E
    is hatched by horizontal lines s = 2r' apart (r' = r - 0.01 mm: passes
    overlap by 0.02 mm, two rounding units). A point p of E is within s/2 of
    a hatch line; the vertical segment from p to it either stays in E (the
    line's stroke covers p) or crosses E's boundary within s/2 (the boundary
    stroke covers p); a point outside E that a disc of radius r inside the
    outline reaches is within r of E's boundary. So the strokes cover the
    outline opened by the tool and draw nothing outside it. Neighbouring
    hatch segments are joined into one zig-zag conductor where the link
    between them stays in E.
    """
    r = tool_mm / 2
    rp = max(r - 0.01, r * 0.6)
    s = 2 * rp
    E = poly.buffer(-r, quad_segs=8)
    if E.is_empty:
        return []
    strokes = _rings_of(E)
    x0, y0, x1, y1 = E.bounds
    n = max(1, math.ceil((y1 - y0) / s))
    ys = [y0 + ((y1 - y0) - (n - 1) * s) / 2 + k * s for k in range(n)]
    nb = max(1, math.ceil((y1 - y0) / BAND_MM))
    bands = [box(x0 - 1, y0 + i * (y1 - y0) / nb - s, x1 + 1, y0 + (i + 1) * (y1 - y0) / nb + s)
             for i in range(nb)] if nb > 1 else [None]
    for i, band in enumerate(bands):
        part = E if band is None else E.intersection(band)
        lo = y0 + i * (y1 - y0) / nb
        hi = y0 + (i + 1) * (y1 - y0) / nb
        mine = [y for y in ys if (band is None) or (lo <= y < hi or (i == nb - 1 and y >= hi))]
        if not mine or part.is_empty:
            continue
        lines = [LineString([(x0 - 1, y), (x1 + 1, y)]) for y in mine]
        cuts = shapely.intersection(part, lines)
        shapely.prepare(part)
        rows: list[list[tuple[float, float]]] = []
        for cut in cuts:
            segs = []
            for g in ([cut] if isinstance(cut, LineString) else getattr(cut, "geoms", [])):
                if isinstance(g, LineString) and g.length > 1e-6:
                    (ax, ay), (bx, by) = g.coords[0], g.coords[-1]
                    segs.append((min(ax, bx), max(ax, bx), ay))
            segs.sort()
            rows.append(segs)
        strokes += _zigzag(rows, part, s)
    return strokes


def _zigzag(rows, part: BaseGeometry, s: float) -> list[list[tuple[float, float]]]:
    """Hatch segments, row by row, joined into zig-zags where the link stays in part."""
    done: list[list[tuple[float, float]]] = []
    open_: list[list[tuple[float, float]]] = []     # chains ending on the previous row
    for segs in rows:
        nxt: list[list[tuple[float, float]]] = []
        for xa, xb, y in segs:
            best, bi, flip = None, -1, False
            for k, ch in enumerate(open_):
                ex, ey = ch[-1]
                for fl, sx in ((False, xa), (True, xb)):
                    d = abs(sx - ex)
                    if d <= 4 * s and (best is None or d < best):
                        best, bi, flip = d, k, fl
            a, b = ((xb, y), (xa, y)) if flip else ((xa, y), (xb, y))
            if bi >= 0 and part.covers(LineString([open_[bi][-1], a])):
                ch = open_.pop(bi)
                ch += [a, b]
                nxt.append(ch)
            else:
                nxt.append([a, b])
        done += open_
        open_ = nxt
    return done + open_


def _axis_rect(g: BaseGeometry) -> tuple[float, float, float, float] | None:
    """(cx, cy, w, h) when g is an axis-aligned rectangle."""
    if not isinstance(g, Polygon) or g.interiors:
        return None
    if g.is_empty:
        return None
    x0, y0, x1, y1 = g.bounds
    a = (x1 - x0) * (y1 - y0)
    if a <= 0 or abs(g.area - a) > 1e-6 * max(a, 1e-6) + 1e-9:
        return None
    return ((x0 + x1) / 2, (y0 + y1) / 2, x1 - x0, y1 - y0)


def _macro_kind(ap) -> str:
    name = getattr(getattr(ap, "macro", None), "name", None)
    if name:
        return re.sub(r"D?\d+$", "", name) or name
    return type(ap).__name__.replace("Aperture", "").lower()


def _object_text(o) -> str:
    """A graphic object as a user finds it in the file: what it is, its
    aperture's D code, where it starts (mm)."""
    from gerbonara.graphic_objects import Arc, Flash, Line, Region
    from gerbonara.utils import MM
    ap = getattr(o, "aperture", None)
    d = f" of D{ap.original_number}" if getattr(ap, "original_number", None) is not None else ""
    if isinstance(o, Flash):
        return f"the flash{d} at {o.x:.3f}, {o.y:.3f} mm"
    if isinstance(o, (Line, Arc)):
        return f"the {'line' if isinstance(o, Line) else 'arc'}{d} from {o.x1:.3f}, {o.y1:.3f} mm"
    if isinstance(o, Region) and o.outline:
        x, y = (o.unit.convert_to(MM, v) for v in o.outline[0])
        return f"the region (G36 to G37) from {x:.3f}, {y:.3f} mm"
    return f"a {type(o).__name__.lower()}"


#: No coordinate or aperture size of a board is more than this (mm, 10 km):
#: beyond it, shapely's arithmetic overflows (an aperture of 1e308 mm).
MAX_NUMBER_MM = 1e7


def _in_range(o) -> bool:
    """Whether every coordinate of a graphic object and every size of its
    aperture is a finite number (gerbonara reads "nan" and "inf" as numbers)
    of at most MAX_NUMBER_MM."""
    vals = [getattr(o, k) for k in ("x", "y", "x1", "y1", "x2", "y2", "cx", "cy")
            if hasattr(o, k)]
    vals += [v for pt in getattr(o, "outline", ()) for v in pt]
    ap = getattr(o, "aperture", None)
    for k in ("diameter", "w", "h", "hole_dia", "rotation", "parameters"):
        v = getattr(ap, k, None)
        vals += list(v) if isinstance(v, (tuple, list)) else [v]
    return all(abs(float(v)) <= MAX_NUMBER_MM for v in vals
               if isinstance(v, (int, float, Decimal)) and not isinstance(v, bool))


def convert(g, holes: Sequence[Hole] = (), tools: tuple[float, float, float] | None = None,
            verbose: bool = True) -> Conversion:
    """A copper layer (gerbonara GerberFile) as the items of a deck."""
    from gerbonara import apertures as ap_
    from gerbonara.graphic_objects import Arc, Flash, Line, Region
    from gerbonara.utils import MM

    t0 = time.monotonic()
    objs = [o if isinstance(o, Region) else o.converted(MM) for o in g.objects]
    for o in objs:
        # gerbonara refuses a line drawn with no aperture selected, but lets a
        # flash through with none
        if isinstance(o, Flash) and o.aperture is None:
            raise Refused(f"a flash (D03) at {o.x:.3f}, {o.y:.3f} mm with no aperture "
                          f"selected before it (a D10 or higher that an AD defines)")
        if not _in_range(o):
            raise Refused(f"{_object_text(o)}: a coordinate or an aperture's size is not "
                          f"a finite number of at most {MAX_NUMBER_MM:.0f} mm (10 km)")
    n = len(objs)
    geoms: list[BaseGeometry] = []
    last = time.monotonic()
    for i, o in enumerate(objs):
        try:
            geoms.append(object_geom(o))
        except (ValueError, ArithmeticError, IndexError, KeyError, TypeError,
                shapely.errors.ShapelyError) as exc:
            # gerbonara's (a macro missing a parameter) or shapely's
            raise Refused(f"{_object_text(o)} cannot be drawn ({exc})") from None
        if verbose and time.monotonic() - last > 2:
            progress(f"outlines: {i + 1} of {n} objects")
            last = time.monotonic()
    # Clear-polarity objects cut what came before them.
    clear_ix = [i for i, o in enumerate(objs) if not o.polarity_dark]
    tree = shapely.STRtree([geoms[i] for i in clear_ix]) if clear_ix else None
    cut_of: dict[int, list[int]] = {}
    dark_ix = [i for i, o in enumerate(objs) if o.polarity_dark]
    if tree is not None and dark_ix:
        pairs = tree.query([geoms[i] for i in dark_ix], predicate="intersects")
        for a, b in zip(*pairs):
            i, j = dark_ix[a], clear_ix[b]
            if j > i:
                cut_of.setdefault(i, []).append(j)

    dark = [gm for o, gm in zip(objs, geoms) if o.polarity_dark and not gm.is_empty]
    if not dark:
        raise Refused("no dark copper in it")
    conv = Conversion(copper=shapely.STRtree(dark))
    x0, y0, x1, y1 = shapely.total_bounds(dark)

    for h in holes:
        x0, y0 = min(x0, h.x - h.dia / 2), min(y0, h.y - h.dia / 2)
        x1, y1 = max(x1, h.x + h.dia / 2), max(y1, h.y + h.dia / 2)
    conv.origin = (math.floor(x0 * 100 + 1e-6) / 100, math.floor(y0 * 100 + 1e-6) / 100)
    conv.size = (x1 - conv.origin[0], y1 - conv.origin[1])
    # before any outline is filled: the hatching of a board kilometres wide
    # (a coordinate in the wrong format or unit) would take hours and all
    # the memory there is
    if max(conv.size) > FIELD_MM:
        raise Refused(f"the copper{' and holes span' if holes else ' spans'} "
                      f"{conv.size[0]:.2f} x {conv.size[1]:.2f} mm, more than the "
                      f"{FIELD_MM:g} x {FIELD_MM:g} mm field of the coordinatograph (are the "
                      f"coordinates in the unit and format the file's header says?)")
    ox, oy = conv.origin

    def pt(x: float, y: float) -> tuple[int, int]:
        return _u(x - ox), _u(y - oy)

    counts: Counter[str] = Counter()
    to_fill: list[BaseGeometry] = []
    narrow: list[str] = []
    prev_end: tuple[int, int, int] | None = None      # (w, x, y) of the last track
    for i, (o, gm) in enumerate(zip(objs, geoms)):
        if not o.polarity_dark:
            prev_end = None
            continue
        if gm.is_empty:
            counts["objects that draw nothing (an aperture of no size, a region of no "
                   "area) left out"] += 1
            prev_end = None
            continue
        if i in cut_of:
            cut = shapely.union_all([geoms[j] for j in cut_of[i]])
            rest = gm.difference(cut)
            if not rest.is_empty:
                to_fill.append(rest)
                counts["cut by clear polarity"] += 1
            prev_end = None
            continue
        ap = getattr(o, "aperture", None)
        if isinstance(o, Flash):
            prev_end = None
            if isinstance(ap, ap_.CircleAperture) and ap.hole_dia is None:
                d = float(ap.equivalent_width(MM))
                if d < MIN_FEATURE_MM:
                    narrow.append(f"a round flash of {d:.4f} mm at {o.x:.3f}, {o.y:.3f}")
                    continue
                conv.pads.append(Pad(*pt(o.x, o.y), _u(d), None))
                continue
            if isinstance(ap, ap_.ObroundAperture) and ap.hole_dia is None:
                bx0, by0, bx1, by1 = gm.bounds
                w, h = bx1 - bx0, by1 - by0
                cx, cy = (bx0 + bx1) / 2, (by0 + by1) / 2
                wd = min(w, h)
                if wd < MIN_FEATURE_MM:
                    narrow.append(f"an obround flash {wd:.4f} mm wide at {o.x:.3f}, {o.y:.3f}")
                    continue
                if abs(w - h) < 0.005:
                    conv.pads.append(Pad(*pt(cx, cy), _u(wd), None))
                    continue
                half = (max(w, h) - wd) / 2
                a, b = ((cx - half, cy), (cx + half, cy)) if w > h else ((cx, cy - half), (cx, cy + half))
                conv.tracks.append((_u(wd), [pt(*a), pt(*b)]))
                counts["obround pads drawn as short conductors of their width"] += 1
                continue
            rect = _axis_rect(gm)
            if rect is not None:
                cx, cy, w, h = rect
                if min(w, h) < MIN_FEATURE_MM:
                    narrow.append(f"a rectangular flash {min(w, h):.4f} mm wide at "
                                  f"{o.x:.3f}, {o.y:.3f}")
                    continue
                conv.pads.append(Pad(*pt(cx, cy), _u(w), _u(h)))
                if not isinstance(ap, ap_.RectangleAperture):
                    counts[f"{_macro_kind(ap)} pads that are plain rectangles: D cards"] += 1
                continue
            to_fill.append(gm)
            counts[f"{_macro_kind(ap)} pads filled by strokes"] += 1
            continue
        if isinstance(o, (Line, Arc)) and isinstance(ap, ap_.CircleAperture) and ap.hole_dia is None:
            w = float(ap.equivalent_width(MM))
            if w < MIN_FEATURE_MM:
                narrow.append(f"a track {w:.4f} mm wide at {o.x1:.3f}, {o.y1:.3f}")
                continue
            wu = _u(w)
            if isinstance(o, Line):
                a, b = pt(o.x1, o.y1), pt(o.x2, o.y2)
                if a == b:
                    conv.pads.append(Pad(a[0], a[1], wu, None))
                    counts["zero-length tracks drawn as round pads"] += 1
                    prev_end = None
                    continue
                if prev_end == (wu, *a) and conv.tracks and conv.tracks[-1][0] == wu:
                    conv.tracks[-1][1].append(b)
                else:
                    conv.tracks.append((wu, [a, b]))
                prev_end = (wu, *b)
                continue
            prev_end = None
            cx, cy = o.center
            pts, r, sweep = _arc_points(o.x1, o.y1, o.x2, o.y2, cx, cy, o.clockwise)
            conv.tracks.append((wu, [pt(*p) for p in pts]))   # decided below (A or chords)
            conv.tracks[-1] = (wu, conv.tracks[-1][1], (o.x1, o.y1, o.x2, o.y2, cx, cy,
                                                        o.clockwise, r, sweep))  # type: ignore
            continue
        prev_end = None
        to_fill.append(gm)
        if isinstance(o, Region):
            counts["regions (G36/G37) filled by strokes"] += 1
        else:
            counts[f"{type(o).__name__.lower()}s of a {_macro_kind(ap)} aperture filled by strokes"] += 1

    if narrow:
        raise Refused(f"{len(narrow)} feature(s) narrower than {MIN_FEATURE_MM} mm, the "
                      f"deck's unit, e.g. {narrow[0]}; such copper cannot be drawn")
    if clear_ix:
        counts[f"clear-polarity objects honoured ({len(clear_ix)})"] += 0

    # The tools: W3 no wider than the narrowest track, no pad smaller than its tool.
    if tools is not None:
        w1, w2, w3 = (_u(t) for t in tools)
    else:
        widths = [t[0] for t in conv.tracks]
        w3 = min(widths) if widths else _u(DEFAULT_TOOL_MM)
        small = [min(p.w, p.h or p.w) for p in conv.pads if max(p.w, p.h or 0) <= _u(DMAX_MM)]
        large = [min(p.w, p.h or p.w) for p in conv.pads if max(p.w, p.h or 0) > _u(DMAX_MM)]
        w3 = min([w3, _u(MAX_TOOL_MM)] + small + large)
        w1 = min([w3] + small)
        w2 = min([w3] + large)
    conv.tools = (w1, w2, w3)
    if min(conv.tools) < 1:
        raise Refused("a tool of less than 0.01 mm")
    for p in conv.pads:
        tool = w1 if max(p.w, p.h or 0) <= _u(DMAX_MM) else w2
        if min(p.w, p.h or p.w) < tool:
            raise Refused(f"a pad of {min(p.w, p.h or p.w) / 100:.2f} mm at board "
                          f"{p.x / 100 + ox:.2f}, {p.y / 100 + oy:.2f} mm is smaller than its "
                          f"tool ({tool / 100:.2f} mm): give smaller tools with --tools")

    # Tracks narrower than W3 cannot be drawn; arcs of W3 become A cards.
    tracks = []
    chorded = 0
    for t in conv.tracks:
        wu, pts = t[0], t[1]
        if wu < w3:
            raise Refused(f"a track {wu / 100:.2f} mm wide is narrower than the conductor tool "
                          f"W3 = {w3 / 100:.2f} mm: give a smaller W3 with --tools")
        if len(t) == 3:
            x1, y1, x2, y2, cx, cy, cw, r, sweep = t[2]
            card = _arc_card(pt(cx, cy), pt(x1, y1), pt(x2, y2), cw) if wu == w3 else None
            if card is not None:
                conv.arcs.append(card)
                continue
            chorded += 1
        tracks.append((wu, pts))
    conv.tracks = tracks
    if chorded:
        counts[f"arc tracks drawn as conductors along chords within {CHORD_TOL} mm "
               f"(wider than W3, or their ends off the 0.01 mm grid)"] += chorded

    # Fill the rest with strokes of W3.
    if to_fill:
        whole = shapely.union_all(to_fill)
        polys = _components(whole)
        last = time.monotonic()
        lost = 0.0
        for k, poly in enumerate(polys):
            rings = fill_rings(poly, w3 / 100)
            if not rings:
                lost += poly.area
            for ring in rings:
                conv.fills.append([pt(x, y) for x, y in ring])
            if verbose and time.monotonic() - last > 2:
                progress(f"filling outlines: {k + 1} of {len(polys)} ({len(conv.fills)} strokes)")
                last = time.monotonic()
        r = w3 / 200
        for what, c in counts.items():
            if "filled by strokes" in what or "cut by clear" in what:
                conv.notes.append(f"{c} {what}; corners within {r * (math.sqrt(2) - 1):.3f} mm "
                                  f"(rounded to the tool's radius {r:.3f} mm)")
        if lost > 0:
            conv.notes.append(f"{lost:.3f} mm² of copper in outlines narrower than the tool "
                              f"({w3 / 100:.2f} mm) cannot be reached and is left out")
    for what, c in counts.items():
        if "filled by strokes" in what or "cut by clear" in what:
            continue
        conv.notes.append(f"{c} {what}" if c else what)
    if verbose:
        progress(f"{len(objs)} objects -> {len(conv.pads)} pads, {len(conv.tracks)} conductors, "
                 f"{len(conv.arcs)} arcs, {len(conv.fills)} fill strokes "
                 f"in {time.monotonic() - t0:.1f} s")
    return conv


def _arc_card(c: tuple[int, int], s: tuple[int, int], e: tuple[int, int], clockwise: bool
              ) -> str | None:
    """An A (or O) card of an arc whose ends, rounded, lie on its rounded
    circle within 0.01 mm (TENZOR's check); None when they do not."""
    r2 = (s[0] - c[0]) ** 2 + (s[1] - c[1]) ** 2
    if r2 == 0:
        return None
    r = math.sqrt(r2)
    direction = "+" if clockwise else "-"
    if s == e:
        return cards.o_card(direction, c[0], c[1], int(round(r))) if abs(r - round(r)) < 1e-9 \
            else None
    best = None
    for dx in (0, -1, 1):
        for dy in (0, -1, 1):
            q = (e[0] + dx, e[1] + dy)
            if abs(math.hypot(q[0] - c[0], q[1] - c[1]) - r) <= 0.5:
                best = q
                break
        if best:
            break
    if best is None or best == s:
        return None
    return cards.a_card(direction, c[0], c[1], s[0], s[1], best[0], best[1])


# ---------------------------------------------------------------------------
# Cards.
# ---------------------------------------------------------------------------
def pad_cards(pads: Iterable[Pad]) -> list[str]:
    """D cards, with equal pads in a line at an equal step as one row."""
    out: list[str] = []
    groups: dict[tuple, list[Pad]] = defaultdict(list)
    for p in pads:
        groups[(p.w, p.h)].append(p)
    for (w, h), ps in groups.items():
        left: list[Pad] = []
        for axis in (0, 1):
            lines: dict[int, list[Pad]] = defaultdict(list)
            for p in (ps if axis == 0 else left):
                lines[p.y if axis == 0 else p.x].append(p)
            rest: list[Pad] = []
            for _, row in sorted(lines.items()):
                row.sort(key=lambda p: (p.x, p.y) if axis == 0 else (p.y, p.x))
                i = 0
                while i < len(row):
                    j = i + 1
                    if j < len(row):
                        step = (row[j].x - row[i].x) if axis == 0 else (row[j].y - row[i].y)
                        while (j + 1 < len(row) and step > 0 and
                               ((row[j + 1].x - row[j].x) if axis == 0
                                else (row[j + 1].y - row[j].y)) == step):
                            j += 1
                        if step > 0 and j - i + 1 >= 2:
                            nrow = j - i + 1
                            sx, sy = (step, 0) if axis == 0 else (0, step)
                            out.append(cards.d_card(row[i].x, row[i].y, w, h, nrow, sx, sy))
                            i = j + 1
                            continue
                    rest.append(row[i])
                    i += 1
            left = rest
        out += [cards.d_card(p.x, p.y, w, h) for p in left]
    return out


def copper_cards(conv: Conversion) -> list[str]:
    """The data cards of a conversion (no P card)."""
    out = pad_cards(conv.pads)
    for w, pts in conv.tracks:
        out += _polyline(pts, w)
    out += conv.arcs
    for ring in conv.fills:
        out += _polyline(ring, None)
    return out


def _polyline(pts: Sequence[tuple[int, int]], w: int | None) -> list[str]:
    clean = [pts[0]]
    for p in pts[1:]:
        if p != clean[-1]:
            clean.append(p)
    if len(clean) == 1:                 # a ring that rounds to one point: a tiny stroke
        clean.append((clean[0][0] + 1, clean[0][1]))
    return [cards.l_card(clean[0][0], clean[0][1], w)] + [cards.plus_card(x, y) for x, y in clean[1:]]


def drill_tool(holes: Sequence[Hole]) -> int:
    """The tool (units) of the drill package: the smallest hole rounded down,
    0.01 to 20 mm."""
    return min(min(max(_floor_u(h.dia), 1) for h in holes), _u(MAX_TOOL_MM))


def drill_cards(holes: Sequence[Hole], origin: tuple[float, float]) -> tuple[list[str], int]:
    """One D card a hole, in file order, and the tool (units) for them."""
    ox, oy = origin
    tool = drill_tool(holes)
    return [cards.d_card(_u(h.x - ox), _u(h.y - oy), max(_u(h.dia), tool)) for h in holes], tool


def package_name(path: str | Path) -> str:
    stem = re.sub(r"[^A-Za-z0-9_-]", "_", Path(path).stem).upper() or "GERBER"
    return stem[:NAME_LEN] + ("_" if stem in ("C", "E") else "")   # a bare C or E ends a package


def deck_text(conv: Conversion, name: str, holes: Sequence[Hole] = (),
              start_mm: tuple[float, float] = START_MM, job: str = "GERBER2DECK") -> str:
    sx, sy = _u(start_mm[0]), _u(start_mm[1])
    w1, w2, w3 = conv.tools
    pkgs = [cards.CardPackage(name, [cards.p_card(sx, sy, w1, w2, w3, _u(DMAX_MM))]
                              + copper_cards(conv))]
    if holes:
        dc, tool = drill_cards(holes, conv.origin)
        pkgs.append(cards.CardPackage(f"{name}-DRILL",
                                      [cards.p_card(sx, sy, tool, tool, tool, _u(DMAX_MM))] + dc))
    return cards.deck(pkgs, job=job)


def holes_without_copper(conv: Conversion, holes: Sequence[Hole]) -> list[Hole]:
    """The holes whose centre is on no dark object's outline."""
    if conv.copper is None or not holes:
        return []
    pts = shapely.points([(h.x, h.y) for h in holes])
    hit = conv.copper.query(pts, predicate="intersects")
    on = set(hit[0].tolist())
    return [h for k, h in enumerate(holes) if k not in on]


# ---------------------------------------------------------------------------
# The command.
# ---------------------------------------------------------------------------
def _run(args: argparse.Namespace) -> int:
    try:
        start = mm_list(args.start, "--start", 2) if args.start else START_MM
        tools = mm_list(args.tools, "--tools", 3) if args.tools else None
        if tools is not None and not all(MIN_FEATURE_MM <= t <= MAX_TOOL_MM
                                         and abs(t * 100 - round(t * 100)) < 1e-6 for t in tools):
            raise ValueError(f"--tools {args.tools}: each tool is {MIN_FEATURE_MM:.2f} to "
                             f"{MAX_TOOL_MM:.2f} mm, in whole 0.01 mm")
    except ValueError as exc:
        print(f"gerber2deck: {exc}", file=sys.stderr)
        return 2
    name = args.name or package_name(args.copper)
    if not re.fullmatch(r"[A-Za-z0-9_-]{1,12}", name) or name in ("C", "E"):
        print(f"gerber2deck: --name {name!r}: 1 to 12 letters, digits, - or _ (so that "
              f"NAME-DRILL fits the 18 columns of a name card), not a bare C or E (they "
              f"end a package)", file=sys.stderr)
        return 2
    try:
        g = read_gerber(args.copper)
        holes, slots, g85 = read_drill(args.drill) if args.drill else ([], 0, [])
        conv = convert(g, holes, tools)
    except Unreadable as exc:
        print(f"gerber2deck: {exc}", file=sys.stderr)
        return 2
    except Refused as exc:
        print(f"gerber2deck: {args.copper}: {exc}; no deck written", file=sys.stderr)
        return 1
    w, h = conv.size
    if start[0] + w > FIELD_MM or start[1] + h > FIELD_MM or min(start) < 0:
        print(f"gerber2deck: {args.copper}: the board is {w:.2f} x {h:.2f} mm; placed at "
              f"{start[0]:g}, {start[1]:g} mm it does not fit the {FIELD_MM:g} x {FIELD_MM:g} mm "
              f"field of the coordinatograph; no deck written", file=sys.stderr)
        return 1
    if ends_without_m02(args.copper):
        print(f"gerber2deck: {args.copper}: the file ends without M02 (end of file): it may be "
              f"cut short, and its last objects missing from the deck", file=sys.stderr)
    for line in conv.notes:
        print(f"gerber2deck: {args.copper}: {line}", file=sys.stderr)
    if args.drill:
        bare = holes_without_copper(conv, holes)
        if bare:
            eg = ", ".join(f"{b.x:.2f}, {b.y:.2f}" for b in bare[:3])
            print(f"gerber2deck: {args.drill}: {len(bare)} of {len(holes)} holes have no copper "
                  f"pad around them (e.g. at {eg} mm)", file=sys.stderr)
        if slots:
            print(f"gerber2deck: {args.drill}: {slots} slots (routed holes) left out",
                  file=sys.stderr)
        for k in g85:
            print(f"gerber2deck: {args.drill}:{k}: a slot (G85, a routed hole) left out",
                  file=sys.stderr)
        if holes:
            print(f"gerber2deck: {args.drill}: {len(holes)} holes -> package {name}-DRILL "
                  f"(tool {drill_tool(holes) / 100:.2f} mm)",
                  file=sys.stderr)
        else:
            print(f"gerber2deck: {args.drill}: no round holes, only slots: no package "
                  f"{name}-DRILL", file=sys.stderr)
    w1, w2, w3 = conv.tools
    print(f"gerber2deck: {args.copper}: {w:.2f} x {h:.2f} mm, start point at board "
          f"{conv.origin[0]:.2f}, {conv.origin[1]:.2f} mm; tools W1 {w1 / 100:.2f}, "
          f"W2 {w2 / 100:.2f}, W3 {w3 / 100:.2f} mm", file=sys.stderr)
    text = deck_text(conv, name, holes, start, job=f"GERBER2DECK {Path(args.copper).name}"[:60])
    if args.output:
        inputs = [args.copper] + ([args.drill] if args.drill else [])
        try:
            write_whole(args.output, text, inputs=inputs)
        except OSError as exc:
            print(f"gerber2deck: {args.output}: {exc.strerror or exc}", file=sys.stderr)
            return 2
    else:
        sys.stdout.write(text)
    return 0


HELP = ("Turn a board's copper layer (RS-274X) and, with --drill, its drill file "
        "(Excellon) into a TENZOR card deck whose tapes draw that copper: round and "
        "rectangular pads -> D cards (rows where they line up), tracks -> L cards, "
        "arcs -> A cards, other pads and regions -> strokes that fill them; the holes "
        "-> a second package NAME-DRILL, one D card a hole. What had to be approximated "
        "is said on standard error; a board the deck cannot hold is refused (exit 1).")


def _arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("copper", metavar="COPPER.gbr")
    p.add_argument("--drill", metavar="FILE.drl", help="the board's Excellon drill file")
    p.add_argument("-o", "--output", metavar="DECK.crd", help="output deck (default stdout)")
    p.add_argument("--name", help=f"package name, at most {NAME_LEN} characters "
                                  "(default: the file's stem)")
    p.add_argument("--start", metavar="X0,Y0",
                   help="where the start point (the board's lower-left corner) goes on the "
                        "field, mm (default 10,10)")
    p.add_argument("--tools", metavar="W1,W2,W3",
                   help="the tools, mm, each 0.01 to 20 (default: W3 the narrowest track, "
                        "W1 and W2 no wider than W3 nor the smallest pad of their tape)")
    p.set_defaults(func=_run)


def add_gerber2deck(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("gerber2deck", help="a Gerber copper layer (+ Excellon drill) to a deck",
                       description=HELP)
    _arguments(p)


@quiet_when_output_closes
def main(argv: Sequence[str] | None = None) -> int:
    """The console script ``gerber2deck``."""
    parser = Parser(prog="gerber2deck", description=HELP)
    _arguments(parser)
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0)
    try:
        return int(args.func(args))
    except KeyboardInterrupt:
        print("gerber2deck: interrupted; no deck written", file=sys.stderr)
        return 130
