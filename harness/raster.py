"""Rasterised coverage: what a tape draws against what the deck asks for.

Everything is sampled at pixel centres on a square grid (default pitch
0.02 mm, i.e. 2 units of 0.01 mm), evaluated with numpy per shape inside
the shape's own bounding-box window.  :func:`compare` works tile by tile
(256 x 256 pixels) and only on tiles that some shape can reach, so memory
stays small and the pixel budget (:data:`MAX_PIXELS`) counts only the
pixels actually evaluated; the pitch grows (up to 0.04 mm, always below the
tolerance) when a board needs it, and a board that still needs more pixels
is refused with ValueError rather than swapping.

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
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from .shapes import AnyShape, Layer, run_shapes
from .sim import Run

#: Default pitch and the pitches tried for big boards, in units (0.01 mm).
PITCH = 2.0
PITCHES: tuple[float, ...] = (2.0, 3.0, 4.0)
#: Most pixels evaluated by one rasterisation.
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


def _tiles(grid: Grid, shapes: Sequence[AnyShape], pad: float,
           tiles: dict[tuple[int, int], list[int]], offset: int) -> None:
    """Add shape indices (plus ``offset``) to the tiles they can reach."""
    span = TILE * grid.pitch
    half = span * math.sqrt(0.5)
    for n, s in enumerate(shapes):
        b = s.bbox()
        ti0 = max(0, math.floor((b[0] - pad - grid.x0) / span))
        ti1 = min(math.ceil(grid.nx / TILE) - 1, math.floor((b[1] + pad - grid.x0) / span))
        tj0 = max(0, math.floor((b[2] - pad - grid.y0) / span))
        tj1 = min(math.ceil(grid.ny / TILE) - 1, math.floor((b[3] + pad - grid.y0) / span))
        if ti0 > ti1 or tj0 > tj1:
            continue
        # a few tile rows at a time, so that a huge shape (a 10 m circle
        # has some 15 million tiles in its box) needs little memory
        rows = max(1, _TILE_CHUNK // (ti1 - ti0 + 1))
        for r0 in range(tj0, tj1 + 1, rows):
            ti, tj = np.meshgrid(np.arange(ti0, ti1 + 1), np.arange(r0, min(tj1, r0 + rows - 1) + 1))
            cx = grid.x0 + (ti + 0.5) * span
            cy = grid.y0 + (tj + 0.5) * span
            near = s.sdf(cx, cy) <= half + pad
            for a, c in zip(tj[near].tolist(), ti[near].tolist()):
                tiles.setdefault((a, c), []).append(n + offset)


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


@dataclass
class Plan:
    """The tiles :func:`compare` evaluates: ``shapes`` is the ideal shapes
    then the drawn ones (``n_ideal`` of the first kind); ``tiles`` maps
    (tile row, tile column) to the indices into ``shapes`` that may reach
    the tile; ideal shapes are evaluated with window margin ``pad``, drawn
    ones with ``pitch``."""

    grid: Grid
    pitch: float
    pad: float
    shapes: list[AnyShape]
    n_ideal: int
    tiles: dict[tuple[int, int], list[int]]
    pixels: int

    def tile(self, tj: int, ti: int) -> Grid:
        """The grid of one tile."""
        js = slice(tj * TILE, min(self.grid.ny, (tj + 1) * TILE))
        is_ = slice(ti * TILE, min(self.grid.nx, (ti + 1) * TILE))
        return self.grid.sub(js, is_)


def plan(ideal: Sequence[AnyShape], drawn: Sequence[AnyShape], tol: float,
         pitch: float | None = None, max_pixels: int = MAX_PIXELS,
         reach: float = 0.0) -> Plan | None:
    """Choose the pitch (the first of :data:`PITCHES` below ``tol`` that
    keeps the evaluated pixels within ``max_pixels``) and the tiles for
    comparing ``drawn`` with ``ideal`` at tolerance ``tol``; None when both
    are empty.  ValueError when no pitch is small enough.  Ideal shapes are
    evaluated up to ``tol`` + pitch + ``reach`` outside themselves (more
    ``reach`` tells how far excess lies from the nearest shape)."""
    if pitch is not None:
        candidates: tuple[float, ...] = (pitch,)
    else:
        candidates = tuple(p for p in PITCHES if p < tol) or (tol / 2,)
    if any(p >= tol for p in candidates):
        raise ValueError(f"pitch {candidates[0]} must be smaller than tolerance {tol}")
    box = union_box([s.bbox() for s in ideal] + [s.bbox() for s in drawn])
    if box is None:
        return None
    for p in candidates:
        grid = make_grid(box, p, tol + 2 * p, max_pixels=10**15)
        pad = tol + p + reach
        tiles: dict[tuple[int, int], list[int]] = {}
        _tiles(grid, ideal, pad, tiles, 0)
        _tiles(grid, drawn, p, tiles, len(ideal))
        pixels = sum((min(grid.nx, (ti + 1) * TILE) - ti * TILE)
                     * (min(grid.ny, (tj + 1) * TILE) - tj * TILE) for tj, ti in tiles)
        if pixels <= max_pixels:
            break
    else:
        raise ValueError(f"coverage check needs about {pixels} pixels even at "
                         f"{candidates[-1] / 100:.2f} mm pitch (limit {max_pixels})")
    return Plan(grid, p, pad, list(ideal) + list(drawn), len(ideal), tiles, pixels)


def compare(run: Run, tool: float, layer: Layer | Sequence[AnyShape], tol: float = 5,
            pitch: float | None = None, max_pixels: int = MAX_PIXELS,
            examples: int = 5) -> Report:
    """Compare what ``run`` draws with ``tool`` (units) against the ideal
    ``layer`` at tolerance ``tol`` (units).

    holes = pixels of the ideal shrunk by ``tol`` that are not drawn;
    excess = drawn pixels outside the ideal grown by ``tol``.
    """
    ideal = layer.shapes if isinstance(layer, Layer) else list(layer)
    drawn = run_shapes(run, tool)
    pl = plan(ideal, drawn, tol, pitch, max_pixels)
    if pl is None:
        p = pitch if pitch is not None else (
            next((q for q in PITCHES if q < tol), tol / 2))
        return Report(tol / 100, p / 100, 0, 0, 0, 0)
    p, pad, shapes, n_ideal, tiles = pl.pitch, pl.pad, pl.shapes, pl.n_ideal, pl.tiles
    counted = n_drawn = n_holes = n_excess = 0
    hole_c: list[tuple[float, ...]] = []
    exc_pts: list[tuple[float, float]] = []
    for (tj, ti) in sorted(tiles):
        tile = pl.tile(tj, ti)
        counted += tile.pixels
        members = tiles[(tj, ti)]
        ideal_d = min_sdf([shapes[n] for n in members if n < n_ideal], tile, pad)
        drawn_d = min_sdf([shapes[n] for n in members if n >= n_ideal], tile, p)
        on = drawn_d <= 0
        n_drawn += int(on.sum())
        holes = ~on & (ideal_d <= -tol)
        excess = on & (ideal_d > tol)
        if holes.any() or excess.any():
            x, y = tile.centres()
        if holes.any():
            n_holes += int(holes.sum())
            depth = -ideal_d[holes]
            for k in _top(depth, examples):
                hole_c.append((x[holes][k], y[holes][k], depth[k], drawn_d[holes][k]))
        if excess.any():
            n_excess += int(excess.sum())
            far = ideal_d[excess]
            for k in _top(far, examples):
                exc_pts.append((x[excess][k], y[excess][k]))
    exc_c: list[tuple[float, ...]] = []
    if exc_pts:
        ex = np.array([q[0] for q in exc_pts])
        ey = np.array([q[1] for q in exc_pts])
        dist = np.full(ex.shape, np.inf)
        for s in ideal:
            np.minimum(dist, s.sdf(ex, ey), out=dist)
        exc_c = [(float(a), float(b), float(c)) for a, b, c in zip(ex, ey, dist)]
    def mm(items: list[tuple[float, ...]]) -> list[tuple[float, ...]]:
        return [tuple(float(v) / 100 for v in t) for t in _spread(items, examples, 50.0)]

    return Report(tol_mm=tol / 100, pitch_mm=p / 100, pixels=counted, drawn=n_drawn,
                  holes=n_holes, excess=n_excess,
                  worst_holes=mm(hole_c), worst_excess=mm(exc_c))
