"""The ideal shapes of a board, each with a signed distance and a box.

What a deck asks the coordinatograph to draw, as the film should show it
(:mod:`harness.deck` reads the cards into them; :mod:`harness.raster` turns
them into pixels; :mod:`harness.verify` names the card of a shape drawn
wrong).  All lengths are integers in 0.01 mm ("units").

* round pad: :class:`Disc` of diameter W;
* rectangular pad: :class:`RoundRect`, the W x H rectangle with corners
  rounded to the radius of its tape's tool;
* conductor: :class:`Stroke`, polyline (+) disc of diameter W (round caps
  and joins);
* circle O / arc A: :class:`ArcBand`, the points within w3/2 of the circle
  or arc;
* a simulated run of the machine (M frames, or anyone's tape): its strokes
  and dots with the tool's width (:func:`run_shapes`).

Each shape has a vectorised signed distance ``sdf(x, y)`` in units,
negative inside, and a ``bbox()``.  Every shape of a :class:`Layer` has an
:class:`Origin` (``Layer.origins``, parallel to ``Layer.shapes``): the card
that asks for it.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from typing import Protocol, Union

import numpy as np

from . import sim

TWO_PI = 2.0 * math.pi
Box = tuple[float, float, float, float]

# ---------------------------------------------------------------------------
# Shapes.
# ---------------------------------------------------------------------------
class Shape(Protocol):
    """An ideal shape: signed distance (units, < 0 inside) and bounding box."""

    def sdf(self, x: np.ndarray, y: np.ndarray) -> np.ndarray: ...

    def bbox(self) -> Box: ...


@dataclass(frozen=True)
class Disc:
    """Disc of radius r about (cx, cy)."""

    cx: float
    cy: float
    r: float

    def sdf(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        return np.hypot(x - self.cx, y - self.cy) - self.r

    def bbox(self) -> Box:
        return self.cx - self.r, self.cx + self.r, self.cy - self.r, self.cy + self.r


@dataclass(frozen=True)
class RoundRect:
    """Axis-parallel w x h rectangle about (cx, cy), corners rounded to rc."""

    cx: float
    cy: float
    w: float
    h: float
    rc: float

    def __post_init__(self) -> None:
        if not 0 <= self.rc <= min(self.w, self.h) / 2:
            raise ValueError(f"corner radius {self.rc} does not fit {self.w} x {self.h}")

    def sdf(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        qx = np.abs(x - self.cx) - (self.w / 2 - self.rc)
        qy = np.abs(y - self.cy) - (self.h / 2 - self.rc)
        outside = np.hypot(np.maximum(qx, 0.0), np.maximum(qy, 0.0))
        inside = np.minimum(np.maximum(qx, qy), 0.0)
        return outside + inside - self.rc

    def bbox(self) -> Box:
        return (self.cx - self.w / 2, self.cx + self.w / 2,
                self.cy - self.h / 2, self.cy + self.h / 2)


@dataclass(frozen=True)
class Stroke:
    """Points within r of a polyline (a single point gives a disc)."""

    points: tuple[tuple[float, float], ...]
    r: float

    def sdf(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        pts = self.points
        best = np.hypot(x - pts[0][0], y - pts[0][1])
        for (ax, ay), (bx, by) in zip(pts, pts[1:]):
            ex, ey = bx - ax, by - ay
            ee = ex * ex + ey * ey
            if ee == 0:
                continue
            px, py = x - ax, y - ay
            t = np.clip((px * ex + py * ey) / ee, 0.0, 1.0)
            np.minimum(best, np.hypot(px - t * ex, py - t * ey), out=best)
        return best - self.r

    def bbox(self) -> Box:
        xs = [p[0] for p in self.points]
        ys = [p[1] for p in self.points]
        return min(xs) - self.r, max(xs) + self.r, min(ys) - self.r, max(ys) + self.r


@dataclass(frozen=True)
class ArcBand:
    """Points within hw of the arc about (cx, cy) of radius rad from angle a0
    through the signed sweep (radians, + = counter-clockwise); a sweep of
    +-2*pi is the full circle (an annulus, or a disc if rad < hw)."""

    cx: float
    cy: float
    rad: float
    a0: float
    sweep: float
    hw: float

    @property
    def full(self) -> bool:
        return abs(self.sweep) >= TWO_PI - 1e-12

    def sdf(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        rx, ry = x - self.cx, y - self.cy
        ring = np.abs(np.hypot(rx, ry) - self.rad)
        if self.full:
            return ring - self.hw
        ang = np.arctan2(ry, rx)
        if self.sweep >= 0:
            t = np.mod(ang - self.a0, TWO_PI)
        else:
            t = np.mod(self.a0 - ang, TWO_PI)
        a1 = self.a0 + self.sweep
        sx, sy = self.rad * math.cos(self.a0), self.rad * math.sin(self.a0)
        ex, ey = self.rad * math.cos(a1), self.rad * math.sin(a1)
        ends = np.minimum(np.hypot(rx - sx, ry - sy), np.hypot(rx - ex, ry - ey))
        return np.where(t <= abs(self.sweep), ring, ends) - self.hw

    def bbox(self) -> Box:
        x0, x1, y0, y1 = sim.arc_extent(self.cx, self.cy, self.rad, self.a0, self.sweep)
        return x0 - self.hw, x1 + self.hw, y0 - self.hw, y1 + self.hw


AnyShape = Union[Disc, RoundRect, Stroke, ArcBand]


def stroke_shape(s: sim.Stroke, tool: float) -> AnyShape:
    """What one stroke of a simulated run covers with a round tool of
    diameter ``tool`` (units)."""
    r = tool / 2
    if isinstance(s, sim.Dot):
        return Disc(s.x, s.y, r)
    if isinstance(s, sim.Line):
        return Stroke(((s.x0, s.y0), (s.x1, s.y1)), r)
    return ArcBand(s.cx, s.cy, s.r, s.a0, s.sweep, r)


def run_shapes(run: sim.Run, tool: float) -> list[AnyShape]:
    """The shapes covered by a run's strokes with the given tool (units)."""
    return [stroke_shape(s, tool) for s in run.strokes]


def distinct_strokes(drawn: Sequence[AnyShape], stroke_frame: Sequence[int]
                     ) -> tuple[list[AnyShape], list[int]]:
    """Each shape of ``drawn`` once, at its first stroke, with the tape
    frame of that stroke (``stroke_frame`` is parallel to ``drawn``).

    A cycle that goes over the same line again and again (a CYC of 99 999
    turns) draws nothing new after its first turn, while a coverage check
    costs time and memory per shape (such a saw grew to 24 GB).  The set
    of points drawn is the same, and a pixel the repeats cover is still
    laid at the first stroke that covers it, as a nearest-shape search
    that keeps the first of equals would have laid it."""
    seen: set[AnyShape] = set()
    shapes: list[AnyShape] = []
    frames: list[int] = []
    for shape, fr in zip(drawn, stroke_frame, strict=True):
        if shape not in seen:
            seen.add(shape)
            shapes.append(shape)
            frames.append(fr)
    return shapes, frames


@dataclass(frozen=True)
class Origin:
    """Where an ideal shape comes from: the 1-based ``card`` (line) number,
    its type ``kind`` ('D', 'L', 'O', 'A' or 'M') and ``item``: for a D card
    the pad's place in its row of ``count`` pads (0-based), for an M card
    the frame's index on its tape (0-based), else 0."""

    card: int
    kind: str
    item: int = 0
    count: int = 1


@dataclass
class Layer:
    """An ideal layer: a union of shapes, drawn with ``tool`` (units).

    ``origins`` is parallel to ``shapes`` when the layer comes from a deck
    (:func:`parse_deck`); a layer built by hand may leave it empty."""

    tool: int
    shapes: list[AnyShape] = field(default_factory=list)
    origins: list[Origin] = field(default_factory=list)

    def add(self, shape: AnyShape, origin: Origin) -> None:
        """Append a shape with the card it comes from."""
        self.shapes.append(shape)
        self.origins.append(origin)

    def origin(self, index: int) -> Origin | None:
        """The origin of shape ``index``, or None if the layer has none."""
        return self.origins[index] if len(self.origins) == len(self.shapes) else None

    def __iter__(self) -> Iterator[AnyShape]:
        return iter(self.shapes)

    def __len__(self) -> int:
        return len(self.shapes)

    def sdf(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Minimum of the shapes' signed distances: exact outside the union,
        and inside it a lower bound of the depth (see raster.py)."""
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        out = np.full(np.broadcast(x, y).shape, np.inf)
        for s in self.shapes:
            np.minimum(out, s.sdf(x, y), out=out)
        return out

    def contains(self, x: np.ndarray, y: np.ndarray, offset: float = 0.0) -> np.ndarray:
        """Inside the layer grown by ``offset`` units (negative = shrunk,
        per shape)."""
        return self.sdf(x, y) <= offset

    def bbox(self) -> Box | None:
        """Union bounding box in units, or None if empty."""
        if not self.shapes:
            return None
        boxes = [s.bbox() for s in self.shapes]
        return (min(b[0] for b in boxes), max(b[1] for b in boxes),
                min(b[2] for b in boxes), max(b[3] for b in boxes))
