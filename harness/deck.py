"""TENZOR card decks, read independently, and the IDEAL layers they describe.

Source: docs/CARDS.md (the card layouts) and the harness's decisions on
what each card should look like on film.  All lengths are integers in
0.01 mm ("units") unless a name ends in ``_mm``.

The parser reads VALID decks only, strictly: anything it does not
understand (a malformed number, a non-blank unused column, a card out of
place) raises ValueError naming the 1-based card (line) number, so that a
test can never pass on a misread deck.  Error diagnosis is TENZOR's job.
It refuses every card fault TENZOR refuses, at the same card, but whether
the drawing stays on the field (verify checks the tapes against it), FMAX
(how moves are cut into frames, never what is drawn), TENZOR's capacities
(MXCRD ...), and names that make the same file (verify refuses a deck with
two).

The ideal shapes and layers (:class:`~harness.shapes.Disc`,
:class:`~harness.shapes.RoundRect`, :class:`~harness.shapes.Stroke`,
:class:`~harness.shapes.ArcBand`, :class:`~harness.shapes.Layer`) are in
:mod:`harness.shapes`; each shape of a layer has the card that asks for it.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from decimal import Decimal

from . import sim
from .shapes import (TWO_PI, AnyShape, ArcBand, Disc, Layer, Origin, RoundRect, Stroke,
                     distinct_strokes, run_shapes)
from .tape import MAX_RADIUS, Frame, sequence_problem

LAYERS: tuple[str, ...] = ("small", "large", "cond")
#: Tape letter of an M card (column 2) -> layer key.
M_TAPES: dict[str, str] = {"S": "small", "B": "large", "L": "cond", " ": "cond"}
#: The P card's ranges (docs/CARDS.md), in units: a tool; the working field
#: on both axes, 1200 mm (X0, Y0, DMAX; verify's field too); the machine's
#: nine scales (N, D).
MAX_TOOL = 2000
FIELD = 120_000
SCALES: tuple[tuple[int, int], ...] = ((1, 100), (1, 10), (1, 5), (1, 2), (1, 1), (2, 1),
                                      (5, 1), (50, 1), (100, 1))

# ---------------------------------------------------------------------------
# Deck items.
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Pad:
    """One D card: N pads of W (x H) at (x + i*sx, y + i*sy)."""

    card: int
    x: int
    y: int
    w: int
    h: int | None
    n: int
    sx: int
    sy: int

    @property
    def size(self) -> int:
        return max(self.w, self.h or 0)

    def centres(self) -> list[tuple[int, int]]:
        return [(self.x + i * self.sx, self.y + i * self.sy) for i in range(self.n)]


@dataclass(frozen=True)
class Conductor:
    """An L card and its + cards; ``point_cards``: the card of each point."""

    card: int
    w: int
    points: tuple[tuple[int, int], ...]
    point_cards: tuple[int, ...] = field(compare=False)


@dataclass(frozen=True)
class Circle:
    """An O card; ``clockwise`` is the + direction."""

    card: int
    clockwise: bool
    x: int
    y: int
    r: int


@dataclass(frozen=True)
class ArcCard:
    """An A card; ``clockwise`` is the + direction."""

    card: int
    clockwise: bool
    xc: int
    yc: int
    xs: int
    ys: int
    xe: int
    ye: int


@dataclass
class Package:
    """One data package of a deck, with its ideal layers.

    ``start_mm``: the start point's place on the field (X0, Y0) in mm;
    ``tools``: (w1, w2, w3) and ``dmax`` in units; ``scale``: (N, D);
    ``code``: "8" or "K"; ``order``: "O" or "D"; ``layers``: 'small',
    'large', 'cond'; ``m_frames``: the M frames per layer key, and
    ``m_cards`` the card number of each.
    """

    name: str
    start_mm: tuple[Decimal, Decimal]
    tools: tuple[int, int, int]
    dmax: int
    scale: tuple[int, int]
    code: str
    order: str
    layers: dict[str, Layer]
    m_frames: dict[str, list[Frame]] = field(default_factory=dict)
    m_cards: dict[str, list[int]] = field(default_factory=dict)
    pads: list[Pad] = field(default_factory=list)
    conductors: list[Conductor] = field(default_factory=list)
    circles: list[Circle] = field(default_factory=list)
    arcs: list[ArcCard] = field(default_factory=list)
    first_card: int = 0

    @property
    def start(self) -> tuple[int, int]:
        """(X0, Y0) in units."""
        return int(self.start_mm[0] * 100), int(self.start_mm[1] * 100)

    @property
    def file_name(self) -> str:
        """The package name as TENZOR's output files spell it."""
        return sanitise(self.name)


def sanitise(name: str) -> str:
    """docs/FILES.md: letters, digits, '-' and '_' kept, anything else becomes '_'
    (leading and trailing blanks of the name card dropped first)."""
    return re.sub(r"[^A-Za-z0-9_-]", "_", name.strip())


# ---------------------------------------------------------------------------
# Fields.
# ---------------------------------------------------------------------------
class CardError(ValueError):
    """A card the strict parser does not understand."""

    def __init__(self, card: int, message: str) -> None:
        super().__init__(f"card {card}: {message}" if card else
                         f"at the end of the deck: {message}")
        self.card = card            # 0: a fault of the deck as a whole, at its end


_REAL = re.compile(r"^ *([+-]?)(\d*)(\.?)(\d*) *$")
_INT = re.compile(r"^ *([+-]?\d+)$")
#: A character that is not printable ASCII (space to tilde).
_NOT_PRINTABLE = re.compile(r"[^ -~]")


def _cols(card: str, a: int, b: int) -> str:
    """Columns a..b (1-based, inclusive) of a card padded to 80."""
    return card[a - 1:b].ljust(b - a + 1)


def real(card: str, a: int, b: int, no: int, default: int | None = 0) -> int | None:
    """Fw.2 field in columns a..b -> units; blank -> ``default``.

    Without a decimal point the value has two implied decimals and must be
    right-justified (trailing blanks would mean different values under
    Fortran's BN and BZ modes).  More than two decimals must be zeros.
    """
    text = _cols(card, a, b)
    if not text.strip():
        return default
    m = _REAL.match(text)
    if not m or not (m.group(2) or m.group(4)):
        raise CardError(no, f"columns {a}-{b}: not a number: {text!r}")
    sign, whole, point, frac = m.groups()
    if not point:
        if text.rstrip() != text:
            raise CardError(no, f"columns {a}-{b}: a number without a point must "
                                f"be right-justified: {text!r}")
        value = int(whole + frac)
    else:
        if frac[2:].strip("0"):
            raise CardError(no, f"columns {a}-{b}: more than two decimals: {text!r}")
        value = int(whole or "0") * 100 + int((frac + "00")[:2])
    if value > 999_999_999:
        raise CardError(no, f"columns {a}-{b}: more than nine digits (at most "
                            f"9999999.99 mm): {text!r}")
    return -value if sign == "-" else value


def integer(card: str, a: int, b: int, no: int, default: int | None = None) -> int | None:
    """Iw field in columns a..b (right-justified); blank -> ``default``."""
    text = _cols(card, a, b)
    if not text.strip():
        return default
    if not _INT.match(text):
        raise CardError(no, f"columns {a}-{b}: not a right-justified integer: {text!r}")
    return int(text)


def _blank(card: str, cols: Sequence[tuple[int, int]], no: int) -> None:
    for a, b in cols:
        if _cols(card, a, b).strip():
            raise CardError(no, f"columns {a}-{b} must be blank: {_cols(card, a, b)!r}")


#: The number fields of each data card type: (first column, last column,
#: implied decimals); docs/CARDS.md's tables.
FIELDS: dict[str, tuple[tuple[int, int, int], ...]] = {
    "P": ((3, 10, 0), (11, 20, 2), (21, 30, 2), (31, 38, 2), (39, 46, 2), (47, 54, 2),
          (55, 62, 2), (63, 65, 0), (66, 68, 0)),
    "D": ((11, 20, 2), (21, 30, 2), (31, 38, 2), (39, 46, 2), (47, 50, 0), (51, 60, 2),
          (61, 70, 2)),
    "L": ((11, 20, 2), (21, 30, 2), (31, 38, 2)),
    "+": ((11, 20, 2), (21, 30, 2)),
    "O": ((11, 20, 2), (21, 30, 2), (31, 40, 2)),
    "A": tuple((a, a + 9, 2) for a in (11, 21, 31, 41, 51, 61)),
    "M": ((11, 20, 2), (21, 30, 2), (31, 40, 2), (41, 50, 2), (51, 55, 0), (56, 60, 0)),
}
#: The letter columns of each type and the letters they accept.
LETTERS: dict[str, tuple[tuple[int, str], ...]] = {
    "P": ((70, " 8K"), (71, " OD")), "O": ((2, "+-"),), "A": ((2, "+-"),),
    "M": ((2, " SBL"),),
}


def reads_as_data(card: str) -> str | None:
    """The type of data card a name card reads as, or None (docs/CARDS.md,
    "Packages"): column 1 is a data card type, every number field of the
    type is a well-formed number or blank and one at least is not blank,
    its letter columns hold letters it accepts, and no other column of
    2-72 is used."""
    kind = card[:1]
    if kind not in FIELDS:
        return None
    used = {1}
    for a, b, _ in FIELDS[kind]:
        used.update(range(a, b + 1))
    for col, ok in LETTERS.get(kind, ()):
        used.add(col)
        if _cols(card, col, col) not in ok:
            return None
    if any(c != " " and i not in used for i, c in enumerate(card.ljust(72)[:72], 1)):
        return None
    try:
        values = [real(card, a, b, 0, None) if d else integer(card, a, b, 0, None)
                  for a, b, d in FIELDS[kind]]
    except CardError:
        return None
    return kind if any(v is not None for v in values) else None


def _need(value: int | None, no: int, what: str) -> int:
    if value is None:
        raise CardError(no, f"{what} is required")
    return value


# ---------------------------------------------------------------------------
# The deck.
# ---------------------------------------------------------------------------
#: The monitor's control cards: keyword (blanks and ``_`` not counted) -> name,
#: and whether an argument may follow it (``*TIME:00.05``): ``*NO LOAD LIST``,
#: ``*EXECUTE`` and ``*END FILE`` take none, so ``*EXECUTEX`` is no card.
_CONTROL = {"NAME": ("NAME", True), "TIME": ("TIME", True), "PASS": ("PASS", True),
            "TAPE": ("TAPE", True), "PERSO": ("PERSO", True), "MAIN": ("MAIN", True),
            "NOLOADLIST": ("NO LOAD LIST", False), "CALL": ("CALL", True),
            "EXECUTE": ("EXECUTE", False), "ENDFILE": ("END FILE", False)}


def _control(card: str, no: int) -> str:
    """The keyword of a job control card (``*`` or ``#`` in column 1), read
    as the monitor read it (docs/CARDS.md): columns 2-72 in either case,
    blanks and ``_`` not counted, so ``#no _load _list`` is ``*NO LOAD
    LIST``; the first keyword the letters begin with.  ``*MAIN``'s argument
    (after blanks and colons) must be TENZOR."""
    text = card[1:72].replace("_", " ").upper()
    letters = text.replace(" ", "")
    for key, (name, argument) in _CONTROL.items():
        if letters == key or (argument and letters.startswith(key)):
            if name == "MAIN":
                # TENZOR's reading: after the first MAIN (else column 5 on)
                program = text[text.find("MAIN") + 4:].lstrip(" :").rstrip()
                if program != "TENZOR":
                    raise CardError(no, f"*MAIN names another program: {card!r}")
            return name
    raise CardError(no, f"unknown control card {card!r}")


def _cards(text: str) -> Iterator[tuple[int, str]]:
    """(number, card columns 1-72) for each non-blank data card, envelope
    removed; *END FILE (or the end of the text) ends the data."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    in_envelope = None
    for no, raw in enumerate(lines, 1):
        line = raw[:-1] if raw.endswith("\r") else raw
        if len(line) > 80:
            raise CardError(no, f"longer than 80 columns ({len(line)})")
        bad = _NOT_PRINTABLE.search(line)
        if bad:
            raise CardError(no, f"column {bad.start() + 1}: byte {bad.group()!r}")
        card = line[:72].rstrip()
        if not card:
            continue
        if card[0] in "*#":
            key = _control(card, no)
            if key == "END FILE":
                return
            if in_envelope is None:
                in_envelope = True
            if not in_envelope:
                raise CardError(no, f"control card among the data: {card!r}")
            if key == "EXECUTE":
                in_envelope = False
            continue
        if in_envelope:
            raise CardError(no, f"data card before *EXECUTE: {card!r}")
        in_envelope = False
        yield no, card


class _Builder:
    """Collects one package's cards."""

    def __init__(self, name: str, no: int) -> None:
        self.name = name
        self.first = no
        self.p_seen = False
        self.geometry = False
        self.x0 = self.y0 = 0
        self.w1, self.w2, self.w3 = 50, 100, 50
        self.dmax = 200
        self.scale = (1, 1)
        self.code = "8"
        self.order = "O"
        self.fmax = 0
        self.pads: list[Pad] = []
        self.conductors: list[Conductor] = []
        self.circles: list[Circle] = []
        self.arcs: list[ArcCard] = []
        self.m: dict[str, list[tuple[int, Frame]]] = {k: [] for k in LAYERS}
        self.open: tuple[int, int, list[tuple[int, int]], list[int]] | None = None
        # ^ the L card, W, the points and the card of each

    def close(self) -> None:
        if self.open is None:
            return
        no, w, pts, nos = self.open
        self.open = None
        if len(set(pts)) < 2:
            raise CardError(no, "conductor of zero length")
        self.conductors.append(Conductor(no, w, tuple(pts), tuple(nos)))

    def card(self, no: int, c: str) -> None:
        kind = c[0]
        if kind != "+":
            self.close()
        if kind == "P":
            self.p_card(no, c)
            return
        if kind in "DLOA":
            self.geometry = True
        handler = {"D": self.d_card, "L": self.l_card, "+": self.plus_card,
                   "O": self.o_card, "A": self.a_card, "M": self.m_card}.get(kind)
        if handler is None:
            raise CardError(no, f"unknown card type {kind!r} in column 1")
        handler(no, c)

    def p_card(self, no: int, c: str) -> None:
        if self.p_seen or self.geometry or any(self.m.values()):
            raise CardError(no, "P card must be the only one, before the geometry")
        self.p_seen = True
        _blank(c, [(2, 2), (69, 69), (72, 72)], no)
        # columns 3-10: FMAX, the frame limit (seed 004); it changes how the
        # moves are cut into frames, never what is drawn
        self.fmax = integer(c, 3, 10, no, 0)
        if self.fmax < 0:
            raise CardError(no, "FMAX must not be negative")
        self.x0 = real(c, 11, 20, no)
        self.y0 = real(c, 21, 30, no)
        self.w1 = real(c, 31, 38, no, 50)
        self.w2 = real(c, 39, 46, no, 100)
        self.w3 = real(c, 47, 54, no, 50)
        self.dmax = real(c, 55, 62, no, 200)
        self.scale = (integer(c, 63, 65, no, 1), integer(c, 66, 68, no, 1))
        code = _cols(c, 70, 70)
        order = _cols(c, 71, 71)
        if code not in " 8K" or order not in " OD":
            raise CardError(no, f"column 70 code {code!r} / column 71 order {order!r}")
        self.code = "K" if code == "K" else "8"
        self.order = "D" if order == "D" else "O"
        for v, what in ((self.w1, "w1"), (self.w2, "w2"), (self.w3, "w3"),
                        (self.dmax, "Dmax"), (self.scale[0], "scale N"),
                        (self.scale[1], "scale D")):
            if v <= 0:
                raise CardError(no, f"{what} must be positive")
        for v, what in ((self.w1, "w1"), (self.w2, "w2"), (self.w3, "w3")):
            if v > MAX_TOOL:
                raise CardError(no, f"{what} {v / 100:.2f} mm: tools are 0.01 to 20.00 mm")
        if self.dmax > FIELD:
            raise CardError(no, "Dmax is at most 1200.00 mm")
        if not (0 <= self.x0 <= FIELD and 0 <= self.y0 <= FIELD):
            raise CardError(no, "the start point X0, Y0 is off the 1200 x 1200 mm field")
        if self.scale not in SCALES:
            raise CardError(no, f"scale {self.scale[0]}:{self.scale[1]} is not one of the "
                                f"machine's")

    def d_card(self, no: int, c: str) -> None:
        _blank(c, [(2, 10), (71, 72)], no)
        w = _need(real(c, 31, 38, no, None), no, "pad W")
        h = real(c, 39, 46, no, None) or None          # blank or 0: a round pad
        n = integer(c, 47, 50, no, 1)
        if w <= 0 or (h is not None and h < 0) or n < 1:
            raise CardError(no, "pad W, H and N must be positive")
        sx, sy = real(c, 51, 60, no), real(c, 61, 70, no)
        if n > 1 and sx == sy == 0:
            raise CardError(no, f"a row of {n} pads needs a step (SX or SY)")
        self.pads.append(Pad(no, real(c, 11, 20, no), real(c, 21, 30, no), w, h, n, sx, sy))

    def l_card(self, no: int, c: str) -> None:
        _blank(c, [(2, 10), (39, 72)], no)
        w = real(c, 31, 38, no, None)
        w = self.w3 if w is None else w
        if w < self.w3:
            raise CardError(no, "conductor narrower than its tool")
        self.open = (no, w, [(real(c, 11, 20, no), real(c, 21, 30, no))], [no])

    def plus_card(self, no: int, c: str) -> None:
        _blank(c, [(2, 10), (31, 72)], no)
        if self.open is None:
            raise CardError(no, "+ card with no conductor open")
        self.open[2].append((real(c, 11, 20, no), real(c, 21, 30, no)))
        self.open[3].append(no)

    def _direction(self, no: int, c: str) -> bool:
        d = _cols(c, 2, 2)
        if d not in "+-":
            raise CardError(no, f"column 2 must be + or -, not {d!r}")
        return d == "+"

    def o_card(self, no: int, c: str) -> None:
        _blank(c, [(3, 10), (41, 72)], no)
        cw = self._direction(no, c)
        r = _need(real(c, 31, 40, no, None), no, "radius")
        if r <= 0:
            raise CardError(no, "radius must be positive")
        if r > MAX_RADIUS:
            raise CardError(no, "radius over 10 m, the machine's largest arc")
        self.circles.append(Circle(no, cw, real(c, 11, 20, no), real(c, 21, 30, no), r))

    def a_card(self, no: int, c: str) -> None:
        _blank(c, [(3, 10), (71, 72)], no)
        cw = self._direction(no, c)
        v = [real(c, a, a + 9, no) for a in (11, 21, 31, 41, 51, 61)]
        arc = ArcCard(no, cw, *v)
        rs = math.hypot(arc.xs - arc.xc, arc.ys - arc.yc)
        re_ = math.hypot(arc.xe - arc.xc, arc.ye - arc.yc)
        # the same checks as TENZOR's TZACRD, in its order
        if rs == 0:
            raise CardError(no, "the start of the arc is its centre")
        if re_ == 0:
            raise CardError(no, "the end of the arc is its centre")
        if (arc.xs, arc.ys) == (arc.xe, arc.ye):
            raise CardError(no, "the arc ends where it starts (a full circle is an O card)")
        if abs(rs - re_) > 1:
            raise CardError(no, f"arc start and end not on one circle ({rs:.2f}, {re_:.2f})")
        if rs > MAX_RADIUS:
            raise CardError(no, "radius over 10 m, the machine's largest arc")
        self.arcs.append(arc)

    def m_card(self, no: int, c: str) -> None:
        _blank(c, [(3, 10), (61, 72)], no)
        tape = _cols(c, 2, 2)
        if tape not in M_TAPES:
            raise CardError(no, f"column 2 tape must be S, B, L or blank, not {tape!r}")
        vals = [real(c, a, a + 9, no) for a in (11, 21, 31, 41)]
        cyc = integer(c, 51, 55, no, 0)
        k = _need(integer(c, 56, 60, no, None), no, "K")
        frame = Frame(*vals, cyc=cyc, k=k)
        self.m[M_TAPES[tape]].append((no, frame))

    def package(self) -> Package:
        self.close()
        tools = {"small": self.w1, "large": self.w2, "cond": self.w3}
        layers = {k: Layer(tools[k]) for k in LAYERS}
        m_frames: dict[str, list[Frame]] = {}
        m_cards: dict[str, list[int]] = {}
        for key in LAYERS:
            frames = [f for _, f in self.m[key]]
            m_frames[key] = frames
            m_cards[key] = [no for no, _ in self.m[key]]
            problem = sequence_problem(frames)
            if problem is not None:
                raise CardError(self.m[key][problem[0]][0], f"M frame: {problem[1]}")
            try:
                run = sim.simulate(frames)
            except ValueError as exc:
                no = self.m[key][0][0] if frames else self.first
                raise CardError(no, f"M frames of tape {key}: {exc}") from None
            for shape, i in zip(*distinct_strokes(run_shapes(run, tools[key]),
                                                  sim.stroke_frames(frames))):
                layers[key].add(shape, Origin(self.m[key][i][0], "M", i))
        for pad in self.pads:
            key = "small" if pad.size <= self.dmax else "large"
            tool = tools[key]
            if min(pad.w, pad.h or pad.w) < tool:
                raise CardError(pad.card, "pad smaller than its tool")
            for i, (cx, cy) in enumerate(pad.centres()):
                if pad.h is None:
                    shape: AnyShape = Disc(cx, cy, pad.w / 2)
                else:
                    shape = RoundRect(cx, cy, pad.w, pad.h, tool / 2)
                layers[key].add(shape, Origin(pad.card, "D", i, pad.n))
        cond = layers["cond"]
        for con in self.conductors:
            cond.add(Stroke(tuple((float(x), float(y)) for x, y in con.points),
                            con.w / 2), Origin(con.card, "L"))
        hw = self.w3 / 2
        for o in self.circles:
            cond.add(ArcBand(o.x, o.y, o.r, 0.0, -TWO_PI if o.clockwise else TWO_PI, hw),
                     Origin(o.card, "O"))
        for a in self.arcs:
            sx, sy = a.xs - a.xc, a.ys - a.yc
            sweep = sim.arc_sweep(sx, sy, a.xe - a.xc, a.ye - a.yc, a.clockwise)
            cond.add(ArcBand(a.xc, a.yc, math.hypot(sx, sy), math.atan2(sy, sx),
                             sweep, hw), Origin(a.card, "A"))
        return Package(
            name=self.name,
            start_mm=(Decimal(self.x0) / 100, Decimal(self.y0) / 100),
            tools=(self.w1, self.w2, self.w3), dmax=self.dmax, scale=self.scale,
            code=self.code, order=self.order, layers=layers, m_frames=m_frames,
            m_cards=m_cards,
            pads=self.pads, conductors=self.conductors, circles=self.circles,
            arcs=self.arcs, first_card=self.first)


def parse_deck(text: str) -> list[Package]:
    """Parse a valid deck into its packages (see the module doc).

    Raises :class:`CardError` (a ValueError) with the card number on
    anything it does not understand, including a deck without the final E.
    """
    packages: list[Package] = []
    builder: _Builder | None = None
    state = "name"            # "name": expecting a name card; "data"; "done" after E
    for no, card in _cards(text):
        if state == "done":
            raise CardError(no, f"card after the final E: {card!r}")
        if state == "name":
            if card in ("C", "E"):
                raise CardError(no, f"a bare {card} where a name card is due (the package "
                                    f"before ends with one C or one E)")
            builder = _Builder(card[:18].rstrip(), no)
            if not builder.name.strip():
                raise CardError(no, "blank package name")
            kind = reads_as_data(card)
            if kind is not None:
                raise CardError(no, f"the name card reads as a {kind} card: "
                                    f"is the name card missing? {card!r}")
            _blank(card, [(19, 72)], no)
            state = "data"
            continue
        assert builder is not None
        if card[0] in "CE":
            _blank(card, [(2, 72)], no)
            packages.append(builder.package())
            state = "name" if card[0] == "C" else "done"
            builder = None
            continue
        builder.card(no, card)
    if state != "done":
        raise CardError(0, "the deck ends without the E card (the last package must end "
                           "with a card of E in column 1)")
    return packages
