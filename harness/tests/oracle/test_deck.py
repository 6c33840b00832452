"""The oracle's own strict reading of a deck (harness/deck.py): the columns
of a field, a card shorter than the field, a byte that is not printable."""
from __future__ import annotations

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
