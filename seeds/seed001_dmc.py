"""Seed 001's own output: a DXF drawing to a program for a Galil motion
controller of the DMC-1040 kind (``dxf2dmc``).

The paper (seed 001, docs/SEED001-DXF.md) drove a laser direct-writing
device through a Galil DMC-1040; its interpreter read the drawing's TEXT
labels (FIRST, LAST, 1, 2, 3 ...) and macros (start, end, writing, stop,
with OUT switching commands), attached each to its nearest segment, and
wrote the controller's motion code in the labels' order, in one of two
modes: continuous (one motion, segment after segment) or intermittent (a
stop after every segment).  This module shares seed001's reader
(``read_drawing``: the entities, the labels, the problem lines, SPLINEs
flattened within the tolerance) and its ordering (``sequence``) with
``dxf2deck``, and writes the program in the subset of Galil's command
language docs/SEED001-DXF.md lists with the reference each follows:

* ``VM XY`` vector mode; ``VP x,y`` a straight segment to (x, y), counts,
  relative to the sequence's start point; ``CR r,θ,Δθ`` an arc of radius r
  counts starting at angle θ (degrees, 0 = +X, counter-clockwise positive)
  and traversing Δθ (negative: clockwise), angles to 1/256 of a degree;
  ``VE`` the sequence's end, ``BGS`` its start, ``AMS`` wait for its end;
  at most 511 segments a sequence;
* ``AV n`` waits until the sequence has gone n counts along its path:
  continuous mode switches the tool (and runs the macros) in the stream;
* ``PA x,y`` / ``BG XY`` / ``AM XY`` absolute moves with the tool off
  (intermittent mode's travel, and a new sequence's start);
* ``SB n`` / ``CB n`` set and clear output bit n: the writing tool (the
  laser, ``--tool-bit``) on and off around every drawn segment, and the
  macros' ``OUT n`` / ``OUT n OFF``; ``WT ms`` a macro's ``WAIT ms``;
* ``DP 0,0`` the drawing's origin is where the tool stands at the start;
  ``VS`` / ``SP`` the speeds; ``NO`` comments; ``#DXF`` the label; ``EN``.
"""

from __future__ import annotations

import argparse
import math
import re
import sys
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from harness.files import quiet_when_output_closes, write_whole

from . import seed001
from .contour import ArcEl, Seg, arc_chords
from .options import Parser, mm_list
from .seed001 import Item, Label, Point, TooBig

#: Default counts of the axes' encoders per mm (1 count = 1 µm).
COUNTS_PER_MM = 1000.0
#: Default vector and travel speed, mm/s.
SPEED_MM_S = 10.0
#: The output bit of the writing tool (the laser) by default.
TOOL_BIT = 1
#: Output bits a DMC-1040 has for OUT (1-8).
BITS = range(1, 9)
#: Segments (VP, CR) one vector sequence holds.
SEQ_MAX = 511
#: The largest count a position command takes.
COUNT_MAX = 2_147_483_647
#: A Galil program line holds at most this many characters.
LINE_MAX = 80

MODES = ("continuous", "intermittent")
MACROS = ("START", "END", "WRITING", "STOP")


@dataclass
class Macros:
    """The macro lines attached to one item, by kind."""

    start: list[str] = field(default_factory=list)
    end: list[str] = field(default_factory=list)
    writing: list[str] = field(default_factory=list)
    stop: list[str] = field(default_factory=list)


@dataclass
class Plan:
    """What dxf2dmc draws: the items in order with their macros, FIRST's and
    LAST's bodies, the mode the drawing asks for, the problems (each one line
    naming the handle and layer) and the notes that do not fail the run."""

    items: list[Item]
    macros: list[Macros]
    first_body: list[str]
    last_body: list[str]
    mode: str | None
    problems: list[str]
    notes: list[str]
    splines: int
    tolerance: float


def macro_body(words: Sequence[str]) -> list[str]:
    """Galil lines of a macro body: ``OUT n`` (SB n), ``OUT n OFF`` (CB n),
    ``OUT n ON``, ``WAIT ms`` (WT ms).  ValueError names what is unknown."""
    out: list[str] = []
    k = 0
    while k < len(words):
        w = words[k].upper()
        if w == "OUT" and k + 1 < len(words) and words[k + 1].isdigit():
            bit = int(words[k + 1])
            if bit not in BITS:
                raise ValueError(f"output {bit} is not one of {BITS.start}-{BITS.stop - 1}")
            k += 2
            state = "ON"
            if k < len(words) and words[k].upper() in ("ON", "OFF"):
                state = words[k].upper()
                k += 1
            out.append(f"{'SB' if state == 'ON' else 'CB'} {bit}")
        elif w == "WAIT" and k + 1 < len(words) and words[k + 1].isdigit():
            ms = int(words[k + 1])
            if not 2 <= ms <= 2_147_483_646:
                raise ValueError(f"WAIT {ms} ms is not 2 to 2147483646 ms")
            out.append(f"WT {ms}")
            k += 2
        else:
            raise ValueError(f"unknown macro command {' '.join(words[k:k + 2])!r} "
                             f"(OUT n, OUT n OFF, WAIT ms)")
    return out


def _where(lab: Label) -> str:
    return lab.where


def plan(reading: seed001.Reading) -> Plan:
    """Attach the labels and macros of a reading to their nearest items
    (section 4 of the paper) and order the items."""
    items = reading.items
    problems, notes = reading.problems, []
    first: list[int] = []
    last: list[int] = []
    numbered: dict[int, int] = {}
    attached: list[tuple[str, int, list[str]]] = []
    first_body: list[str] = []
    last_body: list[str] = []
    mode: str | None = None
    last_where = "LAST"
    nearest = seed001._Nearest(items) if items else None
    for lab in reading.labels:
        words = lab.text.split()
        if not words:
            continue
        head = words[0].upper()
        where = _where(lab)
        if head in ("MODE", "CONTINUOUS", "INTERMITTENT"):
            word = (words[1] if head == "MODE" and len(words) == 2 else
                    words[0] if head != "MODE" and len(words) == 1 else "").lower()
            if word not in MODES:
                problems.append(f"{where}: {lab.text!r} is not MODE CONTINUOUS or "
                                f"MODE INTERMITTENT; left out")
            elif mode and mode != word:
                problems.append(f"{where}: a second mode {word}; the first, {mode}, is used")
            else:
                mode = word
            continue
        is_label = head in ("FIRST", "LAST") or words[0].isdigit()
        if not is_label and head not in MACROS:
            if any(w.upper() in ("OUT", "WAIT") for w in words):
                problems.append(f"{where}: unknown macro {words[0]!r} in {lab.text!r} "
                                f"(START, END, WRITING, STOP, FIRST, LAST); left out")
            else:
                notes.append(f"{where}: text {lab.text!r} is a hint, not a label or "
                             f"macro; left out")
            continue
        try:
            body = macro_body(words[1:])
        except ValueError as exc:
            problems.append(f"{where}: {exc}; {lab.text!r} left out")
            continue
        if nearest is None:
            problems.append(f"{where}: {words[0]} has no segment to attach to")
            continue
        if head in ("FIRST", "LAST") and (first if head == "FIRST" else last):
            problems.append(f"{where}: {head} given again; the first in the drawing is used, "
                            f"this one ignored")
            continue
        near = nearest(lab.at)
        if head == "FIRST":
            first.append(near)
            first_body = body
        elif head == "LAST":
            last.append(near)
            last_body = body
            last_where = where
        elif is_label:
            n = int(words[0])
            if body:
                problems.append(f"{where}: a number carries no macro; write it as its own "
                                f"text (START, END, WRITING, STOP); {lab.text!r} left out")
                continue
            if n in numbered:
                problems.append(f"{where}: order number {n} given twice; this one ignored")
                continue
            numbered[n] = near
        else:
            if not body:
                problems.append(f"{where}: macro {head} has no commands; left out")
                continue
            attached.append((head, near, body))
    order = seed001.sequence(len(items), first, numbered, last, problems, last_where)
    if order is None:
        order = list(range(len(items)))
    per_item = [Macros() for _ in items]
    for head, near, body in attached:
        getattr(per_item[near], head.lower()).extend(body)
    return Plan([items[i] for i in order], [per_item[i] for i in order], first_body,
                last_body, mode, problems, notes, reading.splines, reading.tolerance)


# ---------------------------------------------------------------------------
# The path of an item, in counts.
# ---------------------------------------------------------------------------
def item_path(it: Item) -> list[Seg | ArcEl]:
    """The elements an item draws: its segments; a pad's circle (from its
    rightmost point, counter-clockwise) or rectangle (counter-clockwise)."""
    if it.disc is not None:
        x, y, r = it.disc
        return [ArcEl(x, y, x + r, y, x + r, y, cw=False)]
    if it.rect is not None:
        x0, y0, x1, y1 = it.rect
        return [Seg(x0, y0, x1, y0), Seg(x1, y0, x1, y1), Seg(x1, y1, x0, y1), Seg(x0, y1, x0, y0)]
    return list(it.segments)


@dataclass
class Move:
    """One segment of a vector sequence: VP to ``to`` (absolute counts) or
    CR r, θ, Δθ (θ, Δθ in 1/256 degree) ending at ``to`` (the controller's
    end, not on the count grid)."""

    to: tuple[float, float]
    cr: tuple[int, int, int] | None = None

    def length(self, at: tuple[float, float]) -> float:
        if self.cr is None:
            return math.dist(at, self.to)
        r, _, d = self.cr
        return r * abs(d) / 256 * math.pi / 180


def _q(v: float, cpm: float) -> int:
    return int(math.floor(v * cpm + 0.5))


def _angle(k: int) -> str:
    """k/256 of a degree, exactly, as a decimal."""
    text = f"{k / 256:.8f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def arc_move(at: tuple[float, float], a: ArcEl, cpm: float) -> Move:
    """A CR from the controller's position ``at`` (counts) along arc a."""
    r = _q(a.r, cpm)
    th = math.degrees(math.atan2(a.y0 - a.cy, a.x0 - a.cx))
    sweep = math.degrees(a.sweep) * (-1 if a.cw else 1)
    kt, kd = round(th * 256), round(sweep * 256)
    cx = at[0] - r * math.cos(math.radians(kt / 256))
    cy = at[1] - r * math.sin(math.radians(kt / 256))
    e = math.radians((kt + kd) / 256)
    return Move((cx + r * math.cos(e), cy + r * math.sin(e)), (r, kt, kd))


def item_moves(it: Item, cpm: float, tol: float) -> tuple[tuple[int, int], list[Move]]:
    """The start point (counts) and the moves that draw an item.  An arc is a
    CR when the CR's own rounding (a count of radius and start, 1/256 degree
    of each angle) stays within the tolerance, else chords within the
    tolerance less a count.  ValueError: a count beyond the controller's."""
    path = item_path(it)
    start = (_q(path[0].x0, cpm), _q(path[0].y0, cpm))
    at: tuple[float, float] = start
    moves: list[Move] = []
    chord_tol = tol - 1 / cpm
    for el in path:
        if isinstance(el, ArcEl):
            r = el.r * cpm
            if r >= 10 and 1.0 + r * math.pi / 180 / 256 <= tol * cpm:
                m = arc_move(at, el, cpm)
                moves.append(m)
                at = m.to
                continue
            pts = arc_chords(el, chord_tol)[1:]
        else:
            pts = [(el.x1, el.y1)]
        for x, y in pts:
            to = (_q(x, cpm), _q(y, cpm))
            if to != at:
                moves.append(Move(to))
                at = to
    for m in moves:
        if max(abs(m.to[0]), abs(m.to[1])) + (m.cr[0] if m.cr else 0) > COUNT_MAX:
            raise ValueError(f"a position of {max(abs(m.to[0]), abs(m.to[1])):.0f} counts is "
                             f"beyond the controller's {COUNT_MAX}")
    return start, moves


# ---------------------------------------------------------------------------
# The program.
# ---------------------------------------------------------------------------
@dataclass
class Run:
    """One stretch the tool draws: its start (counts), its moves, the macro
    lines before the tool goes on, just after, and after it goes off."""

    title: str
    start: tuple[int, int]
    moves: list[Move]
    before: list[str]
    writing: list[str]
    after: list[str]
    stop: list[str]


def runs_of(pl: Plan, cpm: float, tol: float) -> list[Run]:
    """The runs of a plan; an item of more moves than a sequence holds is cut
    into several runs (the tool off and on again between them)."""
    runs: list[Run] = []
    for n, (it, mac) in enumerate(zip(pl.items, pl.macros), 1):
        try:
            start, moves = item_moves(it, cpm, tol)
        except ValueError as exc:
            pl.problems.append(f"{it.kind} of #{it.handle} on layer {it.layer}: {exc}; left out")
            continue
        if not moves:
            pl.problems.append(f"{it.kind} of #{it.handle} on layer {it.layer}: shorter than "
                               f"a count; left out")
            continue
        parts = [moves[k:k + SEQ_MAX - 1] for k in range(0, len(moves), SEQ_MAX - 1)]
        at: tuple[float, float] = start
        for k, part in enumerate(parts):
            first, final = k == 0, k == len(parts) - 1
            title = f"segment {n}: #{it.handle} on layer {it.layer}"
            if len(parts) > 1:
                title += f" (part {k + 1} of {len(parts)})"
            p0 = (round(at[0]), round(at[1]))
            runs.append(Run(title, p0, part, mac.start if first else [],
                            mac.writing if first else [], mac.end if final else [],
                            mac.stop if final else []))
            at = part[-1].to
    return runs


def _move_line(m: Move, origin: tuple[int, int]) -> str:
    if m.cr is None:
        return f"VP {round(m.to[0]) - origin[0]},{round(m.to[1]) - origin[1]}"
    r, kt, kd = m.cr
    return f"CR {r},{_angle(kt)},{_angle(kd)}"


def _comment(text: str) -> str:
    text = re.sub(r"[^A-Za-z0-9 .,:#()_+=/-]", "_", text)
    return ("NO " + text)[:LINE_MAX]


def program(pl: Plan, mode: str, cpm: float = COUNTS_PER_MM, tol: float = seed001.SPLINE_TOL,
            speed: float = SPEED_MM_S, tool: int = TOOL_BIT, title: str = "") -> str:
    """The Galil program of a plan, one command a line."""
    runs = runs_of(pl, cpm, tol)
    vs = max(1, round(speed * cpm))
    out = ["#DXF", _comment(f"dxf2dmc {title}"),
           _comment(f"{mode} mode, {cpm:g} counts/mm, tolerance {tol:g} mm, tool bit {tool}"),
           "DP 0,0", f"CB {tool}", f"VS {vs}", f"SP {vs},{vs}"]
    out += pl.first_body
    pos: tuple[float, float] = (0.0, 0.0)
    if mode == "intermittent":
        for run in runs:
            out.append(_comment(run.title))
            if pos != run.start:
                out += [f"PA {run.start[0]},{run.start[1]}", "BG XY", "AM XY"]
            out += run.before + [f"SB {tool}"] + run.writing + ["VM XY"]
            out += [_move_line(m, run.start) for m in run.moves]
            out += ["VE", "BGS", "AMS", f"CB {tool}"] + run.after + run.stop
            pos = run.moves[-1].to
    else:
        for run in runs:
            if run.stop:
                pl.notes.append(f"{run.title}: a STOP macro works in intermittent mode only "
                                f"(the paper); not used")
        seq: list[str] = []
        trips: list[tuple[float, list[str]]] = []
        origin = (0, 0)
        dist = 0.0

        def flush() -> None:
            if not seq:
                return
            out.extend(["VM XY"] + seq + ["VE", "BGS"])
            for d, lines in trips:
                if round(d) > 0:
                    out.append(f"AV {round(d)}")
                out.extend(lines)
            out.append("AMS")
            seq.clear()
            trips.clear()

        for run in runs:
            travel = pos != run.start
            if seq and len(seq) + len(run.moves) + travel > SEQ_MAX:
                flush()
                if pos != run.start:
                    out += [f"PA {run.start[0]},{run.start[1]}", "BG XY", "AM XY"]
                    pos = run.start
                origin, dist = run.start, 0.0
                travel = False
            if travel:
                m = Move(run.start)
                dist += m.length(pos)
                seq.append(_move_line(m, origin))
                pos = run.start
            trips.append((dist, [_comment(run.title)] + run.before + [f"SB {tool}"] + run.writing))
            for m in run.moves:
                dist += m.length(pos)
                seq.append(_move_line(m, origin))
                pos = m.to
            trips.append((dist, [f"CB {tool}"] + run.after))
        flush()
    out += pl.last_body
    out.append("EN")
    return "".join(line + "\n" for line in out)


# ---------------------------------------------------------------------------
# The command line.
# ---------------------------------------------------------------------------
DXF2DMC_HELP = (
    "Turn a DXF drawing (mm) into a Galil motion-controller program (DMC-1040 "
    "kind): LINE, LWPOLYLINE, POLYLINE, ARC, CIRCLE, SPLINE (flattened within "
    "--tolerance), INSERT exploded; TEXT labels FIRST, LAST, 1, 2, 3 ... order "
    "the segments, macros START/END/WRITING/STOP with OUT n [OFF] and WAIT ms "
    "attach to the nearest segment; the tool's output bit is set and cleared "
    "around every segment.  Whatever cannot be used is reported with its handle "
    "and layer (exit status 1; the program is still written).")


def _number(v: float) -> str:
    """A number as it was most likely given: a whole one without exponent."""
    return str(int(v)) if float(v).is_integer() and abs(v) < 1e16 else f"{v:.15g}"


def _run(args: argparse.Namespace) -> int:
    try:
        tol = seed001.check_tolerance(args.tolerance)
        cpm = float(args.counts_per_mm)
        if not (math.isfinite(cpm) and 1 <= cpm <= 1_000_000):
            raise ValueError(f"--counts-per-mm {_number(cpm)} is not 1 to 1000000")
        if 2 / cpm > tol:
            raise ValueError(f"a count ({1 / cpm:g} mm) must be at most half the tolerance "
                             f"({tol:g} mm): --counts-per-mm {_number(cpm)} with --tolerance "
                             f"{tol:g} mm, where at least {_number(math.ceil(2 / tol - 1e-9))} counts "
                             f"a mm would do")
        speed = float(args.speed)
        if not (math.isfinite(speed) and 0 < speed <= 10_000):
            raise ValueError(f"--speed {speed:g} mm/s is not above 0 and at most 10000")
        if args.tool_bit not in BITS:
            raise ValueError(f"--tool-bit {args.tool_bit} is not one of 1-8")
        origin = mm_list(args.origin, "--origin", 2) if args.origin else (0.0, 0.0)
    except (ValueError, ArithmeticError) as exc:
        print(f"dxf2dmc: {exc}", file=sys.stderr)
        return 2
    try:
        doc = seed001.open_drawing(args.drawing)
    except seed001.Unreadable as exc:
        print(f"dxf2dmc: {exc}", file=sys.stderr)
        return 2
    try:
        # splines flattened a count inside the tolerance: the counts' rounding
        # then keeps every chord within it
        reading = seed001.read_drawing(doc, origin, tol - 1 / cpm)
    except TooBig as exc:
        print(f"dxf2dmc: {args.drawing}: {exc}", file=sys.stderr)
        return 1
    pl = plan(reading)
    mode = args.mode or pl.mode or "continuous"
    text = program(pl, mode, cpm, tol, speed, args.tool_bit, Path(args.drawing).name)
    for line in pl.problems + pl.notes:
        print(f"dxf2dmc: {args.drawing}: {line}", file=sys.stderr)
    if reading.splines:
        print(f"dxf2dmc: {args.drawing}: {reading.spline_note()} (the tolerance {tol:g} mm "
              f"less a count)", file=sys.stderr)
    if not pl.items:
        print(f"dxf2dmc: {args.drawing}: nothing to draw", file=sys.stderr)
        return 1
    if args.output:
        try:
            write_whole(args.output, text, inputs=[args.drawing])
        except OSError as exc:
            print(f"dxf2dmc: {args.output}: {exc.strerror or exc}", file=sys.stderr)
            return 2
    else:
        sys.stdout.write(text)
    return 1 if pl.problems else 0


def _arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("drawing", metavar="DRAWING.dxf")
    p.add_argument("-o", "--output", metavar="PROG.dmc", help="output program (default stdout)")
    p.add_argument("--mode", choices=MODES,
                   help="continuous: one vector sequence, the tool switched in the stream; "
                        "intermittent: a stop after every segment (default: the drawing's "
                        "MODE text, else continuous)")
    p.add_argument("--tolerance", metavar="MM", type=float, default=seed001.SPLINE_TOL,
                   help=f"the program stays within this of the drawing (default "
                        f"{seed001.SPLINE_TOL} mm): splines and wide arcs become chords")
    p.add_argument("--counts-per-mm", metavar="N", type=float, default=COUNTS_PER_MM,
                   help=f"encoder counts per mm (default {COUNTS_PER_MM:g}: 1 count = 1 µm)")
    p.add_argument("--speed", metavar="MM/S", type=float, default=SPEED_MM_S,
                   help=f"vector and travel speed (default {SPEED_MM_S:g} mm/s)")
    p.add_argument("--tool-bit", metavar="N", type=int, default=TOOL_BIT,
                   help=f"the output bit that switches the writing tool (default {TOOL_BIT})")
    p.add_argument("--origin", metavar="X,Y",
                   help="the drawing point (mm) where the tool stands at the start (default 0,0)")
    p.set_defaults(func=_run)


def add_dxf2dmc(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("dxf2dmc", help="a DXF drawing to a Galil DMC program (seed 001)",
                       description=DXF2DMC_HELP)
    _arguments(p)


@quiet_when_output_closes
def main(argv: Sequence[str] | None = None) -> int:
    """The console script ``dxf2dmc``: ``python -m seeds dxf2dmc`` alone."""
    parser = Parser(prog="dxf2dmc", description=DXF2DMC_HELP)
    _arguments(parser)
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0)
    return int(args.func(args))
