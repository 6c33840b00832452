"""TENZOR built by other compilers punches the same bytes as the gfortran build.

scripts/judges.sh builds legacy/ a second and a third way: `make f2c`
translates it with f2c -A -u, the classic FORTRAN 77 to C translator, and
compiles the C with gcc and libf2c (build/f2c/tenzor); `make flang` compiles
it with LLVM flang (build/flang/tenzor). The shell and the monitor stay
gfortran's. Compilers that share nothing but the FORTRAN 77 text must agree
on every output byte: the tapes, their frame text, the listing, the job
sheet, what goes to standard output and standard error, and the exit status.
A routine that leaned on a gfortran extension, on an uninitialised variable,
on the processor's rounding of NINT or on the optional zero of an F edit
descriptor would show here.

f2c is installed by `make setup`; a machine without it fails. flang-16 is
large (about 800 MB) and installed only by `make flang` and by CI, which sets
REQUIRE_FLANG=1: there its absence is a failure, elsewhere the flang tests
are skipped with that reason.

The decks: every deck of examples/, the benchmark's generated boards of
1 000 pads (uniform, clustered, on a grid) and one of 10 000, and random decks, valid and
hostile, drawn by the fuzz suites' strategies.
"""
from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bench import boards
from harness import cards
from harness.tests.helpers import DECKS, ROOT
from harness.tests.strategies import (st_card_soup, st_extreme_deck, st_mutated_deck,
                                      st_package, st_stress_deck)

JUDGES = {"f2c": ("f2c", "gcc", "gfortran"), "flang": ("flang-new-16", "gfortran")}
EXAMPLES = 100 if os.environ.get("HYPOTHESIS_PROFILE") != "long" else 500
SETTINGS = settings(max_examples=EXAMPLES, deadline=None,
                    suppress_health_check=[HealthCheck.function_scoped_fixture,
                                           HealthCheck.too_slow, HealthCheck.data_too_large])


@pytest.fixture(scope="session", params=sorted(JUDGES))
def judge_tenzor(request) -> Path:
    """build/JUDGE/tenzor, built afresh by scripts/judges.sh."""
    judge = request.param
    for tool in JUDGES[judge]:
        if shutil.which(tool) is None:
            why = f"{tool} is not installed: `make {judge}` installs it"
            if judge == "flang" and os.environ.get("REQUIRE_FLANG") != "1":
                pytest.skip(why)
            pytest.fail(why, pytrace=False)
    proc = subprocess.run(["bash", str(ROOT / "scripts" / "judges.sh"), judge],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    exe = ROOT / "build" / judge / "tenzor"
    assert exe.is_file()
    return exe


def outputs(exe: Path, deck: Path, work: Path, *args: str) -> dict[str, bytes]:
    """Everything a run of tenzor leaves: its files, standard output and
    error (the output directory's path replaced by OUT), exit status."""
    out = work / "out"
    proc = subprocess.run([str(exe), str(deck), "-o", str(out), *args], capture_output=True,
                          timeout=300)
    files = {p.name: p.read_bytes() for p in sorted(out.iterdir())} if out.is_dir() else {}
    files["(standard output)"] = proc.stdout.replace(bytes(out), b"OUT")
    files["(standard error)"] = proc.stderr.replace(bytes(out), b"OUT")
    files["(exit status)"] = str(proc.returncode).encode()
    return files


def assert_same(judge: Path, gfortran: Path, deck: Path, work: Path, *args: str) -> dict:
    """The judge's outputs are the gfortran build's (returned)."""
    want = outputs(gfortran, deck, work / "gfortran", *args)
    got = outputs(judge, deck, work / "judge", *args)
    assert sorted(got) == sorted(want), (deck.name, sorted(got), sorted(want))
    differ = [name for name in want if got[name] != want[name]]
    assert not differ, f"{deck.name}: the {judge.parent.name} build differs in {differ}"
    return want


@pytest.mark.parametrize("deck", DECKS, ids=[str(d.relative_to(ROOT / "examples")) for d in DECKS])
def test_every_example_deck(judge_tenzor, tenzor_exe, deck, tmp_path):
    files = assert_same(judge_tenzor, tenzor_exe, deck, tmp_path)
    tapes = [name for name in files if name.endswith(".ptp")]
    assert tapes and all(any(files[t][20:]) for t in tapes), "blank tapes"


@pytest.mark.parametrize("dist,pads", [(d, 1000) for d in boards.DISTRIBUTIONS]
                         + [("uniform", 10000)])
def test_generated_boards(judge_tenzor, tenzor_exe, dist, pads, tmp_path):
    deck = tmp_path / "board.crd"
    deck.write_text(boards.make_board(dist, pads).deck())
    files = assert_same(judge_tenzor, tenzor_exe, deck, tmp_path)
    assert files["(exit status)"] == b"0"


@pytest.mark.parametrize("args", [("--code", "K"), ("--code", "8"), ("--code", "X"),
                                  ("--bogus",), ("-o",)])
def test_command_line(judge_tenzor, tenzor_exe, args, tmp_path):
    assert_same(judge_tenzor, tenzor_exe, DECKS[0], tmp_path, *args)


_cases = iter(range(10**9))


def _compare(judge: Path, gfortran: Path, tmp: Path, deck: bytes) -> None:
    work = tmp / f"case{next(_cases)}"
    work.mkdir()
    path = work / "deck.crd"
    path.write_bytes(deck)
    assert_same(judge, gfortran, path, work)


@SETTINGS
@given(packages=st.lists(st_package(), min_size=1, max_size=3,
                         unique_by=lambda p: p.name))
def test_random_valid_decks(judge_tenzor, tenzor_exe, tmp_path, packages):
    _compare(judge_tenzor, tenzor_exe, tmp_path, cards.deck(packages).encode("latin-1"))


@SETTINGS
@given(deck=st.one_of(st_mutated_deck(), st_extreme_deck(), st_stress_deck(),
                      st_card_soup()))
def test_random_hostile_decks(judge_tenzor, tenzor_exe, tmp_path, deck):
    _compare(judge_tenzor, tenzor_exe, tmp_path, deck)
