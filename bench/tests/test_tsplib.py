"""The TSPLIB drilling problems of the benchmark: the copies and their scoring.

TENZOR's figure on them belongs in the benchmark's output and in
docs/PERFORMANCE.md; here only that the instances read back whole, that the
decks fit the field, that TENZOR's tape of d198 visits every node once
with a tour no shorter than the proven optimum, and that the tours of the
recorded TSPLIB run are this tree's, to the unit; and that the OR-Tools
column's adapter tours a ring (when OR-Tools is installed) or is empty.
"""
from __future__ import annotations

import dataclasses
import math
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from bench import measure, report, tsplib

RECORDED = Path(__file__).resolve().parents[1] / "results" / "tsplib.csv"


@pytest.mark.parametrize("name", tsplib.NAMES)
def test_instance_reads_back_whole(name):
    inst = tsplib.load(name)
    assert inst.name == name and inst.kind == "EUC_2D" and inst.optimum > 0
    assert len(inst.nodes) == int(name.lstrip("abcdefghijklmnopqrstuvwxyz"))
    pts = inst.points()
    assert pts[0] == (0, 0)
    assert max(max(abs(x), abs(y)) for x, y in pts) <= tsplib.FIELD
    # the deck's coordinates are the instance's, scaled, within half a unit
    # (exact where TSPLIB gives one decimal at most: all but u574, u1060, fl1400)
    s = inst.scale
    err = max(max(abs((x - inst.nodes[0][0]) * s - px), abs((y - inst.nodes[0][1]) * s - py))
              for (x, y), (px, py) in zip(inst.nodes, pts))
    assert err <= 0.5 + 1e-6
    if name not in ("u574", "u1060", "fl1400"):
        assert err < 1e-6
    assert inst.deck().count("\nD ") == len(inst.nodes)


def test_distance_is_tsplib_nint():
    inst = tsplib.Instance("t", "EUC_2D", 1, ((0.0, 0.0), (3.0, 4.4), (0.0, 0.5)))
    assert inst.dist(0, 1) == 5          # 5.37 -> 5
    assert inst.dist(0, 2) == 1          # 0.5 -> 1 (nint rounds half up, as TSPLIB's (int)(d + 0.5))
    assert inst.dist(1, 2) == 5          # 4.92 -> 5
    assert inst.tour_length([0, 1, 2]) == 5 + 5 + 1


def test_tenzor_tours_d198(tenzor_exe, tmp_path):
    row = tsplib.run_instance("d198", tenzor_exe, tmp_path, 1, 0.0, refs=False)
    assert row["tenzor_len"] >= row["optimum"]
    assert 0 <= row["tenzor_pct"] < 10
    assert report.tsplib_table([row]).count("d198") == 1


@pytest.mark.parametrize("name", ["d198", "pcb442", "u574", "pcb1173", "d1291", "fl1400",
                                  "d2103", "pcb3038"])
def test_tenzor_tour_is_the_recorded_one(name, tenzor_exe, tmp_path):
    """The tour's search is deterministic: a fixed seed, and bounds that are
    counts, not seconds (docs/RECONSTRUCTION.md, order). So TENZOR's tour
    length on an instance is one number on every machine and with every
    compiler, and the one in bench/results/tsplib.csv, the run
    docs/PERFORMANCE.md shows. A change to the search (a move, a candidate,
    a kick, a bound) changes it; the benchmark's run is then made again, and
    its table with it, on purpose. (The check before, d198 within 10 % of
    its optimum, passed four faults of the search that this one catches:
    Or-opt on runs of one or two items, kicks' runs of one to five items,
    kicks stopping after three failures an item, a > for a >= in Or-opt's
    candidate test; pcb442 ended 0.12 to 0.43 points longer. u574 is here
    because a wait of 5 kicks an item instead of 10 leaves d198's, pcb442's
    and the demo deck's tours as they are, and ends u574 at 0.98 % instead
    of 0.21 %. d1291, fl1400 and pcb3038 are here because their kicks end
    at the work bound, 50 million (the other eight's at their window).
    (d1291 was also here for the near-end lists' tie rule at the sixteenth
    end, which its drilling grid meets; since its kicks stop at the work
    bound its tour is as long either way, and two decks of bench.variants
    pin the rule, test_variants.py.) pcb1173 is here because the first move tried from the tool's
    start's side changes its tour and none of the others'. The work bound's
    count, an undone kick's reversals included, which pcb3038 pinned, is
    pinned now by the demo's listing in docs/FILES.md. d1291 and fl1400
    also pin the kicks' window growing with what they gain (without it
    they would stop long before the work bound, 3.2 % and 0.49 % over the
    optimum), and d1291 that it may grow to two kicks an item (with one,
    2.6 % over). d2103 and pcb3038 are the
    two whose tapes have more than 2000 items, where the chain tries 16
    near ends, not 8.) One run each, timed by nothing. Whether a recorded
    tour is within 1 % of the optimum is the benchmark's verdict (`make
    bench` prints MET or MISSED), not this test's."""
    recorded = {r["instance"]: r for r in report.read_csv(RECORDED)}[name]
    inst = tsplib.load(name)
    measure.run_once(tenzor_exe, tsplib.write_deck(inst, tmp_path), tmp_path / name)
    length = tsplib.tenzor_length(inst, tmp_path / name)
    assert length == int(recorded["tenzor_len"]), (name, length)


def _ring(n: int, r: float = 1000.0) -> tsplib.Instance:
    """n nodes on a circle, listed out of order: the optimum is the ring."""
    nodes = tuple((round(r * math.cos(2 * math.pi * k / n), 1),
                   round(r * math.sin(2 * math.pi * k / n), 1))
                  for k in [(7 * j) % n for j in range(n)])
    inst = tsplib.Instance("ring", "EUC_2D", 0, nodes)
    ring = sorted(range(n), key=lambda i: math.atan2(nodes[i][1], nodes[i][0]))
    return dataclasses.replace(inst, optimum=inst.tour_length(ring))


def test_ortools_column_is_empty_without_ortools(monkeypatch):
    """A missing OR-Tools leaves its columns empty; it is not an error."""
    monkeypatch.setitem(sys.modules, "ortools", None)
    assert tsplib.ortools(_ring(12), 1) is None


def test_ortools_tours_a_ring():
    """With OR-Tools installed (make bench installs it, the tests do not), its
    tour visits every node once: on a ring of 12 nodes it is the ring."""
    pytest.importorskip("ortools.constraint_solver.pywrapcp")
    inst = _ring(12)
    assert tsplib.ortools(inst, 1) == inst.optimum


def test_tsplib_figure_puts_each_tour_on_its_side_of_the_targets():
    """tsplib.svg: one column per instance, by nodes; a TENZOR mark lies
    below the 1 % line exactly when its tour is within 1 %, and below the
    hundredth's line exactly when its time is; a tour at the optimum sits
    on the floor; an empty OR-Tools column draws nothing."""
    def row(name, nodes, pct, ratio, ort):
        return {"instance": name, "nodes": str(nodes), "tenzor_pct": str(pct),
                "tenzor_s": str(ratio * 2.0), "lkh_pct": "0", "lkh_s": "2.0",
                "time_vs_lkh": str(ratio), "ortools1_pct": ort, "ortools3_pct": ort}
    rows = [row("b", 500, 1.5, 0.02, "12.5"), row("a", 100, 0.0, 0.005, ""),
            row("c", 900, 0.99, 0.0099, "30")]
    ns = "{http://www.w3.org/2000/svg}"
    root = ET.fromstring(report.tsplib_svg(rows))
    texts = [t.text for t in root.iter(ns + "text")]
    assert texts.index("a") < texts.index("b") < texts.index("c")
    boxes = [(float(r.get("y")), float(r.get("y")) + float(r.get("height")))
             for r in root.iter(ns + "rect") if r.get("stroke") == "#444"]
    targets = sorted(float(ln.get("y1")) for ln in root.iter(ns + "line")
                     if ln.get("stroke-dasharray"))
    assert len(boxes) == 2 and len(targets) == 2     # the tours' chart, the times'

    def marks(box, **attrs):
        """(x, y) of the circles inside a chart's box with these attributes."""
        return sorted((float(c.get("cx")), float(c.get("cy"))) for c in root.iter(ns + "circle")
                      if all(c.get(k) == v for k, v in attrs.items())
                      and box[0] <= float(c.get("cy")) <= box[1])

    blue = report.TSPLIB_SERIES[0][2]
    for box, line in zip(boxes, targets):
        tenzor = marks(box, fill=blue)
        assert len(tenzor) == 3
        # in the order a, b, c; below a line is a larger y on the screen
        assert [y > line for _, y in tenzor] == [True, False, True]
    assert marks(boxes[0], fill=blue)[0][1] == boxes[0][1]   # a at 0 %: on the floor
    assert len(marks(boxes[0], stroke=report.TSPLIB_SERIES[2][2])) == 2   # b and c
