"""How each tape's order was found, as the listing tells it (docs/FILES.md):
the length of the moves between items after nearest neighbour, after 2-opt
and Or-opt and after the kicks, never longer from one step to the next; the
kicks made, kept and their work against its bound, with the reason they
stopped agreeing with the numbers; on a board of dots (pads as wide as the
tool) the last length is the tape's raised travel as the harness simulator
finds it; and the kicks' bound of a tape shrinks with the size of its whole
package (legacy/cmtour.f)."""
from __future__ import annotations

import random
import re
from pathlib import Path

from harness import cards, sim, tape
from harness.tests.helpers import read_job

HEAD = re.compile(r"^ TAPE (\w)  .*FILE (\S+)")
ORDER = re.compile(r"^ {8}ORDER  NEAREST NEIGHBOUR +([\d.]+) MM   2-OPT, OR-OPT +([\d.]+) MM"
                   r"   KICKS +([\d.]+) MM$")
KICKS = re.compile(r"^ {8}KICKS +(\d+) OF +(\d+), +(\d+) KEPT   WORK +(\d+) OF +(\d+)"
                   r"   STOPPED: (ALL MADE|NO GAIN IN A ROW OF KICKS|THE WORK BOUND)$")
NONE = "        KICKS  NONE: FEWER THAN 8 ITEMS"
DECK = "        ORDER  AS IN THE DECK"


def _orders(listing: str) -> list[tuple[str, str, str]]:
    """(tape letter, ORDER line, the line after it) for each tape with items
    to order, from the lines after its statistics' heading; a tape without
    them (none at all, or only an M card's frames) has no ORDER line."""
    lines = listing.splitlines()
    found = []
    for i, line in enumerate(lines):
        if (m := HEAD.match(line)):
            if lines[i + 3].startswith("        ORDER"):
                found.append((m.group(1), lines[i + 3], lines[i + 4]))
            else:
                assert lines[i + 3] == "", lines[i:i + 4]
    return found


def _check(order: str, kicks: str) -> tuple[float, float, float] | None:
    """Assert one tape's two lines are consistent; its three lengths, or
    None for deck order."""
    if order == DECK:
        return None
    m = ORDER.match(order)
    assert m, order
    nn, opt, kicked = (float(v) for v in m.groups())
    assert nn >= opt >= kicked > 0, order
    if kicks == NONE:
        # 2-opt and Or-opt may still have shortened a tape of 3 to 7 items
        assert opt == kicked, (order, kicks)
        return nn, opt, kicked
    k = KICKS.match(kicks)
    assert k, kicks
    made, most, kept, work, bound = (int(v) for v in k.groups()[:5])
    why = k.group(6)
    assert 0 <= kept <= made <= most, kicks
    assert 20_000_000 <= bound <= 50_000_000, kicks
    if why == "ALL MADE":
        assert made == most and work <= bound, kicks
    elif why == "THE WORK BOUND":
        assert work > bound and made < most, kicks
    else:
        assert work <= bound and made < most, kicks
    if kept == 0:
        assert kicked == opt, (order, kicks)
    return nn, opt, kicked


def test_every_tape_tells_how_its_order_was_found(examples):
    toured = deck_order = 0
    for ex in examples:
        for job_path in ex.jobs:
            job = read_job(job_path)
            for _, order, kicks in _orders((ex.out / job["listing"]).read_text()):
                if _check(order, kicks) is None:
                    assert job["order"] == "D", (job_path, order)
                    deck_order += 1
                else:
                    assert job["order"] == "O", (job_path, order)
                    toured += 1
    assert toured >= 3 and deck_order >= 3


def _board(run_tenzor, small: int, large: int):
    """A package of random pads: `small` dots of the small-pad tool and
    `large` dots of the large-pad tool; its listing and output directory."""
    rnd = random.Random(1977)
    body = [cards.p_card(50000, 50000, w1=50, w2=200, dmax=100)]
    body += [cards.d_card(rnd.randrange(-40000, 40000), rnd.randrange(-40000, 40000), 50)
             for _ in range(small)]
    body += [cards.d_card(rnd.randrange(-40000, 40000), rnd.randrange(-40000, 40000), 200)
             for _ in range(large)]
    proc, out = run_tenzor(cards.deck([cards.CardPackage("DOTS", body)], envelope=False))
    assert proc.returncode == 0, proc.stderr.decode()
    return (out / "DOTS.lst").read_text(), out


def test_the_tour_of_dots_is_the_tape_travel(run_tenzor):
    listing, out = _board(run_tenzor, 400, 60)
    tapes = {"S": "DOTS-small.ptp", "B": "DOTS-large.ptp"}
    seen = 0
    for letter, order, kicks in _orders(listing):
        if letter not in tapes:
            continue
        lengths = _check(order, kicks)
        assert lengths is not None
        run = sim.simulate(tape.decode((out / tapes[letter]).read_bytes()).frames)
        # a dot is drawn where it stands: every raised move is a move of the tour
        assert abs(lengths[2] - run.travel_mm) <= 0.006, (letter, lengths, run.travel_mm)
        assert run.drawn_mm == 0
        seen += 1
    assert seen == 2


def _bounds(listing: str) -> dict[str, int]:
    found = {}
    for letter, _, kicks in _orders(listing):
        if (k := KICKS.match(kicks)):
            found[letter] = int(k.group(5))
    return found


def test_a_big_package_gives_each_tape_fewer_kicks(run_tenzor):
    """400 dots alone: 100 000 work units an item, 40 million; 1 000 dots
    alone: 100 million, cut to the most a tape has, 50 million; the same
    1 000 dots in a package of 18 500 items: 400 million less 20 000 a
    package item, 30 million, and the 17 500 large dots the same."""
    few, _ = _board(run_tenzor, 400, 0)
    assert _bounds(few) == {"S": 40_000_000}
    alone, _ = _board(run_tenzor, 1000, 0)
    assert _bounds(alone) == {"S": 50_000_000}
    big, _ = _board(run_tenzor, 1000, 17500)
    assert _bounds(big) == {"S": 30_000_000, "B": 30_000_000}
