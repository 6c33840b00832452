"""TSPLIB drilling problems with proven optima: TENZOR against the optimum.

The instances are in ``bench/tsplib/`` (``SOURCE.md`` there says where each
copy comes from), in a compact form of TSPLIB's own: the header lines of the
original (NAME, COMMENT, TYPE, DIMENSION, EDGE_WEIGHT_TYPE), an ``OPTIMUM``
line (the proven optimal tour length from TSPLIB's published list), then
``NODE_COORD_SECTION`` and one node a line, ``x y`` without the node number,
each value TSPLIB's written without its exponent (``5.51200e+02`` is
``551.2``: the same number).

Each instance becomes a deck of one package: one D card per node, a round
pad of the small-pad tool's width (0.50 mm), so that each pad is punched as
one dot at its centre.  The coordinates are scaled by a factor ``s`` (units
of 0.01 mm per TSPLIB unit: the largest of 100, 50, 20, 10, 5, 2, 1 that
keeps the board within 1 100 mm; 20 for every instance here but u1060, 5,
and fl1400, 50, so a coordinate with one decimal stays an exact integer; the
two decimals of u574 and u1060 and the three of fl1400 are rounded to the
nearest 0.01 mm, a fortieth, a tenth and a hundredth of a TSPLIB unit at
most, which moves the geometry TENZOR sees but not the scoring, which uses
TSPLIB's coordinates).  The start point is put on node 1
(the deck's coordinates are relative to node 1), so TENZOR's path from the
start point through every pad back to it is a closed tour through the nodes:
the optimal path has the optimal tour's length.

TENZOR's order is read back from its simulated small-pad tape (each dot to
the node at that point; nodes at the same point are interchangeable) and
its length computed with the instance's own distance function on the
original coordinates (EUC_2D: ``nint`` of the Euclidean distance; CEIL_2D:
its ceiling; ATT: the pseudo-Euclidean distance), not from the tape's
travel.  That length over the proven optimum is the figure of merit.

The references, on the same coordinates and distance function:

* LKH-3 (elkai, ``_elkai.solve_problem``), one run with LKH's default
  parameters (``RUNS = 1``, ``MAX_TRIALS`` = the dimension, alpha candidate
  sets, full subgradient ascent), ``SEED = 1``: "a single run of LKH-3".
* OR-Tools (``ortools``, pinned in requirements-bench.txt, which only
  ``make bench`` installs; without it the columns stay empty), the routing
  solver with PATH_CHEAPEST_ARC and guided local search, for 1 s and for
  3 s of search, the distances given as a matrix; empty where no tour was
  found in the time.
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from harness import cards

from . import measure

DIR = Path(__file__).resolve().parent / "tsplib"
#: The instances of the benchmark, smallest first.
NAMES: tuple[str, ...] = ("d198", "pcb442", "d493", "u574", "d657", "u1060", "pcb1173",
                          "d1291", "fl1400", "d2103", "pcb3038")
FIELD = 110_000            #: the board's largest extent, units (1 100 mm)
MARGIN = 2_000             #: units between the field's edge and the board
PAD = 50                   #: pad diameter, units: the small-pad tool's width


@dataclass(frozen=True)
class Instance:
    name: str
    kind: str                           # EUC_2D, CEIL_2D or ATT
    optimum: int
    nodes: tuple[tuple[float, float], ...]

    def dist(self, i: int, j: int) -> int:
        (xa, ya), (xb, yb) = self.nodes[i], self.nodes[j]
        dx, dy = xa - xb, ya - yb
        if self.kind == "EUC_2D":
            return int(math.sqrt(dx * dx + dy * dy) + 0.5)
        if self.kind == "CEIL_2D":
            return int(math.ceil(math.sqrt(dx * dx + dy * dy)))
        if self.kind == "ATT":
            r = math.sqrt((dx * dx + dy * dy) / 10.0)
            t = int(r + 0.5)
            return t + 1 if t < r else t
        raise ValueError(f"{self.name}: distance type {self.kind}")

    def tour_length(self, cycle: Sequence[int]) -> int:
        return sum(self.dist(cycle[k - 1], cycle[k]) for k in range(len(cycle)))

    @property
    def scale(self) -> int:
        xs = [x for x, _ in self.nodes]
        ys = [y for _, y in self.nodes]
        span = max(max(xs) - min(xs), max(ys) - min(ys), 1.0)
        for s in (100, 50, 20, 10, 5, 2, 1):
            if span * s <= FIELD:
                return s
        raise ValueError(f"{self.name}: too large for the field")

    def points(self) -> list[tuple[int, int]]:
        """The pad centres, units, relative to node 1 (the start point)."""
        s = self.scale
        x1, y1 = self.nodes[0]
        return [(round((x - x1) * s), round((y - y1) * s)) for x, y in self.nodes]

    def deck(self) -> str:
        s = self.scale
        x1, y1 = self.nodes[0]
        x0 = MARGIN + round((x1 - min(x for x, _ in self.nodes)) * s)
        y0 = MARGIN + round((y1 - min(y for _, y in self.nodes)) * s)
        lines = [cards.p_card(x0, y0, 50, 100, 50, 200, (1, 1), "8", "O")]
        lines += [cards.d_card(x, y, PAD) for x, y in self.points()]
        return cards.deck([cards.CardPackage(self.name.upper()[:8], lines)],
                          job=f"TSPLIB {self.name.upper()}")


def parse_names(option: str, text: str) -> tuple[list[str], str | None]:
    """The instances a comma-separated ``text`` names, and None; or, when it
    names none or one that is not in bench/tsplib/, a message that says so
    for the command-line ``option``."""
    names = [n for n in text.split(",") if n]
    if names and all(n in NAMES for n in names):
        return names, None
    return names, f"{option} {text!r}: the instances are of bench/tsplib/: " + ", ".join(NAMES)


def load(name: str) -> Instance:
    """Read ``bench/tsplib/NAME.tsp`` and check its DIMENSION."""
    head, body = (DIR / f"{name}.tsp").read_text(encoding="ascii").split("NODE_COORD_SECTION")
    meta = {}
    for line in head.strip().splitlines():
        key, _, value = line.partition(":")
        meta[key.strip()] = value.strip()
    values = [v for v in body.split() if v != "EOF"]
    nodes = tuple((float(values[k]), float(values[k + 1])) for k in range(0, len(values), 2))
    if len(values) % 2 or len(nodes) != int(meta["DIMENSION"]):
        raise ValueError(f"{name}: {len(nodes)} nodes, DIMENSION {meta['DIMENSION']}")
    return Instance(meta["NAME"], meta["EDGE_WEIGHT_TYPE"], int(meta["OPTIMUM"]), nodes)


def tenzor_cycle(inst: Instance, run) -> list[int]:
    """The nodes in the order TENZOR's small-pad tape punches them."""
    at: dict[tuple[int, int], list[int]] = {}
    for k, p in enumerate(inst.points()):
        at.setdefault(p, []).append(k)
    cycle: list[int] = []
    for stroke in run.strokes:
        x, y = (stroke.x, stroke.y) if hasattr(stroke, "x") else (stroke.x0, stroke.y0)
        nodes = at.get((x, y))
        if not nodes:
            raise ValueError(f"{inst.name}: a stroke at ({x}, {y}) is at no node")
        cycle.append(nodes.pop())
    if sorted(cycle) != list(range(len(inst.nodes))):
        raise ValueError(f"{inst.name}: the tape does not punch every node once")
    return cycle


def write_deck(inst: Instance, scratch: Path) -> Path:
    """The instance's deck, written to ``scratch/NAME.crd``; its path."""
    deck = scratch / f"{inst.name}.crd"
    deck.write_text(inst.deck(), encoding="ascii")
    return deck


def tenzor_length(inst: Instance, out: Path) -> int:
    """The length, in the instance's own distance, of the tour TENZOR's
    small-pad tape in ``out`` punches."""
    stats = measure.read_tapes(out, inst.name.upper()[:8])
    return inst.tour_length(tenzor_cycle(inst, stats["small"].run))


def _problem(inst: Instance) -> str:
    return (f"NAME : {inst.name}\nTYPE : TSP\nDIMENSION : {len(inst.nodes)}\n"
            f"EDGE_WEIGHT_TYPE : {inst.kind}\nNODE_COORD_SECTION\n"
            + "".join(f"{k + 1} {x!r} {y!r}\n" for k, (x, y) in enumerate(inst.nodes))
            + "EOF\n")


def lkh(inst: Instance) -> tuple[int, float] | None:
    """LKH-3's single run with its default parameters: (length, seconds)."""
    try:
        from elkai import _elkai
    except ImportError:
        return None
    t = time.perf_counter()
    tour = _elkai.solve_problem("RUNS = 1\nSEED = 1\nPROBLEM_FILE = :stdin:\n", _problem(inst))
    seconds = time.perf_counter() - t
    cycle = [v - 1 for v in tour]
    if sorted(cycle) != list(range(len(inst.nodes))):
        raise RuntimeError(f"{inst.name}: LKH did not return a tour")
    return inst.tour_length(cycle), seconds


def ortools(inst: Instance, seconds: int) -> int | None:
    """OR-Tools' routing solver, guided local search for ``seconds``: the
    length of its tour, or None (not installed, or no tour in the time)."""
    try:
        from ortools.constraint_solver import pywrapcp, routing_enums_pb2
    except ImportError:
        return None
    n = len(inst.nodes)
    matrix = [[inst.dist(i, j) for j in range(n)] for i in range(n)]
    manager = pywrapcp.RoutingIndexManager(n, 1, 0)
    routing = pywrapcp.RoutingModel(manager)
    # the distances as a matrix OR-Tools reads in C++: a Python callback per
    # arc (FlatCAM's way) is slow enough that no tour of 1 000 nodes or more
    # comes within 1 s
    routing.SetArcCostEvaluatorOfAllVehicles(routing.RegisterTransitMatrix(matrix))
    params = pywrapcp.DefaultRoutingSearchParameters()
    params.first_solution_strategy = routing_enums_pb2.FirstSolutionStrategy.PATH_CHEAPEST_ARC
    params.local_search_metaheuristic = (
        routing_enums_pb2.LocalSearchMetaheuristic.GUIDED_LOCAL_SEARCH)
    params.time_limit.seconds = seconds
    solution = routing.SolveWithParameters(params)
    if solution is None:
        return None
    cycle, index = [], routing.Start(0)
    while not routing.IsEnd(index):
        cycle.append(manager.IndexToNode(index))
        index = solution.Value(routing.NextVar(index))
    return inst.tour_length(cycle) if len(cycle) == n else None


def run_instance(name: str, exe: Path, scratch: Path, repeats: int,
                 min_seconds: float = 1.0, refs: bool = True) -> dict:
    """Every figure of one instance, as a row of report.TSPLIB_COLUMNS."""
    inst = load(name)
    deck = write_deck(inst, scratch)
    out = scratch / name
    seconds, cpu = measure.time_tenzor(exe, deck, out, repeats, budget=min_seconds)
    rss_kb = measure.peak_rss(exe, deck, out)
    length = tenzor_length(inst, out)
    row: dict = {"instance": name, "nodes": len(inst.nodes), "type": inst.kind,
                 "optimum": inst.optimum, "tenzor_len": length,
                 "tenzor_pct": 100.0 * (length / inst.optimum - 1),
                 "tenzor_s": min(seconds), "tenzor_cpu_s": min(cpu),
                 "peak_rss_mb": rss_kb / 1024,
                 "lkh_len": None, "lkh_pct": None, "lkh_s": None, "time_vs_lkh": None,
                 "ortools1_pct": None, "ortools3_pct": None}
    if not refs:
        return row
    ref = lkh(inst)
    if ref is not None:
        if ref[0] < inst.optimum:
            raise RuntimeError(f"{name}: LKH-3 found {ref[0]}, below the optimum "
                               f"{inst.optimum}: the copy or the optimum is wrong")
        row.update(lkh_len=ref[0], lkh_pct=100.0 * (ref[0] / inst.optimum - 1),
                   lkh_s=ref[1], time_vs_lkh=min(seconds) / ref[1])
    for limit, key in ((1, "ortools1_pct"), (3, "ortools3_pct")):
        got = ortools(inst, limit)
        if got is not None:
            row[key] = 100.0 * (got / inst.optimum - 1)
    return row
