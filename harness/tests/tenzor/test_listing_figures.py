"""The figures of each tape in the listing and the job sheet are the tape's:
its rows are its bytes, its length is 2.54 mm a row (one tenth of an inch,
docs/FILES.md), and the drawn and travel lengths are the harness simulator's
for that tape, rounded half up to 0.01 mm (legacy/cmfdp.f), for every package
of every example deck. A figure that lies within a millionth of a rounding
half is not judged: the two simulators may add in another order."""
from __future__ import annotations

import random
import re
from decimal import ROUND_HALF_UP, Decimal
from pathlib import Path

from harness import cards, sim, tape
from harness.tests.helpers import Example, read_job

LAYER = {"S": "small", "B": "large", "L": "cond"}
HEAD = re.compile(r"^ TAPE (\w)  .*FILE (\S+)")
COUNTS = re.compile(r"^ +FRAMES +(\d+) +ROWS +(\d+) +TAPE LENGTH +([\d.]+) M")
LENGTHS = re.compile(r"^ +DRAWN +([\d.]+) MM +TRAVEL +([\d.]+) MM")


def _half_up(v: float) -> str:
    return str(Decimal(repr(v)).quantize(Decimal("0.01"), rounding=ROUND_HALF_UP))


def _judged(v: float) -> bool:
    frac = v * 100 - int(v * 100)
    return abs(frac - 0.5) > 1e-6


def _pads(run_tenzor) -> Example:
    """Forty packages of a few pads at random places: travels and drawn
    lengths with every kind of third decimal."""
    rnd = random.Random(1977)
    packages = []
    for k in range(40):
        body = [cards.p_card(10000, 10000, order="D")]
        body += [cards.d_card(rnd.randrange(-5000, 5000), rnd.randrange(-5000, 5000),
                              rnd.choice([60, 90, 160, 300])) for _ in range(3)]
        packages.append(cards.CardPackage(f"PADS{k}", body))
    proc, out = run_tenzor(cards.deck(packages, envelope=False))
    assert proc.returncode == 0, proc.stderr.decode()
    return Example(Path("pads.crd"), out)


def test_listing_and_job_figures_are_the_tapes(examples, run_tenzor):
    seen = half_up_cases = 0
    for ex in [*examples, _pads(run_tenzor)]:
        for job_path in ex.jobs:
            job = read_job(job_path)
            lines = (ex.out / job["listing"]).read_text().splitlines()
            for i, line in enumerate(lines):
                m = HEAD.match(line)
                if not m:
                    continue
                layer = LAYER[m.group(1)]
                data = (ex.out / m.group(2)).read_bytes()
                frames, rows, length = COUNTS.match(lines[i + 1]).groups()
                drawn, travel = LENGTHS.match(lines[i + 2]).groups()
                assert int(rows) == len(data) == int(job[f"{layer}.rows"])
                assert length == _half_up(len(data) * 2.54 / 1000)
                run = sim.simulate(tape.decode(data).frames)
                for shown, in_job, value in ((drawn, job[f"{layer}.drawn_mm"], run.drawn_mm),
                                             (travel, job[f"{layer}.travel_mm"], run.travel_mm)):
                    assert shown == in_job
                    if _judged(value):
                        assert shown == _half_up(value), (job_path.name, layer, value)
                        # a figure that rounding at 0.6 (or truncation) would get wrong
                        half_up_cases += 0.5 <= (value * 100) % 1 < 0.6
                seen += 1
    assert seen >= 30
    assert half_up_cases >= 5, "too few figures test the rounding"


def test_the_job_sheet_gives_the_listings_figures_however_large(run_tenzor) -> None:
    """A saw of 99 999 teeth of 1 m draws 199 998 km: the job sheet says
    so, figure for figure with the listing (it was capped at 20 km)."""
    deck = ("ONE\nP             100.00    100.00\n"
            "M                                1000.00          99999   10\n"
            "M                               -1000.00                  10\nE\n")
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0, proc.stderr.decode()
    job = read_job(out / "ONE.job")
    listing = (out / "ONE.lst").read_text()
    lines = re.findall(r"DRAWN +([\d.]+) MM +TRAVEL +([\d.]+) MM +RUN TIME +([\d.]+) MIN", listing)
    assert [tuple(job[f"{t}.{k}"] for k in ("drawn_mm", "travel_mm", "minutes"))
            for t in ("small", "large", "cond")] == lines
    assert job["cond.drawn_mm"] == "199998000.00"
