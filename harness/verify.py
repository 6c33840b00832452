"""Check anyone's EM-703 tapes against a TENZOR deck.

``python -m harness verify DECK TAPEDIR`` reads the deck with the harness's
own strict parser (:mod:`harness.deck`), finds the three tapes of each
package in TAPEDIR (``NAME-small.ptp``, ``NAME-large.ptp``,
``NAME-cond.ptp``, NAME sanitised as TENZOR does), and checks each one with
the harness's own decoder (:mod:`harness.tape`, code variant detected from
the tape), simulator (:mod:`harness.sim`) and rasteriser
(:mod:`harness.raster`).  The tapes may come from TENZOR or from any other
implementation: nothing but the deck and the tape images is read (tool
widths come from the deck's P card, not from a job sheet).

A tape passes when

* it decodes (code and frame grammar; an error names its row);
* it ends with the tool raised at its start point;
* the tool centre stays on the 1200 x 1200 mm field at the P card's start
  point and scale (the first frame that leaves is named, with its row);
* what it draws with its tool equals the deck's ideal layer within the
  machine's accuracy, 0.05 mm (:func:`harness.raster.compare`).

When the coverage differs, every hole is attributed to the ideal shape it
lies in (the deepest one) and so to its card, and every pixel drawn outside
the ideal to the tape frame that drew it:

* a pad with nothing drawn inside it is *missing*; a pad whose holes form a
  band all round its rim, with everything deeper drawn, is *drawn too
  small*; a pad with the ring just outside it drawn nearly all round is
  *drawn too large*; other holes in a pad are *not filled*;
* a conductor (L, O or A card) is cut into cross-sections one pitch apart
  along its centre line: a cross-section with nothing drawn is a *break*,
  one drawn only away from an edge is *too narrow*; other holes (round ends,
  gaps inside) are *not filled*;
* drawing outside every shape is reported per frame that drew it (frame
  number, row, its text), with its area and how far it strays.

Coordinates in messages are board coordinates in mm relative to the start
point.  The output is deterministic.  Coverage is checked on the field (and
the deck's shapes) with :data:`FIELD_MARGIN` round; beyond it a tape's
drawing is the reason ``field``.  The command prints progress lines on
standard error when a run takes more than two seconds (:class:`Progress`),
never on standard output.  Exit status of the command: 0 PASS,
1 FAIL, 2 usage or I/O (or a deck the oracle cannot read).
"""

from __future__ import annotations

import hashlib
import math
import sys
import os
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

import numpy as np

from . import raster, sim
from .deck import FIELD, LAYERS, MAX_TOOL, CardError, Package, parse_deck
from .shapes import (AnyShape, ArcBand, Disc, Layer, Origin, RoundRect, Stroke,
                     distinct_strokes, run_shapes)
from .tape import (DIGITS_8, DIGITS_K, Frame, Tape, TapeError, decode, frame_rows,
                   frame_text)

#: The machine's accuracy, in units (0.01 mm): the coverage tolerance.
TOLERANCE = 5
#: The widest tolerance the command takes, units: half the widest tool.
#: A wider one would let a tape leave out whole pads, and its check needs
#: a raster as coarse as itself.
MAX_TOLERANCE = MAX_TOOL // 2
#: Most reasons about shapes, and most about stray frames, listed per tape
#: (then a count of the others).
MAX_REASONS = 15
#: Share of a pad's rim band (or outer ring) that must be undrawn (drawn)
#: to call the pad drawn too small (too large).
RING_SHARE = 0.9

#: Rows that tell the plain code from the code with control: digits 3, 5, 6, 9.
DECIDING = frozenset(DIGITS_8[d] for d in (3, 5, 6, 9)) | frozenset(
    DIGITS_K[d] for d in (3, 5, 6, 9))

#: What each tape holds, for the listing.
TAPE_TITLES: dict[str, str] = {"small": "small pads", "large": "large pads",
                               "cond": "conductors"}


class VerifyError(Exception):
    """The check cannot be made: the deck cannot be read by the oracle, or a
    file cannot be read (exit status 2)."""


@dataclass(frozen=True)
class Reason:
    """One reason for FAIL.

    ``kind`` is one of: ``tape-missing``, ``code`` (code or grammar error,
    ``row`` set), ``simulation``, ``not-at-start``, ``field``,
    ``pad-missing``, ``pad-size``, ``pad-holes``, ``conductor-missing``,
    ``conductor-broken``, ``conductor-narrow``, ``conductor-holes``,
    ``m-drawing`` (an M card's drawing incomplete), ``holes`` (a shape of
    unknown card), ``excess`` (drawn where the deck holds nothing),
    ``uncheckable``.  ``card`` is the card
    that defines the shape, ``frame`` the 1-based frame of the tape and
    ``row`` its 1-based row, where they apply.
    """

    package: str
    tape: str
    kind: str
    message: str
    card: int | None = None
    frame: int | None = None
    row: int | None = None

    def __str__(self) -> str:
        return f"{self.tape}: {self.message}"


@dataclass
class TapeCheck:
    """What was found for one tape file."""

    package: str
    layer: str
    file: str
    tool: int
    deck_code: str = "8"
    code: str | None = None
    frames: int | None = None
    rows: int | None = None
    reasons: list[Reason] = field(default_factory=list)
    #: Reasons found beyond the :data:`MAX_REASONS` listed.
    omitted: int = 0

    @property
    def ok(self) -> bool:
        return not self.reasons

    def line(self) -> str:
        """One line for the listing (without the reasons)."""
        bits = []
        if self.code is not None:
            other = (f" (the P card says {self.deck_code}: overridden, e.g. by --code?)"
                     if self.code in ("8", "K") and self.code != self.deck_code else "")
            bits.append(f"code {self.code}{other}, {self.frames} frames, {self.rows} rows")
        bits.append(f"tool {self.tool / 100:.2f} mm")
        return (f"  {'ok  ' if self.ok else 'FAIL'} {self.file}  "
                f"({TAPE_TITLES[self.layer]}; {', '.join(bits)})")


@dataclass
class PackageCheck:
    """The three tapes of one package."""

    name: str
    card: int
    scale: tuple[int, int]
    start_mm: tuple[str, str]
    tapes: list[TapeCheck] = field(default_factory=list)


@dataclass
class Verdict:
    """The result of :func:`verify`."""

    deck: str
    tapedir: str
    tol: int
    packages: list[PackageCheck] = field(default_factory=list)

    @property
    def reasons(self) -> list[Reason]:
        return [r for p in self.packages for t in p.tapes for r in t.reasons]

    @property
    def count(self) -> int:
        """Reasons found, including those not listed."""
        return sum(len(t.reasons) + t.omitted for p in self.packages for t in p.tapes)

    @property
    def passed(self) -> bool:
        return self.count == 0

    def text(self) -> str:
        """The listing printed by ``python -m harness verify``."""
        lines = [f"verify {self.deck} against {self.tapedir} "
                 f"(tolerance {self.tol / 100:.2f} mm)"]
        for p in self.packages:
            lines.append(f"package {p.name} (card {p.card}): scale {p.scale[0]}:{p.scale[1]}, "
                         f"start point at {p.start_mm[0]}, {p.start_mm[1]} mm on the field")
            for t in p.tapes:
                lines.append(t.line())
                lines += [f"       {r.message}" for r in t.reasons]
                if t.omitted:
                    lines.append(f"       ... and {t.omitted} more reasons like these")
        n = self.count
        lines.append("PASS" if n == 0 else f"FAIL: {n} reason{'s' if n != 1 else ''}")
        return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------
# Frames on the tape: rows, extents, the field.
# ---------------------------------------------------------------------------
def frame_start_rows(data: bytes, tape: Tape) -> list[int]:
    """The 1-based row of the first row of each frame of a decoded tape.

    Valid because the decoder is strict (no leading zeros, no zero values,
    fixed order): a decoded frame has exactly one punching.  The rows the
    decoder noted, when it did."""
    if tape.starts is not None:
        return list(tape.starts)
    lead = next((i for i, v in enumerate(data) if v != 0), 0)
    row = lead + 2                          # leader rows, then GM
    out = []
    for f in tape.frames:
        out.append(row)
        row += len(frame_rows(f, tape.code))
    return out


Box = tuple[float, float, float, float]


def _frame_extent(f: Frame, px: int, py: int) -> tuple[Box, tuple[int, int]]:
    """The box swept by the tool centre in frame ``f`` from (px, py), and
    the end point (units)."""
    if f.k in (10, 20):
        nx, ny = px + f.dx, py + f.dy
        return (min(px, nx), max(px, nx), min(py, ny), max(py, ny)), (nx, ny)
    cx, cy = px - f.x, py - f.y
    r = math.hypot(f.x, f.y)
    if f.dx or f.dy:
        nx, ny = px + f.dx, py + f.dy
        sweep = sim.arc_sweep(f.x, f.y, nx - cx, ny - cy, f.k == 13)
    else:
        nx, ny = px, py
        sweep = -sim.TWO_PI if f.k == 13 else sim.TWO_PI
    x0, x1, y0, y1 = sim.arc_extent(cx, cy, r, math.atan2(f.y, f.x), sweep)
    return ((min(x0, px, nx), max(x1, px, nx), min(y0, py, ny), max(y1, py, ny)),
            (nx, ny))


def _shift(b: Box, dx: float, dy: float) -> Box:
    return b[0] + dx, b[1] + dx, b[2] + dy, b[3] + dy


def field_exit(frames: Sequence[Frame], start: tuple[int, int],
               scale: tuple[int, int]) -> tuple[int, int, str] | None:
    """The first frame whose tool path leaves the field, or None.

    ``start``: the start point's place on the field (units); ``scale``:
    (N, D), a board length v is N*v/D on the field.  Returns (0-based frame
    index, repetition (1-based, 0 if not in a cycle), what leaves)."""
    num, den = scale
    slack = 1e-6

    def leaves(b: Box) -> str | None:
        lo_x = start[0] + b[0] * num / den
        hi_x = start[0] + b[1] * num / den
        lo_y = start[1] + b[2] * num / den
        hi_y = start[1] + b[3] * num / den
        for value, axis in ((lo_x, "x"), (hi_x, "x"), (lo_y, "y"), (hi_y, "y")):
            if value < -slack or value > FIELD + slack:
                return f"{axis} = {value / 100:.2f} mm"
        return None

    px = py = 0
    i = 0
    while i < len(frames):
        f = frames[i]
        if f.cyc and i + 1 < len(frames):
            g = frames[i + 1]
            box_a, (ax, ay) = _frame_extent(f, px, py)
            box_b, (bx, by) = _frame_extent(g, ax, ay)
            dx, dy = bx - px, by - py
            for rep in range(f.cyc):
                for index, box in ((i, box_a), (i + 1, box_b)):
                    what = leaves(_shift(box, rep * dx, rep * dy))
                    if what:
                        return index, rep + 1, what
                if rep == 0:
                    last = f.cyc - 1
                    union = (min(box_a[0], box_b[0]), max(box_a[1], box_b[1]),
                             min(box_a[2], box_b[2]), max(box_a[3], box_b[3]))
                    whole = (min(union[0], union[0] + last * dx),
                             max(union[1], union[1] + last * dx),
                             min(union[2], union[2] + last * dy),
                             max(union[3], union[3] + last * dy))
                    if not leaves(whole):
                        break
            px, py = px + f.cyc * dx, py + f.cyc * dy
            i += 2
            continue
        box, (px, py) = _frame_extent(f, px, py)
        what = leaves(box)
        if what:
            return i, 0, what
        i += 1
    return None


# ---------------------------------------------------------------------------
# Coverage, attributed.
# ---------------------------------------------------------------------------
def _mm(v: float) -> str:
    return f"{v / 100:.2f}"


def _pt(x: float, y: float) -> str:
    return f"({_mm(x)}, {_mm(y)}) mm"


def describe_shape(shape: AnyShape, origin: Origin | None) -> str:
    """What a shape is, for a message: 'card 12 (D): round 1.60 mm pad at
    (10.00, 20.00) mm'."""
    head = f"card {origin.card} ({origin.kind})" if origin else "a shape"
    if origin and origin.kind == "D" and origin.count > 1:
        head += f", pad {origin.item + 1} of {origin.count}"
    if origin and origin.kind == "M":
        head += f", M frame {origin.item + 1} of this tape"
    if origin and origin.kind == "M":
        if isinstance(shape, Disc):
            what = f"the dot it draws at {_pt(shape.cx, shape.cy)}"
        elif isinstance(shape, Stroke):
            what = (f"the line it draws from {_pt(*shape.points[0])} to "
                    f"{_pt(*shape.points[-1])}")
        else:
            what = (f"the {'circle' if shape.full else 'arc'} it draws about "
                    f"{_pt(shape.cx, shape.cy)}, radius {_mm(shape.rad)} mm")
    elif isinstance(shape, Disc):
        what = f"round {_mm(2 * shape.r)} mm pad at {_pt(shape.cx, shape.cy)}"
    elif isinstance(shape, RoundRect):
        what = f"{_mm(shape.w)} x {_mm(shape.h)} mm pad at {_pt(shape.cx, shape.cy)}"
    elif isinstance(shape, Stroke):
        (ax, ay), (bx, by) = shape.points[0], shape.points[-1]
        what = (f"{_mm(2 * shape.r)} mm conductor from {_pt(ax, ay)} to {_pt(bx, by)}")
    else:
        kind = "circle" if shape.full else "arc"
        what = (f"{kind} of radius {_mm(shape.rad)} mm about {_pt(shape.cx, shape.cy)}, "
                f"{_mm(2 * shape.hw)} mm wide")
    return f"{head}: {what}"


@dataclass
class _ShapeStats:
    """Pixel counts per ideal shape (each pixel counted for the shape it is
    deepest in, or nearest to); ``ring``/``ring_on``: pixels outside the
    shape in bands one pitch wide from ``tol`` outwards, and how many of
    them are drawn."""

    n: int
    bins: int

    def __post_init__(self) -> None:
        z = lambda: np.zeros(self.n, dtype=np.int64)  # noqa: E731
        self.inner, self.holes, self.drawn_in = z(), z(), z()
        self.rim, self.rim_holes = z(), z()
        self.ring = np.zeros((self.n, self.bins), dtype=np.int64)
        self.ring_on = np.zeros((self.n, self.bins), dtype=np.int64)
        self.hole_max = np.zeros(self.n)
        self.drawn_min = np.full(self.n, np.inf)
        self.deepest: dict[int, tuple[float, float, float]] = {}   # k -> (depth, x, y)


@dataclass
class _Excess:
    """Every pixel drawn outside the ideal: tape frame, nearest ideal shape
    (-1 if none within reach), distance outside it (inf if none), x, y."""

    frame: np.ndarray
    near: np.ndarray
    dist: np.ndarray
    x: np.ndarray
    y: np.ndarray


def _bincount(keys: np.ndarray, n: int) -> np.ndarray:
    return np.bincount(keys, minlength=n)[:n] if keys.size else np.zeros(n, dtype=np.int64)


def _scan(pl: raster.Plan, tol: float, stroke_frame: Sequence[int], bins: int,
          tiles: np.ndarray, progress: Callable[[int, int], None] | None = None
          ) -> tuple[_ShapeStats, _Excess]:
    """One pass over the given tiles of ``pl`` (tile numbers): per-shape
    statistics, and the excess pixels."""
    n_ideal = pl.n_ideal
    st = _ShapeStats(n_ideal, bins)
    p = pl.pitch
    sf = np.asarray(stroke_frame, dtype=np.int64)
    parts: list[tuple[np.ndarray, ...]] = []
    seen = 0
    for batch in pl.batches(tiles, raster.BATCH_TILES // 8):
        ideal_all, k_all = pl.distances(batch, True)
        drawn_all, j_all = pl.distances(batch, False)
        seen += batch.size
        if progress is not None:
            progress(seen, tiles.size)
        for slot, t in enumerate(batch.tolist()):
            tile = pl.tile(*pl.where(t))
            ideal_d = ideal_all[slot, :tile.ny, :tile.nx]
            ideal_k = k_all[slot, :tile.ny, :tile.nx]
            drawn_d = drawn_all[slot, :tile.ny, :tile.nx]
            drawn_j = j_all[slot, :tile.ny, :tile.nx]
            on = drawn_d <= 0
            inner = ideal_d <= -tol
            hole = inner & ~on
            excess = on & (ideal_d > tol)
            ring = (ideal_d > tol) & (ideal_d <= tol + bins * p)
            if not (inner.any() or ring.any() or excess.any()):
                continue
            rim = inner & (ideal_d > -(tol + 2 * p))
            st.inner += _bincount(ideal_k[inner], n_ideal)
            st.holes += _bincount(ideal_k[hole], n_ideal)
            st.drawn_in += _bincount(ideal_k[inner & on], n_ideal)
            st.rim += _bincount(ideal_k[rim], n_ideal)
            st.rim_holes += _bincount(ideal_k[rim & ~on], n_ideal)
            if ring.any():
                b = np.minimum(((ideal_d[ring] - tol) // p).astype(np.int64), bins - 1)
                np.add.at(st.ring, (ideal_k[ring], b), 1)
                np.add.at(st.ring_on, (ideal_k[ring], b), on[ring].astype(np.int64))
            x, y = tile.centres()
            if hole.any():
                np.maximum.at(st.hole_max, ideal_k[hole], -ideal_d[hole])
                hk, hd, hx, hy = ideal_k[hole], -ideal_d[hole], x[hole], y[hole]
                order = np.lexsort((hy, hx, -hd, hk))       # per shape: deepest first
                first = np.ones(order.size, dtype=bool)
                first[1:] = hk[order][1:] != hk[order][:-1]
                for idx in order[first]:
                    k = int(hk[idx])
                    cand = (float(hd[idx]), float(hx[idx]), float(hy[idx]))
                    old = st.deepest.get(k)
                    if old is None or (cand[0], -cand[1], -cand[2]) > (old[0], -old[1], -old[2]):
                        st.deepest[k] = cand
            done = inner & on
            if done.any():
                np.minimum.at(st.drawn_min, ideal_k[done], -ideal_d[done])
            if excess.any():
                parts.append((sf[drawn_j[excess] - n_ideal], ideal_k[excess], ideal_d[excess],
                              x[excess], y[excess]))
    if parts:
        cols = [np.concatenate([q[i] for q in parts]) for i in range(5)]
    else:
        cols = [np.zeros(0, dtype=np.int64)] * 2 + [np.zeros(0)] * 3
    return st, _Excess(*cols)


def _centre_samples(shape: AnyShape, step: float
                    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, float]:
    """Points along a conductor's centre line ``step`` apart, their unit
    normals, and the half width: (x, y, nx, ny, half)."""
    xs: list[np.ndarray] = []
    ys: list[np.ndarray] = []
    nxs: list[np.ndarray] = []
    nys: list[np.ndarray] = []
    if isinstance(shape, Stroke):
        for (ax, ay), (bx, by) in zip(shape.points, shape.points[1:]):
            length = math.hypot(bx - ax, by - ay)
            if length == 0:
                continue
            t = (np.arange(max(1, math.ceil(length / step))) + 0.5) / max(1, math.ceil(length / step))
            xs.append(ax + t * (bx - ax))
            ys.append(ay + t * (by - ay))
            nxs.append(np.full(t.shape, -(by - ay) / length))
            nys.append(np.full(t.shape, (bx - ax) / length))
        half = shape.r
    else:
        assert isinstance(shape, ArcBand)
        length = abs(shape.sweep) * shape.rad
        count = max(1, math.ceil(length / step))
        a = shape.a0 + shape.sweep * (np.arange(count) + 0.5) / count
        xs.append(shape.cx + shape.rad * np.cos(a))
        ys.append(shape.cy + shape.rad * np.sin(a))
        nxs.append(np.cos(a))
        nys.append(np.sin(a))
        half = shape.hw
    if not xs:
        empty = np.zeros(0)
        return empty, empty, empty, empty, half
    return (np.concatenate(xs), np.concatenate(ys), np.concatenate(nxs),
            np.concatenate(nys), half)


def _cross_sections(shape: AnyShape, drawn: Sequence[AnyShape], boxes: np.ndarray,
                    tol: float, step: float) -> dict[str, object] | None:
    """Classify the cross-sections of a conductor shape: returns a dict with
    'broken' (list of (x, y) of cross-sections with nothing drawn),
    'narrow' (list of (drawn width, x, y)), 'gaps' (count of cross-sections
    with an undrawn gap between drawn parts), 'count', 'half'; None when the
    shape has no centre line to cut (a circle smaller than its tool)."""
    if isinstance(shape, ArcBand) and shape.rad <= shape.hw:
        return None
    cx, cy, nx, ny, half = _centre_samples(shape, step)
    reach = half - tol
    if cx.size == 0 or reach <= 0:
        return None
    us = np.arange(-math.floor(reach / step), math.floor(reach / step) + 1) * step
    broken: list[tuple[float, float]] = []
    narrow: list[tuple[float, float, float]] = []
    gaps = 0
    chunk = max(1, 4096 // us.size)
    for a in range(0, cx.size, chunk):
        sl = slice(a, a + chunk)
        px = cx[sl, None] + us[None, :] * nx[sl, None]
        py = cy[sl, None] + us[None, :] * ny[sl, None]
        lo_x, hi_x, lo_y, hi_y = px.min(), px.max(), py.min(), py.max()
        near = np.nonzero((boxes[:, 0] <= hi_x) & (boxes[:, 1] >= lo_x)
                          & (boxes[:, 2] <= hi_y) & (boxes[:, 3] >= lo_y))[0]
        d = np.full(px.shape, np.inf)
        for j in near:
            np.minimum(d, drawn[j].sdf(px, py), out=d)
        on = d <= 0
        for r in range(on.shape[0]):
            row = on[r]
            x0, y0 = float(cx[a + r]), float(cy[a + r])
            if not row.any():
                broken.append((x0, y0))
                continue
            if row.all():
                continue
            idx = np.nonzero(row)[0]
            if idx[-1] - idx[0] + 1 != idx.size:
                gaps += 1
            if not row[0] or not row[-1]:
                hi = half if row[-1] else us[idx[-1]] + step / 2
                lo = -half if row[0] else us[idx[0]] - step / 2
                narrow.append((float(hi - lo), x0, y0))
    return {"broken": broken, "narrow": narrow, "gaps": gaps, "count": int(cx.size),
            "half": half}


def _runs(points: list[tuple[float, float]], step: float) -> int:
    """Number of separate runs in a list of centre-line points ``step``
    apart (a new run where two listed points are farther than 1.5 steps)."""
    runs = 0
    last = None
    for p in points:
        if last is None or math.hypot(p[0] - last[0], p[1] - last[1]) > 1.5 * step:
            runs += 1
        last = p
    return runs


def coverage_reasons(layer: Layer, run: sim.Run, tool: int, frames: Sequence[Frame],
                     rows: Sequence[int], tol: int = TOLERANCE, pkg: str = "",
                     tape_file: str = "", clip: Box | None = None,
                     progress: Progress | None = None, title: str = "") -> list[Reason]:
    """Why what ``run`` draws with ``tool`` differs from ``layer`` (an empty
    list when :func:`harness.raster.compare` finds no difference).  Only
    the tiles meeting the box ``clip`` (units) are looked at, when given."""
    def reason(kind: str, message: str, card: int | None = None,
               frame: int | None = None, row: int | None = None) -> Reason:
        return Reason(pkg, tape_file, kind, message, card, frame, row)

    def told(what: str) -> Callable[[int, int], None] | None:
        if progress is None:
            return None
        return lambda done, total: progress.say(f"{title}: {what} tile {done} of {total}")

    drawn, stroke_frame = distinct_strokes(run_shapes(run, tool), sim.stroke_frames(frames))
    shapes = raster.ShapeSet.of(list(layer.shapes) + drawn)
    try:
        report = raster.compare(run, tool, layer, tol=tol, clip=clip, drawn=drawn,
                                shapes=shapes, progress=told("coverage,"), examples=0)
    except ValueError as exc:
        return [reason("uncheckable", f"coverage cannot be checked: {exc}")]
    if report.ok:
        return []
    p = report.pitch_mm * 100
    reach = max(float(tool), 10 * p)
    bins = math.ceil(reach / p)
    pl = raster.plan(layer.shapes, drawn, tol, pitch=p, reach=reach, clip=clip, shapes=shapes)
    assert pl is not None
    # The tiles that differ, and every tile of a shape that reaches one of
    # them: each such shape's statistics are whole, and no other shape has
    # a hole or a drawn ring (those pixels would differ).
    differ = np.flatnonzero(np.isin(pl.keys, [ti + tj * pl.ntx for tj, ti in report.differ]))
    row_tile = np.repeat(np.arange(pl.keys.size), np.diff(pl.start))
    in_differ = np.isin(row_tile, differ)
    suspects = np.unique(pl.members[in_differ & (pl.members < pl.n_ideal)])
    tiles = np.union1d(differ, row_tile[np.isin(pl.members, suspects)])
    st, ex = _scan(pl, tol, stroke_frame, bins, tiles, told("differences,"))
    area = (p / 100) ** 2
    out: list[tuple[tuple, Reason]] = []
    boxes = np.array([s.bbox() for s in drawn]) if drawn else np.zeros((0, 4))

    # Pads drawn too large: the bands just outside drawn nearly all round;
    # ``grown``: how far out the bands are drawn so.
    grown = np.zeros(pl.n_ideal)
    for k in suspects.tolist():
        o = layer.origin(k)
        if not (o and o.kind == "D"):
            continue
        b = 0
        while (b < bins and st.ring[k, b]
               and st.ring_on[k, b] >= RING_SHARE * st.ring[k, b]):
            b += 1
        if b:
            grown[k] = tol + b * p

    # Holes, per shape.
    for k in np.nonzero(st.holes)[0].tolist():
        shape, o = layer.shapes[k], layer.origin(k)
        what = describe_shape(shape, o)
        card = o.card if o else None
        key = (card or 0, o.item if o else k, 0)
        depth, hx, hy = st.deepest[k]
        undrawn = f"{st.holes[k] * area:.4f} mm2 undrawn, deepest at {_pt(hx, hy)}"
        kind = o.kind if o else ""
        if kind == "D":
            if st.drawn_in[k] == 0:
                out.append((key, reason("pad-missing", f"{what}: missing, nothing drawn "
                                        "inside it", card)))
            elif (st.rim_holes[k] >= RING_SHARE * st.rim[k]
                  and st.hole_max[k] <= st.drawn_min[k] + 2 * p):
                out.append((key, reason("pad-size", f"{what}: drawn too small, its rim "
                                        "is missing all round, up to "
                                        f"{_mm(st.hole_max[k])} mm deep", card)))
            else:
                out.append((key, reason("pad-holes", f"{what}: not filled, {undrawn}", card)))
        elif kind in ("L", "O", "A"):
            if st.drawn_in[k] == 0:
                out.append((key, reason("conductor-missing", f"{what}: missing, nothing "
                                        "drawn inside it", card)))
                continue
            cs = _cross_sections(shape, drawn, boxes, tol, p)
            if cs and cs["broken"]:
                br = cs["broken"]
                n = _runs(br, p)
                out.append((key, reason("conductor-broken", f"{what}: broken at "
                                        f"{_pt(*br[0])}: nothing drawn across it over "
                                        f"{len(br) * p / 100:.2f} mm"
                                        + (f", in {n} places" if n > 1 else ""), card)))
            elif cs and cs["narrow"]:
                width, nx_, ny_ = min(cs["narrow"])
                share = len(cs["narrow"]) / cs["count"]
                out.append((key, reason("conductor-narrow", f"{what}: too narrow, about "
                                        f"{_mm(width)} mm drawn at {_pt(nx_, ny_)}, over "
                                        f"{share:.0%} of its length", card)))
            else:
                out.append((key, reason("conductor-holes", f"{what}: not filled, "
                                        f"{undrawn}", card)))
        elif kind == "M":
            out.append((key, reason("m-drawing", f"{what}: incomplete, {undrawn}", card)))
        else:
            out.append((key, reason("holes", f"{what}: {undrawn}", card)))

    for k in np.nonzero(grown)[0].tolist():
        o = layer.origin(k)
        out.append(((o.card, o.item, 1), reason(
            "pad-size", f"{describe_shape(layer.shapes[k], o)}: drawn too large, "
            f"{'at least' if grown[k] >= tol + bins * p else 'about'} {_mm(grown[k])} mm "
            "beyond its rim all round", o.card)))

    # Drawing outside the deck that no pad drawn too large explains, per frame.
    near = np.where(ex.near >= 0, ex.near, 0)
    explained = (ex.near >= 0) & (ex.dist <= grown[near] + p) if pl.n_ideal else \
        np.zeros(ex.dist.shape, dtype=bool)
    keep = ~explained
    fr_all, d_all, x_all, y_all = ex.frame[keep], ex.dist[keep], ex.x[keep], ex.y[keep]
    for fr in np.unique(fr_all).tolist():
        sel = fr_all == fr
        d, xs, ys = d_all[sel], x_all[sel], y_all[sel]
        i = np.lexsort((ys, xs, -d))[0]
        fx, fy = float(xs[i]), float(ys[i])
        if pl.n_ideal:
            dist, which = pl.set.nearest(np.array([fx]), np.array([fy]), upto=pl.n_ideal)
            k = int(which[0])
            o = layer.origin(k)
            where = (f", {_mm(float(dist[0]))} mm from the nearest shape"
                     + (f" (card {o.card})" if o else ""))
        else:
            where = ", and this tape's layer holds nothing"
        f = frames[fr]
        out.append(((10**9, fr, 0), reason(
            "excess", f"frame {fr + 1} (row {rows[fr]}, {frame_text(f)}) draws where the "
            f"deck holds nothing: {int(sel.sum()) * area:.4f} mm2, farthest at "
            f"{_pt(fx, fy)}{where}", frame=fr + 1, row=rows[fr])))

    out.sort(key=lambda t: t[0])
    reasons = [r for _, r in out]
    if not reasons:                     # cannot happen: the scan repeats compare
        reasons = [reason("holes", "coverage differs:\n" + report.summary())]
    return reasons


# ---------------------------------------------------------------------------
# One tape, one package, the deck.
# ---------------------------------------------------------------------------
#: How far beyond the field (and the deck's shapes), in units, coverage is
#: still looked at.
FIELD_MARGIN = 1000


def field_box(pkg: Package, layer: Layer) -> Box:
    """The part of the board where coverage is checked (units, board
    coordinates): the 1200 x 1200 mm field at the package's start point and
    scale, and the deck's shapes of the layer, with :data:`FIELD_MARGIN`
    round.  A tape's drawing beyond it is the reason ``field`` already
    (the tool centre left the field); so a stray 10 m circle costs no more
    than the field."""
    num, den = pkg.scale
    x0 = -pkg.start[0] * den / num
    y0 = -pkg.start[1] * den / num
    x1 = (FIELD - pkg.start[0]) * den / num
    y1 = (FIELD - pkg.start[1]) * den / num
    box = raster.union_box([(x0, x1, y0, y1), layer.bbox()])
    assert box is not None
    m = FIELD_MARGIN
    return box[0] - m, box[1] + m, box[2] - m, box[3] + m


#: Seconds before the first progress line, and between two of them; the
#: environment variable VERIFY_PROGRESS_AFTER overrides the first.
PROGRESS_AFTER = 2.0
PROGRESS_EVERY = 1.0


class Progress:
    """Progress lines on standard error for a long check: nothing in the
    first :data:`PROGRESS_AFTER` seconds, then a line at most every
    :data:`PROGRESS_EVERY` seconds (rewritten in place on a terminal).
    Standard output is never touched."""

    def __init__(self, stream=None) -> None:
        self.stream = stream if stream is not None else sys.stderr
        self.start = time.monotonic()
        try:
            after = float(os.environ.get("VERIFY_PROGRESS_AFTER", PROGRESS_AFTER))
        except ValueError:
            after = PROGRESS_AFTER
        self.next = self.start + after
        self.shown = False
        try:
            self.tty = self.stream.isatty()
        except (AttributeError, ValueError):
            self.tty = False

    def say(self, text: str) -> None:
        """Show ``text`` if it is time to."""
        now = time.monotonic()
        if now < self.next:
            return
        self.next = now + PROGRESS_EVERY
        line = f"verify: {text} ({now - self.start:.0f} s)"
        try:
            if self.tty:
                self.stream.write("\r\x1b[K" + line)
            else:
                self.stream.write(line + "\n")
            self.stream.flush()
        except (OSError, ValueError):
            return
        self.shown = True

    def end(self) -> None:
        """Finish the line rewritten in place, if any."""
        if self.shown and self.tty:
            try:
                self.stream.write("\n")
                self.stream.flush()
            except (OSError, ValueError):
                pass
        self.shown = False


def check_tape(pkg: Package, layer: str, path: Path, tol: int = TOLERANCE,
               code: str = "auto", progress: Progress | None = None) -> TapeCheck:
    """Check one tape file of a package against the package's ideal layer."""
    if progress is not None:
        progress.say(f"{TAPE_TITLES[layer]}: reading {path.name}")
    tool = dict(zip(LAYERS, pkg.tools))[layer]
    check = TapeCheck(pkg.name, layer, path.name, tool, pkg.code)

    def fail(kind: str, message: str, **kw: int) -> TapeCheck:
        check.reasons.append(Reason(pkg.name, path.name, kind, message, **kw))
        return check

    try:
        data = path.read_bytes()
    except FileNotFoundError:
        return fail("tape-missing", f"tape missing: no file {path.name} in {path.parent}")
    except IsADirectoryError:
        return fail("tape-missing", f"tape missing: {path.name} in {path.parent} is a directory")
    except OSError as exc:
        raise VerifyError(f"{path}: {exc.strerror or exc}") from None
    check.rows = len(data)
    try:
        tape = decode(data, code)
    except TapeError as exc:
        return fail("code", f"row {exc.row}: code or grammar error: {exc.message}", row=exc.row)
    check.code, check.frames = tape.code, len(tape.frames)
    if code == "auto" and not DECIDING.intersection(data):
        check.code = "8 or K (no digit 3, 5, 6 or 9 tells them apart)"
    frames = tape.frames
    rows = frame_start_rows(data, tape)
    try:
        run = sim.simulate(frames)
    except ValueError as exc:
        return fail("simulation", f"cannot be run: {exc}")
    if run.end != (0, 0) or run.tool_down_at_end:
        fail("not-at-start", f"does not end raised at its start point: it ends at "
             f"{_pt(*run.end)} from it with the tool {'down' if run.tool_down_at_end else 'up'}")
    leave = field_exit(frames, pkg.start, pkg.scale)
    if leave is not None:
        i, rep, what = leave
        in_cycle = f", repetition {rep} of its cycle" if rep else ""
        fail("field", f"frame {i + 1} (row {rows[i]}, {frame_text(frames[i])}{in_cycle}) "
             f"leaves the 1200 x 1200 mm field: the tool centre reaches {what} on the "
             f"machine (start point at {pkg.start_mm[0]:.2f}, {pkg.start_mm[1]:.2f} mm, scale "
             f"{pkg.scale[0]}:{pkg.scale[1]})", frame=i + 1, row=rows[i])
    check.reasons += coverage_reasons(pkg.layers[layer], run, tool, frames, rows, tol,
                                      pkg.name, path.name, field_box(pkg, pkg.layers[layer]),
                                      progress, TAPE_TITLES[layer])
    shapes = [r for r in check.reasons if r.kind != "excess"]
    strays = [r for r in check.reasons if r.kind == "excess"]
    check.omitted = max(0, len(shapes) - MAX_REASONS) + max(0, len(strays) - MAX_REASONS)
    check.reasons = shapes[:MAX_REASONS] + strays[:MAX_REASONS]
    return check


#: Job sheet keys of the files TENZOR records (docs/FILES.md): file key, size
#: key, SHA-256 key.
RECORDED = [("listing", "listing.bytes", "listing.sha256")] + [
    (f"{t}.{k}", f"{t}.{'bytes' if k == 'tape' else 'text_bytes'}",
     f"{t}.{'sha256' if k == 'tape' else 'text_sha256'}")
    for t in LAYERS for k in ("tape", "text")]


def package_files_agree(tapedir: Path, file_name: str) -> None:
    """Raise VerifyError when the package's job sheet (if there is one)
    records a size or SHA-256 that a file beside it does not have: the
    files come from different runs, and no verdict on them would mean much."""
    sheet = tapedir / f"{file_name}.job"
    if not sheet.is_file():
        return
    try:
        data = sheet.read_bytes()
    except OSError as exc:
        raise VerifyError(f"{sheet}: {exc.strerror or exc}") from None
    keys: dict[str, str] = {}
    for n, raw in enumerate(data.split(b"\n"), 1):
        line = raw[:-1] if raw.endswith(b"\r") else raw
        if not line.strip() or line.startswith(b"#"):
            continue
        if not line.isascii() or b" = " not in line:
            shown = line[:40].decode("ascii", "backslashreplace")
            raise VerifyError(
                f"{sheet}: line {n}: not a 'key = value' line of a job sheet (\"{shown}"
                f"{'...' if len(line) > 40 else ''}\"): the tapes are checked against the job "
                "sheet beside them; remove or rename it to verify the tapes alone")
        key, value = line.decode("ascii").split(" = ", 1)
        keys[key.strip()] = value.strip()
    for file_key, size_key, sha_key in RECORDED:
        if file_key not in keys or (size_key not in keys and sha_key not in keys):
            continue
        path = tapedir / keys[file_key]
        if not path.exists():
            continue                        # a missing tape is a reason of its own
        try:
            data = path.read_bytes()
        except OSError as exc:
            raise VerifyError(f"{path}: {exc.strerror or exc} (named by {sheet})") from None
        size, sha = keys.get(size_key), keys.get(sha_key)
        if (size is not None and size != str(len(data))) or \
                (sha is not None and sha != hashlib.sha256(data).hexdigest()):
            raise VerifyError(
                f"{path}: not the file the job sheet {sheet} records ({len(data)} bytes, "
                f"SHA-256 {hashlib.sha256(data).hexdigest()}; the sheet says {size} bytes, "
                f"{sha}): the package holds files of different runs; run tenzor again")


def verify(deck_text: str, tapedir: str | Path, tol: int = TOLERANCE,
           code: str = "auto", deck_name: str = "DECK",
           progress: Progress | None = None) -> Verdict:
    """Check the tapes in ``tapedir`` against the deck; see the module doc.

    Raises :class:`VerifyError` when the deck cannot be read by the oracle
    or a file cannot be read."""
    tapedir = Path(tapedir)
    if not tapedir.is_dir():
        raise VerifyError(f"{tapedir}: " + ("not a directory: give the folder the tapes are in"
                                            if tapedir.exists() else "no such directory"))
    try:
        packages = parse_deck(deck_text)
    except CardError as exc:
        raise VerifyError(f"{deck_name}: {exc} (the harness cannot read this deck, so "
                          f"there is nothing to verify against)") from None
    seen: dict[str, int] = {}
    for p in packages:
        if p.file_name in seen:
            raise VerifyError(f"{deck_name}: card {p.first_card}: package name {p.name!r} "
                              f"names the same files as card {seen[p.file_name]}")
        seen[p.file_name] = p.first_card
    for p in packages:
        package_files_agree(tapedir, p.file_name)
    verdict = Verdict(deck_name, str(tapedir), tol)
    for p in packages:
        pc = PackageCheck(p.name.strip(), p.first_card, p.scale,
                          (f"{p.start_mm[0]:.2f}", f"{p.start_mm[1]:.2f}"))
        for layer in LAYERS:
            pc.tapes.append(check_tape(p, layer, tapedir / f"{p.file_name}-{layer}.ptp",
                                       tol, code, progress))
        verdict.packages.append(pc)
    return verdict


def main(deck: str, tapedir: str, tol_mm: str = "0.05", code: str = "auto") -> int:
    """The command: print the verdict; 0 PASS, 1 FAIL, 2 usage or I/O."""
    try:
        tol = Fraction(tol_mm) * 100
    except (ValueError, ZeroDivisionError):
        print(f"verify: --tolerance {tol_mm!r} is not a number of mm", file=sys.stderr)
        return 2
    if tol.denominator != 1 or tol < 2 or tol > MAX_TOLERANCE:
        print(f"verify: --tolerance must be whole 0.01 mm, 0.02 to {MAX_TOLERANCE // 100}.00 "
              f"mm, not {tol_mm}", file=sys.stderr)
        return 2
    try:
        text = Path(deck).read_bytes()
    except OSError as exc:
        print(f"verify: {deck}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    try:
        deck_text = text.decode("ascii")
    except UnicodeDecodeError as exc:
        print(f"verify: {deck}: byte {exc.start + 1} is not ASCII: not a card deck",
              file=sys.stderr)
        return 2
    progress = Progress()
    try:
        verdict = verify(deck_text, tapedir, int(tol), code, deck_name=deck, progress=progress)
    except VerifyError as exc:
        progress.end()
        print(f"verify: {exc}", file=sys.stderr)
        return 2
    progress.end()
    sys.stdout.write(verdict.text())
    return 0 if verdict.passed else 1
