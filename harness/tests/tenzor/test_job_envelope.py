"""The job envelope (docs/CARDS.md): TENZOR and the oracle's deck reader
(harness/deck.py) take the same control cards, the report's own job deck
among them, and refuse the same, each naming the card."""
from __future__ import annotations

import re

import pytest

from harness.deck import CardError, parse_deck

PACKAGE = "T\nD               5.00      5.00    1.60\nE\n"

#: The report's job deck ("Пакет задачи") as its reproduction prints it: # for
#: *, _ for a blank, lower case; the X's are its own placeholders.
REPORT = ["#name _XXXXXXXXXXXXXXXXXXXX", "#time:xx.xx", "#pass _XXXXXX",
          "#tape:xxx - XXXXXX , 67,R", "#perso: 67000", "#main _TENZOR", "#no _load _list",
          "#call _ficmemory", "#execute"]

# (control card before *EXECUTE, taken?): blanks and _ do not count; NAME,
# TIME, PASS, TAPE, PERSO, MAIN and CALL take an argument, the others none.
CARDS = [
    ("*NO LOAD LIST", True), ("*NOLOADLIST", True), ("* no_load _list", True),
    ("*TIME:00.05", True), ("*TIMER", True), ("*CALL FICMEMORY", True),
    ("*CALL OTHER", True), ("*MAIN:TENZOR", True), ("*MAINTENZOR", True),
    ("*MAIN  TENZOR" + " " * 59 + "SEQ00001", True),
    ("*NO LOAD LIST X", False), ("*EXECUTEX", False), ("*MAIN TENZOR XYZ", False),
    ("*MAIN", False), ("*MAIN OTHER", False), ("*FOO", False), ("*", False),
]


def _harness_takes(deck: str) -> bool:
    try:
        parse_deck(deck)
    except CardError:
        return False
    return True


def test_the_reports_own_job_deck_is_read_by_both(run_tenzor) -> None:
    deck = "\n".join(REPORT) + "\n" + PACKAGE + "#end _file\n"
    proc, out = run_tenzor(deck)
    assert (proc.returncode, proc.stderr) == (0, b""), proc.stderr.decode()
    assert (out / "T-small.ptp").exists()
    assert "XXXXXXXXXXXXXXXXXXXX" in (out / "T.lst").read_text()
    assert [p.name for p in parse_deck(deck)] == ["T"]


@pytest.mark.parametrize("control, taken", CARDS, ids=[c for c, _ in CARDS])
def test_a_control_card_is_taken_or_refused_by_both(run_tenzor, control, taken) -> None:
    deck = f"*NAME J\n{control}\n*EXECUTE\n{PACKAGE}"
    proc, out = run_tenzor(deck)
    err = proc.stderr.decode()
    assert (proc.returncode == 0) == taken, err
    assert _harness_takes(deck) == taken
    if not taken:                   # named by its card, and no tape punched
        assert re.search(r"TENZOR ERROR CARD 2 COL \d+: ", err), err
        assert not list(out.glob("*.ptp"))


@pytest.mark.parametrize("control, column, words", [
    ("*EXECUTEX", 2, "UNKNOWN CONTROL CARD; EXPECTED NAME, TIME"),
    ("*MAIN", 6, "*MAIN NAMES NO PROGRAM; THIS SUBSYSTEM RUNS *MAIN TENZOR"),
    ("*MAIN:", 6, "*MAIN NAMES NO PROGRAM"),
    ("*MAIN  OTHER", 8, "*MAIN NAMES OTHER; THIS SUBSYSTEM RUNS *MAIN TENZOR"),
])
def test_a_refused_control_card_names_its_column(run_tenzor, control, column, words) -> None:
    proc, _ = run_tenzor(f"*NAME J\n{control}\n*EXECUTE\n{PACKAGE}")
    assert f"TENZOR ERROR CARD 2 COL {column}: {words}" in proc.stderr.decode()


@pytest.mark.parametrize("end", ["*END FILE\t", "*END FILE" + " " * 71 + "X"])
@pytest.mark.parametrize("e_card", ["E\n", ""])
def test_a_faulty_end_file_card_still_ends_the_deck(run_tenzor, end, e_card) -> None:
    """Its fault is reported, and nothing after it is read (the garbage
    after it is no second error)."""
    deck = f"ONE\nD               5.00      5.00    0.50\n{e_card}{end}\nGARBAGE\n"
    proc, _ = run_tenzor(deck)
    err = proc.stderr.decode()
    assert proc.returncode == 1
    assert "GARBAGE" not in err and "CARD 5" not in err and "UNKNOWN CARD TYPE" not in err, err
    assert err.count("TENZOR ERROR") == (1 if e_card else 2), err
