"""Fuzzing TENZOR (docs/ROBUSTNESS.md): malformed and hostile decks and arguments.

Whatever it is given -- random bytes, cut cards, shifted columns, numbers at
and past every limit, decks past every capacity, no E, empty files, CR or
NUL bytes, lines of 100000 characters, thousands of packages, directories,
FIFOs and missing paths as arguments -- TENZOR must:

* exit with 0, 1 or 2, never by a signal;
* print no Fortran run-time error, backtrace or signal report;
* when it exits non-zero, say why on standard error, naming the card
  (``CARD n``, or ``AT THE END OF THE DECK``) or the usage;
* leave no partial output: no tape, frame text or job sheet of a package
  that failed, no temporary file, every tape it wrote decodes (harness.tape),
  every listing line is printable ASCII of at most 128 characters;
* read a deck the same from a file and from standard input.

CI runs the default profile in bounded time; the long run is
``HYPOTHESIS_PROFILE=long python -m pytest harness/tests/tenzor/test_fuzz_tenzor.py``
(see docs/ROBUSTNESS.md for its case count and findings).
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
import threading
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from harness import cards, tape
from harness.tests.strategies import (GOOD_M, st_card_soup, st_extreme_deck, st_mutated_deck,
                                      st_stress_deck)
from harness.tests.helpers import FORBIDDEN

#: Examples per property test: the CI profile, or the long run.
LONG = os.environ.get("HYPOTHESIS_PROFILE") == "long"
N = 2500 if LONG else 100
FUZZ = settings(max_examples=N, deadline=None,
                suppress_health_check=[HealthCheck.function_scoped_fixture,
                                       HealthCheck.too_slow, HealthCheck.data_too_large])

TAPE_SUFFIXES = ("-small.ptp", "-large.ptp", "-cond.ptp", "-small.txt", "-large.txt",
                 "-cond.txt", ".job")


# ---------------------------------------------------------------------------
# Running TENZOR and checking what it did.
# ---------------------------------------------------------------------------
@dataclass
class Outcome:
    """A run: the process, its output directory (None when the arguments
    leave it unknown), standard error and output as text."""

    proc: subprocess.CompletedProcess
    out: Path | None
    err: str
    stdout: str


def _is_dir(path: Path) -> bool:
    try:
        return path.is_dir()
    except OSError:                 # e.g. a name too long
        return False


def run(exe: Path, tmp: Path, deck: bytes | None, *args: str, stdin: bytes | None = None,
        name: str = "deck.crd") -> Outcome:
    """Run tenzor on ``deck`` (written to ``tmp/name``; None: no deck
    argument) into ``tmp/out``."""
    tmp.mkdir(parents=True, exist_ok=True)
    out = tmp / "out"
    cmd = [str(exe)]
    if deck is not None:
        path = tmp / name
        path.write_bytes(deck)
        cmd.append(str(path))
    cmd += ["-o", str(out), *args] if "-o" not in args else list(args)
    proc = subprocess.run(cmd, input=stdin, capture_output=True, timeout=300)
    return Outcome(proc, out, proc.stderr.decode("latin-1"), proc.stdout.decode("latin-1"))


def check(o: Outcome) -> None:
    """Every invariant of the module doc."""
    rc = o.proc.returncode
    assert rc in (0, 1, 2), f"exit status {rc} (a negative one is a signal)\n{o.err[-3000:]}"
    for text in FORBIDDEN:
        assert text not in o.err and text not in o.stdout, f"{text!r} printed:\n{o.err[-3000:]}"
    if rc:
        assert re.search(r"ERROR CARD \d+|ERROR AT THE END OF THE DECK|usage: tenzor|^tenzor: ",
                         o.err, re.M), f"exit {rc} without a message:\n{o.err[-3000:]}"
    if rc == 1:
        assert "ERROR" in o.err
    if o.out is None:
        return
    if not _is_dir(o.out):
        assert rc == 2, "no output directory, but the exit status says the run was done"
        return
    names = sorted(p.name for p in o.out.iterdir())
    assert not [n for n in names if n.startswith(".") and n.endswith(".tmp")], \
        f"temporary files left: {names}"
    # per package, from standard output: punched, not punched, not written
    punched = re.findall(r"^(\S+): tapes ", o.stdout, re.M)
    failed = re.findall(r"^(\S+): (?:errors, no tapes punched|cannot write)", o.stdout, re.M)
    for pkg in failed:
        if pkg in punched:          # a later package of the same name wrote them
            continue
        left = [pkg + s for s in TAPE_SUFFIXES if (o.out / (pkg + s)).exists()]
        assert not left, f"package {pkg} failed but left {left}"
    for pkg in punched:
        for s in TAPE_SUFFIXES + (".lst",):
            assert (o.out / (pkg + s)).is_file(), f"package {pkg} punched but {pkg + s} missing"
    if rc == 0:
        assert not failed
    for p in o.out.iterdir():
        if p.suffix == ".ptp":
            try:
                tape.decode(p.read_bytes())
            except tape.TapeError as exc:
                raise AssertionError(f"{p.name} does not decode: {exc}") from None
        elif p.suffix == ".lst":
            for no, line in enumerate(p.read_bytes().split(b"\n"), 1):
                assert len(line) <= 128, f"{p.name} line {no} has {len(line)} characters"
                assert all(32 <= b < 127 for b in line), f"{p.name} line {no}: {line[:200]!r}"


def run_checked(exe: Path, tmp: Path, deck: bytes, *args: str) -> Outcome:
    o = run(exe, tmp, deck, *args)
    check(o)
    return o


_counter = iter(range(10**9))


def fresh(tmp_path: Path) -> Path:
    """A new directory for one hypothesis example (tmp_path is per test)."""
    return tmp_path / f"case{next(_counter)}"


# ---------------------------------------------------------------------------
# Property tests.
# ---------------------------------------------------------------------------
@FUZZ
@given(deck=st.binary(max_size=3000))
@example(deck=b"")
@example(deck=b"\x00" * 100)
@example(deck=b"\r\r\r")
@example(deck=b"\n" * 1000)
@example(deck=b"\xff\xfe" + "ДЕКА\n".encode("utf-8"))
def test_random_bytes(tenzor_exe, tmp_path, deck):
    run_checked(tenzor_exe, fresh(tmp_path), deck)


@FUZZ
@given(deck=st_card_soup())
def test_card_soup(tenzor_exe, tmp_path, deck):
    run_checked(tenzor_exe, fresh(tmp_path), deck)


@FUZZ
@given(deck=st_mutated_deck())
def test_valid_decks_broken_by_mutations(tenzor_exe, tmp_path, deck):
    run_checked(tenzor_exe, fresh(tmp_path), deck)


@FUZZ
@given(deck=st_extreme_deck())
@example(deck=b"X\nP              0.00      0.00    0.01    0.01    0.01   0.01\n"
              b"D                                 100.00\nE\n")
@example(deck=b"X\nO+        9999999.99-9999999.99  10000.00\nE\n")
@example(deck=b"X\nD               0.00      0.00    0.50        9999      0.01      0.01\nE\n")
@example(deck=b"X\nA+             0.00      0.00  10000.00      0.00      0.00  10000.00\nE\n")
@example(deck=b"X\nM             999999999 999999999 999999999 999999999    2   13\n"
              b"M                                   0.01                  10\nE\n")
def test_numbers_at_and_past_the_limits(tenzor_exe, tmp_path, deck):
    run_checked(tenzor_exe, fresh(tmp_path), deck)


@FUZZ
@given(deck=st_stress_deck())
def test_huge_and_tiny_boards(tenzor_exe, tmp_path, deck):
    run_checked(tenzor_exe, fresh(tmp_path), deck)


@settings(max_examples=max(10, N // 4), deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(deck=st.one_of(st.binary(max_size=500), st_mutated_deck()))
def test_standard_input_reads_like_a_file(tenzor_exe, tmp_path, deck):
    here = fresh(tmp_path)
    a = run(tenzor_exe, here / "file", deck)
    b = run(tenzor_exe, here / "stdin", None, stdin=deck)
    check(a)
    check(b)
    assert a.proc.returncode == b.proc.returncode
    label = str(here / "file" / "deck.crd")
    assert a.err.replace(label, "DECK").replace(str(a.out), "OUT") == \
        b.err.replace("<stdin>", "DECK").replace(str(b.out), "OUT")
    files_a = {p.name: p.read_bytes() for p in a.out.iterdir()} if a.out.exists() else {}
    files_b = {p.name: p.read_bytes() for p in b.out.iterdir()} if b.out.exists() else {}
    assert files_a == files_b


# ---------------------------------------------------------------------------
# Fixed hostile decks: shapes, sizes and capacities.
# ---------------------------------------------------------------------------
P = cards.p_card(10000, 10000)
DEMO = (Path(__file__).resolve().parents[3] / "examples" / "demo.crd").read_text()


def f10(v: float) -> str:
    return f"{v:10.2f}"


def package(name: str, body: list[str], end: str = "E") -> str:
    return "\n".join([name, *body, end]) + "\n"


def many_packages(n: int, card: str = GOOD_M) -> str:
    return "".join(f"P{i}\n{card}\n" + ("C\n" if i < n - 1 else "E\n") for i in range(n))


# (id, deck text, exit status, fragment of standard error or None)
FIXED: list[tuple[str, object, int, str | None]] = [
    ("empty", "", 1, "THE DECK HOLDS NO PACKAGE"),
    ("only-blank-lines", "\n\n\n   \n", 1, "THE DECK HOLDS NO PACKAGE"),
    ("cr-only-line-ends", package("CR", [GOOD_M]).replace("\n", "\r"), 1, "BYTE 13"),
    ("crlf-line-ends", package("CRLF", [GOOD_M]).replace("\n", "\r\n"), 0, None),
    ("nul-bytes", "A\n\x00\x00\x00\nE\n", 1, "BYTE 0 IS NOT A CARD CHARACTER"),
    ("line-of-100000", package("LONG", ["M" * 100000]), 1, "LINE OF 100000 CHARACTERS"),
    ("last-line-without-newline", package("NOLF", [GOOD_M])[:-1], 0, None),
    ("missing-e", "A\n" + GOOD_M + "\n", 1, "THE DECK ENDS WITHOUT THE E CARD"),
    ("missing-e-in-envelope", "*NAME J\n*EXECUTE\nA\n" + GOOD_M + "\n*END FILE\n", 1,
     "*END FILE BEFORE THE E CARD"),
    ("only-end-file", "*END FILE\n", 1, None),
    ("every-column-shifted-right", "\n".join(" " + ln for ln in DEMO.splitlines()) + "\n", 1,
     "ERROR CARD 1 (SEQ  DEMO001) COL 81: LINE OF 81 CHARACTERS"),
    ("every-column-shifted-left", "\n".join(ln[1:] for ln in DEMO.splitlines()) + "\n", 1,
     "ERROR CARD"),
    ("cards-cut-at-40", "\n".join(ln[:40] for ln in DEMO.splitlines()) + "\n", 1, "ERROR CARD"),
    ("thousands-of-packages", many_packages(2000), 0, None),
    ("capacity-packages-MXPKG", many_packages(10001, "Q"), 1,
     "MORE THAN 10000 PACKAGES IN ONE JOB (PARAMETER MXPKG)"),
    ("capacity-envelope-MXENV", "*NAME J\n" + "*TIME 1\n" * 25 + "*EXECUTE\n"
     + package("A", [GOOD_M]), 1, "(PARAMETER MXENV)"),
    ("capacity-pads-MXPAD-MXCRD", package("PADS", [P] + [
        "D" + " " * 9 + f10(i % 400 * 0.5) + f10(i // 400 * 0.5) + "    0.50"
        for i in range(200001)]), 1, "(PARAMETER MXPAD)"),
    ("capacity-blank-cards-MXCRD", package("BLANKS", [P, GOOD_M] + [""] * 200000), 1,
     "(PARAMETER MXCRD, BLANK CARDS COUNTED); DROP THE BLANK CARDS OR SPLIT THE BOARD"),
    ("capacity-conductors-MXCON", package("CONS", [P] + [
        c for i in range(50001) for c in (
            "L" + " " * 9 + f10(i % 200 * 2.0) + f10(i // 200 * 2.0),
            "+" + " " * 9 + f10(i % 200 * 2.0 + 1) + f10(i // 200 * 2.0))]), 1,
     "(PARAMETER MXCON)"),
    ("capacity-vertices-MXVTX", package("VTX", [P, "L" + " " * 9 + f10(0) + f10(0)] + [
        "+" + " " * 9 + f10(i % 2) + f10(i * 0.01 + 0.01) for i in range(200000)]), 1,
     "(PARAMETER MXVTX)"),
    ("capacity-circles-MXARC", package("ARCS", [P] + [
        "O+" + " " * 8 + f10(i % 200 * 2.0) + f10(i // 200 * 2.0) + f10(0.5)
        for i in range(50001)]), 1, "(PARAMETER MXARC)"),
    ("capacity-manual-MXMAN", package("MAN", [P] + [cards.m_card("L", dx=1, k=10)] * 20001), 1,
     "(PARAMETER MXMAN)"),
    ("capacity-frames-MXFRM", package("FRM", [cards.p_card(1000, 1000, 10, 10, None, 500)] + [
        cards.d_card(i % 200 * 400, i // 200 * 400, 300) for i in range(40000)]), 1,
     "(PARAMETER MXFRM)"),
    ("capacity-strokes-MXSTK", package("STK", [cards.p_card(60000, 60000, 1, 1),
                                               cards.d_card(0, 0, 10000)]), 1,
     "(PARAMETER MXSTK)"),
    ("capacity-errors-MXERR", package("ERRS", ["Q"] * 60), 1, "TOO MANY ERRORS"),
]


@pytest.fixture
def roomy_tmp(tmp_path):
    """A directory for decks with thousands of packages: in memory
    (/dev/shm) where there is one, since creating tens of thousands of
    files on a disk file system takes seconds; removed afterwards."""
    shm = Path("/dev/shm")
    if shm.is_dir() and os.access(shm, os.W_OK):
        path = Path(tempfile.mkdtemp(prefix="tenzor-fuzz-", dir=shm))
        yield path
        shutil.rmtree(path, ignore_errors=True)
    else:
        yield tmp_path


@pytest.mark.parametrize("deck,status,fragment", [c[1:] for c in FIXED], ids=[c[0] for c in FIXED])
def test_fixed_hostile_deck(tenzor_exe, roomy_tmp, deck, status, fragment):
    data = deck.encode("latin-1") if isinstance(deck, str) else deck
    o = run_checked(tenzor_exe, roomy_tmp, data)
    assert o.proc.returncode == status, o.err[-2000:]
    if fragment:
        assert fragment in o.err, o.err[-2000:]


# ---------------------------------------------------------------------------
# Faults found by fuzzing (docs/ROBUSTNESS.md), kept as their smallest decks.
# ---------------------------------------------------------------------------
def test_arc_ending_at_its_centre(tenzor_exe, tmp_path):
    """Finding 6: this card was accepted and drawn from its end, punching
    DX1 K11 KK (an arc without X or Y) with exit status 0."""
    deck = (b"ARC\nP             100.00    100.00\n"
            b"A+              0.00      0.00      0.01      0.00      0.00      0.00\nE\n")
    o = run_checked(tenzor_exe, tmp_path, deck)
    assert o.proc.returncode == 1 and "ERROR CARD 3 " in o.err


def test_a_pad_beyond_mxstk_is_one_message(tenzor_exe, tmp_path):
    """Finding 8: a pad needing more than MXSTK strokes was reported twice,
    with the same card and column; one fault is one message, on standard
    error and in the listing."""
    deck = (b"BIG\nP             600.00    600.00    0.01    0.01\n"
            b"D              50.00     50.00  100.00\nE\n")
    o = run_checked(tenzor_exe, tmp_path, deck)
    assert o.proc.returncode == 1
    said = "M703T ERROR CARD 3 COL 31: CAPACITY EXCEEDED: THE PAD NEEDS MORE THAN"
    assert o.err.count(said) == 1, o.err
    assert (o.out / "BIG.lst").read_text().count("CAPACITY EXCEEDED") == 1


# ---------------------------------------------------------------------------
# Hostile arguments.
# ---------------------------------------------------------------------------
def test_directory_as_deck(tenzor_exe, tmp_path):
    o = run(tenzor_exe, tmp_path, None, str(tmp_path), "-o", str(tmp_path / "out"))
    check(o)
    assert o.proc.returncode == 2 and "cannot read the deck" in o.err


def test_missing_and_dangling_deck(tenzor_exe, tmp_path):
    (tmp_path / "link.crd").symlink_to(tmp_path / "nowhere")
    for path in (str(tmp_path / "nowhere.crd"), str(tmp_path / "link.crd"), ""):
        o = run(tenzor_exe, tmp_path, None, path, "-o", str(tmp_path / "out"))
        check(o)
        assert o.proc.returncode == 2, o.err


def test_unreadable_deck(tenzor_exe, tmp_path):
    if os.geteuid() == 0:
        pytest.skip("running as root: a mode-000 file is still readable")
    path = tmp_path / "secret.crd"
    path.write_text(package("A", [GOOD_M]))
    path.chmod(0)
    o = run(tenzor_exe, tmp_path, None, str(path), "-o", str(tmp_path / "out"))
    check(o)
    assert o.proc.returncode == 2 and "cannot open the deck" in o.err


def test_fifo_as_deck(tenzor_exe, tmp_path):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    writer = threading.Thread(target=fifo.write_bytes,
                              args=(package("FIFO", [GOOD_M]).encode("ascii"),))
    writer.start()
    o = run(tenzor_exe, tmp_path, None, str(fifo), "-o", str(tmp_path / "out"))
    writer.join()
    check(o)
    assert o.proc.returncode == 0 and (o.out / "FIFO-cond.ptp").exists()


@pytest.mark.parametrize("what", ["output-is-a-file", "output-parent-is-a-file",
                                  "output-empty", "output-name-too-long", "deck-name-too-long"])
def test_hostile_output_and_paths(tenzor_exe, tmp_path, what):
    deck = tmp_path / "deck.crd"
    deck.write_text(package("A", [GOOD_M]))
    (tmp_path / "file").write_text("a file")
    out = {"output-is-a-file": str(tmp_path / "file"),
           "output-parent-is-a-file": str(tmp_path / "file" / "out"),
           "output-empty": "",
           "output-name-too-long": str(tmp_path / ("d" * 300) / "x"),
           "deck-name-too-long": str(tmp_path / "out")}[what]
    path = str(tmp_path / ("n" * 5000)) if what == "deck-name-too-long" else str(deck)
    proc = subprocess.run([tenzor_exe, path, "-o", out], capture_output=True, timeout=60)
    o = Outcome(proc, Path(out or tmp_path / "none"), proc.stderr.decode("latin-1"),
                proc.stdout.decode("latin-1"))
    check(o)
    assert proc.returncode == 2, o.err
    assert (tmp_path / "file").read_text() == "a file"


@FUZZ
@given(args=st.lists(st.sampled_from(["-o", "--output", "--code", "8", "K", "k", "9", "-h",
                                      "--help", "-", "--", "x.crd", "", "-x", "--code=K",
                                      "\x01", "ü"]), max_size=5))
def test_random_arguments(tenzor_exe, tmp_path, args):
    here = fresh(tmp_path)
    here.mkdir(parents=True)
    proc = subprocess.run([tenzor_exe, *args], capture_output=True, timeout=60, cwd=here,
                          stdin=subprocess.DEVNULL)
    o = Outcome(proc, None, proc.stderr.decode("latin-1"), proc.stdout.decode("latin-1"))
    check(o)
