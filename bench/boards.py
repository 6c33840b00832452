"""Benchmark boards: uniform, clustered and 2.5 mm grid, made from fixed seeds.

Every board is one package of one deck at scale 1:1, start point at
X0 = Y0 = 20 mm on the field, tools W1 = 0.50, W2 = 1.00, W3 = 0.50 mm and
DMAX = 2.00 mm.  Board coordinates (relative to the start point) run from 0
to the board's side S = sqrt(12 mm^2 x pads), rounded up to the 2.5 mm grid:
35 mm for 100 pads, 110 mm for 1 000, 347.5 mm for 10 000, 1 097.5 mm for
100 000 (so 20 + 1 097.5 mm stays on the 1 200 mm field).  Lengths are
integers in 0.01 mm ("units"), as everywhere in the harness.

Pads never overlap (a fill of one pad never lies in another), so every
stroke of a tape can be told apart by the pad that contains it
(:mod:`bench.tours` recovers TENZOR's order that way).

* ``uniform``: single pads (D cards with N = 1) anywhere, by random
  sequential addition with 0.2 mm clearance: round 1.2 / 1.6 / 2.0 mm and
  rectangular 1.0 x 1.8 mm (small-pad tape), round 2.5 / 3.0 mm and 2 x 5 mm
  fingers (large-pad tape).
* ``clustered``: the same pads, 90 % of them in Gaussian clusters of about
  50 pads (sigma 6 mm) and 10 % scattered.
* ``grid``: what a 1977 board looked like: every pad centre on the 2.5 mm
  grid; DIP packages (two rows of 7 or 8 pads of 1.6 mm, 7.5 mm apart),
  pin headers (a row of 5-10 pads of 1.8 mm), rows of 8 rectangular 1.0 x
  1.8 mm pads, edge connectors (10-20 fingers of 2 x 5 mm, large-pad tape),
  all as D cards with N > 1 (one tour item per row), plus discrete parts
  (two single 1.6 or 2.0 mm pads 10 mm apart) and mounting pads (3.0 mm).
  A pad takes its grid node; a finger the three nodes it covers; a mounting
  pad its node and the eight around it.  The rows are of pads that TENZOR
  fills with an even number of passes, so a row starts and ends at its
  first pad (see ``tours.py``: that keeps every tour item a point).

Conductors come in proportion: one L card with 2-4 + cards per 10 pads,
starting at a pad centre and turning at right angles (steps of 2.5 to 25 mm,
on the grid for the grid boards), 80 % of the conductor tool's width (one
pass) and 20 % 1.0 mm wide (drawn as loops).
"""

from __future__ import annotations

import argparse
import math
import random
from dataclasses import dataclass, field

from harness import cards

#: Distributions, in the order of the table.
DISTRIBUTIONS: tuple[str, ...] = ("uniform", "clustered", "grid")
#: Board sizes (pads) of a full run.
SIZES: tuple[int, ...] = (100, 1000, 10000, 100000)

GRID = 250                 #: the 2.5 mm grid, units
AREA_PER_PAD = 12.0        #: mm^2 of board per pad
X0_MM = 20                 #: start point on the field, mm (both axes)
TOOLS = (50, 100, 50)      #: W1, W2, W3, units
DMAX = 200                 #: small pads up to 2.00 mm
CLEARANCE = 20             #: 0.2 mm between pads of the uniform/clustered boards

#: Pad kinds of the uniform and clustered boards: (weight, W, H or 0).
_FREE_KINDS: tuple[tuple[float, int, int], ...] = (
    (0.20, 120, 0), (0.25, 160, 0), (0.15, 200, 0),    # small round
    (0.10, 100, 180), (0.10, 180, 100),                # small rectangle
    (0.08, 250, 0), (0.07, 300, 0),                    # large round
    (0.025, 200, 500), (0.025, 500, 200),              # large fingers
)


@dataclass
class PadCard:
    """One D card: N pads of W x H (H = 0: round) from (x, y) at (sx, sy)."""

    x: int
    y: int
    w: int
    h: int = 0
    n: int = 1
    sx: int = 0
    sy: int = 0

    @property
    def size(self) -> int:
        """The larger of W and H: the pad's class against DMAX."""
        return max(self.w, self.h)

    @property
    def tape(self) -> str:
        """'small' or 'large'."""
        return "small" if self.size <= DMAX else "large"

    def centres(self) -> list[tuple[int, int]]:
        """The centres of its pads, first to last."""
        return [(self.x + k * self.sx, self.y + k * self.sy) for k in range(self.n)]

    def card(self) -> str:
        return cards.d_card(self.x, self.y, self.w, self.h or None,
                            self.n if self.n > 1 else None,
                            self.sx or None, self.sy or None)


@dataclass
class Board:
    """A generated board: its pad cards, its conductors, and how it was made."""

    name: str
    dist: str
    size: int                              # pads asked for (the row label)
    side: int                              # units
    seed: int
    pads: list[PadCard] = field(default_factory=list)
    conductors: list[tuple[int, list[tuple[int, int]]]] = field(default_factory=list)

    @property
    def pad_count(self) -> int:
        return sum(p.n for p in self.pads)

    @property
    def vertex_count(self) -> int:
        return sum(len(v) for _, v in self.conductors)

    def deck(self) -> str:
        """The deck: envelope, one package (P card, pads, conductors), E."""
        lines = [cards.p_card(X0_MM * 100, X0_MM * 100, TOOLS[0], TOOLS[1], TOOLS[2],
                              DMAX, (1, 1), "8", "O")]
        lines += [p.card() for p in self.pads]
        for width, vertices in self.conductors:
            (x, y), rest = vertices[0], vertices[1:]
            lines.append(cards.l_card(x, y, width or None))
            lines += [cards.plus_card(vx, vy) for vx, vy in rest]
        return cards.deck([cards.CardPackage(self.name, lines)], job=f"BENCH {self.name}")


def sizes_argument(text: str) -> list[int]:
    """``--sizes``' value, pad counts separated by commas (``10_000`` too),
    each at least 10; argparse's type, so a bad list is a usage error."""
    try:
        sizes = [int(s.replace("_", "")) for s in text.split(",") if s.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a list of sizes: {text!r}") from None
    if not sizes or min(sizes) < 10:
        raise argparse.ArgumentTypeError("sizes are pad counts of at least 10")
    return sizes


def board_side(pads: int) -> int:
    """Side of the square board for this many pads, units, on the grid."""
    side = math.sqrt(AREA_PER_PAD * pads) * 100
    return int(math.ceil(side / GRID)) * GRID


def seed_of(dist: str, size: int) -> int:
    """The fixed seed of a board."""
    return (DISTRIBUTIONS.index(dist) + 1) * 1_000_003 + size


def make_board(dist: str, size: int) -> Board:
    """The board of a distribution and size (deterministic)."""
    if dist not in DISTRIBUTIONS:
        raise ValueError(f"unknown distribution {dist!r}")
    seed = seed_of(dist, size)
    rng = random.Random(seed)
    board = Board(name=f"{dist[:4].upper()}{size}", dist=dist, size=size,
                  side=board_side(size), seed=seed)
    if dist == "grid":
        _grid_pads(board, rng)
    else:
        _free_pads(board, rng, clustered=dist == "clustered")
    _conductors(board, rng, on_grid=dist == "grid")
    return board


# ---------------------------------------------------------------------------
# Uniform and clustered: random sequential addition without overlap.
# ---------------------------------------------------------------------------
def _half(w: int, h: int) -> tuple[int, int]:
    """Half the sides of the box around a pad (round: the square), units."""
    return (w + 1) // 2, ((h or w) + 1) // 2


def _free_pads(board: Board, rng: random.Random, clustered: bool) -> None:
    side = board.side
    cell = 600                                  # > 2 * largest half side + clearance
    hash_: dict[tuple[int, int], list[tuple[int, int, int, int]]] = {}
    weights = [k[0] for k in _FREE_KINDS]
    centres: list[tuple[float, float]] = []
    if clustered:
        count = max(2, round(board.size / 50))
        centres = [(rng.uniform(0.1, 0.9) * side, rng.uniform(0.1, 0.9) * side)
                   for _ in range(count)]
    sigma = 600.0

    def fits(x: int, y: int, a: int, b: int) -> bool:
        """The pad's box (half sides a, b) at (x, y) is on the board and
        CLEARANCE away from every other pad's box."""
        if not (a + 10 <= x <= side - a - 10 and b + 10 <= y <= side - b - 10):
            return False
        cx, cy = x // cell, y // cell
        for i in (cx - 1, cx, cx + 1):
            for j in (cy - 1, cy, cy + 1):
                for px, py, pa, pb in hash_.get((i, j), ()):
                    if abs(px - x) < a + pa + CLEARANCE and abs(py - y) < b + pb + CLEARANCE:
                        return False
        return True

    while len(board.pads) < board.size:
        _, w, h = rng.choices(_FREE_KINDS, weights)[0]
        a, b = _half(w, h)
        for attempt in range(1000):
            if clustered and attempt < 200 and rng.random() < 0.9:
                mx, my = centres[rng.randrange(len(centres))]
                x, y = round(rng.gauss(mx, sigma)), round(rng.gauss(my, sigma))
            else:
                x, y = rng.randrange(side + 1), rng.randrange(side + 1)
            if fits(x, y, a, b):
                break
        else:
            raise RuntimeError(f"{board.name}: no room for pad {len(board.pads) + 1}")
        hash_.setdefault((x // cell, y // cell), []).append((x, y, a, b))
        board.pads.append(PadCard(x, y, w, h))


# ---------------------------------------------------------------------------
# The grid board: packages on the 2.5 mm grid.
# ---------------------------------------------------------------------------
#: Parts of the grid board: (weight in pads, name).  Each is made by _part.
_GRID_PARTS: tuple[tuple[float, str], ...] = (
    (0.50, "dip"), (0.10, "header"), (0.10, "smd"), (0.05, "edge"),
    (0.23, "discrete"), (0.02, "mount"),
)


def _part(kind: str, rng: random.Random) -> list[tuple[PadCard, list[tuple[int, int]]]]:
    """A part at the origin (grid nodes): its pad cards, each with the grid
    nodes (i, j) it takes."""
    vertical = rng.random() < 0.5

    def row(i: int, j: int, w: int, h: int, n: int, extra: int = 0):
        """A row of n pads from node (i, j) along the part's direction;
        extra = nodes taken on each side across the row (fingers)."""
        di, dj = (0, 1) if vertical else (1, 0)
        nodes = [(i + k * di + e * dj, j + k * dj + e * di)
                 for k in range(n) for e in range(-extra, extra + 1)]
        if vertical and h:
            w, h = h, w
        card = PadCard(i * GRID, j * GRID, w, h, n, di * GRID, dj * GRID)
        return card, nodes

    if kind == "dip":
        n = rng.choice((7, 8))
        across = (3, 0) if vertical else (0, 3)
        return [row(0, 0, 160, 0, n), row(across[0], across[1], 160, 0, n)]
    if kind == "header":
        return [row(0, 0, 180, 0, rng.randint(5, 10))]
    if kind == "smd":
        return [row(0, 0, 100, 180, 8)]
    if kind == "edge":
        # fingers across the row: 2 mm along it, 5 mm across
        return [row(0, 0, 200, 500, rng.randint(10, 20), extra=1)]
    if kind == "discrete":
        w = rng.choice((160, 200))
        far = (0, 4) if vertical else (4, 0)
        return [(PadCard(0, 0, w), [(0, 0)]),
                (PadCard(far[0] * GRID, far[1] * GRID, w), [far])]
    if kind == "mount":
        return [(PadCard(0, 0, 300), [(i, j) for i in (-1, 0, 1) for j in (-1, 0, 1)])]
    raise ValueError(kind)


def _grid_pads(board: Board, rng: random.Random) -> None:
    nodes = board.side // GRID                  # grid nodes 1 .. nodes-1 are on the board
    taken: set[tuple[int, int]] = set()
    kinds = [k for _, k in _GRID_PARTS]
    weights = [w for w, _ in _GRID_PARTS]
    placed = 0
    failures = 0
    while placed < board.size:
        kind = rng.choices(kinds, weights)[0]
        part = _part(kind, rng)
        count = sum(c.n for c, _ in part)
        if placed + count > board.size:
            kind, part = "single", [(PadCard(0, 0, 160), [(0, 0)])]
            count = 1
        for _ in range(200):
            oi, oj = rng.randint(2, nodes - 2), rng.randint(2, nodes - 2)
            want = [(i + oi, j + oj) for _, ns in part for i, j in ns]
            if all(1 <= i <= nodes - 1 and 1 <= j <= nodes - 1 and (i, j) not in taken
                   for i, j in want):
                break
        else:
            failures += 1
            if failures > 1000:
                raise RuntimeError(f"{board.name}: the grid is full at {placed} pads")
            continue
        taken.update(want)
        for card, _ in part:
            card.x += oi * GRID
            card.y += oj * GRID
            board.pads.append(card)
        placed += count


# ---------------------------------------------------------------------------
# Conductors.
# ---------------------------------------------------------------------------
def _conductors(board: Board, rng: random.Random, on_grid: bool) -> None:
    centres = [c for p in board.pads for c in p.centres()]
    side = board.side
    lo, hi = 100, side - 100                    # keep a 1 mm margin for the 1 mm tracks
    for _ in range(max(1, board.pad_count // 10)):
        width = 100 if rng.random() < 0.2 else 0
        x, y = rng.choice(centres)
        x, y = min(max(x, lo), hi), min(max(y, lo), hi)
        vertices = [(x, y)]
        horizontal = rng.random() < 0.5
        for _ in range(rng.randint(2, 4)):
            for _attempt in range(20):
                step = rng.randint(1, 10) * GRID if on_grid else rng.randint(GRID, 10 * GRID)
                step *= rng.choice((-1, 1))
                nx, ny = (x + step, y) if horizontal else (x, y + step)
                if lo <= nx <= hi and lo <= ny <= hi:
                    break
            else:
                continue
            x, y = nx, ny
            vertices.append((x, y))
            horizontal = not horizontal
        if len(vertices) >= 2:
            board.conductors.append((width, vertices))
