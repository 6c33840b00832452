"""Seed 002 end to end: a part's contour to a 5121 tape, as the Ural-1 did it.

Source: seed 002 (docs/SOURCES.md), the section "Расчет программы обработки
контура фланца" and the punch's relay block.  The steps, each the paper's:

1. the contour (a TENZOR deck of L/+ and A cards, one closed contour a
   package) and the cutter-centre equidistant (cutter 20 mm), unless the
   deck already is the cutter's path (``path=True``: the reading of Table 5
   argued in docs/SEED002-URAL1.md);
2. every arc as chords with the step angle Δφ = 2 arccos(1 - y/R0) (y the
   tolerance, 0.02 mm in the paper);
3. each section's length l and time t = l/s · 60 s at the feed s
   (60 mm/min in the paper);
4. the chords in pulses (0.01 mm), split at the interpolator counter's limit
   (9999 pulses, seed 004), each frame with its speed code (below);
5. the numbers translated into the 5121 code the way the Ural-1 program
   did it, by masks and shifts (:func:`translate_5121`), and the even frames
   shifted by two rows; the tape's length and its punching time on the
   ST-2M at 300 numbers a minute.

The speed code.  The paper's frame has one digit for it and gives no table.
Seed 004 says how a pulse-multiplier interpolator takes it: one cycle of
its counter is one frame, whatever the frame's length, and the cycle's time
is set by the generator's frequency, "as the program requires".  So the
code must give each frame its time: here code d (1-9) is a cycle of
``2**(d-1)`` seconds (1 s to 256 s, :data:`CYCLE_S`), and a frame takes the
shortest cycle not shorter than its time at the feed (the cutter never runs
faster than s).  The table is ours; docs/SEED002-URAL1.md says so.
"""

from __future__ import annotations

import argparse
import math
import sys
from dataclasses import dataclass
from collections.abc import Sequence
from pathlib import Path

from harness.deck import parse_deck
from harness.files import ascii_text, write_whole

from .contour import ArcEl, Element, Seg, arc_chords, equidistant, package_contour, units
from .seed002 import (CODE_5121, EVEN_SHIFT_ROWS, FLANGE_CUTTER_MM, ROWS_PER_FRAME, Frame5121,
                      cutter_problem, frame_rows_5121, punch_5121, read_5121, tetrad)
from .seed004 import DOCUMENT_MAX, split_move

#: The paper's feed (s_мин = 60 mm/min) and sag of the chords (y = 0.02 mm).
FEED_MM_MIN = 60.0
TOLERANCE_MM = 0.02
#: Speed code -> the interpolator's cycle (one frame), seconds.
CYCLE_S: dict[int, float] = {d: float(2 ** (d - 1)) for d in range(1, 10)}
#: The ST-2M punches "up to 300 numbers a minute" (one number = one row).
PUNCH_ROWS_PER_MIN = 300
#: A row of the tape image is 2.54 mm (the project's tapes' pitch).
ROW_MM = 2.54


@dataclass(frozen=True)
class Section:
    """One section of the cutter's path: its element, length (mm), the
    chord ends in pulses after its start, and its frames."""

    number: int
    element: Element
    length: float
    chords: int
    frames: tuple[Frame5121, ...]

    @property
    def kind(self) -> str:
        return "line" if isinstance(self.element, Seg) else "arc"

    def time_s(self, feed: float) -> float:
        """The paper's t = l/s · 60 (seconds)."""
        return self.length / feed * 60

    @property
    def coded_s(self) -> float:
        """The time of its frames at their speed codes (seconds)."""
        return sum(CYCLE_S[f.speed] for f in self.frames)


def speed_code(pulses_x: int, pulses_y: int, feed: float) -> int:
    """The speed code of a frame: the shortest cycle (:data:`CYCLE_S`) not
    shorter than the frame's time at ``feed`` mm/min; ValueError past 256 s."""
    t = math.hypot(pulses_x, pulses_y) / 100 / feed * 60
    for d, cycle in CYCLE_S.items():
        if cycle >= t - 1e-9:
            return d
    raise ValueError(f"a frame of {t:.1f} s at {feed:g} mm/min is longer than the longest "
                     f"cycle ({CYCLE_S[9]:g} s): raise the feed or lower --max")


def _length(e: Element) -> float:
    if isinstance(e, Seg):
        return math.hypot(e.x1 - e.x0, e.y1 - e.y0)
    return e.r * e.sweep


def sections(path: Sequence[Element], tol: float = TOLERANCE_MM, feed: float = FEED_MM_MIN,
             max_pulses: int = DOCUMENT_MAX) -> list[Section]:
    """The path's sections with their chords and frames.  Chord ends are
    rounded to whole pulses, so the frames of the whole path add up to the
    rounded ends exactly: the tape closes where the path does."""
    out: list[Section] = []
    for n, e in enumerate(path, 1):
        pts = [(e.x1, e.y1)] if isinstance(e, Seg) else arc_chords(e, tol)[1:]
        prev = (units(e.x0), units(e.y0))
        frames: list[Frame5121] = []
        for x, y in pts:
            cur = (units(x), units(y))
            for fx, fy in split_move(cur[0] - prev[0], cur[1] - prev[1], max_pulses):
                frames.append(Frame5121(fx, fy, 0, speed_code(fx, fy, feed)))
            prev = cur
        out.append(Section(n, e, _length(e), len(pts), tuple(frames)))
    return out


# ---------------------------------------------------------------------------
# The Ural-1's translation into 5121: masks and shifts.
# ---------------------------------------------------------------------------
#: The Ural-1 word: a sign and 35 digits.  A decimal number of up to eight
#: digits sits in it as BCD tetrads right after the sign.
WORD_BITS = 35


def bcd_word(value: int, digits: int) -> int:
    """|value| as BCD (8-4-2-1) tetrads from the word's top: the form in
    which the Ural-1 held its decimal results."""
    word = 0
    for i, ch in enumerate(str(abs(value)).rjust(digits, "0")):
        word |= int(ch) << (WORD_BITS - 4 * (i + 1))
    return word


def _bits(word: int, digits: int) -> str:
    """The word's sign and first tetrads as the paper prints its mask,
    "0,1111 0000 ...", then "..." for the rest of the word."""
    text = format(word >> (WORD_BITS - 4 * digits), f"0{4 * digits}b")
    return "0," + " ".join(text[i:i + 4] for i in range(0, len(text), 4)) + " ..."


def translate_5121(value: int, digits: int, explain: list[str] | None = None) -> list[int]:
    """The 5121 tetrads of |value| (``digits`` of them), found as the paper's
    Ural-1 program found them: the mask 0,1111 00...0 picks the first
    tetrad of the BCD word; a counter steps through the combinations x
    (0000, 0001, ... in the tetrad's place) until one equals it, and the
    counter's state sends its "bundle" combination y (the digit's 5121
    tetrad, Table 6) into the working cell, where the tetrads are added up;
    then the mask, x and y move four places right for the next tetrad.  With
    ``explain``, the steps are appended as lines of text."""
    word = bcd_word(value, digits)
    mask = 0b1111 << (WORD_BITS - 4)
    x_unit = 1 << (WORD_BITS - 4)            # combination x = counter * x_unit
    y_table = {d: tetrad(d) << (WORD_BITS - 4) for d in range(10)}
    cell = 0
    if explain is not None:
        explain.append(f"  number {abs(value)}: BCD word {_bits(word, digits)}")
    for i in range(digits):
        picked = word & mask
        counter = 0
        while counter * x_unit != picked:      # the counter's comparisons
            counter += 1
            if counter > 9:
                raise ValueError(f"tetrad {i + 1} of {value} is not a decimal digit")
        cell += y_table[counter]
        if explain is not None:
            explain.append(f"    tetrad {i + 1}: mask {_bits(mask, digits)} picks "
                           f"{_bits(picked, digits)}; x = {format(counter, '04b')} at count "
                           f"{counter}, y = {CODE_5121[counter]}; cell {_bits(cell, digits)}")
        mask >>= 4
        x_unit >>= 4
        y_table = {d: y >> 4 for d, y in y_table.items()}
    out = [(cell >> (WORD_BITS - 4 * (i + 1))) & 15 for i in range(digits)]
    if explain is not None:
        explain.append(f"    5121: {' '.join(format(t, '04b') for t in out)} "
                       f"(Table 6: {' '.join(str(abs(value)).rjust(digits, '0'))})")
    return out


def frame_rows_translated(f: Frame5121, explain: list[str] | None = None) -> list[int]:
    """The frame's 15 rows with every tetrad from :func:`translate_5121`;
    the same rows as :func:`seeds.seed002.frame_rows_5121` (its lookup
    table), which is checked here."""
    rows = frame_rows_5121(f)
    got = (translate_5121(f.dx, 4, explain) + translate_5121(f.dy, 4, explain)
           + translate_5121(f.dz, 3, explain) + translate_5121(f.speed, 1, explain))
    if [r & 15 for r in rows[:12]] != got:
        raise AssertionError(f"the translation of {f} differs from Table 6")
    return rows


# ---------------------------------------------------------------------------
# The whole run.
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Ural1Run:
    name: str
    sections: tuple[Section, ...]
    tape: bytes
    even_shift: bool

    @property
    def frames(self) -> list[Frame5121]:
        return [f for s in self.sections for f in s.frames]

    @property
    def frame_rows(self) -> int:
        """Rows of the frames (leader and trailer not counted)."""
        n = len(self.frames)
        return n * ROWS_PER_FRAME + (n // 2 * EVEN_SHIFT_ROWS if self.even_shift else 0)


def ural1_runs(text: str, path_given: bool = False, cutter_mm: float = FLANGE_CUTTER_MM,
               tol: float = TOLERANCE_MM, feed: float = FEED_MM_MIN,
               max_pulses: int = DOCUMENT_MAX, even_shift: bool = True,
               explain: list[str] | None = None) -> list[Ural1Run]:
    """Every package of a deck through the whole chain; one tape each."""
    out = []
    for pkg in parse_deck(text):
        try:
            contour, labels = package_contour(pkg)
            path = contour if path_given else equidistant(contour, cutter_mm / 2, True, labels)
            secs = sections(path, tol, feed, max_pulses)
        except ValueError as exc:
            raise ValueError(f"package {pkg.name.strip()}: {exc}") from None
        frames = [f for s in secs for f in s.frames]
        for k, f in enumerate(frames):
            frame_rows_translated(f, explain if (explain is not None and k == 0) else None)
        tape = punch_5121(frames, even_shift=even_shift)
        if read_5121(tape) != frames:
            raise AssertionError("the tape does not read back")
        out.append(Ural1Run(pkg.name.strip(), tuple(secs), tape, even_shift))
    return out


def report(run: Ural1Run, feed: float, tol: float) -> str:
    """What ``ural1`` prints for one tape."""
    lines = [f"{run.name}: {len(run.sections)} sections, feed {feed:g} mm/min, chords within "
             f"{tol:g} mm",
             "section  kind  length_mm  chords  frames  speed  t_s (l/s*60)  coded_s"]
    for s in run.sections:
        codes = sorted({f.speed for f in s.frames})
        # a section whose ends round to one pulse has no frame, and no code
        code = ("-" if not codes else str(codes[0]) if len(codes) == 1
                else f"{codes[0]}-{codes[-1]}")
        lines.append(f"{s.number:7d}  {s.kind:4s}  {s.length:9.2f}  {s.chords:6d}  "
                     f"{len(s.frames):6d}  {code:>5s}  {s.time_s(feed):12.1f}  "
                     f"{s.coded_s:7.0f}")
    total = sum(s.length for s in run.sections)
    t = sum(s.time_s(feed) for s in run.sections)
    coded = sum(s.coded_s for s in run.sections)
    n = len(run.frames)
    rows = run.frame_rows
    lines.append(f"path {total:.2f} mm, {t:.1f} s = {t / 60:.2f} min at {feed:g} mm/min "
                 f"({coded:.0f} s at the coded cycles)")
    lines.append(f"tape: {n} frames, {rows} rows"
                 + (f" (even frames shifted {EVEN_SHIFT_ROWS} rows)" if run.even_shift else "")
                 + f", {rows * ROW_MM / 1000:.2f} m; punching on the ST-2M at "
                 f"{PUNCH_ROWS_PER_MIN} numbers a minute: {rows / PUNCH_ROWS_PER_MIN:.1f} min")
    return "\n".join(lines) + "\n"


def _run_ural1(args: argparse.Namespace) -> int:
    problem = cutter_problem(args.cutter)
    if problem is None and not (math.isfinite(args.feed) and args.feed > 0):
        problem = f"--feed {args.feed:g}: a feed is a number of mm/min above 0"
    if problem is None and not (math.isfinite(args.tolerance) and args.tolerance > 0):
        problem = f"--tolerance {args.tolerance:g}: a chord tolerance is a number of mm above 0"
    if problem:
        print(f"ural1: {problem}", file=sys.stderr)
        return 2
    try:
        text = sys.stdin.read() if args.deck == "-" else ascii_text(Path(args.deck).read_bytes())
        explain: list[str] | None = [] if args.explain else None
        runs = ural1_runs(text, args.path, args.cutter, args.tolerance, args.feed, args.max,
                          not args.no_even_shift, explain)
        if len(runs) != 1 and args.output:
            raise ValueError(f"{len(runs)} packages: -o takes a deck of one contour")
        for run in runs:
            sys.stdout.write(report(run, args.feed, args.tolerance))
        if explain:
            sys.stdout.write("the first frame through the Ural-1's translation into 5121:\n")
            sys.stdout.write("\n".join(explain) + "\n")
        if args.output:
            write_whole(args.output, runs[0].tape, inputs=[args.deck])
    except OSError as exc:
        print(f"ural1: {exc.filename or args.deck}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    except ValueError as exc:
        print(f"ural1: {args.deck}: {exc}", file=sys.stderr)
        return 1
    return 0


def add_ural1(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "ural1", help="a part's contour to a 5121 tape, as the Ural-1 did it (seed 002)",
        description="Read a card deck whose L/+ and A cards form one closed contour, "
                    "compute the cutter-centre equidistant, cut the arcs into chords "
                    "within the tolerance, split the chords into frames at the counter's "
                    "limit with speed codes, and punch a 5121 tape (the LKP-01F's code); "
                    "print per section its length, speed code and time, and the tape's "
                    "length and punching time.")
    p.add_argument("deck", metavar="PART.crd", help="card deck ('-' = standard input)")
    p.add_argument("-o", "--output", metavar="PART.5121", help="the tape image (.ptp layout)")
    p.add_argument("--tolerance", type=float, default=TOLERANCE_MM, metavar="MM",
                   help="the chords' sag y, mm (default 0.02, the paper's)")
    p.add_argument("--cutter", type=float, default=FLANGE_CUTTER_MM,
                   help="cutter diameter, mm (default 20, the paper's)")
    p.add_argument("--feed", type=float, default=FEED_MM_MIN,
                   help="feed s, mm/min (default 60, the paper's)")
    p.add_argument("--max", type=int, default=DOCUMENT_MAX, metavar="N",
                   help="the most pulses of a frame (default 9999, four digits)")
    p.add_argument("--path", action="store_true",
                   help="the deck already is the cutter-centre path: no equidistant")
    p.add_argument("--no-even-shift", action="store_true",
                   help="do not shift the even frames two rows along the tape")
    p.add_argument("--explain", action="store_true",
                   help="show the first frame's translation into 5121 step by step")
    p.set_defaults(func=_run_ural1)
