"""The oracle's own strict reading of a deck (harness/deck.py): the columns
of a field, a card shorter than the field, a byte that is not printable."""
from __future__ import annotations

import math

import pytest

from harness.deck import CardError, parse_deck

HEAD = ("*NAME T\n*MAIN TENZOR\n*EXECUTE\nT\n"
        "P             100.00    100.00    0.40    1.00    0.50    2.00\n")


def _deck(*cards: str) -> str:
    return HEAD + "".join(c + "\n" for c in cards) + "E\n"


def test_a_pad_read_from_its_columns() -> None:
    pkg, = parse_deck(_deck("D              30.00      4.00    2.00    5.00  15      2.50"))
    pad, = pkg.pads
    assert (pad.x, pad.y, pad.w, pad.h, pad.n, pad.sx, pad.sy) == (3000, 400, 200, 500, 15, 250, 0)


def test_a_card_cut_short_reads_blank_past_its_end() -> None:
    # H (39-46) and N (47-50) lie past the card's last character: blank, so
    # H is absent and N is 1, as the 80-column card would read
    pkg, = parse_deck(_deck("D              30.00      4.00    2.00"))
    pad, = pkg.pads
    assert (pad.w, pad.h, pad.n) == (200, None, 1)


def test_a_field_cut_by_the_card_end_is_not_right_justified() -> None:
    # W in 31-38 ends at column 36 of a card of 36 columns: its last two
    # columns are blank, which the strict reading refuses for a number
    # without a point
    with pytest.raises(CardError, match=r"card 6: columns 31-38: a number without a point"):
        parse_deck(_deck("D              30.00      4.00   200"))


@pytest.mark.parametrize("byte, column", [("\x01", 12), ("\x7f", 1), ("\u00e9", 80)])
def test_a_byte_that_is_not_printable_is_named_by_its_column(byte: str, column: int) -> None:
    card = ("D              30.00      4.00    2.00" + " " * 42)[:80]
    card = card[:column - 1] + byte + card[column:]
    with pytest.raises(CardError) as err:
        parse_deck(_deck(card))
    assert str(err.value) == f"card 6: column {column}: byte {byte!r}"


def test_the_start_point_may_lie_on_the_far_edges_of_the_field() -> None:
    """X0 and Y0 run from 0 to 1200.00 mm inclusive (docs/CARDS.md; TENZOR
    takes 1200.00 and refuses 1200.01 alike)."""
    def p_card(x0: str, y0: str) -> str:
        return "P" + " " * 9 + x0.rjust(10) + y0.rjust(10)

    for x0, y0, start in (("1200.00", "0.00", (120_000, 0)), ("0.00", "1200.00", (0, 120_000)),
                          ("1200.00", "1200.00", (120_000, 120_000))):
        pkg, = parse_deck(f"T\n{p_card(x0, y0)}\nE\n")
        assert pkg.start == start
    for x0, y0 in (("1200.01", "0.00"), ("0.00", "1200.01"), ("-0.01", "0.00"), ("0.00", "-0.01")):
        with pytest.raises(CardError) as err:
            parse_deck(f"T\n{p_card(x0, y0)}\nE\n")
        assert str(err.value) == "card 2: the start point X0, Y0 is off the 1200 x 1200 mm field"


def test_a_card_has_at_most_80_columns() -> None:
    """Columns 73-80 (the sequence field) are not read, column 81 does not
    exist: a line of 81 is refused at its card, as TENZOR refuses it."""
    pad = "D              30.00      4.00    2.00"
    pkg, = parse_deck(_deck(pad.ljust(72) + "SEQ00001"))
    assert [(p.x, p.y, p.w) for p in pkg.pads] == [(3000, 400, 200)]
    with pytest.raises(CardError) as err:
        parse_deck(_deck(pad.ljust(72) + "SEQ000001"))
    assert str(err.value) == "card 6: longer than 80 columns (81)"


def test_circles_and_arcs_turn_in_their_cards_direction() -> None:
    """+ is clockwise (a negative sweep), - counter-clockwise, for the full
    circle of an O card as for the arc of an A card."""
    o = "O{}        " + "     10.00" + "     20.00" + "      3.00"
    a = "A{}        " + "     10.00" + "     20.00" + "     13.00" + "     20.00" \
        + "     10.00" + "     23.00"
    pkg, = parse_deck(_deck(o.format("+"), o.format("-"), a.format("+"), a.format("-")))
    circle_cw, circle_ccw, arc_cw, arc_ccw = pkg.layers["cond"].shapes
    assert (circle_cw.cx, circle_cw.cy, circle_cw.rad, circle_cw.hw) == (1000, 2000, 300, 25)
    assert (circle_cw.sweep, circle_ccw.sweep) == (-2 * math.pi, 2 * math.pi)
    assert (arc_cw.a0, arc_ccw.a0) == (0.0, 0.0)
    assert arc_cw.sweep == pytest.approx(-1.5 * math.pi)
    assert arc_ccw.sweep == pytest.approx(0.5 * math.pi)
    assert [o.card for o in pkg.layers["cond"].origins] == [6, 7, 8, 9]
