"""Rasterised coverage: what a tape draws against what the deck asks for.

Everything is sampled at pixel centres on a square grid (default pitch
0.02 mm, i.e. 2 units of 0.01 mm).  :func:`compare` works by tiles (256 x
256 pixels), only on the tiles that some shape can reach (found for all
shapes at once with numpy: a shape whose box lies in one tile is in that
tile, a larger one in the tiles whose centre is near enough), a batch of
tiles at a time, so memory is bounded by the batch, not the board.  The
shapes are arrays (:class:`ShapeSet`).  The first pass (drawn, inside the
shrunk ideal, inside the grown ideal: :meth:`Plan.cover`) fills each
shape's spans on each pixel row, computed analytically, and evaluates only
the pixels on or near an outline, with one numpy call per kind of shape
and the same formula as the shape's own ``sdf``, so it finds exactly the
pixels that evaluating every (pixel, shape) pair would; the tiles that
differ are then evaluated pair by pair (:meth:`Plan.distances`) to tell
where and by how much.  The pixel budget (:data:`MAX_PIXELS`) only chooses the
pitch: the finest of :data:`PITCHES` whose tiles fit in it, else the
coarsest (0.04 mm, still below the tolerance); no board is refused for its
size.  A caller may limit the check to a box (verify: the field).

Decisions:

* drawn = pixel centres within tool/2 of a stroke (a dot is a disc of the
  tool's width);
* ideal grown by t = centres with min over shapes of the signed distance
  <= t: exact for t >= 0;
* ideal shrunk by t = centres at depth >= t inside ONE shape of the layer.
  This is a subset of the true erosion of the union; it misses only points
  within about t of a place where two shapes' outlines cross inside the
  union, so it can never report a false hole.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field

import numpy as np

from .shapes import TWO_PI, AnyShape, ArcBand, Disc, Layer, RoundRect, Stroke, run_shapes
from .sim import Run

#: Default pitch and the pitches tried for big boards, in units (0.01 mm).
PITCH = 2.0
PITCHES: tuple[float, ...] = (2.0, 3.0, 4.0)
#: Pixels evaluated at the finest pitch, at most; past it, a coarser pitch.
MAX_PIXELS = 50_000_000
#: Tile edge in pixels for :func:`compare`.
TILE = 256
#: Most tile centres tested against one shape at a time.
_TILE_CHUNK = 1 << 18
Box = tuple[float, float, float, float]


@dataclass(frozen=True)
class Grid:
    """nx x ny pixels of ``pitch`` units; pixel (i, j) has its centre at
    (x0 + (i + 0.5) * pitch, y0 + (j + 0.5) * pitch); arrays are [j, i]."""

    x0: float
    y0: float
    pitch: float
    nx: int
    ny: int

    @property
    def pixels(self) -> int:
        return self.nx * self.ny

    def centres(self, js: slice = slice(None), is_: slice = slice(None)
                ) -> tuple[np.ndarray, np.ndarray]:
        """Coordinate arrays (units) of the pixel centres of a window."""
        i = np.arange(self.nx)[is_]
        j = np.arange(self.ny)[js]
        xs = self.x0 + (i + 0.5) * self.pitch
        ys = self.y0 + (j + 0.5) * self.pitch
        return np.meshgrid(xs, ys)

    def window(self, box: Box, pad: float = 0.0) -> tuple[slice, slice] | None:
        """(rows, columns) of the pixels whose centres may lie in ``box``
        grown by ``pad``; None if none do."""
        i0 = max(0, math.floor((box[0] - pad - self.x0) / self.pitch - 0.5))
        i1 = min(self.nx, math.ceil((box[1] + pad - self.x0) / self.pitch + 0.5))
        j0 = max(0, math.floor((box[2] - pad - self.y0) / self.pitch - 0.5))
        j1 = min(self.ny, math.ceil((box[3] + pad - self.y0) / self.pitch + 0.5))
        if i0 >= i1 or j0 >= j1:
            return None
        return slice(j0, j1), slice(i0, i1)

    def sub(self, js: slice, is_: slice) -> Grid:
        """The grid of a window (slices with explicit start and stop)."""
        return Grid(self.x0 + is_.start * self.pitch, self.y0 + js.start * self.pitch,
                    self.pitch, is_.stop - is_.start, js.stop - js.start)


def union_box(boxes: Sequence[Box | None]) -> Box | None:
    """Smallest box holding every given box (None entries skipped)."""
    real = [b for b in boxes if b is not None]
    if not real:
        return None
    return (min(b[0] for b in real), max(b[1] for b in real),
            min(b[2] for b in real), max(b[3] for b in real))


def make_grid(box: Box, pitch: float = PITCH, margin: float = 10.0,
              max_pixels: int = MAX_PIXELS) -> Grid:
    """A grid over ``box`` grown by ``margin`` (units); ValueError if it
    would exceed ``max_pixels``."""
    x0 = math.floor(box[0] - margin)
    y0 = math.floor(box[2] - margin)
    nx = max(1, math.ceil((box[1] + margin - x0) / pitch))
    ny = max(1, math.ceil((box[3] + margin - y0) / pitch))
    if nx * ny > max_pixels:
        raise ValueError(f"raster of {nx} x {ny} pixels at {pitch / 100:.2f} mm "
                         f"exceeds {max_pixels} pixels")
    return Grid(x0, y0, pitch, nx, ny)


def min_sdf(shapes: Sequence[AnyShape], grid: Grid, pad: float) -> np.ndarray:
    """Minimum signed distance (units) of the shapes at every pixel centre;
    +inf where no shape's box grown by ``pad`` reaches."""
    out = np.full((grid.ny, grid.nx), np.inf)
    for s in shapes:
        win = grid.window(s.bbox(), pad)
        if win is None:
            continue
        x, y = grid.centres(*win)
        np.minimum(out[win], s.sdf(x, y), out=out[win])
    return out


def argmin_sdf(shapes: Sequence[AnyShape], ids: Sequence[int], grid: Grid,
               pad: float) -> tuple[np.ndarray, np.ndarray]:
    """Like :func:`min_sdf` over ``shapes[i] for i in ids``, and which one
    gives the minimum at each pixel (its id; -1 where none reaches; the
    first in ``ids`` order on ties)."""
    out = np.full((grid.ny, grid.nx), np.inf)
    which = np.full((grid.ny, grid.nx), -1, dtype=np.int64)
    for n in ids:
        win = grid.window(shapes[n].bbox(), pad)
        if win is None:
            continue
        x, y = grid.centres(*win)
        d = shapes[n].sdf(x, y)
        better = d < out[win]
        out[win] = np.where(better, d, out[win])
        which[win] = np.where(better, n, which[win])
    return out, which


def render_run(run: Run, tool: float, grid: Grid) -> np.ndarray:
    """Boolean raster of what ``run`` draws with a round tool of diameter
    ``tool`` (units)."""
    return min_sdf(run_shapes(run, tool), grid, grid.pitch) <= 0


def render_layer(layer: Layer | Sequence[AnyShape], grid: Grid,
                 offset: float = 0.0) -> np.ndarray:
    """Boolean raster of the ideal layer grown by ``offset`` units (negative
    = shrunk, per shape; see the module doc)."""
    shapes = layer.shapes if isinstance(layer, Layer) else list(layer)
    return min_sdf(shapes, grid, max(offset, 0.0) + grid.pitch) <= offset


@dataclass
class Report:
    """Result of :func:`compare`.  Counts are pixels.  Examples, worst
    first, in tape coordinates (mm from the start point): holes as (x_mm,
    y_mm, depth inside the ideal, distance to the nearest drawn pixel's
    coverage: a hairline gap shows as a tiny value); excess as (x_mm, y_mm,
    distance outside the ideal)."""

    tol_mm: float
    pitch_mm: float
    pixels: int
    drawn: int
    holes: int
    excess: int
    worst_holes: list[tuple[float, float, float, float]] = field(default_factory=list)
    worst_excess: list[tuple[float, float, float]] = field(default_factory=list)
    #: The tiles (tile row, tile column) with a hole or excess pixel.
    differ: list[tuple[int, int]] = field(default_factory=list, repr=False)

    @property
    def ok(self) -> bool:
        return self.holes == 0 and self.excess == 0

    def summary(self) -> str:
        """A few lines for an assertion message."""
        area = self.pitch_mm ** 2
        lines = [f"coverage at tolerance {self.tol_mm:.2f} mm, pitch {self.pitch_mm:.2f} mm, "
                 f"{self.pixels} pixels evaluated, {self.drawn} drawn: "
                 + ("OK" if self.ok else "FAILED"),
                 f"  holes:  {self.holes} pixels ({self.holes * area:.4f} mm2)",
                 f"  excess: {self.excess} pixels ({self.excess * area:.4f} mm2)"]
        for x, y, d, gap in self.worst_holes:
            lines.append(f"  hole at ({x:.2f}, {y:.2f}) mm, {d:.3f} mm deep inside the "
                         f"ideal, missed by {gap:.4f} mm")
        for x, y, d in self.worst_excess:
            lines.append(f"  excess at ({x:.2f}, {y:.2f}) mm, {d:.3f} mm outside the ideal")
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.summary()


def _top(values: np.ndarray, k: int) -> np.ndarray:
    """Indices of the k largest values (all if fewer); among equal values the
    first in the array.  Not ``argpartition``, whose choice among ties
    depends on the CPU (numpy selects with SIMD where the CPU has it): the
    k-th largest VALUE is the same everywhere, and ties are taken in order."""
    if values.size <= k:
        return np.arange(values.size)
    kth = np.partition(values, values.size - k)[values.size - k]
    above = np.flatnonzero(values > kth)
    ties = np.flatnonzero(values == kth)[:k - above.size]
    return np.concatenate([above, ties])


def _spread(cands: list[tuple[float, ...]], k: int,
            apart: float) -> list[tuple[float, ...]]:
    """The k worst candidates (largest third item) at least ``apart`` from
    each other."""
    out: list[tuple[float, float, float]] = []
    for c in sorted(cands, key=lambda t: (-t[2], t[0], t[1])):
        if all(math.hypot(c[0] - o[0], c[1] - o[1]) >= apart for o in out):
            out.append(c)
            if len(out) == k:
                break
    return out


# ---------------------------------------------------------------------------
# The shapes as arrays: every shape's signed distance, many at once.
# ---------------------------------------------------------------------------
#: Kinds of item a shape is cut into for evaluation in bulk.
_DISC, _RECT, _SEG, _ARC = range(4)
#: Most (pixel, item) pairs evaluated at once.
PAIRS = 1 << 20
#: Most tiles held in one batch (boolean pass; a tenth of it with distances).
BATCH_TILES = 64
#: Most (item, pixel row) pairs given row spans at once (:meth:`Plan.cover`).
SPAN_ROWS = 1 << 18
#: How far (units) the levels of :meth:`Plan.cover`'s sure and possible
#: intervals lie below and above the level asked: 10 nm, some 1e7 times
#: the rounding of a distance on a field of 10^5 units.
SPAN_MARGIN = 1e-3
#: Most pixels of spans filled at once.
PAINT = 1 << 22


def _upright_spans(ax: np.ndarray, ay: np.ndarray, ex: np.ndarray, ey: np.ndarray,
                   r: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The x interval where the line of ordinate ``y`` meets the points
    within ``r`` of an upright segment (ex or ey zero), from (ax, ay) by
    (ex, ey): its box grown by r with round corners (empty: lo > hi)."""
    a = np.abs(ex) / 2
    cx = ax + ex / 2
    qy = np.abs(y - (ay + ey / 2)) - np.abs(ey) / 2
    bulge = np.sqrt(np.maximum(r * r - qy * qy, 0.0))
    half = a + np.where(qy <= 0, r, bulge)
    ok = (r >= 0) & (qy <= r)
    return np.where(ok, cx - half, np.inf), np.where(ok, cx + half, -np.inf)


def _capsule_spans(ax: np.ndarray, ay: np.ndarray, ex: np.ndarray, ey: np.ndarray,
                   ee: np.ndarray, r: np.ndarray, yy: np.ndarray
                   ) -> tuple[np.ndarray, np.ndarray]:
    """The x interval where the line of ordinate ``yy`` meets the points
    within ``r`` of the segment from (ax, ay) by (ex, ey), ee = ex^2 + ey^2
    (empty: lo > hi): the band along it, and the discs about its ends."""
    length = np.sqrt(ee)
    dy = yy - ay
    inf = np.full(dy.shape, np.inf)
    # the band: 0 <= t <= 1 and |perpendicular distance| <= r
    with np.errstate(divide="ignore", invalid="ignore"):
        ta = np.where(ex != 0, (0.0 - dy * ey) / ex, -inf)
        tb = np.where(ex != 0, (ee - dy * ey) / ex, inf)
        t_all = (dy * ey >= 0) & (dy * ey <= ee)
        pa = np.where(ey != 0, (dy * ex - r * length) / ey, -inf)
        pb = np.where(ey != 0, (dy * ex + r * length) / ey, inf)
        p_all = np.abs(dy * ex) <= r * length
    b_lo = np.maximum(np.where(ex != 0, np.minimum(ta, tb), np.where(t_all, -inf, inf)),
                      np.where(ey != 0, np.minimum(pa, pb), np.where(p_all, -inf, inf)))
    b_hi = np.minimum(np.where(ex != 0, np.maximum(ta, tb), np.where(t_all, inf, -inf)),
                      np.where(ey != 0, np.maximum(pa, pb), np.where(p_all, inf, -inf)))
    b_lo = ax + b_lo
    b_hi = ax + b_hi
    empty = b_lo > b_hi
    s_lo = np.where(empty, inf, b_lo)
    s_hi = np.where(empty, -inf, b_hi)
    # the round ends: discs about both ends
    for px, py in ((ax, ay), (ax + ex, ay + ey)):
        d = yy - py
        h2 = r * r - d * d
        ok = h2 >= 0
        h = np.sqrt(np.where(ok, h2, 0.0))
        s_lo = np.minimum(s_lo, np.where(ok, px - h, inf))
        s_hi = np.maximum(s_hi, np.where(ok, px + h, -inf))
    return s_lo, s_hi


@dataclass
class ShapeSet:
    """Shapes as arrays, for evaluating many (point, shape) pairs with one
    numpy call per kind.  Each shape is one or more *items*: a disc, a
    rounded rectangle, a segment of a polyline (the first one also carries
    the distance to the polyline's first point) or an arc band.  An item's
    distance minus nothing is the shape's :meth:`sdf` formula term by term,
    so that the minimum over a shape's items is the shape's own ``sdf``
    bit for bit (``min(a, b) - r == min(a - r, b - r)`` in floating point).
    ``first``/``count``: per shape, its first item and how many."""

    n: int
    bbox: np.ndarray                       # (n, 4): x0, x1, y0, y1
    kind: np.ndarray                       # per item
    owner: np.ndarray                      # per item: shape index
    cols: np.ndarray                       # (12, items): parameter c of item i at [c, i]
    first: np.ndarray                      # per shape
    count: np.ndarray                      # per shape
    ibox: np.ndarray                       # (items, 4): each item's own box

    @classmethod
    def of(cls, shapes: Sequence[AnyShape]) -> ShapeSet:
        n = len(shapes)
        types = [type(s) for s in shapes]
        if not all(t in (Disc, RoundRect, Stroke, ArcBand) for t in types):
            bad = next(s for s in shapes if type(s) not in (Disc, RoundRect, Stroke, ArcBand))
            if not isinstance(bad, (Disc, RoundRect, Stroke, ArcBand)):
                raise TypeError(f"not a shape: {bad!r}")
            return cls._of_each(shapes)
        boxes = np.zeros((n, 4))
        count = np.ones(n, dtype=np.int64)
        # the shapes of one item each, a type at a time
        one: list[tuple[int, np.ndarray, np.ndarray]] = []    # (kind, shape indices, params)
        disc = np.array([i for i, t in enumerate(types) if t is Disc], dtype=np.int64)
        if disc.size:
            q = np.array([(shapes[i].cx, shapes[i].cy, shapes[i].r) for i in disc.tolist()],
                         dtype=float).reshape(-1, 3)
            cx, cy, r = q.T
            boxes[disc] = np.stack([cx - r, cx + r, cy - r, cy + r], axis=1)
            one.append((_DISC, disc, q))
        rect = np.array([i for i, t in enumerate(types) if t is RoundRect], dtype=np.int64)
        if rect.size:
            q = np.array([(shapes[i].cx, shapes[i].cy, shapes[i].w, shapes[i].h, shapes[i].rc)
                          for i in rect.tolist()], dtype=float).reshape(-1, 5)
            cx, cy, w, h, rc = q.T
            boxes[rect] = np.stack([cx - w / 2, cx + w / 2, cy - h / 2, cy + h / 2], axis=1)
            one.append((_RECT, rect, np.stack([cx, cy, w / 2 - rc, h / 2 - rc, rc], axis=1)))
        arc = np.array([i for i, t in enumerate(types) if t is ArcBand], dtype=np.int64)
        if arc.size:
            rows = []
            for i in arc.tolist():
                a = shapes[i]
                a1 = a.a0 + a.sweep
                rows.append((a.cx, a.cy, a.rad, a.a0, a.sweep, a.hw, 1.0 if a.full else 0.0,
                             a.rad * math.cos(a.a0), a.rad * math.sin(a.a0),
                             a.rad * math.cos(a1), a.rad * math.sin(a1)))
            q = np.array(rows, dtype=float).reshape(-1, 11)
            cx, cy, rad, hw, full = q[:, 0], q[:, 1], q[:, 2], q[:, 5], q[:, 6] != 0
            boxes[arc] = np.stack([(cx - rad) - hw, (cx + rad) + hw,
                                   (cy - rad) - hw, (cy + rad) + hw], axis=1)
            for k in np.flatnonzero(~full).tolist():
                boxes[arc[k]] = shapes[int(arc[k])].bbox()
            one.append((_ARC, arc, q))
        # strokes: a segment an item (a disc if none)
        strokes = [i for i, t in enumerate(types) if t is Stroke]
        s_items: list[tuple[float, ...]] = []
        s_kind: list[int] = []
        s_box: list[Box] = []
        s_boxes: list[Box] = []
        for i in strokes:
            st = shapes[i]
            pts = st.points
            r = st.r
            s_boxes.append(st.bbox())
            lead = True
            c = 0
            for (ax, ay), (bx, by) in zip(pts, pts[1:]):
                ex, ey = bx - ax, by - ay
                ee = ex * ex + ey * ey
                if ee == 0:
                    continue
                s_kind.append(_SEG)
                s_items.append((ax, ay, ex, ey, ee, r, 1.0 if lead else 0.0,
                                pts[0][0], pts[0][1]))
                s_box.append((min(ax, bx) - r, max(ax, bx) + r,
                              min(ay, by) - r, max(ay, by) + r))
                lead = False
                c += 1
            if lead:                        # no segment: a disc at the first point
                s_kind.append(_DISC)
                s_items.append((pts[0][0], pts[0][1], r, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0))
                s_box.append(s_boxes[-1])
                c = 1
            count[i] = c
        stroke = np.array(strokes, dtype=np.int64)
        if stroke.size:
            boxes[stroke] = np.array(s_boxes, dtype=float).reshape(-1, 4)
        first = np.cumsum(count) - count
        total = int(count.sum())
        kind = np.zeros(total, dtype=np.int64)
        owner = np.repeat(np.arange(n, dtype=np.int64), count)
        par = np.zeros((12, total))
        ibox = np.zeros((total, 4))
        for k, idx, q in one:
            at = first[idx]
            kind[at] = k
            par[:q.shape[1], at] = q.T
            ibox[at] = boxes[idx]
        if stroke.size:
            c = count[stroke]
            at = (np.repeat(first[stroke], c) + np.arange(int(c.sum()))
                  - np.repeat(np.cumsum(c) - c, c))
            kind[at] = s_kind
            par[:9, at] = np.array(s_items, dtype=float).reshape(-1, 9).T
            ibox[at] = np.array(s_box, dtype=float).reshape(-1, 4)
        return cls(n, boxes, kind, owner, par, first, count, ibox)

    @classmethod
    def _of_each(cls, shapes: Sequence[AnyShape]) -> ShapeSet:
        """:meth:`of` for shapes of subclasses of the shape types: one at a
        time."""
        kinds: list[int] = []
        owners: list[int] = []
        pars: list[tuple[float, ...]] = []
        iboxes: list[Box] = []
        first = np.zeros(len(shapes), dtype=np.int64)
        count = np.zeros(len(shapes), dtype=np.int64)
        boxes = np.zeros((len(shapes), 4))
        for n, s in enumerate(shapes):
            first[n] = len(kinds)
            boxes[n] = s.bbox()
            if isinstance(s, Disc):
                kinds.append(_DISC)
                pars.append((s.cx, s.cy, s.r))
            elif isinstance(s, RoundRect):
                kinds.append(_RECT)
                pars.append((s.cx, s.cy, s.w / 2 - s.rc, s.h / 2 - s.rc, s.rc))
            elif isinstance(s, Stroke):
                pts = s.points
                lead = True
                for (ax, ay), (bx, by) in zip(pts, pts[1:]):
                    ex, ey = bx - ax, by - ay
                    ee = ex * ex + ey * ey
                    if ee == 0:
                        continue
                    kinds.append(_SEG)
                    pars.append((ax, ay, ex, ey, ee, s.r, 1.0 if lead else 0.0,
                                 pts[0][0], pts[0][1]))
                    iboxes.append((min(ax, bx) - s.r, max(ax, bx) + s.r,
                                   min(ay, by) - s.r, max(ay, by) + s.r))
                    owners.append(n)
                    lead = False
                if lead:                    # no segment: a disc at the first point
                    kinds.append(_DISC)
                    pars.append((pts[0][0], pts[0][1], s.r))
                    iboxes.append(s.bbox())
                else:
                    count[n] = len(kinds) - first[n]
                    continue
            elif isinstance(s, ArcBand):
                a1 = s.a0 + s.sweep
                kinds.append(_ARC)
                pars.append((s.cx, s.cy, s.rad, s.a0, s.sweep, s.hw, 1.0 if s.full else 0.0,
                             s.rad * math.cos(s.a0), s.rad * math.sin(s.a0),
                             s.rad * math.cos(a1), s.rad * math.sin(a1)))
            else:
                raise TypeError(f"not a shape: {s!r}")
            if len(iboxes) < len(kinds):
                iboxes.append(tuple(boxes[n]))
            owners.append(n)
            count[n] = len(kinds) - first[n]
        par = np.array([p + (0.0,) * (12 - len(p)) for p in pars]).reshape(-1, 12)
        par = np.ascontiguousarray(par.T)
        return cls(len(shapes), boxes, np.asarray(kinds, dtype=np.int64),
                   np.asarray(owners, dtype=np.int64), par, first, count,
                   np.array(iboxes, dtype=float).reshape(-1, 4))

    def items_of(self, shapes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The items of the given shapes: (item indices, position in
        ``shapes`` of each item's shape)."""
        cnt = self.count[shapes]
        pos = np.repeat(np.arange(shapes.size), cnt)
        start = np.repeat(np.cumsum(cnt) - cnt, cnt)
        items = self.first[shapes][pos] + np.arange(pos.size) - start
        return items, pos

    def item_sdf(self, items: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Each item's term of its shape's signed distance at (x, y) (one
        point per item, same length)."""
        kind = self.kind[items]
        if not kind.size:
            return np.zeros(0)
        if kind.min() == kind.max():
            return self._kind_sdf(int(kind[0]), items, x, y)
        out = np.empty(items.size)
        for k in np.flatnonzero(np.bincount(kind, minlength=4)).tolist():
            sel = np.flatnonzero(kind == k)
            out[sel] = self._kind_sdf(k, items[sel], x[sel], y[sel])
        return out

    def _kind_sdf(self, k: int, items: np.ndarray, x: np.ndarray, y: np.ndarray
                  ) -> np.ndarray:
        """:meth:`item_sdf` of items all of kind ``k``: the formula of the
        shape's ``sdf``, operation for operation."""
        def col(c: int) -> np.ndarray:
            return self.cols[c][items]

        if k == _DISC:
            d = np.hypot(x - col(0), y - col(1))
            d -= col(2)
            return d
        if k == _RECT:
            qx = np.abs(x - col(0))
            qx -= col(2)
            qy = np.abs(y - col(1))
            qy -= col(3)
            outside = np.hypot(np.maximum(qx, 0.0), np.maximum(qy, 0.0))
            inside = np.minimum(np.maximum(qx, qy), 0.0)
            outside += inside
            outside -= col(4)
            return outside
        if k == _SEG:
            px = x - col(0)
            py = y - col(1)
            ex, ey = col(2), col(3)
            t = px * ex
            t += py * ey
            t /= col(4)
            np.clip(t, 0.0, 1.0, out=t)
            ex *= t
            ey *= t
            ex -= px
            np.negative(ex, out=ex)                 # px - t * ex
            ey -= py
            np.negative(ey, out=ey)
            d = np.hypot(ex, ey)
            lead = self.cols[6][items] != 0
            if lead.all():
                np.minimum(np.hypot(px, py), d, out=d)
            elif lead.any():
                d[lead] = np.minimum(np.hypot(px[lead], py[lead]), d[lead])
            d -= col(5)
            return d
        rx = x - col(0)
        ry = y - col(1)
        ring = np.abs(np.hypot(rx, ry) - col(2))
        part = self.cols[6][items] == 0
        if part.any():
            q = items[part]
            prx, pry = rx[part], ry[part]
            a0, sweep = self.cols[3][q], self.cols[4][q]
            ang = np.arctan2(pry, prx)
            t = np.where(sweep >= 0, np.mod(ang - a0, TWO_PI), np.mod(a0 - ang, TWO_PI))
            ends = np.minimum(np.hypot(prx - self.cols[7][q], pry - self.cols[8][q]),
                              np.hypot(prx - self.cols[9][q], pry - self.cols[10][q]))
            ring = ring.copy()
            ring[part] = np.where(t <= np.abs(sweep), ring[part], ends)
        ring -= col(5)
        return ring

    def row_spans(self, items: np.ndarray, y: np.ndarray, level: float
                  ) -> tuple[np.ndarray, np.ndarray]:
        """Where each item's term of the signed distance is at most
        ``level`` on the line of ordinate ``y`` (one line per item), in
        exact arithmetic: two x intervals per item, ``lo[k]`` to ``hi[k]``
        for k = 0, 1 (empty where lo > hi; they may overlap), computed
        analytically: a disc, a rounded rectangle and a segment's capsule
        meet a line in one interval, an annulus in two.  An arc that is
        not a full circle gives the intervals of its full annulus (the arc
        lies within it: a point near an end of the arc is as near the
        circle).  The ends carry rounding errors of about 1e-16 of the
        coordinates, far below the margin :meth:`Plan.cover` allows."""
        n = items.size
        lo = np.full((2, n), np.inf)
        hi = np.full((2, n), -np.inf)
        kind = self.kind[items]
        for k in np.flatnonzero(np.bincount(kind, minlength=4)).tolist():
            sel = np.flatnonzero(kind == k) if kind.min() != kind.max() else slice(None)
            it = items[sel]
            yy = y[sel]

            def col(c: int) -> np.ndarray:
                return self.cols[c][it]

            if k == _DISC:
                r = col(2) + level
                dy = yy - col(1)
                h2 = r * r - dy * dy
                ok = (r >= 0) & (h2 >= 0)
                h = np.sqrt(np.where(ok, h2, 0.0))
                cx = col(0)
                lo[0, sel] = np.where(ok, cx - h, np.inf)
                hi[0, sel] = np.where(ok, cx + h, -np.inf)
            elif k == _RECT:
                r = col(4) + level
                qy = np.abs(yy - col(1)) - col(3)
                a = col(2)
                pos = r >= 0
                bulge = np.sqrt(np.maximum(r * r - qy * qy, 0.0))
                half = np.where(pos, a + np.where(qy <= 0, r, bulge), a + r)
                ok = (qy <= r) & (half >= 0)
                cx = col(0)
                lo[0, sel] = np.where(ok, cx - half, np.inf)
                hi[0, sel] = np.where(ok, cx + half, -np.inf)
            elif k == _SEG:
                ax, ay, ex, ey = col(0), col(1), col(2), col(3)
                r = col(5) + level
                axis = (ex == 0) | (ey == 0)
                if axis.all():
                    s_lo, s_hi = _upright_spans(ax, ay, ex, ey, r, yy)
                else:
                    s_lo, s_hi = _capsule_spans(ax, ay, ex, ey, col(4), r, yy)
                    if axis.any():
                        u = np.flatnonzero(axis)
                        s_lo[u], s_hi[u] = _upright_spans(ax[u], ay[u], ex[u], ey[u], r[u], yy[u])
                neg = r < 0
                lo[0, sel] = np.where(neg, np.inf, s_lo)
                hi[0, sel] = np.where(neg, -np.inf, s_hi)
            else:
                w = col(5) + level
                rad = col(2)
                dy = yy - col(1)
                ro = rad + w
                ri = rad - w
                o2 = ro * ro - dy * dy
                i2 = ri * ri - dy * dy
                ok = (w >= 0) & (o2 >= 0)
                o = np.sqrt(np.where(ok, o2, 0.0))
                i = np.sqrt(np.where((ri > 0) & (i2 > 0), i2, 0.0))
                cx = col(0)
                lo[0, sel] = np.where(ok, cx - o, np.inf)
                hi[0, sel] = np.where(ok, cx - i, -np.inf)
                lo[1, sel] = np.where(ok, cx + i, np.inf)
                hi[1, sel] = np.where(ok, cx + o, -np.inf)
        return lo, hi

    def nearest(self, x: np.ndarray, y: np.ndarray, upto: int | None = None
                ) -> tuple[np.ndarray, np.ndarray]:
        """At each point, the least signed distance of the shapes (the first
        ``upto`` of them, if given) and which shape has it (the first on
        ties; -1 and inf when there are none)."""
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        best = np.full(x.size, np.inf)
        which = np.full(x.size, -1, dtype=np.int64)
        n = self.n if upto is None else upto
        items = np.arange(self.first[n] if n < self.n else self.kind.size)
        step = max(1, PAIRS // max(1, items.size))
        for a in range(0, x.size, step):
            m = min(x.size, a + step) - a
            pt = np.repeat(np.arange(m), items.size)
            it = np.tile(items, m)
            d = self.item_sdf(it, x[a:a + m][pt], y[a:a + m][pt])
            per = np.full((m, n), np.inf)
            np.minimum.at(per, (pt, self.owner[it]), d)
            k = np.argmin(per, axis=1) if n else np.zeros(m, dtype=np.int64)
            if n:
                best[a:a + m] = per[np.arange(m), k]
                which[a:a + m] = np.where(np.isfinite(best[a:a + m]), k, -1)
        return best, which
# ---------------------------------------------------------------------------
# Tiles: which shapes reach which tile, and evaluating many tiles at once.
# ---------------------------------------------------------------------------
def _memberships(grid: Grid, ss: ShapeSet, pads: np.ndarray,
                 clip: tuple[int, int, int, int] | None) -> tuple[np.ndarray, np.ndarray]:
    """(tile key, shape) of every tile each shape can reach: the tiles whose
    centre lies within the tile's half diagonal plus the shape's pad of the
    shape (a shape whose box grown by its pad lies in one tile: that tile).
    Tile key = tile row * tile columns + tile column.  ``clip``: the tile
    ranges (ti0, ti1, tj0, tj1) kept, None for all."""
    span = TILE * grid.pitch
    half = span * math.sqrt(0.5)
    ntx, nty = math.ceil(grid.nx / TILE), math.ceil(grid.ny / TILE)
    b = ss.bbox
    ti0 = np.maximum(0, np.floor((b[:, 0] - pads - grid.x0) / span)).astype(np.int64)
    ti1 = np.minimum(ntx - 1, np.floor((b[:, 1] + pads - grid.x0) / span)).astype(np.int64)
    tj0 = np.maximum(0, np.floor((b[:, 2] - pads - grid.y0) / span)).astype(np.int64)
    tj1 = np.minimum(nty - 1, np.floor((b[:, 3] + pads - grid.y0) / span)).astype(np.int64)
    ok = (ti0 <= ti1) & (tj0 <= tj1)
    one = ok & (ti0 == ti1) & (tj0 == tj1)
    keys = [tj0[one] * ntx + ti0[one]]
    owners = [np.flatnonzero(one)]
    if clip is not None:
        ti0, ti1 = np.maximum(ti0, clip[0]), np.minimum(ti1, clip[1])
        tj0, tj1 = np.maximum(tj0, clip[2]), np.minimum(tj1, clip[3])
    multi = np.flatnonzero(ok & ~one & (ti0 <= ti1) & (tj0 <= tj1))
    wide = ti1[multi] - ti0[multi] + 1
    tiles = wide * (tj1[multi] - tj0[multi] + 1) * ss.count[multi]
    huge = tiles > PAIRS
    for n in multi[huge].tolist():        # one huge shape: a few tile rows at a time
        keys_n = _shape_tiles(grid, ss, n, int(ti0[n]), int(ti1[n]), int(tj0[n]), int(tj1[n]),
                              half + float(pads[n]))
        keys.append(keys_n)
        owners.append(np.full(keys_n.size, n, dtype=np.int64))
    small, cost = multi[~huge], tiles[~huge]
    bounds = np.flatnonzero(np.diff(np.cumsum(cost) // PAIRS)) + 1
    for sel in np.split(small, bounds):    # the others, a few at a time
        if not sel.size:
            continue
        items, pos = ss.items_of(sel)
        n_of = sel[pos]
        w = (ti1 - ti0 + 1)[n_of]
        cnt = w * (tj1 - tj0 + 1)[n_of]
        rep = np.repeat(np.arange(items.size), cnt)
        off = np.arange(rep.size) - np.repeat(np.cumsum(cnt) - cnt, cnt)
        ti = ti0[n_of][rep] + off % w[rep]
        tj = tj0[n_of][rep] + off // w[rep]
        cx = grid.x0 + (ti + 0.5) * span
        cy = grid.y0 + (tj + 0.5) * span
        near = ss.item_sdf(items[rep], cx, cy) <= half + pads[n_of][rep]
        keys.append(tj[near] * ntx + ti[near])
        owners.append(n_of[rep][near])
    key = np.concatenate(keys)
    own = np.concatenate(owners)
    if clip is not None:
        ti, tj = key % ntx, key // ntx
        keep = (ti >= clip[0]) & (ti <= clip[1]) & (tj >= clip[2]) & (tj <= clip[3])
        key, own = key[keep], own[keep]
    # one row per (tile, shape), in tile order, then shape order
    order = np.lexsort((own, key))
    key, own = key[order], own[order]
    first = np.ones(key.size, dtype=bool)
    first[1:] = (key[1:] != key[:-1]) | (own[1:] != own[:-1])
    return key[first], own[first]


def _shape_tiles(grid: Grid, ss: ShapeSet, n: int, ti0: int, ti1: int, tj0: int, tj1: int,
                 reach: float) -> np.ndarray:
    """The tile keys of one huge shape, a few tile rows at a time."""
    span = TILE * grid.pitch
    ntx = math.ceil(grid.nx / TILE)
    its = np.arange(ss.first[n], ss.first[n] + ss.count[n])
    rows = max(1, PAIRS // ((ti1 - ti0 + 1) * its.size))
    out = []
    for r0 in range(tj0, tj1 + 1, rows):
        tj, ti = np.meshgrid(np.arange(r0, min(tj1, r0 + rows - 1) + 1), np.arange(ti0, ti1 + 1),
                             indexing="ij")
        tj, ti = tj.ravel(), ti.ravel()
        m = tj.size
        it = np.tile(its, m)
        at = np.repeat(np.arange(m), its.size)
        d = ss.item_sdf(it, grid.x0 + (ti[at] + 0.5) * span, grid.y0 + (tj[at] + 0.5) * span)
        near = np.zeros(m, dtype=bool)
        near[at[d <= reach]] = True
        out.append(tj[near] * ntx + ti[near])
    return np.concatenate(out) if out else np.zeros(0, dtype=np.int64)


@dataclass
class Plan:
    """The tiles :func:`compare` evaluates: ``shapes`` is the ideal shapes
    then the drawn ones (``n_ideal`` of the first kind); ``keys`` the tiles
    (tile row * ``ntx`` + tile column, ascending), and the shapes that may
    reach tile ``keys[t]`` are ``members[start[t]:start[t + 1]]`` (indices
    into ``shapes``, ascending); ideal shapes are evaluated with window
    margin ``pad``, drawn ones with ``pitch``."""

    grid: Grid
    pitch: float
    pad: float
    shapes: list[AnyShape]
    n_ideal: int
    keys: np.ndarray
    start: np.ndarray
    members: np.ndarray
    pixels: int
    set: ShapeSet

    @property
    def ntx(self) -> int:
        return math.ceil(self.grid.nx / TILE)

    def where(self, t: int) -> tuple[int, int]:
        """(tile row, tile column) of the t-th tile."""
        return divmod(int(self.keys[t]), self.ntx)

    @property
    def tiles(self) -> dict[tuple[int, int], list[int]]:
        """The tiles as a dict (tile row, tile column) -> shape indices."""
        return {self.where(t): self.members[self.start[t]:self.start[t + 1]].tolist()
                for t in range(self.keys.size)}

    def tile(self, tj: int, ti: int) -> Grid:
        """The grid of one tile."""
        js = slice(tj * TILE, min(self.grid.ny, (tj + 1) * TILE))
        is_ = slice(ti * TILE, min(self.grid.nx, (ti + 1) * TILE))
        return self.grid.sub(js, is_)

    def batches(self, tiles: np.ndarray | None = None, limit: int = BATCH_TILES
                ) -> Iterator[np.ndarray]:
        """The given tile numbers (default all), in order, cut into batches
        of at most ``limit`` tiles and about :data:`PAIRS` pairs."""
        ts = np.arange(self.keys.size) if tiles is None else np.asarray(tiles, dtype=np.int64)
        if not ts.size:
            return
        cost = self._tile_cost[ts]
        acc = 0.0
        cur: list[int] = []
        for t, c in zip(ts.tolist(), cost.tolist()):
            if cur and (len(cur) >= limit or acc + c > 4 * PAIRS):
                yield np.asarray(cur, dtype=np.int64)
                cur, acc = [], 0.0
            cur.append(t)
            acc += c
        if cur:
            yield np.asarray(cur, dtype=np.int64)

    def __post_init__(self) -> None:
        self._windows()

    def _windows(self) -> None:
        """Every (tile, item) entry's window in the tile: j0, j1, i0, i1
        (pixels of the tile), and its pixels.  An item's window is its own
        box grown by its shape's pad (a segment of a polyline: the
        segment's box), so the shape's distance is exact where it is within
        the pad, as with :func:`min_sdf`, and a long polyline costs its
        length, not its box."""
        g, p = self.grid, self.pitch
        t = np.repeat(np.arange(self.keys.size), np.diff(self.start))
        items, row = self.set.items_of(self.members)
        self._entry_start = np.concatenate(([0], np.cumsum(self.set.count[self.members])))
        self._item = items
        et = t[row]
        tj, ti = np.divmod(self.keys[et], self.ntx)
        m = self.members[row]
        pad = np.where(m < self.n_ideal, self.pad, p)
        b = self.set.ibox[items]
        tx0 = g.x0 + (ti * TILE) * p
        ty0 = g.y0 + (tj * TILE) * p
        tnx = np.minimum(g.nx, (ti + 1) * TILE) - ti * TILE
        tny = np.minimum(g.ny, (tj + 1) * TILE) - tj * TILE
        i0 = np.maximum(0, np.floor((b[:, 0] - pad - tx0) / p - 0.5)).astype(np.int64)
        i1 = np.minimum(tnx, np.ceil((b[:, 1] + pad - tx0) / p + 0.5)).astype(np.int64)
        j0 = np.maximum(0, np.floor((b[:, 2] - pad - ty0) / p - 0.5)).astype(np.int64)
        j1 = np.minimum(tny, np.ceil((b[:, 3] + pad - ty0) / p + 0.5)).astype(np.int64)
        empty = (i0 >= i1) | (j0 >= j1)
        i1[empty] = i0[empty]
        j1[empty] = j0[empty]
        self._win = np.stack([j0, j1, i0, i1], axis=1)
        self._cost = ((j1 - j0) * (i1 - i0)).astype(float)
        self._tx0, self._ty0 = tx0, ty0
        self._tile_cost = np.bincount(et, weights=self._cost, minlength=self.keys.size)

    def tile_pixels(self, t: np.ndarray) -> np.ndarray:
        """Pixels of each given tile."""
        tj, ti = np.divmod(self.keys[t], self.ntx)
        g = self.grid
        return ((np.minimum(g.nx, (ti + 1) * TILE) - ti * TILE)
                * (np.minimum(g.ny, (tj + 1) * TILE) - tj * TILE))

    def _entries(self, batch: np.ndarray, ideal: bool) -> tuple[np.ndarray, np.ndarray]:
        """The (tile, item) entries of a batch of tiles with a non-empty
        window, ideal or drawn: (entry indices, slot of each entry's tile
        in the batch)."""
        es = self._entry_start
        lo, hi = es[self.start[batch]], es[self.start[batch + 1]]
        n = hi - lo
        ents = (np.arange(int(n.sum())) - np.repeat(np.cumsum(n) - n - lo, n)).astype(np.int64)
        slot = np.repeat(np.arange(batch.size), n)
        own = self.set.owner[self._item[ents]]
        keep = ((own < self.n_ideal) if ideal else (own >= self.n_ideal)) & (self._cost[ents] > 0)
        return ents[keep], slot[keep]

    def pairs(self, batch: np.ndarray, ideal: bool, owners: bool = False
              ) -> Iterator[tuple[np.ndarray, np.ndarray | None, np.ndarray]]:
        """The (pixel, shape) pairs of a batch of tiles, ideal or drawn
        shapes, in chunks of about :data:`PAIRS`: (flat pixel index into
        a (len(batch), TILE, TILE) array, shape index (if ``owners``, else
        None), signed distance)."""
        ents, slot = self._entries(batch, ideal)
        if not ents.size:
            return
        kind = self.set.kind[self._item[ents]]
        order = np.argsort(kind, kind="stable")    # one kind a chunk, mostly
        ents, slot, kind = ents[order], slot[order], kind[order]
        cost = np.cumsum(self._cost[ents])
        cuts = np.union1d(np.searchsorted(cost, np.arange(PAIRS, cost[-1], PAIRS), side="right"),
                          np.flatnonzero(kind[1:] != kind[:-1]) + 1)
        p = self.pitch
        for e, sl in zip(np.split(ents, cuts), np.split(slot, cuts)):
            if not e.size:
                continue
            j0, j1, i0, i1 = self._win[e].T.astype(np.int32)
            w = i1 - i0
            cnt = (j1 - j0) * w
            rep = np.repeat(np.arange(e.size, dtype=np.int32), cnt)
            off = np.arange(rep.size, dtype=np.int32)
            off -= np.repeat((np.cumsum(cnt) - cnt).astype(np.int32), cnt)
            lj, li = np.divmod(off, w[rep])
            lj += j0[rep]
            li += i0[rep]
            x = (li + 0.5) * p
            x += self._tx0[e][rep]
            y = (lj + 0.5) * p
            y += self._ty0[e][rep]
            items = self._item[e][rep]
            d = self.set.item_sdf(items, x, y)
            pix = sl.astype(np.int32)[rep]
            pix *= TILE
            pix += lj
            pix *= TILE
            pix += li
            yield pix, (self.set.owner[items] if owners else None), d

    def cover(self, batch: np.ndarray, ideal: bool, level: float) -> np.ndarray:
        """Booleans of a batch, flat (len(batch) * TILE * TILE): where some
        ideal (or drawn) shape's signed distance is at most ``level``,
        exactly as evaluating every (pixel, shape) pair of :meth:`pairs`
        would find, at the cost of the rows, not the pixels, of each shape.

        Each item meets each pixel row of its window in at most two
        intervals (:meth:`ShapeSet.row_spans`).  Those of the level lowered
        by :data:`SPAN_MARGIN` hold only pixels whose distance, evaluated,
        is surely at most ``level`` (the rounding of both is far smaller
        than the margin); those of the level raised by it hold every pixel
        whose distance surely is.  The first are filled whole, the
        pixels between the two are evaluated with :meth:`ShapeSet.item_sdf`
        as :meth:`pairs` does: the pixels on or near an outline, such as
        the centres that lie exactly on it.  An arc that is not a full
        circle has all its annulus's pixels evaluated."""
        size = batch.size * TILE * TILE
        ents, slot = self._entries(batch, ideal)
        out = np.zeros(size, dtype=bool)
        if not ents.size:
            return out
        win = self._win[ents]
        rows = win[:, 1] - win[:, 0]
        bounds = np.flatnonzero(np.diff(np.cumsum(rows) // SPAN_ROWS)) + 1
        p = self.pitch
        for e_idx in np.split(np.arange(ents.size), bounds):
            if not e_idx.size:
                continue
            e, sl = ents[e_idx], slot[e_idx]
            j0, _, i0, i1 = win[e_idx].T
            cnt = rows[e_idx]
            rep = np.repeat(np.arange(e.size), cnt)
            lj = np.arange(rep.size) - np.repeat(np.cumsum(cnt) - cnt, cnt) + j0[rep]
            items = self._item[e][rep]
            y = (lj + 0.5) * p
            y += self._ty0[e][rep]
            tx0 = self._tx0[e][rep]
            first, last = i0[rep], i1[rep] - 1
            partial = (self.set.kind[items] == _ARC) & (self.set.cols[6][items] == 0)

            def pixels(lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
                # pixel columns whose centres lie in [lo, hi], clipped to the window
                a = np.ceil(np.clip((lo - tx0) / p - 0.5, -1.0, TILE + 1.0))
                b = np.floor(np.clip((hi - tx0) / p - 0.5, -2.0, TILE + 1.0))
                return (np.maximum(a.astype(np.int64), first),
                        np.minimum(b.astype(np.int64), last))

            s_lo, s_hi = self.set.row_spans(items, y, level - SPAN_MARGIN)
            c_lo, c_hi = self.set.row_spans(items, y, level + SPAN_MARGIN)
            base = (sl[rep] * TILE + lj) * TILE
            amb_row: list[np.ndarray] = []
            amb_a: list[np.ndarray] = []
            amb_b: list[np.ndarray] = []
            for k in range(2):
                sa, sb = pixels(s_lo[k], s_hi[k])
                ca, cb = pixels(c_lo[k], c_hi[k])
                sure = (sa <= sb) & ~partial
                _paint(out, base[sure] + sa[sure], sb[sure] - sa[sure] + 1)
                # the pixels between: all of the wide interval where the
                # narrow one is empty, else its two ends
                whole = ~sure & (ca <= cb)
                left = sure & (ca < sa)
                right = sure & (sb < cb)
                amb_row += [np.flatnonzero(whole), np.flatnonzero(left), np.flatnonzero(right)]
                amb_a += [ca[whole], ca[left], sb[right] + 1]
                amb_b += [cb[whole], sa[left] - 1, cb[right]]
            r_ = np.concatenate(amb_row)
            if not r_.size:
                continue
            a_, b_ = np.concatenate(amb_a), np.concatenate(amb_b)
            n = b_ - a_ + 1
            ends = np.cumsum(n)
            cuts = np.searchsorted(ends, np.arange(PAIRS, int(ends[-1]), PAIRS), side="right")
            for rr, aa, nn in zip(np.split(r_, cuts), np.split(a_, cuts), np.split(n, cuts)):
                if not rr.size:
                    continue
                at = np.repeat(rr, nn)
                li = np.arange(at.size) - np.repeat(np.cumsum(nn) - nn, nn) + np.repeat(aa, nn)
                x = (li + 0.5) * p
                x += tx0[at]
                d = self.set.item_sdf(items[at], x, y[at])
                hit = d <= level
                out[base[at[hit]] + li[hit]] = True
        return out

    def flags(self, batch: np.ndarray, tol: float
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Booleans of a batch, (len(batch), TILE, TILE): drawn (a drawn
        shape at distance <= 0), inside the ideal shrunk by ``tol``, inside
        the ideal grown by ``tol``."""
        on = self.cover(batch, False, 0.0)
        inner = self.cover(batch, True, -tol)
        near = self.cover(batch, True, tol)
        shape = (batch.size, TILE, TILE)
        return on.reshape(shape), inner.reshape(shape), near.reshape(shape)

    def distances(self, batch: np.ndarray, ideal: bool) -> tuple[np.ndarray, np.ndarray]:
        """Least signed distance of the batch's ideal (or drawn) shapes at
        every pixel, (len(batch), TILE, TILE), +inf where none reaches, and
        which shape has it (index into ``shapes``; the first on ties, -1
        where none): :func:`argmin_sdf` of each tile."""
        size = batch.size * TILE * TILE
        best = np.full(size, np.inf)
        chunks = list(self.pairs(batch, ideal, owners=True))
        for pix, _, d in chunks:
            np.minimum.at(best, pix, d)
        which = np.full(size, np.iinfo(np.int64).max, dtype=np.int64)
        for pix, own, d in chunks:
            eq = d == best[pix]
            np.minimum.at(which, pix[eq], own[eq])
        which[which == np.iinfo(np.int64).max] = -1
        shape = (batch.size, TILE, TILE)
        return best.reshape(shape), which.reshape(shape)


def _paint(out: np.ndarray, start: np.ndarray, length: np.ndarray) -> None:
    """Set ``out[start[k]:start[k] + length[k]]`` for every k (lengths > 0),
    at most :data:`PAINT` pixels at a time."""
    if not start.size:
        return
    ends = np.cumsum(length)
    cuts = np.searchsorted(ends, np.arange(PAINT, int(ends[-1]), PAINT), side="right")
    for st, ln in zip(np.split(start, cuts), np.split(length, cuts)):
        if not st.size:
            continue
        ln = ln.astype(np.int32)
        first = np.cumsum(ln) - ln
        idx = np.arange(int(first[-1] + ln[-1]), dtype=np.int32)
        idx += np.repeat((st - first).astype(np.int32), ln)
        out[idx] = True


def clip_tiles(grid: Grid, clip: Box | None) -> tuple[int, int, int, int] | None:
    """The tile ranges (ti0, ti1, tj0, tj1) that meet the box ``clip``."""
    if clip is None:
        return None
    span = TILE * grid.pitch
    return (math.floor((clip[0] - grid.x0) / span), math.floor((clip[1] - grid.x0) / span),
            math.floor((clip[2] - grid.y0) / span), math.floor((clip[3] - grid.y0) / span))


def plan(ideal: Sequence[AnyShape], drawn: Sequence[AnyShape], tol: float,
         pitch: float | None = None, max_pixels: int = MAX_PIXELS,
         reach: float = 0.0, clip: Box | None = None,
         shapes: ShapeSet | None = None) -> Plan | None:
    """Choose the pitch (the first of :data:`PITCHES` below ``tol`` that
    keeps the evaluated pixels within ``max_pixels``, else the coarsest)
    and the tiles for comparing ``drawn`` with ``ideal`` at tolerance
    ``tol``; None when both are empty.  Ideal shapes are evaluated up to
    ``tol`` + pitch + ``reach`` outside themselves (more ``reach`` tells
    how far excess lies from the nearest shape).  Only the tiles that meet
    the box ``clip`` (units) are kept, when given.  ``shapes``: the ideal
    then the drawn shapes as a :class:`ShapeSet`, if already made."""
    if pitch is not None:
        candidates: tuple[float, ...] = (pitch,)
    else:
        candidates = tuple(p for p in PITCHES if p < tol) or (tol / 2,)
    if any(p >= tol for p in candidates):
        raise ValueError(f"pitch {candidates[0]} must be smaller than tolerance {tol}")
    all_shapes = list(ideal) + list(drawn)
    if not all_shapes:
        return None
    ss = shapes if shapes is not None else ShapeSet.of(all_shapes)
    b = ss.bbox
    box = (float(b[:, 0].min()), float(b[:, 1].max()), float(b[:, 2].min()),
           float(b[:, 3].max()))
    n_ideal = len(ideal)
    for p in candidates:
        grid = make_grid(box, p, tol + 2 * p, max_pixels=10**15)
        pad = tol + p + reach
        pads = np.where(np.arange(ss.n) < n_ideal, pad, p)
        keys, own = _memberships(grid, ss, pads, clip_tiles(grid, clip))
        tkeys, start = np.unique(keys, return_index=True)
        start = np.append(start, keys.size)
        pl = Plan(grid, p, pad, all_shapes, n_ideal, tkeys, start, own, 0, ss)
        pl.pixels = int(pl.tile_pixels(np.arange(tkeys.size)).sum())
        if pl.pixels <= max_pixels:
            break
    return pl


def compare(run: Run, tool: float, layer: Layer | Sequence[AnyShape], tol: float = 5,
            pitch: float | None = None, max_pixels: int = MAX_PIXELS,
            examples: int = 5, clip: Box | None = None,
            progress: Callable[[int, int], None] | None = None,
            drawn: Sequence[AnyShape] | None = None,
            shapes: ShapeSet | None = None) -> Report:
    """Compare what ``run`` draws with ``tool`` (units) against the ideal
    ``layer`` at tolerance ``tol`` (units).

    holes = pixels of the ideal shrunk by ``tol`` that are not drawn;
    excess = drawn pixels outside the ideal grown by ``tol``.  Only the
    tiles meeting the box ``clip`` are looked at, when given.  ``progress``
    is told (tiles done, tiles) after each batch of tiles.  ``drawn``
    (:func:`run_shapes` of the run) and ``shapes`` (the ideal then the
    drawn shapes as a :class:`ShapeSet`) may be given if already made.
    ``examples``: how many of the worst holes and of the worst excess the
    report gives; 0 gives none, and spares the second look at every tile
    that differs (a caller that finds its own, as verify does).
    """
    ideal = layer.shapes if isinstance(layer, Layer) else list(layer)
    if drawn is None:
        drawn = run_shapes(run, tool)
    pl = plan(ideal, drawn, tol, pitch, max_pixels, clip=clip, shapes=shapes)
    if pl is None:
        p = pitch if pitch is not None else (
            next((q for q in PITCHES if q < tol), tol / 2))
        return Report(tol / 100, p / 100, 0, 0, 0, 0)
    p = pl.pitch
    counted = n_drawn = n_holes = n_excess = 0
    differ: list[int] = []
    done = 0
    for batch in pl.batches():
        on, inner, near = pl.flags(batch, tol)
        holes = inner > on                  # inner and not drawn
        excess = on > near                  # drawn and not near
        counted += int(pl.tile_pixels(batch).sum())
        n_drawn += int(np.count_nonzero(on))
        h, e = int(np.count_nonzero(holes)), int(np.count_nonzero(excess))
        n_holes += h
        n_excess += e
        if h or e:
            differ += batch[(holes | excess).any(axis=(1, 2))].tolist()
        done += batch.size
        if progress is not None:
            progress(done, pl.keys.size)
    # the worst places, from the tiles that differ, one at a time
    hole_c: list[tuple[float, ...]] = []
    exc_pts: list[tuple[float, float]] = []
    for t in differ if examples > 0 else []:
        tj, ti = pl.where(t)
        tile = pl.tile(tj, ti)
        one = np.array([t])
        ideal_d = pl.distances(one, True)[0][0, :tile.ny, :tile.nx]
        drawn_d = pl.distances(one, False)[0][0, :tile.ny, :tile.nx]
        on = drawn_d <= 0
        holes = ~on & (ideal_d <= -tol)
        excess = on & (ideal_d > tol)
        x, y = tile.centres()
        if holes.any():
            depth = -ideal_d[holes]
            for k in _top(depth, examples):
                hole_c.append((x[holes][k], y[holes][k], depth[k], drawn_d[holes][k]))
        if excess.any():
            far = ideal_d[excess]
            for k in _top(far, examples):
                exc_pts.append((x[excess][k], y[excess][k]))
    exc_c: list[tuple[float, ...]] = []
    if exc_pts:
        ex = np.array([q[0] for q in exc_pts])
        ey = np.array([q[1] for q in exc_pts])
        dist, _ = pl.set.nearest(ex, ey, upto=pl.n_ideal)
        exc_c = [(float(a), float(b), float(c)) for a, b, c in zip(ex, ey, dist)]

    def mm(items: list[tuple[float, ...]]) -> list[tuple[float, ...]]:
        return [tuple(float(v) / 100 for v in t) for t in _spread(items, examples, 50.0)]

    return Report(tol_mm=tol / 100, pitch_mm=p / 100, pixels=counted, drawn=n_drawn,
                  holes=n_holes, excess=n_excess,
                  worst_holes=mm(hole_c), worst_excess=mm(exc_c),
                  differ=[pl.where(t) for t in differ])
