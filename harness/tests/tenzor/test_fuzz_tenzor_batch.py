"""TENZOR on thousands of hostile packages a CI run (docs/ROBUSTNESS.md).

TENZOR checks every package of a deck on its own: a package with errors gets
its listing and nothing else, the next package is read afresh. So one deck
of PACKAGES hostile packages is PACKAGES inputs for one start of the program.
Each package's data cards come from one of hostile.BODIES (a valid board
broken by mutations, card soup, random bytes, extreme fields, huge and tiny
boards); its name card is its own (Zdd-nnn) and a C card ends it, so that no
package can run into the next. That they stay apart is checked, not assumed:
TENZOR must report every package by its name, once.

Besides every promise test_fuzz_tenzor.check holds a run to, each package
that fails must have an error message naming one of its own cards.
"""
from __future__ import annotations

import os
import random
import re
import shutil
import tempfile
from pathlib import Path

import pytest

from harness.tests import hostile
from harness.tests.tenzor.test_fuzz_tenzor import check, run

#: Packages a deck, and decks of each kind of body (seed = the deck's number).
PACKAGES = 200
DECKS = {"mutated": 16, "soup": 5, "bytes": 5, "extreme": 6, "stress": 8}
PLAN = [(kind, n) for kind, k in DECKS.items() for n in range(k)]

_REPORT = re.compile(r"^(\S+): (tapes |errors, no tapes punched|cannot write)", re.M)
_CARD = re.compile(r": (?:TENZOR|M703T|M703L) ERROR CARD (\d+)")


@pytest.fixture
def shm_tmp(tmp_path):
    """In memory (/dev/shm) where there is one: a deck of 200 packages
    writes up to 1600 files."""
    shm = Path("/dev/shm")
    if shm.is_dir() and os.access(shm, os.W_OK):
        path = Path(tempfile.mkdtemp(prefix="tenzor-batch-", dir=shm))
        yield path
        shutil.rmtree(path, ignore_errors=True)
    else:
        yield tmp_path


@pytest.mark.hostile
@pytest.mark.parametrize("kind,n", PLAN, ids=[f"{k}-{n}" for k, n in PLAN])
def test_a_deck_of_hostile_packages(tenzor_exe, shm_tmp, kind, n):
    seed = 1000 * list(DECKS).index(kind) + n
    r = random.Random(seed)
    names = [f"Z{seed:04d}-{i:03d}" for i in range(PACKAGES)]
    bodies = [hostile.BODIES[kind](r) for _ in range(PACKAGES)]
    deck, spans = hostile.batch_deck(names, bodies)
    o = run(tenzor_exe, shm_tmp, deck)
    check(o)
    where = f"(seed {seed}, deck {shm_tmp / 'deck.crd'})"
    reported = [m.group(1) for m in _REPORT.finditer(o.stdout)]
    assert sorted(reported) == names, \
        f"the packages did not stay apart {where}: {sorted(set(names) ^ set(reported))[:10]}"
    failed = {m.group(1) for m in _REPORT.finditer(o.stdout) if m.group(2) != "tapes "}
    cards = [int(c) for c in _CARD.findall(o.err)]
    for name, (first, last) in zip(names, spans):
        if name in failed:
            assert any(first <= c <= last for c in cards), \
                f"package {name} (cards {first}-{last}) failed without naming a card {where}"
    hostile.count("tenzor", PACKAGES)
