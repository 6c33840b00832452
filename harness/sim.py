"""The EM-703 coordinatograph, simulated frame by frame (the harness's own).

Source: the report's "Описание координатографа" and "Состав кадра"
(docs/TAPE.md).  Every coordinate is an integer in 0.01 mm ("units"); only
the outputs whose names end in ``_mm`` (and ``minutes``) are in millimetres.

Semantics:

* The tool starts raised at (0, 0), the start point.
* ``K10``: lower the tool and move by (DX, DY), drawing a line; a frame
  without DX/DY is a dot (the tool is lowered where it stands).
* ``K20``: raise the tool and move by (DX, DY) (travel).
* ``K11`` / ``K13``: lower the tool and draw a circle or an arc.  (X, Y) is
  the tool position relative to the centre, so centre = position - (X, Y).
  ``K13`` is the + direction (clockwise), ``K11`` the - direction
  (counter-clockwise).  Without DX/DY the frame is a full circle, ending
  where it started; otherwise an arc ending at position + (DX, DY).
* ``CYC n`` on frame i: frames i and i+1 are executed n times in all, then
  execution goes on at frame i+2.

Arcs are stored with the mathematical convention: angles in radians from
the +X axis, a positive sweep turns counter-clockwise, so a K13 (clockwise)
arc has a negative sweep.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from typing import Protocol, Union

#: Speeds of the report's machine, in mm per minute.
LINE_SPEED_MM_MIN = 5500.0
ARC_SPEED_MM_MIN = 1500.0
TRAVEL_SPEED_MM_MIN = 5500.0
#: At most this many executed frames (cycles unrolled) per simulation.
MAX_EXECUTED = 10**6
TWO_PI = 2.0 * math.pi


class FrameLike(Protocol):
    """What the simulator reads from a frame (``harness.tape.Frame`` fits)."""

    x: int
    y: int
    dx: int
    dy: int
    cyc: int
    k: int


@dataclass(frozen=True)
class Line:
    """A straight move from (x0, y0) to (x1, y1), in units."""

    x0: int
    y0: int
    x1: int
    y1: int

    @property
    def length(self) -> float:
        """Length in units."""
        return math.hypot(self.x1 - self.x0, self.y1 - self.y0)


@dataclass(frozen=True)
class Arc:
    """An arc (or full circle) about (cx, cy) of radius r (units).

    ``a0`` is the start angle, ``sweep`` the signed swept angle (radians,
    positive = counter-clockwise); |sweep| = 2*pi for a full circle.
    ``x0, y0`` / ``x1, y1`` are the exact tool positions at start and end.
    """

    cx: int
    cy: int
    r: float
    a0: float
    sweep: float
    x0: int = 0
    y0: int = 0
    x1: int = 0
    y1: int = 0

    @property
    def length(self) -> float:
        """Length in units."""
        return self.r * abs(self.sweep)

    @property
    def full(self) -> bool:
        """True for a full circle."""
        return abs(self.sweep) >= TWO_PI - 1e-12


@dataclass(frozen=True)
class Dot:
    """The tool lowered at (x, y) without moving: a disc of the tool's width."""

    x: int
    y: int


Stroke = Union[Line, Arc, Dot]


@dataclass
class Run:
    """The result of running a tape.

    ``strokes``: what the lowered tool drew, in execution order;
    ``travel``: the moves with the tool raised; ``end``: final position
    (units); ``bbox``: (xmin, xmax, ymin, ymax) in mm of the tool centre over
    the whole path (start point, travel and arc extremes included);
    ``executed``: frames executed with cycles unrolled.
    """

    strokes: list[Stroke] = field(default_factory=list)
    travel: list[Line] = field(default_factory=list)
    end: tuple[int, int] = (0, 0)
    tool_down_at_end: bool = False
    drawn_mm: float = 0.0
    travel_mm: float = 0.0
    minutes: float = 0.0
    bbox: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
    executed: int = 0

    @property
    def line_mm(self) -> float:
        """Drawn length of the straight strokes, mm."""
        return sum(s.length for s in self.strokes if isinstance(s, Line)) / 100.0

    @property
    def arc_mm(self) -> float:
        """Drawn length of the arcs and circles, mm."""
        return sum(s.length for s in self.strokes if isinstance(s, Arc)) / 100.0


def arc_sweep(x0: float, y0: float, x1: float, y1: float, clockwise: bool) -> float:
    """Signed sweep (radians) from direction (x0, y0) to direction (x1, y1)
    about the origin, turning clockwise (negative) or counter-clockwise
    (positive).  Equal directions give a full turn (+-2*pi)."""
    a0 = math.atan2(y0, x0)
    a1 = math.atan2(y1, x1)
    turn = ((a0 - a1) if clockwise else (a1 - a0)) % TWO_PI
    if turn <= 1e-12:
        turn = TWO_PI
    return -turn if clockwise else turn


def arc_extent(cx: float, cy: float, r: float, a0: float,
               sweep: float) -> tuple[float, float, float, float]:
    """(xmin, xmax, ymin, ymax) of an arc's centre line, in its own units,
    including the axis extremes the arc passes through."""
    if abs(sweep) >= TWO_PI - 1e-12:
        return cx - r, cx + r, cy - r, cy + r
    pts = [(cx + r * math.cos(a0), cy + r * math.sin(a0)),
           (cx + r * math.cos(a0 + sweep), cy + r * math.sin(a0 + sweep))]
    lo, hi = (a0, a0 + sweep) if sweep >= 0 else (a0 + sweep, a0)
    for q in range(math.floor(lo / (math.pi / 2)), math.ceil(hi / (math.pi / 2)) + 1):
        ang = q * math.pi / 2
        if lo - 1e-12 <= ang <= hi + 1e-12:
            pts.append((cx + r * round(math.cos(ang)), cy + r * round(math.sin(ang))))
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    return min(xs), max(xs), min(ys), max(ys)


def unroll(frames: Sequence[FrameLike]) -> Iterator[FrameLike]:
    """The frames in execution order, cycles unrolled.

    Raises ValueError for a CYC without a following frame, a CYC on the
    second frame of a pair, a CYC of 1 or less, or more than
    :data:`MAX_EXECUTED` executed frames (checked before anything runs).
    """
    total = 0
    i = 0
    while i < len(frames):
        n = frames[i].cyc
        if n:
            if n < 2:
                raise ValueError(f"frame {i + 1}: CYC {n} (a cycle runs at least twice)")
            if i + 1 >= len(frames):
                raise ValueError(f"frame {i + 1}: CYC needs a following frame")
            if frames[i + 1].cyc:
                raise ValueError(f"frame {i + 2}: CYC on the second frame of a pair")
            total += 2 * n
            i += 2
        else:
            total += 1
            i += 1
        if total > MAX_EXECUTED:
            raise ValueError(f"more than {MAX_EXECUTED} executed frames")
    i = 0
    while i < len(frames):
        n = frames[i].cyc
        if n:
            for _ in range(n):
                yield frames[i]
                yield frames[i + 1]
            i += 2
        else:
            yield frames[i]
            i += 1


def executed_frames(frames: Sequence[FrameLike]) -> Iterator[int]:
    """The 0-based index on the tape of each frame :func:`unroll` yields,
    in the same order (no checks: call it on frames that simulate)."""
    i = 0
    while i < len(frames):
        n = frames[i].cyc
        if n and i + 1 < len(frames):
            for _ in range(n):
                yield i
                yield i + 1
            i += 2
        else:
            yield i
            i += 1


def stroke_frames(frames: Sequence[FrameLike]) -> list[int]:
    """The 0-based tape index of the frame that draws each stroke of
    ``simulate(frames).strokes`` (every executed frame but K20 draws one)."""
    return [i for i in executed_frames(frames) if frames[i].k != 20]


def simulate(frames: Sequence[FrameLike]) -> Run:
    """Run the frames from (0, 0) with the tool raised; see the module doc.

    Raises ValueError (naming the 1-based frame of the tape) for a command
    other than 10, 20, 11, 13, X/Y on a straight move, or a circle without
    radius.
    """
    for i, f in enumerate(frames, 1):
        if f.k not in (10, 20, 11, 13):
            raise ValueError(f"frame {i}: K{f.k} is not a command")
        if f.k in (10, 20) and (f.x or f.y):
            raise ValueError(f"frame {i}: X/Y on a straight move K{f.k}")
        if f.k in (11, 13) and not (f.x or f.y):
            raise ValueError(f"frame {i}: K{f.k} without X/Y (radius 0)")
    run = Run()
    px = py = 0
    down = False
    xmin = xmax = ymin = ymax = 0.0
    line_len = arc_len = travel_len = 0.0

    def grow(a: float, b: float, c: float, d: float) -> None:
        nonlocal xmin, xmax, ymin, ymax
        xmin, xmax = min(xmin, a), max(xmax, b)
        ymin, ymax = min(ymin, c), max(ymax, d)

    for f in unroll(frames):
        run.executed += 1
        if f.k in (10, 20):
            nx, ny = px + f.dx, py + f.dy
            if f.k == 10:
                down = True
                if f.dx or f.dy:
                    seg = Line(px, py, nx, ny)
                    run.strokes.append(seg)
                    line_len += seg.length
                else:
                    run.strokes.append(Dot(px, py))
            else:
                down = False
                if f.dx or f.dy:
                    seg = Line(px, py, nx, ny)
                    run.travel.append(seg)
                    travel_len += seg.length
            grow(min(px, nx), max(px, nx), min(py, ny), max(py, ny))
            px, py = nx, ny
            continue
        down = True
        cx, cy = px - f.x, py - f.y
        r = math.hypot(f.x, f.y)
        a0 = math.atan2(f.y, f.x)
        clockwise = f.k == 13
        if f.dx or f.dy:
            nx, ny = px + f.dx, py + f.dy
            sweep = arc_sweep(f.x, f.y, nx - cx, ny - cy, clockwise)
        else:
            nx, ny = px, py
            sweep = -TWO_PI if clockwise else TWO_PI
        arc = Arc(cx, cy, r, a0, sweep, px, py, nx, ny)
        run.strokes.append(arc)
        arc_len += arc.length
        grow(*arc_extent(cx, cy, r, a0, sweep))
        grow(min(px, nx), max(px, nx), min(py, ny), max(py, ny))
        px, py = nx, ny

    run.end = (px, py)
    run.tool_down_at_end = down
    run.drawn_mm = (line_len + arc_len) / 100.0
    run.travel_mm = travel_len / 100.0
    run.minutes = (line_len / 100.0 / LINE_SPEED_MM_MIN
                   + arc_len / 100.0 / ARC_SPEED_MM_MIN
                   + travel_len / 100.0 / TRAVEL_SPEED_MM_MIN)
    run.bbox = (xmin / 100.0, xmax / 100.0, ymin / 100.0, ymax / 100.0)
    return run
