"""`python -m seeds tapereport`: its figures against TENZOR's own job sheet
and against a drilling tour worked out by hand, and a message naming the
file and the line, card or row for every job sheet, tape or deck it cannot
use (docs/GERBER.md)."""
from __future__ import annotations

import contextlib
import io
import math
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from seeds.__main__ import main
from seeds.tests.test_gerber_roundtrip import BOARDS, board_run

ROOT = Path(__file__).resolve().parents[2]

# A board of two pads and a conductor, and its drill package: holes of 0.80
# and 1.20 mm (small tape, up to DMAX 2.00) and one of 3.00 mm (large tape).
DECK = """\
*NAME TAPEREPORT
*MAIN TENZOR
*EXECUTE
BOARD
P              10.00     10.00    0.40    0.40    0.40    2.00
D               5.00      5.00    1.60           2     15.00      0.00
L               5.00      5.00    0.40
+              20.00      5.00
C
BOARD-DRILL
P              10.00     10.00    0.80    0.80    0.80    2.00
D              10.00     10.00    0.80
D              40.00     10.00    3.00
D              40.00     30.00    1.20
E
*END FILE
"""
#: The drill file's own order, from the start point and back, by hand:
#: small tape 0 -> (10, 10) -> (40, 30) -> 0, large tape 0 -> (40, 10) -> 0.
OWN_MM = math.hypot(10, 10) + math.hypot(30, 20) + 50 + 2 * math.hypot(40, 10)
#: The card number of the drill package's second D card in DECK.
SECOND_HOLE = 13


@pytest.fixture(scope="module")
def punched(tmp_path_factory, tenzor_exe) -> Path:
    """A folder with DECK (board.crd) and TENZOR's files for it (out/)."""
    here = tmp_path_factory.mktemp("tapereport")
    (here / "board.crd").write_text(DECK, encoding="ascii")
    tz = subprocess.run([str(tenzor_exe), "board.crd", "-o", "out"], cwd=here,
                        capture_output=True, text=True, timeout=120)
    assert tz.returncode == 0, tz.stderr
    return here


@pytest.fixture
def copy(punched, tmp_path) -> Path:
    """A copy of ``punched`` the test may break."""
    shutil.copytree(punched, tmp_path / "c")
    return tmp_path / "c"


def report(here: Path, *argv: str) -> tuple[int, str, str]:
    """(status, standard output, standard error) of tapereport run in the
    folder ``here`` (so that its messages name the files as given)."""
    out, err, cwd = io.StringIO(), io.StringIO(), os.getcwd()
    os.chdir(here)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            status = main(["tapereport", *argv])
    finally:
        os.chdir(cwd)
    assert status in (0, 1, 2)
    assert not status or err.getvalue().startswith("tapereport: "), err.getvalue()
    return status, out.getvalue(), err.getvalue()


def sheet(path: Path) -> dict[str, str]:
    return dict(ln.split(" = ", 1) for ln in path.read_text(encoding="ascii").splitlines()
                if " = " in ln and not ln.startswith("#"))


def test_each_tape_line_agrees_with_tenzors_own_figures(punched):
    """The harness's decoder and simulator, run on the tapes, give the frames,
    rows, drawn length, travel and minutes TENZOR recorded for them."""
    status, out, _ = report(punched, "out/BOARD.job")
    assert status == 0
    lines = out.splitlines()
    assert len(lines) == 7, out               # three tapes each, then the tour
    row = re.compile(r"^(\S+) (small|large|cond ): +(\d+) frames, +([\d.]+) m of tape, +"
                     r"([\d.]+) min \(drawn +([\d.]+) m, travel +([\d.]+) m, tool (\S+) mm\)$")
    for line in lines[:6]:
        m = row.match(line)
        assert m, line
        name, t, frames, metres, minutes, drawn, travel, tool = m.groups()
        job = sheet(punched / "out" / f"{name}.job")
        t = t.strip()
        assert int(frames) == int(job[f"{t}.frames"])
        assert metres == f"{int(job[f'{t}.rows']) * 2.54 / 1000:.2f}"
        assert minutes == job[f"{t}.minutes"]
        assert abs(float(drawn) - float(job[f"{t}.drawn_mm"]) / 1000) <= 0.0051
        assert abs(float(travel) - float(job[f"{t}.travel_mm"]) / 1000) <= 0.0051
        assert tool == job[f"{t}.tool_mm"]
    assert [ln.split()[0] for ln in lines[:6]] == ["BOARD"] * 3 + ["BOARD-DRILL"] * 3
    assert lines[6] == ("BOARD-DRILL drilling: travel in TENZOR's order "
                        f"{_tenzor_mm(punched) / 1000:.2f} m (give --deck for the drill "
                        "file's order)")


def _tenzor_mm(punched: Path) -> float:
    job = sheet(punched / "out" / "BOARD-DRILL.job")
    return float(job["small.travel_mm"]) + float(job["large.travel_mm"])


@pytest.mark.parametrize("job", ["out/BOARD.job", "out/BOARD-DRILL.job"])
def test_the_drilling_tour_against_the_drill_files_order(punched, job):
    """Given the deck, the tour's line has the drill file's own order worked
    out by hand; the job sheet of the copper package or of its NAME-DRILL
    package (README's form) gives the same line."""
    from seeds.tapereport import own_order_travel
    holes, own = own_order_travel(punched / "board.crd", "BOARD-DRILL")
    assert holes == 3 and abs(own - OWN_MM) < 1e-9
    tenzor = _tenzor_mm(punched)
    status, out, err = report(punched, job, "--deck", "board.crd")
    assert status == 0 and not err
    ratio = OWN_MM / tenzor
    than = (f"{ratio:.1f} times shorter" if ratio >= 1.5
            else f"TENZOR's is {100 * (1 - 1 / ratio):.0f} % shorter" if ratio >= 1
            else f"TENZOR's is {100 * (1 / ratio - 1):.0f} % longer")
    assert out.splitlines()[-1] == (
        f"BOARD-DRILL drilling: 3 holes; travel in the drill file's order "
        f"{OWN_MM / 1000:.2f} m, in TENZOR's order {tenzor / 1000:.2f} m ({than})")


def test_a_hole_of_dmax_is_on_the_small_tape(tmp_path):
    """A pad of exactly DMAX goes on the small-pad tape (docs/CARDS.md: "at
    most DMAX"), so the drill file's order visits a 2.00 mm hole on the small
    tape and a 2.01 mm one on the large: 0 -> (10, 10) -> 0 and
    0 -> (40, 10) -> 0."""
    from seeds.tapereport import own_order_travel
    deck = tmp_path / "d.crd"
    deck.write_text("X-DRILL\n"
                    "P              10.00     10.00    0.80    0.80    0.80    2.00\n"
                    "D              10.00     10.00    2.00\n"
                    "D              40.00     10.00    2.01\n"
                    "E\n", encoding="ascii")
    holes, own = own_order_travel(deck, "X-DRILL")
    assert holes == 2 and own == pytest.approx(2 * math.hypot(10, 10) + 2 * math.hypot(40, 10))


def test_a_deck_without_a_drill_package_beside_is_said(copy):
    (copy / "out" / "BOARD-DRILL.job").unlink()
    status, out, err = report(copy, "out/BOARD.job", "--deck", "board.crd")
    assert status == 0 and len(out.splitlines()) == 3
    assert "no BOARD-DRILL.job beside out/BOARD.job" in err and "--deck not used" in err


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_text(encoding="latin-1")
    assert old in text, (path, old)
    path.write_text(text.replace(old, new, 1), encoding="latin-1")


# (what is broken, how, exit status, words of the message)
BROKEN = [
    ("no job sheet", lambda c: (c / "out" / "BOARD.job").unlink(), 2,
     "out/BOARD.job: No such file or directory"),
    ("a line that is no key", lambda c: _edit(c / "out" / "BOARD.job", "code = 8", "code 8"), 2,
     "out/BOARD.job: line 4: not a \"key = value\" line"),
    ("no name", lambda c: _edit(c / "out" / "BOARD.job", "name = BOARD\n", ""), 2,
     "out/BOARD.job: the job sheet has no \"name = ...\" line"),
    ("a name with a path", lambda c: _edit(c / "out" / "BOARD-DRILL.job", "name = BOARD-DRILL",
                                           "name = ../x"), 2,
     "out/BOARD-DRILL.job: line 2: name '../x' is not a package's name"),
    ("a tape elsewhere", lambda c: _edit(c / "out" / "BOARD.job", "small.tape = BOARD-small.ptp",
                                         "small.tape = ../board.crd"), 2,
     "small.tape must name a file beside the job sheet, not '../board.crd'"),
    ("no tool", lambda c: _edit(c / "out" / "BOARD.job", "cond.tool_mm = 0.40\n", ""), 2,
     "the job sheet has no \"cond.tool_mm = ...\" line"),
    ("a tool of nan", lambda c: _edit(c / "out" / "BOARD.job", "large.tool_mm = 0.40",
                                      "large.tool_mm = nan"), 2,
     "large.tool_mm must be a tool width in mm (above 0, at most 1200, two decimals), "
     "not 'nan'"),
    ("a tape missing", lambda c: (c / "out" / "BOARD-large.ptp").unlink(), 2,
     "out/BOARD-large.ptp: No such file or directory (the large tape of out/BOARD.job)"),
    ("a tape of another run", lambda c: (c / "out" / "BOARD-cond.ptp").write_bytes(
        (c / "out" / "BOARD-DRILL-cond.ptp").read_bytes()), 1,
     "out/BOARD-cond.ptp: not the file the job sheet out/BOARD.job records"),
    ("a tape that breaks the code", lambda c: (
        _edit(c / "out" / "BOARD.job", "small.sha256", "small.sha256x"),
        _edit(c / "out" / "BOARD.job", "small.bytes", "small.bytesx"),
        (c / "out" / "BOARD-small.ptp").write_bytes(b"\x00" * 20 + b"\x1f\x1f\x1f")), 1,
     "out/BOARD-small.ptp: row "),
    ("a deck without the package", lambda c: _edit(c / "board.crd", "BOARD-DRILL\n",
                                                  "BOARD-DRILLED\n"), 1,
     "board.crd: no package named BOARD-DRILL"),
    ("a bad card in it", lambda c: _edit(c / "board.crd", "D              40.00     10.00    3.00",
                                        "D              40.00     10.00    3.0x"), 1,
     f"board.crd: card {SECOND_HOLE}: columns 31-38: not a number: '    3.0x' "
     "(package BOARD-DRILL)"),
    ("a byte not ASCII in it", lambda c: _edit(c / "board.crd", "D              40.00     10.00",
                                              "D              40.00     1\xff.00"), 1,
     f"board.crd: card {SECOND_HOLE}, column 27: byte 0xff is not ASCII: not a card deck"),
    ("no end card after it", lambda c: _edit(c / "board.crd", "E\n*END FILE\n", ""), 1,
     "board.crd: card 10: package BOARD-DRILL has no C or E card after it"),
    ("a directory for the deck", lambda c: ((c / "board.crd").unlink(),
                                            (c / "board.crd").mkdir()), 2,
     "board.crd: Is a directory"),
]


@pytest.mark.parametrize("what,breaking,status,words", BROKEN, ids=[b[0] for b in BROKEN])
def test_what_it_cannot_use_is_named(copy, what, breaking, status, words):
    breaking(copy)
    got, out, err = report(copy, "out/BOARD.job", "--deck", "board.crd")
    assert (got, words in err) == (status, True), err
    assert err.count("\n") == 1 and not out.strip(), (out, err)


@pytest.mark.parametrize("tool, status", [("1200.00", 0), ("1200", 0), ("1200.01", 2),
                                          ("0.01", 0), ("0.00", 2)])
def test_a_tool_of_the_job_sheet_is_above_0_and_at_most_1200_mm(copy, tool, status):
    """The job sheet's tools: above 0 and at most 1200 mm (the field), both
    ends as the message says."""
    _edit(copy / "out" / "BOARD.job", "large.tool_mm = 0.40", f"large.tool_mm = {tool}")
    got, out, err = report(copy, "out/BOARD.job")
    assert got == status, err
    if status:
        assert err == (f"tapereport: out/BOARD.job: line {_line(copy, 'large.tool_mm')}: "
                       f"large.tool_mm must be a tool width in mm (above 0, at most 1200, two "
                       f"decimals), not '{tool}'\n")
    else:
        assert f"tool {tool} mm)" in out.splitlines()[1]


def _line(here: Path, key: str) -> int:
    lines = (here / "out" / "BOARD.job").read_text(encoding="ascii").splitlines()
    return next(no for no, ln in enumerate(lines, 1) if ln.startswith(key))


@pytest.mark.parametrize("board", BOARDS, ids=[b[0] for b in BOARDS])
def test_the_real_boards_figures_in_the_docs_are_todays(board, tenzor_exe, tmp_path_factory):
    """docs/GERBER.md's and README.md's drilling figures (and the Altium
    board's whole report) are what tapereport says of today's tapes."""
    run = board_run(board, tenzor_exe, tmp_path_factory)
    copper = next(j for j in run.tapes.glob("*.job") if not j.stem.endswith("-DRILL"))
    status, out, err = report(run.tapes.parent, str(copper), "--deck", "board.crd")
    assert status == 0, err
    m = re.search(r"(\d+) holes; travel in the drill file's order ([\d.]+) m, in TENZOR's "
                  r"order ([\d.]+) m", out.splitlines()[-1])
    assert m, out
    holes, own, tenzor = m.groups()
    gerber = (ROOT / "docs" / "GERBER.md").read_text(encoding="utf-8")
    readme = " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
    if board[0].startswith("altium"):
        assert out in gerber, out
        frames = re.search(r" cond : +(\d+) frames", out)[1]
        def spaced(n: str) -> str:
            return f"{int(n):,}".replace(",", " ")
        assert (f"Altium's {spaced(holes)} holes, {own} m and {tenzor} m. The Altium board's "
                f"conductor tape would be {spaced(frames)} frames") in readme
    else:
        maker = {"geda": "gEDA", "eagle": "Eagle", "diptrace": "DipTrace",
                 "kicad": "KiCad"}[board[0].split("-")[0]]
        assert f"{maker} {own} m against {tenzor} m" in " ".join(gerber.split())
        if maker == "KiCad":
            assert (f"KiCad's {holes} holes, {own} m of travel in the drill file's order, "
                    f"{tenzor} m in TENZOR's") in readme
