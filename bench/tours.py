"""Tours through the pads of a tape, compared on the same points.

The travel comparison is made on a model that every method shares: each
tour item (one D card of the tape) is reduced to the centre of the pad where
it is entered and the centre of the pad where it is left, and a tour is
the path from the start point (0, 0) through all items back to it; its
length is the sum of the moves between items (what is drawn inside an item
does not depend on the order).  A single pad is entered and left at its
centre.  A row (D card with N > 1) that TENZOR fills with an even number of
passes starts and ends at its first pad, whichever way it is drawn, so it
is a point too; a row with an odd number of passes runs from one end pad to
the other, either way (a segment).  Which rows return is read from TENZOR's
own tape (:func:`recover_order`), so every method sees the same items.

The methods:

* deck order: the items in the order of their cards, each drawn forward;
* nearest neighbour (:func:`nearest_neighbour`): from the start point always
  to the nearest free end of an item not yet drawn, on a bucket grid;
* TENZOR: the order in which its simulated small- or large-pad tape visits
  the items (:func:`recover_order`);
* the reference (:func:`lkh_tour`): LKH-3 through elkai, on the points
  (start point and items); only when every item is a point.
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass

from harness import sim
from .boards import PadCard

Point = tuple[int, int]
DEPOT: Point = (0, 0)


@dataclass(frozen=True)
class Item:
    """A tour item of the model: entered at ``a`` and left at ``b`` when
    drawn forward, the other way round when reversed (a == b: a point)."""

    a: Point
    b: Point

    @property
    def point(self) -> bool:
        return self.a == self.b


def tour_length(items: Sequence[Item], order: Sequence[tuple[int, bool]],
                start: Point = DEPOT) -> float:
    """Length (units) of the path from ``start`` through the items in
    ``order`` (item index, reversed) back to ``start``, moves between items
    only."""
    x, y = start
    total = 0.0
    for i, rev in order:
        it = items[i]
        (ex, ey), (xx, xy) = (it.b, it.a) if rev else (it.a, it.b)
        total += math.hypot(ex - x, ey - y)
        x, y = xx, xy
    return total + math.hypot(start[0] - x, start[1] - y)


def check_order(n: int, order: Sequence[tuple[int, bool]]) -> None:
    """Raise ValueError unless ``order`` visits each of the n items once."""
    seen = sorted(i for i, _ in order)
    if seen != list(range(n)):
        raise ValueError(f"the order does not visit each of the {n} items once")


# ---------------------------------------------------------------------------
# TENZOR's order, read back from its simulated tape.
# ---------------------------------------------------------------------------
class PadIndex:
    """Which pad of which D card contains a point (pads do not overlap)."""

    CELL = 500          # units; larger than every pad

    def __init__(self, pads: Sequence[PadCard]) -> None:
        self.cells: dict[tuple[int, int], list[tuple[int, int, int, int, int, int]]] = {}
        for i, p in enumerate(pads):
            for k, (cx, cy) in enumerate(p.centres()):
                key = (cx // self.CELL, cy // self.CELL)
                self.cells.setdefault(key, []).append((i, k, cx, cy, p.w, p.h))

    def find(self, x: int, y: int) -> tuple[int, int] | None:
        """(card index, pad number in its row) of the pad that contains
        (x, y) within 0.01 mm, or None."""
        gx, gy = x // self.CELL, y // self.CELL
        for i in (gx - 1, gx, gx + 1):
            for j in (gy - 1, gy, gy + 1):
                for card, k, cx, cy, w, h in self.cells.get((i, j), ()):
                    dx, dy = abs(x - cx), abs(y - cy)
                    if h:
                        if 2 * dx <= w + 2 and 2 * dy <= h + 2:
                            return card, k
                    elif 4 * (dx * dx + dy * dy) <= (w + 2) ** 2:
                        return card, k
        return None


def _start(stroke: sim.Stroke) -> Point:
    if isinstance(stroke, sim.Dot):
        return stroke.x, stroke.y
    return stroke.x0, stroke.y0


def recover_order(run: sim.Run, pads: Sequence[PadCard]
                  ) -> tuple[list[Item], list[tuple[int, bool]]]:
    """TENZOR's tour of a pad tape, from its simulation.

    ``pads`` are the D cards of this tape in deck order (TENZOR's items).
    Every stroke of the run is matched to the pad that contains its start;
    an item's strokes are contiguous.  Returns the model items (entry and
    exit pad centres as drawn forward, see the module doc) and TENZOR's
    order as (item, reversed).  Raises ValueError if a stroke lies in no pad,
    an item is drawn twice, or an item is missing.
    """
    index = PadIndex(pads)
    visits: list[list[int]] = []          # [card, first pad, last pad]
    done: set[int] = set()
    for stroke in run.strokes:
        x, y = _start(stroke)
        hit = index.find(x, y)
        if hit is None:
            raise ValueError(f"a stroke at ({x}, {y}) lies in no pad of the tape")
        card, k = hit
        if visits and visits[-1][0] == card:
            visits[-1][2] = k
            continue
        if card in done:
            raise ValueError(f"D card {card + 1} of the tape is drawn twice")
        done.add(card)
        visits.append([card, k, k])
    if len(done) != len(pads):
        raise ValueError(f"{len(pads) - len(done)} items of the tape are not drawn")
    ends: dict[int, tuple[int, int]] = {card: (k0, k1) for card, k0, k1 in visits}
    items: list[Item] = []
    for i, p in enumerate(pads):
        c = p.centres()
        k0, k1 = ends[i]
        if k0 == k1:                       # a point: a pad, or a row that returns
            items.append(Item(c[k0], c[k0]))
        elif {k0, k1} == {0, p.n - 1}:     # a row run from end to end
            items.append(Item(c[0], c[-1]))
        else:
            raise ValueError(f"D card {i + 1}: entered at pad {k0 + 1}, "
                             f"left at pad {k1 + 1} of {p.n}")
    order = [(card, not items[card].point and pads[card].centres()[k0] != items[card].a)
             for card, k0, _ in visits]
    return items, order


# ---------------------------------------------------------------------------
# Plain nearest neighbour on a bucket grid.
# ---------------------------------------------------------------------------
def nearest_neighbour(items: Sequence[Item], start: Point = DEPOT
                      ) -> list[tuple[int, bool]]:
    """From ``start``, always to the nearest free end of an item not yet
    drawn (ties to the lower end number), then on from its other end.

    The ends are kept in buckets of a square grid of about two ends a cell,
    searched ring by ring until no unsearched cell can hold a nearer end; the
    grid is rebuilt coarser when three quarters of the ends are used up, so
    the late, sparse searches stay short.
    """
    ends: list[Point] = []
    owner: list[tuple[int, bool]] = []
    for i, it in enumerate(items):
        ends.append(it.a)
        owner.append((i, False))
        if not it.point:
            ends.append(it.b)
            owner.append((i, True))
    if not ends:
        return []
    xs = [p[0] for p in ends] + [start[0]]
    ys = [p[1] for p in ends] + [start[1]]
    x0, y0 = min(xs), min(ys)
    span = max(max(xs) - x0, max(ys) - y0, 1)
    alive = [True] * len(ends)
    ends_of: list[list[int]] = [[] for _ in items]
    for e, (i, _) in enumerate(owner):
        ends_of[i].append(e)

    def build(live: list[int]) -> tuple[int, int, dict[tuple[int, int], list[int]]]:
        cells = max(1, int(math.sqrt(len(live) / 2)))
        size = span // cells + 1
        grid: dict[tuple[int, int], list[int]] = {}
        for e in live:
            ex, ey = ends[e]
            grid.setdefault(((ex - x0) // size, (ey - y0) // size), []).append(e)
        return size, cells, grid

    live_count = len(ends)
    size, cells, grid = build(list(range(len(ends))))
    built = live_count
    order: list[tuple[int, bool]] = []
    px, py = start
    while live_count:
        if live_count < built // 4 and live_count > 64:
            size, cells, grid = build([e for e in range(len(ends)) if alive[e]])
            built = live_count
        qx, qy = (px - x0) // size, (py - y0) // size
        best, best_d = -1, math.inf
        r = 0
        while True:
            for i in range(qx - r, qx + r + 1):
                edge = i in (qx - r, qx + r)
                for j in (range(qy - r, qy + r + 1) if edge else (qy - r, qy + r)):
                    bucket = grid.get((i, j))
                    if not bucket:
                        continue
                    keep = []
                    for e in bucket:
                        if not alive[e]:
                            continue
                        keep.append(e)
                        ex, ey = ends[e]
                        d = (ex - px) ** 2 + (ey - py) ** 2
                        if d < best_d or (d == best_d and e < best):
                            best, best_d = e, d
                    bucket[:] = keep
            # every end in ring r + 1 or beyond is at least r * size away
            if best >= 0 and best_d <= (r * size) ** 2:
                break
            r += 1
            if r > cells + 2 and best >= 0:
                break
        i, rev = owner[best]
        order.append((i, rev))
        for e in ends_of[i]:
            alive[e] = False
            live_count -= 1
        it = items[i]
        px, py = it.a if rev else it.b
    return order


# ---------------------------------------------------------------------------
# The reference: LKH-3 (elkai).
# ---------------------------------------------------------------------------
#: LKH-3 parameters of the reference (see docs/PERFORMANCE.md): one run of at
#: most 100 trials, POPMUSIC candidate sets (5 candidates, the LKH-3 way for
#: large instances) and a short subgradient ascent; fixed seed.
LKH_PARAMS = {
    "RUNS": 1,
    "MAX_TRIALS": 100,
    "CANDIDATE_SET_TYPE": "POPMUSIC",
    "INITIAL_PERIOD": 100,
    "TIME_LIMIT": 120,
    "SEED": 1,
}


def lkh_available() -> bool:
    try:
        from elkai import _elkai  # noqa: F401
    except ImportError:
        return False
    return True


def lkh_tour(items: Sequence[Item], start: Point = DEPOT,
             params: dict[str, object] | None = None
             ) -> tuple[list[tuple[int, bool]], float]:
    """LKH-3's tour through the points (start point first), as an order of
    the items, and the seconds LKH took.  Every item must be a point.

    elkai's public ``Coordinates2D.solve_tsp`` fixes MAX_TRIALS to the number
    of points (hours for 10 000); its ``_elkai.solve_problem`` takes LKH's own
    parameter text and a TSPLIB problem, which is what is used here (elkai is
    pinned in requirements.txt for that reason).
    """
    from elkai import _elkai

    if not all(it.point for it in items):
        raise ValueError("the LKH reference needs every item to be a point")
    n = len(items)
    if n < 3:
        # two items or fewer: both directions are the same cycle
        return [(i, False) for i in range(n)], 0.0
    points = [start] + [it.a for it in items]
    par = dict(LKH_PARAMS, **(params or {}))
    text = "".join(f"{k} = {v}\n" for k, v in par.items()) + "PROBLEM_FILE = :stdin:\n"
    problem = (f"TYPE : TSP\nDIMENSION : {len(points)}\nEDGE_WEIGHT_TYPE : EUC_2D\n"
               "NODE_COORD_SECTION\n"
               + "".join(f"{k + 1} {x} {y}\n" for k, (x, y) in enumerate(points))
               + "EOF\n")
    t = time.perf_counter()
    tour = _elkai.solve_problem(text, problem)
    seconds = time.perf_counter() - t
    nodes = [v - 1 for v in tour]
    if sorted(nodes) != list(range(len(points))):
        raise RuntimeError("LKH did not return a tour through every point")
    at = nodes.index(0)
    cycle = nodes[at + 1:] + nodes[:at]
    return [(v - 1, False) for v in cycle], seconds
