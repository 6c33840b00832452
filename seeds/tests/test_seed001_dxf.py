"""Seed 001 (DXF drawing to motion code): dxf2deck, its labels, and the
round trip: a DXF written with ezdxf from a known board becomes a deck whose
TENZOR tapes draw that very board."""
from __future__ import annotations

import math
from pathlib import Path

import ezdxf
import pytest

from seeds import seed001, seed001_dmc
from seeds.__main__ import main
from harness.deck import parse_deck
from harness.tests.helpers import check_package

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples" / "dxf"


def _data_cards(deck: str) -> list[str]:
    return [c for c in deck.splitlines() if c and c[0] not in "*#"]


def test_example_files_are_the_generators_output(tmp_path: Path) -> None:
    seed001.write_dxf(tmp_path / "board.dxf")
    assert (tmp_path / "board.dxf").read_bytes() == (EXAMPLES / "board.dxf").read_bytes()
    assert seed001.known_deck() == (EXAMPLES / "board-known.crd").read_text()
    conv = seed001.convert(ezdxf.readfile(EXAMPLES / "board.dxf"))
    deck = seed001.deck_text(conv, "BOARD", job="DXF2DECK board.dxf")
    assert deck == (EXAMPLES / "board.crd").read_text()


def test_the_drawing_becomes_the_known_boards_cards() -> None:
    conv = seed001.convert(ezdxf.readfile(EXAMPLES / "board.dxf"))
    deck = seed001.deck_text(conv, "BOARD")
    assert _data_cards(deck) == _data_cards(seed001.known_deck())
    assert conv.ordered
    # reported with handle and layer: the ellipse, the point, the macro, the hint
    assert any(p.startswith("ELLIPSE #") and p.endswith("OUTLINE: cannot map an ELLIPSE; "
                                                         "left out") for p in conv.problems)
    assert any(p.startswith("POINT #") and p.endswith("OUTLINE: cannot map a POINT; left out")
               for p in conv.problems)
    assert any("macro 'OUT 1' after FIRST" in p for p in conv.problems)
    assert any("'DRILL 0.8 MM' is not a label" in p and "layer NOTES" in p for p in conv.problems)
    assert len(conv.problems) == 4


def test_round_trip_through_tenzor(run_tenzor, tmp_path: Path) -> None:
    """The board drawn 50, 30 mm off the origin, read back with --origin
    50,30: TENZOR's tapes draw the known board's ideal layers within
    0.05 mm (coverage, start point, field, job sheet: test_layers' checks)."""
    drawing = tmp_path / "board.dxf"
    seed001.write_dxf(drawing, offset=(50.0, 30.0))
    deck = tmp_path / "board.crd"
    status = main(["dxf2deck", str(drawing), "--origin", "50,30", "-o", str(deck)])
    assert status == 1                              # the ellipse and the point were left out
    assert _data_cards(deck.read_text()) == _data_cards(seed001.known_deck())
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0, proc.stderr.decode("latin-1")
    (known,) = parse_deck(seed001.known_deck())
    problems = check_package(known, out, deck)
    assert not problems, "\n".join(problems)


# ---------------------------------------------------------------------------
# Single rules, on small drawings made here.
# ---------------------------------------------------------------------------
def _doc():
    doc = ezdxf.new("R2000")
    return doc, doc.modelspace()


def test_labels_order_the_items() -> None:
    """FIRST, then 1, 2, 3, then the unlabelled in drawing order, then LAST;
    a label attaches to the nearest item; a repeated number is reported."""
    doc, msp = _doc()
    for k in range(5):                                   # five lines at y = 0, 10, ... 40
        msp.add_line((0, 10 * k), (20, 10 * k))
    msp.add_text("2", dxfattribs={"insert": (5, 1)})     # line 0
    msp.add_text("LAST", dxfattribs={"insert": (5, 11)})  # line 1
    msp.add_text("FIRST", dxfattribs={"insert": (5, 39)})  # line 4
    msp.add_text("1", dxfattribs={"insert": (25, 20)})   # line 2 (beyond its end)
    msp.add_text("1", dxfattribs={"insert": (5, 29)})    # a second 1: reported
    conv = seed001.convert(doc)
    ys = [it.segments[0].y0 for it in conv.items]
    assert ys == [40, 20, 0, 30, 10]
    assert conv.ordered and any("order number 1 given twice" in p for p in conv.problems)
    deck = seed001.deck_text(conv, "T")
    assert deck.splitlines()[4][70] == "D"               # deck order on the P card


def test_a_second_first_or_last_is_named_like_every_report() -> None:
    """A FIRST or LAST given again was "FIRST given 2 times; the first one is
    used", naming no text: now the ignored one's type, handle and layer."""
    doc, msp = _doc()
    for k in range(3):
        msp.add_line((0, 10 * k), (20, 10 * k))
    msp.add_text("FIRST", dxfattribs={"insert": (5, 1)})
    again = msp.add_mtext("FIRST", dxfattribs={"insert": (5, 11), "layer": "NOTES"})
    last = msp.add_text("LAST", dxfattribs={"insert": (5, 1), "layer": "L"})
    conv = seed001.convert(doc)
    assert [it.segments[0].y0 for it in conv.items] == [0, 10, 20, 0]
    assert (f"MTEXT #{again.dxf.handle} on layer NOTES: FIRST given again; the first in "
            f"the drawing is used, this one ignored") in conv.problems, conv.problems
    assert (f"TEXT #{last.dxf.handle} on layer L: LAST is attached to an item that also "
            f"has an earlier label") in conv.problems, conv.problems
    reading = seed001.read_drawing(doc)
    plan = seed001_dmc.plan(reading)
    assert any(p.startswith(f"MTEXT #{again.dxf.handle} on layer NOTES: FIRST given again")
               for p in plan.problems), plan.problems


def test_no_labels_leaves_the_order_to_tenzor() -> None:
    doc, msp = _doc()
    msp.add_circle((1, 1), 0.8)
    msp.add_line((0, 0), (5, 0))
    conv = seed001.convert(doc)
    assert not conv.ordered and conv.problems == []
    p_card = seed001.deck_text(conv, "T").splitlines()[4]
    assert p_card.startswith("P") and len(p_card) < 71
    assert [it.kind for it in conv.items] == ["pad", "conductor"]


def test_widths_and_layers() -> None:
    doc, msp = _doc()
    msp.add_lwpolyline([(0, 0), (10, 0)], dxfattribs={"const_width": 1.2})
    msp.add_line((0, 5), (10, 5), dxfattribs={"layer": "POWER_W2.5"})
    msp.add_line((0, 9), (10, 9))
    msp.add_lwpolyline([(0, 12, 0.3, 0.3), (10, 12, 0.3, 0.3)], format="xyse")
    msp.add_lwpolyline([(0, 15, 0.3, 0.5), (10, 15, 0.5, 0.5)], format="xyse")
    msp.add_circle((3, 20), 2, dxfattribs={"layer": "RING"})
    conv = seed001.convert(doc)
    cards = [it.cards[0] for it in conv.items]
    assert [c[30:38] for c in cards[:4]] == ["    1.20", "    2.50", "", "    0.30"]
    assert cards[4].startswith("O-") and cards[4][30:40] == "      2.00"
    assert len(conv.items) == 5 and any("varying width" in p for p in conv.problems)


def test_old_style_polylines() -> None:
    """POLYLINE (2D): the default width, or the vertices' one common width."""
    doc, msp = _doc()
    msp.add_polyline2d([(0, 0), (10, 0)], dxfattribs={"default_start_width": 0.7,
                                                      "default_end_width": 0.7})
    pl = msp.add_polyline2d([(0, 5), (10, 5)])
    for v in pl.vertices:
        v.dxf.start_width = v.dxf.end_width = 0.4
    msp.add_polyline2d([(0, 9), (10, 9)], dxfattribs={"default_start_width": 0.7,
                                                      "default_end_width": 0.2})
    conv = seed001.convert(doc)
    assert [it.cards[0][30:38] for it in conv.items] == ["    0.70", "    0.40"]
    assert len(conv.problems) == 1 and "POLYLINE #" in conv.problems[0]


def test_bulges_become_chords_within_tolerance() -> None:
    """A polyline vertex with bulge 1 is a half circle (here of radius 5)."""
    doc, msp = _doc()
    msp.add_lwpolyline([(0, 0, 1), (10, 0, 0)], format="xyb")
    (item,) = seed001.convert(doc).items
    pts = [(float(c[10:20]), float(c[20:30])) for c in item.cards]
    assert pts[0] == (0, 0) and pts[-1] == (10, 0) and len(pts) > 20
    assert all(abs(math.hypot(x - 5, y) - 5) <= 0.008 for x, y in pts)
    assert all(y <= 0.006 for _, y in pts)                 # counter-clockwise: below


def test_arcs_both_ways_and_inserts() -> None:
    doc, msp = _doc()
    msp.add_arc((0, 0), 5, 0, 90)
    msp.add_arc((20, 0), 5, 0, 90, dxfattribs={"extrusion": (0, 0, -1)})   # mirrored
    blk = doc.blocks.new("PADS")
    blk.add_circle((0, 0), 0.8)
    blk.add_circle((2.54, 0), 0.8)
    msp.add_blockref("PADS", (30, 30))
    conv = seed001.convert(doc)
    a, b = conv.items[0].cards[0], conv.items[1].cards[0]
    assert a == "A-              0.00      0.00      5.00      0.00      0.00      5.00"
    # seen from below: centre (-20, 0), from (-25, 0) clockwise to (-20, 5)
    assert b == "A+            -20.00      0.00    -25.00      0.00    -20.00      5.00"
    assert [it.cards[0][10:30] for it in conv.items[2:]] == [
        "     30.00     30.00", "     32.54     30.00"]


def test_what_cannot_be_mapped_is_reported(tmp_path: Path) -> None:
    doc, msp = _doc()
    msp.add_line((0, 0), (5, 5))
    msp.add_ellipse((0, 0), (3, 0), 0.5, dxfattribs={"layer": "ART"})
    msp.add_circle((0, 0), 1, dxfattribs={"extrusion": (0, 1, 0)})
    path = tmp_path / "x.dxf"
    doc.saveas(path)
    conv = seed001.convert(ezdxf.readfile(path))
    assert len(conv.items) == 1
    handles = list(seed001.iter_problem_handles(conv.problems))
    assert len(handles) == 2 and all(h in " ".join(conv.problems) for h in handles)
    assert any(p.startswith("ELLIPSE #") and "layer ART" in p for p in conv.problems)
    assert any("tilted plane" in p for p in conv.problems)
    assert main(["dxf2deck", str(path), "-o", str(tmp_path / "x.crd")]) == 1
    assert main(["dxf2deck", str(tmp_path / "missing.dxf")]) == 2
    (tmp_path / "bad.dxf").write_text("not a drawing\n")
    assert main(["dxf2deck", str(tmp_path / "bad.dxf")]) == 2


@pytest.mark.parametrize("origin", [(0.0, 0.0), (-120.5, 33.25)])
def test_origin_moves_the_start_point(origin: tuple[float, float], tmp_path: Path) -> None:
    doc, msp = _doc()
    msp.add_line((origin[0] + 1, origin[1] + 2), (origin[0] + 6, origin[1] + 2))
    conv = seed001.convert(doc, origin)
    card = conv.items[0].cards[0]
    assert card[10:30] == "      1.00      2.00"


def test_a_label_inside_a_pad_attaches_to_the_pad() -> None:
    """A pad's distance is to its disc, 0 inside it (SEED001-DXF.md), not to
    its centre: "1" inside a pad of radius 5, 4 mm from the pad's centre and
    3 mm from a line, is the pad's."""
    doc, msp = _doc()
    msp.add_line((7, -5), (7, 5))
    msp.add_circle((0, 0), 5)
    msp.add_text("1", dxfattribs={"insert": (4, 0)})
    conv = seed001.convert(doc)
    assert conv.ordered and [it.kind for it in conv.items] == ["pad", "conductor"]


def test_a_drawing_far_from_its_origin_keeps_its_place() -> None:
    """The default start point puts the drawing's lower-left corner 10 mm
    inside the field, but goes no lower than the field's corner: a drawing
    50 mm right of its origin and 5 mm above it starts at 0, 5 mm."""
    doc, msp = _doc()
    msp.add_line((50, 5), (60, 5))
    deck = seed001.deck_text(seed001.convert(doc), "T")
    assert _data_cards(deck)[1:4] == ["P               0.00      5.00",
                                      "L              50.00      5.00",
                                      "+              60.00      5.00"]


def test_package_name_is_the_name_cards_18_columns() -> None:
    """From the file name: letters, digits, - and _, upper case, the first
    18 (the name card's columns 1-18); a bare C or E gets a _."""
    assert seed001.package_name("a-very-long board name.v2.dxf") == "A-VERY-LONG_BOARD_"
    assert seed001.package_name("dir/c.dxf") == "C_"


def test_tools_from_0_01_to_20_mm(tmp_path: Path, capsys) -> None:
    """--tools: each 0.01 to 20 mm (SEED001-DXF.md), both ends taken, in
    whole 0.01 mm."""
    doc, msp = _doc()
    msp.add_line((0, 0), (5, 0))
    doc.saveas(tmp_path / "t.dxf")
    out = tmp_path / "t.crd"
    assert main(["dxf2deck", str(tmp_path / "t.dxf"), "--tools", "0.01,20,20",
                 "-o", str(out)]) == 0
    assert _data_cards(out.read_text())[1][30:54] == "    0.01   20.00   20.00"
    for bad in ("0.01,20.01,1", "0.009,1,1", "0.5,1,1.005"):
        assert main(["dxf2deck", str(tmp_path / "t.dxf"), "--tools", bad]) == 2
        assert f"dxf2deck: --tools {bad}: each tool is 0.01 to 20.00 mm, in whole 0.01 mm" \
            in capsys.readouterr().err


@pytest.mark.parametrize("argv", [
    ["dxf2deck", "--origin", "1,2,3"], ["dxf2deck", "--start", "10"],
    ["dxf2deck", "--tools", "0.2,0.2,0.2,0.2"], ["dxf2dmc", "--origin", "1,2,3"],
    ["gerber2deck", "--start", "10,10,10"], ["gerber2deck", "--tools", "0.2,0.2"]])
def test_a_list_of_mm_has_exactly_its_count(tmp_path: Path, capsys, argv: list[str]) -> None:
    """X,Y and W1,W2,W3: a value too many is as wrong as one too few (a
    third coordinate was taken and dropped without a word)."""
    n = {"--origin": 2, "--start": 2, "--tools": 3}[argv[1]]
    assert main([*argv, str(tmp_path / "any.dxf")]) == 2
    assert capsys.readouterr().err == (f"{argv[0]}: {argv[1]} {argv[2]}: {n} finite numbers "
                                       f"of mm separated by commas\n")


def test_dxf2deck_will_not_write_over_its_drawing(tmp_path: Path, capsys) -> None:
    drawing = tmp_path / "board.dxf"
    drawing.write_bytes((EXAMPLES / "board.dxf").read_bytes())
    assert main(["dxf2deck", str(drawing), "-o", str(tmp_path / "." / "board.dxf")]) == 2
    assert "will not write over its own input" in capsys.readouterr().err
    assert drawing.read_bytes() == (EXAMPLES / "board.dxf").read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["board.dxf"]


def test_the_reports_exit_status_is_as_the_page_says(tmp_path: Path, capsys) -> None:
    """SEED001-DXF.md's reports: exit 1 for anything but a hint reported,
    even when nothing is left out (a bow-tie on a PAD layer is drawn); a
    varying width is left out; a drawing with nothing to draw gets no deck
    and no program."""
    page = " ".join((ROOT / "docs" / "SEED001-DXF.md").read_text().split())
    assert "exit status is 1 if anything other than a hint was reported, whether left out " \
           "or not" in page
    assert "A polyline of varying width is reported and left out" in page
    assert "unless nothing is left to draw (`nothing to draw`: exit 1, no deck)" in page
    assert "nothing is left to draw: `nothing to draw`, exit 1, no program" in page
    doc, msp = _doc()
    msp.add_lwpolyline([(0, 0), (4, 2), (4, 0), (0, 2)], close=True, dxfattribs={"layer": "PAD"})
    vary = msp.add_lwpolyline([(0, 10, 0.2, 0.5), (5, 10, 0.2, 0.5)], format="xyse")
    doc.saveas(tmp_path / "b.dxf")
    assert main(["dxf2deck", str(tmp_path / "b.dxf"), "-o", str(tmp_path / "b.crd")]) == 1
    err = capsys.readouterr().err
    assert "drawn as a conductor" in err
    assert f"LWPOLYLINE #{vary.dxf.handle} on layer 0: varying width; left out" in err
    assert (tmp_path / "b.crd").exists()
    doc, msp = _doc()
    msp.add_text("DRILL 0.8 MM", dxfattribs={"insert": (5, 1)})
    doc.saveas(tmp_path / "t.dxf")
    for command, out in (("dxf2deck", "t.crd"), ("dxf2dmc", "t.dmc")):
        assert main([command, str(tmp_path / "t.dxf"), "-o", str(tmp_path / out)]) == 1
        assert f"{command}: {tmp_path / 't.dxf'}: nothing to draw" in capsys.readouterr().err
        assert not (tmp_path / out).exists()
