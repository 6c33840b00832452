"""Hostile inputs in bulk, for the batch fuzz suites (docs/ROBUSTNESS.md).

The hypothesis suites (test_fuzz_tenzor.py, test_fuzz_em703.py) shrink a
failure to its smallest case but pay for it: about 10 ms an example before
the program even starts. The batch suites make thousands of hostile inputs
a CI run instead, from ``random.Random(seed)`` with fixed seeds (the same
inputs on every run and every machine), and batch them where the program
allows: many hostile packages in one TENZOR deck (TENZOR checks each package
on its own), the Python tools called in-process. A failure names the seed
and the input's number, so it can be replayed and pinned as an @example.

``count(program, n)`` records the inputs given to each program; the root
conftest.py prints the totals at the end of the run, and
``harness/tests/test_hostile_total.py`` checks that a whole CI run reaches
:data:`GOAL`.
"""
from __future__ import annotations

import random
from collections import Counter
from pathlib import Path

from harness import cards
from harness.tape import Frame, encode
from harness.tests.strategies import F8, F10, FIELDS, INT

ROOT = Path(__file__).resolve().parents[2]

#: The least number of hostile inputs one CI run (`make test`) gives the programs.
GOAL = 10_000
#: Every program (or input format) the batch suites must reach in a whole run.
PROGRAMS = ("tenzor", "em703", "dxf2deck", "dxf2dmc", "gerber2deck", "profile", "equidistant",
            "punch5121", "ural1", "cnclink", "seeds split", "dda", "tapereport",
            "harness decode", "harness verify")
#: The batch suites, which between them reach every program of PROGRAMS.
SUITES = ("harness/tests/tenzor/test_fuzz_tenzor_batch.py",
          "harness/tests/em703/test_fuzz_em703_batch.py",
          "harness/tests/oracle/test_fuzz_harness_batch.py",
          "seeds/tests/test_fuzz_seeds_batch.py")
#: program -> hostile inputs given in this run (filled by :func:`count`).
COUNTS: Counter[str] = Counter()


def count(program: str, n: int) -> None:
    """Record ``n`` more hostile inputs given to ``program``."""
    assert program in PROGRAMS, program
    COUNTS[program] += n


# ---------------------------------------------------------------------------
# Decks: package bodies (the cards between a package's name card and its C
# or E card). Column 1 of a body card is never C or E: a hostile card there
# would end the package, and the next one would no longer be an input of
# its own (the hypothesis suites attack the deck's structure).
# ---------------------------------------------------------------------------
def _example_bodies() -> list[list[str]]:
    """The data cards of every package of examples/."""
    bodies: list[list[str]] = []
    for deck in sorted((ROOT / "examples").rglob("*.crd")):
        body: list[str] | None = None
        for line in deck.read_text(encoding="ascii").splitlines():
            if line[:1] in ("*", "#") and body is None:
                continue
            if body is None:
                body = []                               # the name card
            elif line[:1] in ("C", "E"):
                bodies.append(body)
                body = None
            else:
                body.append(line[:72])
    return bodies


EXAMPLE_BODIES = _example_bodies()


def random_board(r: random.Random) -> list[str]:
    """A small board TENZOR accepts (mostly): pads, conductors, circles,
    manual frames near a start point in the middle of the field."""
    w1, w2, w3 = r.randint(20, 150), r.randint(20, 150), r.randint(20, 150)
    body = [cards.p_card(r.randint(20000, 100000), r.randint(20000, 100000), w1, w2, w3,
                         r.choice([None, r.randint(100, 500)]), None,
                         r.choice([None, "8", "K"]), r.choice([None, "O", "D"]))]
    for _ in range(r.randint(0, 6)):
        w = r.randint(max(w1, w2), 800)
        body.append(cards.d_card(r.randint(-9000, 9000), r.randint(-9000, 9000), w,
                                 r.choice([None, r.randint(max(w1, w2), 800)])))
    for _ in range(r.randint(0, 3)):
        x, y = r.randint(-9000, 9000), r.randint(-9000, 9000)
        body.append(cards.l_card(x, y, r.choice([None, r.randint(w3, 300)])))
        for _ in range(r.randint(1, 4)):
            x += r.choice([-1, 1]) * r.randint(300, 3000)
            y += r.choice([-1, 1]) * r.randint(300, 3000)
            body.append(cards.plus_card(x, y))
    for _ in range(r.randint(0, 2)):
        body.append(cards.o_card(r.choice("+-"), r.randint(-9000, 9000),
                                 r.randint(-9000, 9000), r.randint(50, 1000)))
    if r.random() < 0.3:
        body.append(cards.m_card("L", dx=r.randint(1, 2000), k=r.choice([10, 20])))
    return body


def _valid_body(r: random.Random) -> list[str]:
    return list(r.choice(EXAMPLE_BODIES)) if r.random() < 0.5 else random_board(r)


MUTATIONS = ("cut", "shift", "unshift", "shift-all", "delete", "duplicate", "swap", "field",
             "field", "byte", "byte", "crlf", "cr-only", "long", "nul", "truncate", "blank")


def mutated_body(r: random.Random, lines: list[str] | None = None) -> list[str]:
    """A valid package (``lines``, else one of the examples' or a random
    board) broken by 1-4 mutations (as strategies.st_mutated_deck, within
    one package)."""
    lines = list(lines) if lines is not None else _valid_body(r)
    lines = lines or [""]
    for _ in range(r.choice([1, 1, 1, 2, 3, 4])):
        what = r.choice(MUTATIONS)
        if not lines:
            lines = [""]
        i = r.randrange(len(lines))
        if what == "cut":
            lines[i] = lines[i][:r.randint(0, 80)]
        elif what == "shift":
            lines[i] = " " * r.randint(1, 10) + lines[i]
        elif what == "unshift":
            lines[i] = lines[i][r.randint(1, 10):]
        elif what == "shift-all":
            k = r.choice([-2, -1, 1, 2])
            lines = [(" " * k + ln) if k > 0 else ln[-k:] for ln in lines]
        elif what == "delete":
            del lines[i]
        elif what == "duplicate":
            lines.insert(i, lines[i])
        elif what == "swap":
            j = r.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
        elif what == "field":
            text = r.choice(r.choice([F10, F8, INT]))
            col = r.randint(2, 72)
            ln = lines[i].ljust(col - 1 + len(text))
            lines[i] = ln[:col - 1] + text + ln[col - 1 + len(text):]
        elif what == "byte":
            col = r.randint(0, 90)
            ch = chr(r.choice([b for b in range(256) if b != 10]))
            lines[i] = lines[i][:col] + ch + lines[i][col + 1:]
        elif what == "crlf":
            lines = [ln + "\r" for ln in lines]
        elif what == "cr-only":
            lines = ["\r".join(lines)]
        elif what == "long":
            lines.insert(i, r.choice("MD *+") * r.choice([81, 200, 5000, 100000]))
        elif what == "nul":
            lines[i] += "\x00" * r.randint(1, 3)
        elif what == "truncate":
            text = "\n".join(lines)
            lines = text[:r.randint(0, len(text))].split("\n")
        else:
            lines.insert(i, "")
    return lines


SOUP = list(" 0123456789.-+PDLOAMCEK8*#_") + ["\r", "\t", "\x00"]


def soup_body(r: random.Random) -> list[str]:
    """Lines of the characters TENZOR cares about, in no order."""
    return ["".join(r.choice(SOUP) for _ in range(r.randint(0, 90)))
            for _ in range(r.randint(0, 30))]


def bytes_body(r: random.Random) -> list[str]:
    """Lines of random bytes (any but LF), as latin-1 text."""
    return ["".join(chr(r.choice(range(256)) if r.random() < 0.5 else r.randint(32, 126))
                    for _ in range(r.randint(0, 100)))
            for _ in range(r.randint(0, 12))]


def extreme_card(r: random.Random, kind: str | None = None) -> str:
    """A card of a known type whose fields are blank, sane or extreme
    (as strategies.st_extreme_card)."""
    kind = kind or r.choice(sorted(FIELDS))
    cols = [" "] * 72
    cols[0] = kind
    for col, width, pool in FIELDS[kind]:
        if r.randint(0, 3) == 0:
            continue
        text = r.choice(pool)[-width:].rjust(width)
        cols[col - 1:col - 1 + width] = list(text)
    return "".join(cols).rstrip()


def extreme_body(r: random.Random) -> list[str]:
    body = [extreme_card(r) for _ in range(r.randint(1, 8))]
    if r.random() < 0.5:
        body.insert(0, extreme_card(r, "P"))
    return body


BIG = [11_999_999, 12_000_000, 12_000_001, 999_999, 1_000_000, 1_000_001, 120_000, 60_000,
       99_999_999, 0, 1, 2, 3]


def _length(r: random.Random, lo: int = -99_999_999, hi: int = 99_999_999) -> int:
    v = r.choice([r.choice(BIG), r.randint(lo, hi), r.randint(-300_000, 300_000)])
    if lo < 0 and r.random() < 0.5:
        v = -v
    return max(lo, min(hi, v))


def stress_body(r: random.Random) -> list[str]:
    """Well-formed cards whose values are huge, tiny or at a limit, at the
    machine's scales (as strategies.st_stress_deck)."""
    tool = lambda: r.randint(1, 2000)                                   # noqa: E731
    body = [cards.p_card(r.randint(0, 120000), r.randint(0, 120000), tool(), tool(), tool(),
                         r.randint(1, 120000),
                         r.choice([(1, 100), (1, 10), (1, 1), (100, 1), (1, 2)]),
                         r.choice("8K"), r.choice("OD"))]
    size = lambda: r.randint(1, 99_999)                                 # noqa: E731
    for _ in range(r.randint(1, 6)):
        kind = r.choice("DDLOAM")
        if kind == "D":
            body.append(cards.d_card(_length(r), _length(r), size(), r.choice([None, size()]),
                                     r.choice([None, 2, 9999, 500]), _length(r), _length(r)))
        elif kind == "L":
            body.append(cards.l_card(_length(r), _length(r), r.choice([None, size()])))
            body += [cards.plus_card(_length(r), _length(r)) for _ in range(r.randint(1, 4))]
        elif kind == "O":
            body.append(cards.o_card(r.choice("+-"), _length(r), _length(r), _length(r, 1)))
        elif kind == "A":
            rad = r.choice([1_000_000, 999_999, 600_000, 1])
            body.append(cards.a_card(r.choice("+-"), 0, 0, rad, 0, r.choice([0, -rad, rad]),
                                     r.choice([rad, -rad, 0])))
        else:
            body.append(cards.m_card(r.choice("SBL"), _length(r), _length(r), _length(r),
                                     _length(r), r.choice([None, 2, 99999]),
                                     r.choice([10, 20, 11, 13])))
    return body


BODIES = {"mutated": mutated_body, "soup": soup_body, "bytes": bytes_body,
          "extreme": extreme_body, "stress": stress_body}


def guard(body: list[str]) -> list[str]:
    """The body with no card that ends the package: a C or E in column 1
    becomes c or e (an unknown card type), a line break inside a card is
    a blank."""
    out = []
    for ln in body:
        ln = ln.replace("\n", " ")
        if ln[:1] in ("C", "E"):
            ln = ln[0].lower() + ln[1:]
        out.append(ln)
    return out


def batch_deck(names: list[str], bodies: list[list[str]]) -> tuple[bytes, list[tuple[int, int]]]:
    """One deck of many packages, and each package's cards (first, last),
    numbered as TENZOR numbers them (one a line, from 1)."""
    lines: list[str] = []
    spans = []
    for n, (name, body) in enumerate(zip(names, bodies)):
        first = len(lines) + 1
        lines.append(name)
        lines += guard(body)
        lines.append("E" if n == len(names) - 1 else "C")
        spans.append((first, len(lines)))
    return ("\n".join(lines) + "\n").encode("latin-1"), spans


# ---------------------------------------------------------------------------
# Tapes and job sheets.
# ---------------------------------------------------------------------------
def random_frames(r: random.Random) -> list[Frame]:
    """Lines, travel, dots, full circles and cycles (valid, mostly)."""
    frames: list[Frame] = []
    for _ in range(r.randint(1, 8)):
        kind = r.random()
        if kind < 0.5:
            f = Frame(dx=r.randint(-6000, 6000), dy=r.randint(-6000, 6000), k=r.choice([10, 20]))
        elif kind < 0.7:
            x, y = r.randint(-3000, 3000), r.randint(-3000, 3000)
            f = Frame(x=x or 1, y=y, k=r.choice([11, 13]))
        else:
            f = Frame(k=10)
        if r.random() < 0.2:
            frames += [Frame(f.x, f.y, f.dx, f.dy, r.randint(2, 12), f.k),
                       Frame(dx=r.randint(-500, 500) or 1, k=20)]
        else:
            frames.append(f)
    return frames


def valid_tape(r: random.Random) -> bytes:
    """An encoded random frame list (code 8 or K); an empty tape if the
    frames break a rule."""
    try:
        return encode(random_frames(r), r.choice("8K"))
    except ValueError:
        return encode([])


def mutated_tape(r: random.Random, base: bytes) -> bytes:
    """A tape with rows flipped, set above 31, dropped, duplicated,
    inserted, swapped, or the tape cut (as test_fuzz_em703.st_mutated_tape)."""
    rows = bytearray(base)
    for _ in range(r.randint(1, 4)):
        if not rows:
            rows.append(0)
        what = r.choice(["flip", "flip", "drop", "dup", "insert", "swap", "cut", "high"])
        i = r.randrange(len(rows))
        if what == "flip":
            rows[i] = r.randint(0, 31)
        elif what == "high":
            rows[i] = r.randint(32, 255)
        elif what == "drop":
            del rows[i]
        elif what == "dup":
            rows.insert(i, rows[i])
        elif what == "insert":
            rows.insert(i, r.randint(0, 31))
        elif what == "swap":
            j = r.randrange(len(rows))
            rows[i], rows[j] = rows[j], rows[i]
        else:
            del rows[r.randint(0, len(rows)):]
    return bytes(rows)


def random_bytes(r: random.Random, most: int) -> bytes:
    return bytes(r.getrandbits(8) for _ in range(r.randint(0, most)))


def random_text(r: random.Random, most: int) -> str:
    """Text of printable ASCII, controls, Cyrillic and astral characters."""
    pools = [range(32, 127), range(32, 127), range(0, 32), range(0x400, 0x450),
             range(0x1F600, 0x1F610)]
    return "".join(chr(r.choice(r.choice(pools))) for _ in range(r.randint(0, most)))


#: Job sheet values (as test_fuzz_em703.VALUES).
JOB_VALUES = ["", " ", "-1", "0", "0.00", "1e309", "nan", "inf", "999999999999",
              "-999999999999", "1:0", "0:1", "a:b", "1:1:1", "100:1", "1:100", "8", "K", "Q",
              "x" * 3000, "\x00", "../nowhere.ptp", "/", ".", "t-small.ptp", "\u0416", "0.001",
              "20.00", "1200.01"]


def mutated_job(r: random.Random, base: str) -> bytes:
    lines = base.splitlines()
    for _ in range(r.randint(1, 5)):
        what = r.choice(["value", "value", "drop", "dup", "key", "raw", "blank"])
        i = r.randrange(len(lines))
        if what == "value" and " = " in lines[i]:
            lines[i] = f"{lines[i].split(' = ', 1)[0]} = {r.choice(JOB_VALUES)}"
        elif what == "drop":
            del lines[i]
            lines = lines or [""]
        elif what == "dup":
            lines.insert(i, lines[i])
        elif what == "key":
            lines.insert(i, f"{r.choice(['small.x', 'zz', '', 'scale ', '='])} = 1")
        elif what == "raw":
            lines[i] = random_text(r, 60)
        else:
            lines.insert(i, "")
    return ("\n".join(lines) + r.choice(["\n", "", "\r\n"])).encode("utf-8", "surrogatepass")


#: Numbers and words for command-line number arguments.
NUMBERS = ["0", "1", "-1", "9999", "10000", "99999999", "2147483647", "2147483648",
           "-2147483648", "-2147483649", "99999999999999999999", "1e9", "1.5", "", "-", "x",
           "0x10", "nan", "inf", " 5", "5 ", "+3", "\u0661"]


def number_word(r: random.Random) -> str:
    return r.choice(NUMBERS) if r.random() < 0.6 else str(r.randint(-20000, 20000))
