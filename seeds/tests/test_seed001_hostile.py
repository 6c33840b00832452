"""dxf2deck on hostile and huge drawings: a coordinate far off the field or
not a number, a block that inserts itself, nested INSERTs that stand for
millions of circles, a self-crossing PAD outline, and labels matched through
a spatial index with the same answer as trying every item. Each is a problem
line naming the entity (or, for the runaway drawing, one refusal), never a
traceback, and never a silently different deck."""
from __future__ import annotations

import math
import random
from pathlib import Path

import ezdxf
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from seeds import seed001
from seeds.__main__ import main
from seeds.contour import ArcEl, Seg


def _doc():
    doc = ezdxf.new()
    return doc, doc.modelspace()


def _run(doc, tmp_path: Path, capsys) -> tuple[int, str, str]:
    path = tmp_path / "board.dxf"
    doc.saveas(path)
    out = tmp_path / "board.crd"
    status = main(["dxf2deck", str(path), "-o", str(out)])
    err = capsys.readouterr().err
    return status, err, out.read_text() if out.exists() else ""


@pytest.mark.parametrize("centre, words", [
    ((1e12, 5.0), "coordinate 1e+12 mm is off the 1200 mm field around the origin"),
    ((-1300.0, 5.0), "coordinate -1300 mm is off the 1200 mm field around the origin"),
    ((float("nan"), 5.0), "a coordinate is nan, not a number"),
    ((5.0, float("inf")), "a coordinate is inf, not a number"),
])
def test_a_coordinate_off_the_field_or_not_a_number_is_left_out(tmp_path, capsys, centre, words):
    doc, msp = _doc()
    msp.add_circle((10, 10), 1.0)
    bad = msp.add_circle(centre, 1.0)
    status, err, deck = _run(doc, tmp_path, capsys)
    assert status == 1
    assert f"CIRCLE #{bad.dxf.handle} on layer 0: {words}; left out" in err
    assert "Traceback" not in err
    assert sum(1 for c in deck.splitlines() if c.startswith("D")) == 1


def test_a_coordinate_off_the_field_around_origin_names_its_distance(tmp_path, capsys):
    # with --origin 5000,0 a point at x = 0 was "coordinate 0 mm is off the
    # 1200 mm field around the origin", which is not what is wrong with 0
    doc, msp = _doc()
    msp.add_circle((5010, 10), 1.0)
    bad = msp.add_circle((0, 10), 1.0)
    path = tmp_path / "board.dxf"
    doc.saveas(path)
    status = main(["dxf2deck", str(path), "--origin", "5000,0", "-o", str(tmp_path / "b.crd")])
    err = capsys.readouterr().err
    assert status == 1
    assert (f"CIRCLE #{bad.dxf.handle} on layer 0: x coordinate 0 mm is -5000 mm from the "
            f"origin's x (5000 mm, --origin): off the 1200 mm field around the origin; "
            f"left out") in err, err


def test_a_coordinate_at_the_fields_edge_is_kept(tmp_path, capsys):
    """Off the field is farther than 1200 mm from the origin: a pad 1200 mm
    out, either way, is drawn; one a micrometre farther is left out."""
    doc, msp = _doc()
    msp.add_circle((1200.0, 5.0), 1.0)
    msp.add_circle((-1200.0, 5.0), 1.0)
    far = msp.add_circle((5.0, 1200.001), 1.0)
    status, err, deck = _run(doc, tmp_path, capsys)
    assert status == 1
    assert err.count("left out") == 1
    assert (f"CIRCLE #{far.dxf.handle} on layer 0: coordinate 1200 mm is off the 1200 mm "
            f"field around the origin; left out") in err, err
    assert [c[:30] for c in deck.splitlines() if c.startswith("D")] == [
        "D            1200.00      5.00", "D           -1200.00      5.00"]


@pytest.mark.parametrize("kind", ["radius", "width", "line", "text", "arc"])
def test_every_kind_of_entity_is_checked(tmp_path, capsys, kind):
    doc, msp = _doc()
    msp.add_circle((10, 10), 1.0)
    if kind == "radius":
        e = msp.add_circle((10, 10), 1e9)
    elif kind == "width":
        e = msp.add_lwpolyline([(0, 0), (5, 0)], dxfattribs={"const_width": float("nan")})
    elif kind == "line":
        e = msp.add_line((0, 0), (5e6, 0))
    elif kind == "text":
        e = msp.add_text("1", dxfattribs={"insert": (float("nan"), 0)})
    else:
        e = msp.add_arc((0, 0), 5.0, float("nan"), 90)
    status, err, deck = _run(doc, tmp_path, capsys)
    assert f"#{e.dxf.handle} on layer 0: " in err and "left out" in err, err
    assert "Traceback" not in err
    assert status == 1
    assert "D" in {c[:1] for c in deck.splitlines()}


def test_a_block_that_inserts_itself_is_reported(tmp_path, capsys):
    doc, msp = _doc()
    a = doc.blocks.new("A")
    a.add_circle((0, 0), 1.0)
    b = doc.blocks.new("B")
    b.add_blockref("A", (5, 0))
    a.add_blockref("B", (5, 0))               # A -> B -> A
    msp.add_blockref("A", (10, 10))
    status, err, deck = _run(doc, tmp_path, capsys)
    assert status == 1
    assert "block A inserts itself (A -> B -> A); left out" in err
    # what the blocks draw before the cycle is kept: A's circle
    assert sum(1 for c in deck.splitlines() if c.startswith("D")) == 1


def _bomb(doc, msp, levels: int = 24) -> None:
    """2^levels circles in a few kilobytes: each block inserts the one below twice."""
    doc.blocks.new("B0").add_circle((0, 0), 0.5)
    for k in range(1, levels + 1):
        blk = doc.blocks.new(f"B{k}")
        blk.add_blockref(f"B{k - 1}", (0, 0))
        blk.add_blockref(f"B{k - 1}", (0.01 * k, 0))
    msp.add_blockref(f"B{levels}", (10, 10))


@pytest.mark.parametrize("budget", [5000, None])
def test_nested_inserts_past_the_budget_are_refused(tmp_path, capsys, monkeypatch, budget):
    """2^24 circles in a few kilobytes; the budget the message names (read
    when a reading starts) refuses them before a single entity is read: the
    blocks are counted first (expanding 200 000 of them before the refusal
    took half a minute)."""
    if budget is not None:
        monkeypatch.setattr(seed001, "ENTITY_BUDGET", budget)
    read = 0
    entity_items_of = seed001._entity_items_of

    def counted(*args, **kwargs):
        nonlocal read
        read += 1
        return entity_items_of(*args, **kwargs)

    monkeypatch.setattr(seed001, "_entity_items_of", counted)
    doc, msp = _doc()
    _bomb(doc, msp)
    status, err, deck = _run(doc, tmp_path, capsys)
    assert status == 1
    assert err.strip().endswith(f"the drawing expands to more than {budget or 200000} "
                                f"entities (blocks inserted into blocks); split it, or explode "
                                f"fewer blocks")
    assert deck == ""                          # nothing written
    assert read == 0                           # refused before anything is exploded


def test_the_count_before_reading_is_the_readings_own(monkeypatch):
    """Just at the budget a drawing is read whole; one entity more and it is
    refused, whether the count first or the reading finds it (a block that
    inserts itself leaves the counting to the reading)."""
    doc, msp = _doc()
    _bomb(doc, msp, levels=6)                  # 64 circles, 2 * 63 INSERTs below msp's one
    assert seed001.expanded_count(doc) == 64 + 126 + 1
    monkeypatch.setattr(seed001, "ENTITY_BUDGET", 191)
    assert len(seed001.read_drawing(doc).items) == 64
    monkeypatch.setattr(seed001, "ENTITY_BUDGET", 190)
    with pytest.raises(seed001.TooBig):
        seed001.read_drawing(doc)
    doc.blocks.get("B0").add_blockref("B3", (0, 0))   # B3 -> B2 -> B1 -> B0 -> B3
    assert seed001.expanded_count(doc) is None


@pytest.mark.parametrize("corners", [
    [(0, 0), (4, 2), (4, 0), (0, 2)],          # a bow-tie: the same corners, crossed
    [(0, 0), (4, 2), (0, 2), (4, 0)],
])
def test_a_self_crossing_pad_outline_is_not_a_rectangle(tmp_path, capsys, corners):
    doc, msp = _doc()
    e = msp.add_lwpolyline(corners, close=True, dxfattribs={"layer": "PADS"})
    status, err, deck = _run(doc, tmp_path, capsys)
    assert (f"LWPOLYLINE #{e.dxf.handle} on layer PADS: a closed polyline on a PAD layer "
            "that is not an axis-parallel rectangle; drawn as a conductor") in err
    assert not any(c.startswith("D") for c in deck.splitlines())
    assert any(c.startswith("L") for c in deck.splitlines())


def test_a_true_rectangle_is_still_a_pad(tmp_path, capsys):
    doc, msp = _doc()
    msp.add_lwpolyline([(0, 0), (4, 0), (4, 2), (0, 2)], close=True, dxfattribs={"layer": "PADS"})
    status, err, deck = _run(doc, tmp_path, capsys)
    assert status == 0, err
    assert [c[:1] for c in deck.splitlines() if c[:1] in "DL"] == ["D"]


# ---- the spatial index gives the answer of trying every item ---------------

def _item(kind: str, a: float, b: float, c: float, d: float) -> seed001.Item:
    if kind == "disc":
        return seed001.Item("pad", [], "0", "0", disc=(a, b, 0.1 + abs(c) % 3))
    if kind == "rect":
        return seed001.Item("pad", [], "0", "0", rect=(min(a, c), min(b, d), max(a, c), max(b, d)))
    if kind == "line":
        if (a, b) == (c, d):                   # dxf2deck drops zero-length segments
            d += 1
        return seed001.Item("conductor", [], "0", "0", segments=[Seg(a, b, c, d)])
    r = 0.5 + abs(c) % 5
    return seed001.Item("arc", [], "0", "0",
                        segments=[ArcEl(a, b, a + r, b, a, b + r, cw=d > 0)])


coord = st.integers(-50, 50).map(float)        # whole mm: ties are common
items_st = st.lists(st.tuples(st.sampled_from(["disc", "rect", "line", "arc"]),
                              coord, coord, coord, coord), min_size=1, max_size=40)


@settings(max_examples=200, deadline=None)
@given(items=items_st, points=st.lists(st.tuples(coord, coord), min_size=1, max_size=20))
def test_the_nearest_item_is_the_one_trying_every_item_finds(items, points):
    its = [_item(*t) for t in items]
    nearest = seed001._Nearest(its)
    for p in points:
        want = min(range(len(its)), key=lambda i: (its[i].distance(p), i))
        assert nearest(p) == want


def test_many_labels_many_items_match_as_by_brute_force():
    rnd = random.Random(7)
    its = [_item(rnd.choice(["disc", "rect", "line", "arc"]),
                 *(rnd.uniform(0, 1000) for _ in range(2)),
                 *(rnd.uniform(0, 1000) if k == "rect" else rnd.uniform(-3, 3) for k in "xx"))
           for _ in range(5000)]
    nearest = seed001._Nearest(its)
    for _ in range(300):
        p = (rnd.uniform(-10, 1010), rnd.uniform(-10, 1010))
        want = min(range(len(its)), key=lambda i: (its[i].distance(p), i))
        assert nearest(p) == want
    assert math.isfinite(its[0].distance((0.0, 0.0)))
