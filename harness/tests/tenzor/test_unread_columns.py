"""No silent misreads (docs/CARDS.md, "Packages" and "Columns not read").

A deck that lost its name card must not name its package after the first data
card and drop that card: a name card that reads as a data card is an error at
the name card. Data in columns a card type does not read (a second vertex on an
L card, a width on a + card) is said on standard error as a warning naming the
card and the columns; the tapes are still punched, exactly as without the
stray data. `tenzor --strict` makes every warning an error. The harness's deck
reader refuses the same decks, by its own code (harness/deck.py), and a
differential property holds the two to the same rule.
"""
from __future__ import annotations

import re
import subprocess
import tempfile
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from harness.deck import FIELDS, LETTERS, CardError, parse_deck, reads_as_data
from harness.tests.tenzor.test_bad_decks import card, f10

P = card(c1="P", c11=f10("100.00"), c21=f10("100.00"))
PAD = card(c1="D", c11=f10("15.00"), c21=f10("20.00"), c31="    1.60")
LINE = card(c1="L", c11=f10("5.00"), c21=f10("44.00"), c31="    1.50")
PLUS = card(c1="+", c11=f10("65.00"), c21=f10("44.00"))
CIRCLE = card(c1="O", c2="+", c11=f10("30.00"), c21=f10("30.00"), c31=f10("2.00"))
ARC = card(c1="A", c2="-", c11=f10("90.00"), c21=f10("12.00"), c31=f10("90.00"),
           c41=f10("22.00"), c51=f10("80.00"), c61=f10("12.00"))
MAN = card(c1="M", c31=f10("3.00"), c41=f10("4.00"), c56="   10")


def deck(*cards: str, name: str = "BOARD") -> str:
    return "\n".join([name, P, *cards, "E"]) + "\n"


def with_cols(base: str, col: int, text: str) -> str:
    """`base` with `text` punched from column `col` on."""
    line = list(base.ljust(80))
    line[col - 1:col - 1 + len(text)] = list(text)
    return "".join(line).rstrip()


def tapes(out):
    return {p.name: p.read_bytes() for p in sorted(out.glob("*.ptp"))}


# ---- the missing name card ------------------------------------------------

@pytest.mark.parametrize("first", [P, PAD, LINE, PLUS, CIRCLE, ARC, MAN],
                         ids=["P", "D", "L", "+", "O", "A", "M"])
def test_a_data_card_where_the_name_card_is_due_is_an_error(run_tenzor, first):
    proc, out = run_tenzor(first + "\n" + PAD + "\nE\n")
    err = proc.stderr.decode()
    assert proc.returncode == 1, err
    assert (f"TENZOR ERROR CARD 1 COL 1: THE NAME CARD READS AS A {first[0]} CARD; "
            "A PACKAGE STARTS WITH ITS NAME IN COLS 1-18") in err
    assert not list(out.glob("*.ptp"))
    with pytest.raises(CardError, match=f"card 1: the name card reads as a {re.escape(first[0])} card"):
        parse_deck(first + "\n" + PAD + "\nE\n")


def test_the_name_card_is_checked_after_c_too(run_tenzor):
    text = deck(PAD).replace("\nE\n", "\nC\n") + PAD + "\n" + PAD + "\nE\n"
    proc, _ = run_tenzor(text)
    assert proc.returncode == 1
    assert "TENZOR ERROR CARD 5 COL 1: THE NAME CARD READS AS A D CARD" in proc.stderr.decode()


@pytest.mark.parametrize("name", [
    "LOGIC-CARD-A", "DEMO", "P1", "D_1", "PLUS", "M", "MS", "L", "+", "O+", "A-",
    "P_    9999",          # a character in a column the P card does not read
    "D        12.5_",      # the D card does not read columns 2-10
])
def test_names_that_only_begin_like_a_card_are_names(run_tenzor, name):
    proc, out = run_tenzor(deck(PAD, name=name))
    assert proc.returncode == 0, proc.stderr.decode()
    assert b"READS AS A" not in proc.stderr
    assert reads_as_data(name) is None
    assert parse_deck(deck(PAD, name=name))[0].name == name


def test_a_p_card_of_one_field_is_not_a_name(run_tenzor):
    name = "P     9999"                    # FMAX 9999: a P card, cols 3-10
    proc, _ = run_tenzor(deck(PAD, name=name))
    assert proc.returncode == 1
    assert "THE NAME CARD READS AS A P CARD" in proc.stderr.decode()
    assert reads_as_data(name) == "P"


# ---- columns a card does not read -----------------------------------------

# (id, the cards with stray data, the same cards without, the card number in
# deck(...), the columns said, the words on the card type)
STRAY = [
    ("second-vertex-on-l", [with_cols(LINE, 41, "     65.00     44.00"), PLUS], [LINE, PLUS],
     3, "46-60", "AN L CARD DOES NOT READ THEM (IT READS COLS 1, 11-38)"),
    ("width-on-plus", [LINE, with_cols(PLUS, 31, "    1.50")], [LINE, PLUS],
     4, "35-38", "A + CARD DOES NOT READ THEM (IT READS COLS 1, 11-30)"),
    ("junk-in-col-2", [with_cols(PAD, 2, "X")], [PAD],
     3, "2", "A D CARD DOES NOT READ THEM (IT READS COLS 1, 11-70)"),
    ("junk-in-cols-71-72", [with_cols(PAD, 71, "ZZ")], [PAD],
     3, "71-72", "A D CARD DOES NOT READ THEM (IT READS COLS 1, 11-70)"),
    ("after-the-radius", [with_cols(CIRCLE, 45, "7")], [CIRCLE],
     3, "45", "AN O CARD DOES NOT READ THEM (IT READS COLS 1-2, 11-40)"),
    ("arc-col-3", [with_cols(ARC, 3, "+")], [ARC],
     3, "3", "AN A CARD DOES NOT READ THEM (IT READS COLS 1-2, 11-70)"),
    ("after-k", [with_cols(MAN, 61, "10")], [MAN],
     3, "61-62", "AN M CARD DOES NOT READ THEM (IT READS COLS 1-2, 11-60)"),
]


@pytest.mark.parametrize("cards, clean, cardno, cols, words", [c[1:] for c in STRAY],
                         ids=[c[0] for c in STRAY])
def test_data_in_unread_columns_is_a_warning_and_changes_nothing(run_tenzor, cards, clean,
                                                                 cardno, cols, words):
    proc, out = run_tenzor(deck(*cards))
    err = proc.stderr.decode()
    assert proc.returncode == 0, err
    label = "COL" if "-" not in cols else "COLS"
    assert f"TENZOR WARNING CARD {cardno} {label} {cols}: NOT BLANK, BUT {words}" in err
    assert err.count("WARNING") == 1
    ref, ref_out = run_tenzor(deck(*clean))
    assert ref.returncode == 0 and ref.stderr == b""
    assert tapes(out) == tapes(ref_out)
    listing = (out / "BOARD.lst").read_text()
    assert f" *** TENZOR WARNING CARD {cardno} {label} {cols}:" in listing
    # under the card's echo, a caret under each column of the run (the card's
    # column c is the listing's column 9 + c)
    lines = listing.splitlines()
    at = next(i for i, line in enumerate(lines) if f"WARNING CARD {cardno} " in line)
    first, last = (int(c) for c in (cols.split("-") * 2)[:2])
    assert lines[at - 2] == f"{cardno:8d} {cards[cardno - 3]}"
    assert lines[at - 1].rstrip() == " " * (8 + first) + "^" * (last - first + 1)
    # the harness's strict reader refuses what TENZOR only warns of
    with pytest.raises(CardError, match=f"card {cardno}: columns"):
        parse_deck(deck(*cards))


@pytest.mark.parametrize("text, cardno, cols, words", [
    ("BOARD               A COMMENT", 1, "21-29", "THE NAME CARD DOES NOT READ THEM (IT READS COLS 1-18)"),
    ("E   THE END", 4, "5-11", "AN E CARD DOES NOT READ THEM (IT READS COL 1)"),
    (with_cols(P, 69, "X"), 2, "69", "A P CARD DOES NOT READ THEM (IT READS COLS 1, 3-68, 70-71)"),
])
def test_name_end_and_p_cards_have_unread_columns_too(run_tenzor, text, cardno, cols, words):
    lines = deck(PAD).splitlines()
    lines[cardno - 1] = text
    proc, _ = run_tenzor("\n".join(lines) + "\n")
    err = proc.stderr.decode()
    assert proc.returncode == 0, err
    label = "COL" if "-" not in cols else "COLS"
    assert f"TENZOR WARNING CARD {cardno} {label} {cols}: NOT BLANK, BUT {words}" in err


def test_the_sequence_field_is_not_an_unread_column(run_tenzor):
    text = "\n".join(c.ljust(72) + "%08d" % (10 * i) for i, c in
                     enumerate(deck(PAD).splitlines(), 1)) + "\n"
    proc, _ = run_tenzor(text)
    assert proc.returncode == 0 and proc.stderr == b""


def test_strict_makes_the_warning_an_error_and_punches_nothing(run_tenzor):
    stray = with_cols(LINE, 41, "     65.00     44.00")
    proc, out = run_tenzor(deck(stray, PLUS), "--strict")
    err = proc.stderr.decode()
    assert proc.returncode == 1, err
    assert ("TENZOR ERROR CARD 3 COL 46: COLS 46-60 NOT BLANK, BUT AN L CARD DOES NOT "
            "READ THEM") in err
    assert "WARNING" not in err
    assert not list(out.glob("*.ptp"))
    proc, out = run_tenzor(deck(LINE, PLUS), "--strict")
    assert proc.returncode == 0 and proc.stderr == b""


def test_warnings_are_cut_at_fifty_a_package(run_tenzor):
    proc, out = run_tenzor(deck(*[with_cols(PAD, 2, "X")] * 60))
    err = proc.stderr.decode().splitlines()
    assert proc.returncode == 0
    assert len([e for e in err if "WARNING CARD" in e]) == 50
    assert err[-1].endswith("TOO MANY WARNINGS IN PACKAGE BOARD, ONLY THE FIRST 50 ARE LISTED")


def test_a_later_error_on_a_warned_card_shows_the_card_again(run_tenzor):
    bad = with_cols(card(c1="D", c11=f10("15.00")), 2, "X")       # no W: an error too
    proc, out = run_tenzor(deck(bad))
    assert proc.returncode == 1
    listing = (out / "BOARD.lst").read_text().splitlines()
    at = [i for i, l in enumerate(listing) if "PAD SIZE W IN COLS 31-38" in l][0]
    assert listing[at - 2].strip().startswith("3 DX")           # the card, then the caret


# ---- one rule in TENZOR and in the harness --------------------------------

FIELD_TEXT = st.sampled_from(["", "     12.50", "      1250", "  1.5     ", "12", "   x",
                              " 1 2", "    -0.01", "   7", "1.255"])


@st.composite
def name_cards(draw) -> str:
    """Cards as a deck without its name card would begin: a type letter, its
    fields filled (well or badly) or blank, its letters right or wrong, and
    now and then a character in a column the type does not read."""
    kind = draw(st.sampled_from("PDL+OAMX"))
    line = [" "] * 72
    line[0] = kind
    for a, b, _ in FIELDS.get(kind, ((11, 20, 2),)):
        if draw(st.booleans()):
            text = draw(FIELD_TEXT)[-(b - a + 1):]
            line[b - len(text):b] = list(text)
    for col, ok in LETTERS.get(kind, ()):
        line[col - 1] = draw(st.sampled_from(ok + "Q"))
    if draw(st.integers(0, 4)) == 0:
        line[draw(st.integers(2, 72)) - 1] = draw(st.sampled_from("X_9."))
    return "".join(line).rstrip()


@settings(max_examples=60, deadline=None)
@given(names=st.lists(name_cards(), min_size=1, max_size=30))
def test_tenzor_and_the_harness_agree_on_what_reads_as_a_data_card(tenzor_exe, names):
    """One job of many packages, each a candidate name card and an M card;
    TENZOR's error at a name card <=> the harness's reads_as_data."""
    lines, at = [], {}
    for i, name in enumerate(names):
        at[len(lines) + 1] = name
        lines += [name, MAN, "C" if i < len(names) - 1 else "E"]
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "names.crd"
        path.write_text("\n".join(lines) + "\n")
        proc = subprocess.run([str(tenzor_exe), str(path), "-o", str(Path(tmp) / "out")],
                              capture_output=True, timeout=120)
    err = proc.stderr.decode()
    assert proc.returncode in (0, 1), err
    said = {int(m) for m in re.findall(r"ERROR CARD (\d+) COL 1: THE NAME CARD READS AS A", err)}
    assert said == {n for n, c in at.items() if reads_as_data(c) is not None}


def test_the_messages_docs_cards_md_quotes_are_tenzors(run_tenzor):
    text = (Path(__file__).resolve().parents[3] / "docs" / "CARDS.md").read_text()
    quoted = [l for l in text.splitlines() if l.startswith("TENZOR ")]
    assert len(quoted) == 2
    proc, _ = run_tenzor(PAD + "\nE\n")
    assert quoted[0] in proc.stderr.decode()
    proc, _ = run_tenzor(deck(PAD, PAD, PAD, PAD, with_cols(LINE, 41, "     65.00     44.00"),
                              PLUS))
    assert quoted[1] in proc.stderr.decode()
