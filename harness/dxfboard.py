"""The known board of the DXF round trip (seed 001), as a card deck and as
a DXF drawing written with ezdxf.

    python -m harness dxfboard examples/dxf

writes ``board.dxf`` (the drawing, with the paper's ordering labels, a
macro, a hint and two entities dxf2deck cannot map) and ``board-known.crd``
(the same board as cards, written directly).  ``python -m harness dxf2deck
examples/dxf/board.dxf -o examples/dxf/board.crd`` must give a deck whose
tapes draw exactly the known board: harness/tests/test_seed001_dxf.py runs
TENZOR on it and checks every tape against ``board-known.crd``'s ideal
layers.  The files are byte-identical from run to run (ezdxf's fixed
metadata: no clock, no random GUID).

Board (mm, start point at the drawing's origin): a DIP-8 footprint of 1.6 mm
pads, four 3.5 mm mounting holes (large-pad tape), five 2 x 5 mm connector
fingers (closed rectangles on layer PAD), a 1.5 mm supply conductor
(constant width), a signal on layer 0 (the tool's width), a LINE on layer
SIGNAL_W0.8 (the layer rule), an ARC and a circle on layer RING.
"""

from __future__ import annotations

import argparse

from decimal import Decimal as D
from pathlib import Path

from . import cards

NAME = "BOARD"
#: Where dxf2deck puts the start point by default: the lower-left corner of
#: the board (x: a mounting hole's edge at 2.25 mm; y: the fingers' at 2 mm)
#: 10 mm inside the field.
START_MM = (D("7.75"), D("8.00"))

DIP = [(D("20.00"), D("20.00") + D("2.54") * i) for i in range(4)] + \
      [(D("27.62"), D("20.00") + D("2.54") * i) for i in range(4)]
HOLES = [(D(4), D(4)), (D(56), D(4)), (D(4), D(46)), (D(56), D(46))]
FINGERS = [(D("30.00") + D("2.54") * i, D("4.50")) for i in range(5)]
SUPPLY = [(D(8), D(10)), (D(50), D(10)), (D(50), D(40))]
SIGNAL1 = [(D("20.00"), D("27.62")), (D(14), D(34)), (D(14), D(42))]
SIGNAL2 = [(D("27.62"), D("20.00")), (D(36), D(20))]
ARC = ((D(44), D(28)), D(4))                        # 0 to 90 degrees, counter-clockwise
RING = ((D(10), D(30)), D(3))

#: Labels: text -> insertion point.  The order they give: FIRST the supply,
#: 1 the LINE, 2 the arc, 3 the signal on layer 0, 4 the LINE again (the
#: paper's "later numbers" for a path walked twice), LAST the ring.
LABELS = [("FIRST OUT 1", (30, 11.5)), ("1", (32, 21)), ("2", (47, 31)), ("3", (15, 38)),
          ("4", (33, 19)), ("LAST", (10, 34))]


def known_cards() -> list[str]:
    """The board as cards, in the order the labels ask for."""
    p = cards.p_card(*START_MM, order="D")
    pads = [cards.d_card(x, y, D("1.6")) for x, y in DIP]
    pads += [cards.d_card(x, y, D("3.5")) for x, y in HOLES]
    pads += [cards.d_card(x, y, D(2), D(5)) for x, y in FINGERS]

    def cond(pts: list, w: D | None) -> list[str]:
        return [cards.l_card(*pts[0], w)] + [cards.plus_card(*q) for q in pts[1:]]

    (cx, cy), r = ARC
    arc = [cards.a_card("-", cx, cy, cx + r, cy, cx, cy + r)]
    ring = [cards.o_card("-", *RING[0], RING[1])]
    sig2 = cond(SIGNAL2, D("0.8"))
    # deck order: FIRST, 1, 2, 3, 4, then the unlabelled items in drawing
    # order (as write_dxf draws them), then LAST
    return [p] + cond(SUPPLY, D("1.5")) + sig2 + arc + cond(SIGNAL1, None) + sig2 + pads + ring


def known_deck() -> str:
    return cards.deck([cards.CardPackage(NAME, known_cards())], job="DXF ROUND TRIP, KNOWN BOARD")


def write_dxf(path: str | Path, offset: tuple[float, float] = (0.0, 0.0)) -> None:
    """The board as a DXF drawing (R2000), every point moved by ``offset``
    mm (so ``dxf2deck --origin`` can be tested)."""
    import ezdxf

    ox, oy = offset

    def pt(p: tuple) -> tuple[float, float]:
        return float(p[0]) + ox, float(p[1]) + oy

    saved = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        doc = ezdxf.new("R2000")
        for name in ("PAD", "SIGNAL_W0.8", "RING", "OUTLINE", "NOTES"):
            doc.layers.add(name)
        msp = doc.modelspace()
        # drawing order: conductors, arc, pads, ring (the unlabelled pads
        # follow the labelled items in this order)
        msp.add_lwpolyline([pt(p) for p in SUPPLY], dxfattribs={"const_width": 1.5})
        msp.add_line(pt(SIGNAL2[0]), pt(SIGNAL2[1]), dxfattribs={"layer": "SIGNAL_W0.8"})
        (cx, cy), r = ARC
        msp.add_arc(pt((cx, cy)), float(r), 0, 90)
        msp.add_lwpolyline([pt(p) for p in SIGNAL1])
        for x, y in DIP:
            msp.add_circle(pt((x, y)), 0.8)
        for x, y in HOLES:
            msp.add_circle(pt((x, y)), 1.75)
        for x, y in FINGERS:
            x0, x1, y0, y1 = float(x) - 1, float(x) + 1, float(y) - 2.5, float(y) + 2.5
            msp.add_lwpolyline([pt((x0, y0)), pt((x1, y0)), pt((x1, y1)), pt((x0, y1))],
                               close=True, dxfattribs={"layer": "PAD"})
        msp.add_circle(pt(RING[0]), float(RING[1]), dxfattribs={"layer": "RING"})
        for text, at in LABELS:
            msp.add_text(text, height=1.0, dxfattribs={"insert": pt(at), "layer": "NOTES"})
        # what dxf2deck reports and leaves out: a hint, a spline, a point
        msp.add_text("DRILL 0.8 MM", height=1.0, dxfattribs={"insert": pt((40, 46)),
                                                             "layer": "NOTES"})
        msp.add_spline([pt((0, 0)), pt((30, -2)), pt((60, 0))], dxfattribs={"layer": "OUTLINE"})
        msp.add_point(pt((30, 25)), dxfattribs={"layer": "OUTLINE"})
        doc.saveas(str(path))
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = saved


def _run(args: argparse.Namespace) -> int:
    import sys

    out = Path(args.dir)
    try:
        out.mkdir(parents=True, exist_ok=True)
        write_dxf(out / "board.dxf")
        (out / "board-known.crd").write_text(known_deck(), encoding="ascii")
    except OSError as exc:
        print(f"dxfboard: {out}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    return 0


def add_dxfboard(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("dxfboard", help="write the DXF round trip's known board (seed 001)",
                       description="Write DIR/board.dxf (with ezdxf) and DIR/board-known.crd: "
                                   "the same board as a drawing and as cards.")
    p.add_argument("dir", nargs="?", default="examples/dxf", metavar="DIR")
    p.set_defaults(func=_run)
