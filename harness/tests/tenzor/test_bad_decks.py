"""Bad decks: every fault is reported with its card and column, no tape of the
faulty package is written, the other packages are, and the exit status is 1.
Nothing a deck holds may crash TENZOR or leak a Fortran runtime message."""
from __future__ import annotations

import re

import subprocess

import pytest

from harness import tape
from harness.deck import CardError, parse_deck
from harness.tests.helpers import file_size_limit


def card(**cols: str) -> str:
    """A card image: card(c1='D', c11='     12.50') puts text at those columns."""
    line = [" "] * 80
    for key, text in cols.items():
        start = int(key[1:]) - 1
        line[start:start + len(text)] = list(text)
    return "".join(line).rstrip()


def f10(v: str) -> str:
    return v.rjust(10)


GOOD = "GOOD\n" + card(c1="M", c31=f10("1.00"), c56="   10") + "\nC\n"
NAME = "BAD\n"
P = card(c1="P", c11=f10("100.00"), c21=f10("100.00"))

# (id, the faulty package's cards after its name card, card number, column, message fragment)
# Card numbers count from 1 over the whole deck: GOOD is cards 1-3, BAD's name card is 4.
CASES = [
    ("malformed-number", [P, card(c1="M", c31="    1.2x5 ", c56="   10")], 6, 38,
     "DX IN COLS 31-40: 'x' IS NOT PART OF A NUMBER"),
    ("blank-inside", [P, card(c1="M", c31="   1 2.50 ", c56="   10")], 6, 35, "BLANK INSIDE"),
    ("not-right-justified", [P, card(c1="M", c31="1250      ", c56="   10")], 6, 35, "RIGHT-JUSTIFY"),
    ("third-decimal", [P, card(c1="M", c31="    1.255 ", c56="   10")], 6, 39, "MORE THAN 2 DECIMALS"),
    # a sign only leads the number: a trailing minus (an accounting habit) is
    # not a negative number, and ':' (the code after '9') is not a digit
    ("trailing-minus", [P, card(c1="M", c31="    12.00-", c56="   10")], 6, 40,
     "DX IN COLS 31-40: '-' IS NOT PART OF A NUMBER"),
    ("sign-inside", [P, card(c1="M", c31="    1-2.00", c56="   10")], 6, 36,
     "DX IN COLS 31-40: '-' IS NOT PART OF A NUMBER"),
    ("colon-after-nine", [P, card(c1="M", c31="     1:.00", c56="   10")], 6, 37,
     "DX IN COLS 31-40: ':' IS NOT PART OF A NUMBER"),
    ("bad-k", [P, card(c1="M", c31=f10("1.00"), c56="   15")], 6, 56, "K 15 IS NOT A COMMAND"),
    ("blank-k", [P, card(c1="M", c31=f10("1.00"))], 6, 60, "K IN COLS 56-60 IS BLANK"),
    ("cyc-one", [P, card(c1="M", c31=f10("1.00"), c51="    1", c56="   10")], 6, 51, "CYC MUST BE 2 OR MORE"),
    ("arc-off-circle", [P, card(c1="M", c11=f10("3.00"), c31=f10("-3.00"), c41=f10("-2.00"), c56="   13")],
     6, 31, "ARC END IS OFF ITS CIRCLE"),
    ("x-on-a-line", [P, card(c1="M", c11=f10("3.00"), c31=f10("1.00"), c56="   10")], 6, 11, "X IS FOR ARCS"),
    ("arc-without-radius", [P, card(c1="M", c31=f10("1.00"), c56="   11")], 6, 11, "AN ARC NEEDS X OR Y"),
    ("radius-over-10m", [P, card(c1="M", c11=f10("10000.01"), c56="   13")], 6, 11,
     "RADIUS OVER 10 M, THE LARGEST ARC OF THE MACHINE"),
    ("bad-tape-letter", [P, card(c1="M", c2="Q", c31=f10("1.00"), c56="   10")], 6, 2, "TAPE 'Q'"),
    ("cyc-on-last-frame", [P, card(c1="M", c31=f10("1.00"), c51="    3", c56="   10")], 6, 51,
     "CYC ON THE LAST M FRAME OF TAPE L"),
    ("line-too-long", [P, "M" + " " * 85], 6, 81, "A CARD HAS AT MOST 80 COLUMNS"),
    ("tab", [P, "M\t" + " " * 20], 6, 2, "TAB CHARACTER"),
    ("non-ascii", [P, "M  \u0416"], 6, 4, "IS NOT A CARD CHARACTER"),
    ("delete", [P, "M  \x7f"], 6, 4,
     "BYTE 127 IS NOT A CARD CHARACTER; EXPECTED PRINTABLE ASCII (32-126)"),
    ("unknown-type", [P, card(c1="Q")], 6, 1, "UNKNOWN CARD TYPE 'Q'"),
    ("lower-case-type", [P, card(c1="m", c31=f10("1.00"), c56="   10")], 6, 1, "LOWER CASE"),
    ("no-type", [P, card(c11=f10("1.00"))], 6, 1, "NO CARD TYPE IN COL 1"),
    ("second-p", [P, P], 6, 1, "SECOND P CARD"),
    ("p-after-geometry", [card(c1="M", c31=f10("1.00"), c56="   10"), P], 6, 1, "P CARD AFTER THE GEOMETRY"),
    ("scale-off-list", [card(c1="P", c11=f10("100.00"), c21=f10("100.00"), c63="  3", c66="  1")], 5, 63,
     "SCALE IS NOT ONE OF THE MACHINE'S"),
    ("start-off-field", [card(c1="P", c11=f10("1300.00"))], 5, 11, "OFF THE 1200 X 1200 MM FIELD"),
    ("zero-tool", [card(c1="P", c11=f10("10.00"), c21=f10("10.00"), c31="    0.00")], 5, 31, "TOOL W1"),
    ("bad-code-letter", [card(c1="P", c11=f10("10.00"), c21=f10("10.00"), c70="Q")], 5, 70, "TAPE CODE 'Q'"),
    ("bad-order-letter", [card(c1="P", c11=f10("10.00"), c21=f10("10.00"), c71="X")], 5, 71, "ORDER 'X'"),
    ("leaves-field", [card(c1="M", c31=f10("-1.00"), c56="   10")], 5, 31,
     "LEAVES THE 1200 X 1200 MM FIELD HERE (START 0.00, 0.00 MM, SCALE 1:1)"),
    ("leaves-field-at-scale", [card(c1="P", c11=f10("600.00"), c21=f10("600.00"), c63="100", c66="  1"),
                               card(c1="M", c31=f10("7.00"), c56="   10")], 6, 31, "SCALE 100:1"),
    ("pad-smaller-than-tool", [P, card(c1="D", c11=f10("1.00"), c21=f10("1.00"), c31="    0.30")], 6, 31,
     "PAD SIZE 0.30 MM IS SMALLER THAN TOOL W1 0.50 MM"),
    ("rect-pad-too-thin", [P, card(c1="D", c31="    1.00", c39="    0.40")], 6, 39, "SMALLER THAN TOOL W1"),
    ("row-without-step", [P, card(c1="D", c31="    1.00", c47="   4")], 6, 51, "A ROW OF N PADS NEEDS A STEP"),
    ("row-of-two-without-step", [P, card(c1="D", c31="    1.00", c47="   2")], 6, 51,
     "A ROW OF N PADS NEEDS A STEP"),
    # a pad's size is the larger of W and H: 0.60 x 3.00 mm is a large pad
    # (DMAX 2.00), drawn with W2 = 1.00 mm, which is wider than it
    ("tall-pad-thinner-than-w2", [P, card(c1="D", c31="    0.60", c39="    3.00")], 6, 31,
     "PAD SIZE 0.60 MM IS SMALLER THAN TOOL W2 1.00 MM OF THE LARGE-PAD TAPE"),
    ("pad-without-size", [P, card(c1="D", c11=f10("1.00"))], 6, 31, "PAD SIZE W IN COLS 31-38"),
    ("plus-without-l", [P, card(c1="+", c11=f10("1.00"))], 6, 1, "+ CARD WITH NO CONDUCTOR OPEN"),
    ("zero-length-conductor", [P, card(c1="L", c11=f10("1.00")), card(c1="+", c11=f10("1.00"))], 6, 11,
     "ZERO-LENGTH CONDUCTOR"),
    ("lonely-l", [P, card(c1="L", c11=f10("1.00"))], 6, 11, "ZERO-LENGTH CONDUCTOR"),
    ("narrow-conductor", [P, card(c1="L", c31="    0.20"), card(c1="+", c11=f10("5.00"))], 6, 31,
     "NARROWER THAN TOOL W3"),
    ("circle-without-direction", [P, card(c1="O", c31=f10("2.00"))], 6, 2, "DIRECTION ' '"),
    ("circle-radius-zero", [P, card(c1="O", c2="+", c31=f10("0.00"))], 6, 31, "RADIUS R IN COLS 31-40"),
    ("circle-too-big", [P, card(c1="O", c2="+", c31=f10("10000.01"))], 6, 31,
     "RADIUS OVER 10 M, THE LARGEST ARC OF THE MACHINE; DRAW IT AS CONDUCTORS (L, +)"),
    ("arc-card-off-circle", [P, card(c1="A", c2="+", c31=f10("5.00"), c51=f10("0.00"), c61=f10("5.02"))],
     6, 51, "ARC END IS OFF ITS CIRCLE"),
    ("arc-start-is-end", [P, card(c1="A", c2="+", c31=f10("5.00"), c51=f10("5.00"))], 6, 51,
     "ENDS WHERE IT STARTS"),
    # found by fuzzing: radius 0.01 mm, end at the centre, within the tolerance; drawn
    # from that end it would be an arc without X or Y
    ("arc-end-is-centre", [P, card(c1="A", c2="+", c31=f10("0.01"))], 6, 51,
     "THE END OF THE ARC IS ITS CENTRE"),
    ("coordinate-beyond-any-field", [P, card(c1="D", c11=f10("130000.00"), c31="    1.00")], 6, 11,
     "OFF THE FIELD AT EVERY SCALE"),
    ("ten-digits", [P, card(c1="D", c11="9999999999", c31="    1.00")], 6, 11,
     "X IN COLS 11-20: NUMBER TOO LARGE; AT MOST 9999999.99"),
    # nine digits are a number however the point splits them: 9999999.9 is
    # 9999999.90 mm (off the field), not too large to read
    ("nine-digits-one-decimal", [P, card(c1="D", c11=" 9999999.9", c31="    1.00")], 6, 11,
     "X IS MORE THAN 120000.00 MM FROM THE START POINT: OFF THE FIELD AT EVERY SCALE"),
    ("ten-digits-one-decimal", [P, card(c1="D", c11="10000000.0", c31="    1.00")], 6, 11,
     "X IN COLS 11-20: NUMBER TOO LARGE; AT MOST 9999999.99"),
    ("pad-beyond-any-field", [P, card(c1="D", c11=f10("10.00"), c31="99999999")], 6, 31,
     "W IS MORE THAN 120000.00 MM: LARGER THAN THE FIELD AT EVERY SCALE"),
    ("control-card-inside", [P, "*NAME X"], 6, 1, "CONTROL CARD INSIDE A PACKAGE"),
]


def _deck(cards: list[str], end: str = "E") -> str:
    return GOOD + NAME + "\n".join(cards) + f"\n{end}\n"


@pytest.mark.parametrize("cards,cardno,col,fragment", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_bad_card_is_reported_and_stops_only_its_package(run_tenzor, cards, cardno, col, fragment):
    proc, out = run_tenzor(_deck(cards))
    err = proc.stderr.decode()
    assert proc.returncode == 1, err
    assert f"ERROR CARD {cardno} COL {col}: " in err, err
    assert fragment in err, err
    assert "Fortran runtime" not in err and "Backtrace" not in err
    if "LEAVES THE" in fragment:            # and what would be right
        assert f"{fragment}; MOVE THE START POINT (X0, Y0 OF THE P CARD) OR TAKE A " \
               "SMALLER SCALE" in err, err
    # the good package is punched, the bad one has a listing and nothing else
    assert (out / "GOOD-cond.ptp").exists()
    assert sorted(p.name for p in out.glob("BAD*")) == ["BAD.lst"]
    assert not list(out.glob(".*")), "temporary files left behind"
    listing = (out / "BAD.lst").read_text()
    assert fragment in listing
    assert "NO TAPES PUNCHED" in listing
    # the listing shows a caret under the column of the fault
    lines = listing.splitlines()
    at = next(i for i, line in enumerate(lines) if f"ERROR CARD {cardno} COL {col}" in line)
    assert lines[at - 1].rstrip().endswith("^") and len(lines[at - 1].rstrip()) == 9 + col


#: The faults the oracle's reader leaves to the tapes: whether the drawing
#: stays on the machine's field, which verify checks on the tapes TENZOR
#: punches, not on the cards.
THE_MACHINES = {"leaves-field", "leaves-field-at-scale", "coordinate-beyond-any-field",
                "pad-beyond-any-field", "nine-digits-one-decimal"}


def test_the_oracle_refuses_each_bad_card_at_the_same_card():
    """harness/deck.py, an independent reader, refuses every card TENZOR
    refuses above, naming the same card: but the machine's own limits."""
    wrong = []
    for name, cards, cardno, _, _ in CASES:
        try:
            parse_deck(_deck(cards))
            if name not in THE_MACHINES:
                wrong.append((name, "taken"))
        except CardError as exc:
            if name in THE_MACHINES or exc.card != cardno:
                wrong.append((name, str(exc)))
    assert wrong == []


def test_missing_e_card(run_tenzor):
    proc, out = run_tenzor(GOOD + NAME + P + "\n")
    err = proc.stderr.decode()
    assert proc.returncode == 1
    assert "THE DECK ENDS WITHOUT THE E CARD" in err
    assert sorted(p.name for p in out.glob("BAD*")) == ["BAD.lst"]
    assert (out / "GOOD-cond.ptp").exists()


def test_main_naming_another_program_refuses_the_job(run_tenzor):
    deck = "*NAME JOB\n*MAIN OTHER\n*EXECUTE\n" + GOOD.replace("C\n", "E\n")
    proc, out = run_tenzor(deck)
    err = proc.stderr.decode()
    assert proc.returncode == 1
    assert re.search(r"ERROR CARD 2 COL \d+: \*MAIN NAMES OTHER", err), err
    assert not list(out.glob("*.ptp")), "no tapes when the envelope is wrong"
    assert "NO TAPES ARE PUNCHED" in (out / "GOOD.lst").read_text()


@pytest.mark.parametrize("deck,fragment", [
    ("", "THE DECK HOLDS NO PACKAGE"),
    ("\n\n   \n", "THE DECK HOLDS NO PACKAGE"),
    ("*NAME X\n*EXECUTE\n", "NO PACKAGE AFTER *EXECUTE"),
    ("*NAME X\n*EXECUTE\n*END FILE\n", "CARD 3 COL 1: NO PACKAGE AFTER *EXECUTE"),
    (GOOD + "E\n", "CARD 4 COL 1: A BARE E WHERE A NAME CARD IS DUE; END THE PACKAGE BEFORE"),
    (GOOD + "C\n" + GOOD.replace("GOOD", "TWO").replace("C\n", "E\n"),
     "CARD 4 COL 1: A BARE C WHERE A NAME CARD IS DUE"),
    (GOOD, "ENDED WITH C BUT NO PACKAGE FOLLOWS"),
    (GOOD.replace("C\n", "E\n") + "MORE\n", "CARD AFTER THE FINAL E CARD"),
    ("*NAME X\nGOOD\nE\n", "DATA BEFORE *EXECUTE"),
    ("*WHAT\n*EXECUTE\nGOOD\nE\n", "UNKNOWN CONTROL CARD"),
])
def test_deck_level_faults(run_tenzor, deck, fragment):
    proc, out = run_tenzor(deck)
    assert proc.returncode == 1
    assert fragment in proc.stderr.decode()
    if "A BARE" in fragment:        # one error, no package named C or E
        assert proc.stderr.decode().count("TENZOR ERROR") == 1
        assert not list(out.glob("[CE].lst"))
        with pytest.raises(CardError, match="card 4: a bare"):
            parse_deck(deck)


def test_a_card_with_only_a_sequence_number_is_a_blank_card(run_tenzor):
    """Columns 73-80 are never read: a card holding only its sequence number
    is skipped wherever it stands (before *EXECUTE, where a name card is
    due, inside a conductor, after E), and the tapes are those of the deck
    without it."""
    seq = " " * 72 + "SEQ00030"
    conductor = [card(c1="L", c11=f10("5.00"), c21=f10("5.00")), seq,
                 card(c1="+", c11=f10("25.00"), c21=f10("5.00"))]
    plain = "\n".join(["*NAME X", "*EXECUTE", "T", P, *conductor, "E"]) + "\n"
    plain = plain.replace(seq + "\n", "")
    holed = "\n".join([seq, "*NAME X", "*EXECUTE", seq, "T", P, *conductor, "E", seq]) + "\n"
    want, want_out = run_tenzor(plain)
    assert want.returncode == 0, want.stderr.decode()
    got, got_out = run_tenzor(holed)
    assert (got.returncode, got.stderr) == (0, b"")
    for name in ("T-small.ptp", "T-large.ptp", "T-cond.ptp"):
        assert (got_out / name).read_bytes() == (want_out / name).read_bytes()
    assert b"DX2000 K10" in (got_out / "T-cond.txt").read_bytes()   # one line, 20 mm


@pytest.mark.parametrize("first, listing, column", [
    ("\ufeffBOARD", "___BOARD.lst", 1),                      # a byte-order mark
    ("BOARD" + "X" * 76, "BOARDXXXXXXXXXXXXX.lst", 81),       # 81 columns
    ("*EXECUTE\nBO\tARD", "BO_ARD.lst", 3),                  # a tab, after *EXECUTE
])
def test_a_faulty_name_card_is_still_the_name_card(run_tenzor, first, listing, column):
    """A name card with a bad byte is refused, once: its package opens under
    it (and is not punched), and the next card is read as data, not taken
    for the name (which gave a second error, and a listing named after a
    D card)."""
    proc, out = run_tenzor(f"{first}\nD               5.00      5.00    1.60\nE\n")
    err = proc.stderr.decode()
    assert proc.returncode == 1 and err.count("TENZOR ERROR") == 1, err
    assert f" COL {column}: " in err and "READS AS A D CARD" not in err, err
    assert sorted(p.name for p in out.iterdir()) == [listing]


def test_an_envelope_beyond_its_table_is_one_error(run_tenzor):
    """The 21st control card is refused (MXENV), once, not again for each
    card after it; the listing's heading shows the first 20."""
    deck = "*NAME J\n" + "*TIME 1\n" * 25 + "*EXECUTE\n" + GOOD.replace("C\n", "E\n")
    proc, out = run_tenzor(deck)
    err = proc.stderr.decode()
    assert proc.returncode == 1
    assert err.count("(PARAMETER MXENV)") == 1 and "ERROR CARD 21 COL 1: CAPACITY" in err, err
    assert "MORE THAN 20 CONTROL CARDS IN THE JOB ENVELOPE (PARAMETER MXENV)" in err, err
    assert (out / "GOOD.lst").read_text().count(" ENVELOPE *TIME 1") == 19


def test_duplicate_package_names_keep_both_listings(run_tenzor):
    deck = GOOD + GOOD.replace("C\n", "E\n")
    proc, out = run_tenzor(deck)
    assert proc.returncode == 1
    assert ("PACKAGE NAME GOOD IS ALREADY USED IN THIS JOB (A NAME USED AGAIN IS FILED AS "
            "NAME-2, -3, ...)") in proc.stderr.decode()
    assert (out / "GOOD.lst").exists() and (out / "GOOD-2.lst").exists()
    assert not (out / "GOOD-2-cond.ptp").exists()


def test_package_names_that_differ_only_in_case_are_duplicates(run_tenzor):
    """On a file system that folds case (macOS, Windows) GOOD and good would
    be one file: the second is a duplicate, its listing good-2.lst is beside
    the first package's files, and it punches nothing."""
    deck = GOOD + GOOD.replace("C\n", "E\n").replace("GOOD\n", "good\n", 1)
    proc, out = run_tenzor(deck)
    assert proc.returncode == 1
    assert "PACKAGE NAME GOOD IS ALREADY USED" in proc.stderr.decode()
    assert sorted(p.name for p in out.glob("*.lst")) == ["GOOD.lst", "good-2.lst"]
    assert sorted(p.name for p in out.glob("good*")) == ["good-2.lst"]


def test_blank_name_card_is_an_error(run_tenzor):
    deck = card(c20="X") + "\n" + card(c1="M", c31=f10("1.00"), c56="   10") + "\nE\n"
    proc, out = run_tenzor(deck)
    assert proc.returncode == 1
    assert "THE NAME CARD IS BLANK IN COLS 1-18" in proc.stderr.decode()
    assert (out / "PACKAGE.lst").exists()


def test_too_many_errors_are_cut_at_fifty(run_tenzor):
    cards = [P] + [card(c1="Q")] * 70
    proc, out = run_tenzor(_deck(cards))
    err = proc.stderr.decode()
    assert err.count("UNKNOWN CARD TYPE") == 50
    assert "TOO MANY ERRORS" in err
    assert "TOO MANY ERRORS" in (out / "BAD.lst").read_text()


def test_capacity_of_m_cards_is_named(run_tenzor):
    cards = [P] + [card(c1="M", c31=f10("0.01"), c56="   10")] * 20001
    proc, _ = run_tenzor(_deck(cards))
    assert proc.returncode == 1
    assert "(PARAMETER MXMAN)" in proc.stderr.decode()


def test_failed_package_leaves_earlier_good_tapes_untouched(run_tenzor, tmp_path):
    out = tmp_path / "keep"
    good = "BAD\n" + P + "\n" + card(c1="M", c31=f10("1.00"), c56="   10") + "\nE\n"
    proc, _ = run_tenzor(good, out=out)
    assert proc.returncode == 0
    before = (out / "BAD-cond.ptp").read_bytes()
    proc, _ = run_tenzor(_deck([P, card(c1="Q")]), out=out)
    assert proc.returncode == 1
    assert (out / "BAD-cond.ptp").read_bytes() == before
    assert tape.decode(before).frames[0] == tape.Frame(dx=100, k=10)
    assert "EARLIER TAPES OF THIS NAME, IF ANY, ARE LEFT AS THEY WERE" in (out / "BAD.lst").read_text()


def _snapshot(out):
    return {p.name: (p.read_bytes() if p.is_file() else None) for p in sorted(out.iterdir())}


def test_failed_write_mid_package_leaves_earlier_files_untouched(tenzor_exe, tmp_path):
    """A write that fails part-way through the package (files may not grow
    past 2 000 bytes: the listing's write fails, as on a full disk): no file
    of the package changes, no temporary file is left, and both standard
    error and standard output say so."""
    out = tmp_path / "keep"
    deck = tmp_path / "deck.crd"
    good = "BAD\n" + P + "\n" + card(c1="M", c31=f10("1.00"), c56="   10") + "\nE\n"
    deck.write_text(good)
    assert subprocess.run([str(tenzor_exe), str(deck), "-o", str(out)]).returncode == 0
    before = _snapshot(out)
    deck.write_text(good.replace("1.00", "2.00"))
    proc = subprocess.run([str(tenzor_exe), str(deck), "-o", str(out)], capture_output=True,
                          preexec_fn=file_size_limit(2000), restore_signals=False,
                          timeout=60)
    assert proc.returncode == 2
    err = proc.stderr.decode()
    assert f"tenzor: cannot write {out}/BAD.lst: File too large" in err
    assert "BAD: no file written; earlier files of this name are left as they were" in err
    assert "BAD: cannot write its files; earlier files of this name are left as they were" \
        in proc.stdout.decode()
    assert _snapshot(out) == before, "a file of the failed package changed"
    assert "Fortran runtime" not in err


def test_a_link_planted_in_the_output_directory_is_not_followed(run_tenzor, tmp_path):
    """Symbolic links planted under every name a temporary file could take in
    an older version, and a dot file of each output: TENZOR writes through
    none of them; the files they point to keep their bytes."""
    out = tmp_path / "keep"
    out.mkdir()
    victim = tmp_path / "victim"
    victim.write_text("precious")
    for name in ["BAD.lst", "BAD-small.ptp", "BAD.job"]:
        (out / f".{name}.tmp").symlink_to(victim)
    good = "BAD\n" + P + "\n" + card(c1="M", c31=f10("1.00"), c56="   10") + "\nE\n"
    proc, _ = run_tenzor(good, out=out)
    assert proc.returncode == 0, proc.stderr
    assert victim.read_text() == "precious"
    assert (out / "BAD-small.ptp").is_file() and not (out / "BAD-small.ptp").is_symlink()


def test_directory_in_the_way_leaves_earlier_files_untouched(run_tenzor, tmp_path):
    """A directory under the name of one of the package's files: nothing of the
    package is renamed into place (the listing neither), and the directory
    is left alone."""
    out = tmp_path / "keep"
    good = "BAD\n" + P + "\n" + card(c1="M", c31=f10("1.00"), c56="   10") + "\nE\n"
    assert run_tenzor(good, out=out)[0].returncode == 0
    (out / "BAD.job").unlink()
    (out / "BAD.job").mkdir()
    (out / "BAD.job" / "inside").write_text("x")
    before = _snapshot(out)
    proc, _ = run_tenzor(good.replace("1.00", "2.00"), out=out)
    assert proc.returncode == 2
    assert "BAD.job: a directory has that name" in proc.stderr.decode()
    assert _snapshot(out) == before
    assert (out / "BAD.job" / "inside").read_text() == "x"
    assert not list(out.glob(".*.tmp"))


def test_a_good_package_after_a_failed_write_is_still_punched(run_tenzor, tmp_path):
    out = tmp_path / "o"
    out.mkdir()
    (out / "FIRST.lst").mkdir()
    deck = ("FIRST\n" + card(c1="M", c31=f10("1.00"), c56="   10") + "\nC\n"
            "SECOND\n" + card(c1="M", c31=f10("1.00"), c56="   10") + "\nE\n")
    proc, _ = run_tenzor(deck, out=out)
    assert proc.returncode == 2
    assert (out / "SECOND-cond.ptp").exists()
    assert not list(out.glob("FIRST-*"))


def test_a_long_message_is_wrapped_in_the_listing_at_a_blank(run_tenzor):
    """The listing's lines are at most 128 columns: a longer message goes on
    under it, broken between words (it was cut inside one: "START PO" /
    "INT"), and reads, joined, as standard error gives it."""
    cards = [card(c1="M", c31=f10("-1.00"), c56="   10")]
    proc, out = run_tenzor(_deck(cards))
    said = next(line for line in proc.stderr.decode().splitlines() if "LEAVES THE" in line)
    message = said[said.index("TENZOR ERROR"):]
    lines = (out / "BAD.lst").read_text().splitlines()
    at = next(i for i, line in enumerate(lines) if line.startswith(" *** TENZOR ERROR"))
    wrapped = [lines[at][5:]]
    while lines[at + len(wrapped)].startswith("     ") and lines[at + len(wrapped)].strip():
        wrapped.append(lines[at + len(wrapped)][5:])
    assert len(wrapped) >= 2 and all(len(line) <= 128 for line in lines)
    assert " ".join(wrapped) == message
