"""EM-703 control tapes: the harness's own decoder and encoder.

Source: Pakhomov, JINR P11-10356 (1977), Table I "Коды координатографа
ЭМ-703" and the section "Состав кадра"; docs/TAPE.md and docs/FILES.md.  The code
table below is transcribed from the report by hand and shares nothing with
the Fortran programs this module checks.

A tape image (``.ptp``) holds one byte per row; the row is the low 5 bits
(track k = bit k-1).  Layout: blank leader, GM, frames, GM, blank trailer.
Rows are numbered from 1 = the first byte of the file.  Every error is a
:class:`TapeError` naming one row; an error found only when the data ends
names the row just past the last one (where the missing row should be).
The decoder reads like the machine's reader: row by row, reporting the
first error met, so a row's parity is checked wherever the row stands.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

# ---------------------------------------------------------------------------
# Table I.  Column "8" (octal) and column "8 code with control".
# ---------------------------------------------------------------------------
#: Rows of the digits 0..9 in the "8" code: the digit in binary.
DIGITS_8: tuple[int, ...] = (0o00, 0o01, 0o02, 0o03, 0o04,
                             0o05, 0o06, 0o07, 0o10, 0o11)
#: Rows of the digits in the "8 code with control": 3, 5, 6, 9 (an even
#: number of holes) get track 5, so every non-zero digit has odd parity.
DIGITS_K: tuple[int, ...] = (0o00, 0o01, 0o02, 0o23, 0o04,
                             0o25, 0o26, 0o07, 0o10, 0o31)
MINUS = 0o14   # знак минус
X = 0o12       # признак окружности X
Y = 0o13       # признак окружности Y
DX = 0o20      # ΔX
DY = 0o21      # ΔY
CYC = 0o30     # признак цикла Ц
K = 0o16       # признак команды К
KK = 0o17      # конец кадра КК
GM = 0o37      # граница массива ГМ
BLANK = 0o00   # an unpunched row (leader and trailer; digit 0 inside GM)

#: Service codes (identical in both variants) and their ASCII names.
SERVICE: dict[int, str] = {MINUS: "minus", X: "X", Y: "Y", DX: "DX", DY: "DY",
                           CYC: "CYC", K: "K", KK: "KK", GM: "GM"}

#: The commands of section 3: lower+straight, raise+straight, arc -, arc +.
COMMANDS: tuple[int, ...] = (10, 20, 11, 13)
#: Largest arc radius, 10 m in 0.01 mm units (report: "радиус дуги <= 10 м").
MAX_RADIUS = 1_000_000
#: The most digits a number on a tape has (docs/TAPE.md): 999 999 999 units,
#: 10 km; a tenth digit is an error at its row.
MAX_DIGITS = 9
#: An arc's end point may be off the start circle by at most this much.
ARC_TOLERANCE = 1
#: Codes accepted by :func:`decode` and :func:`encode`.
CODES: tuple[str, ...] = ("8", "K")

_FIELDS: tuple[str, ...] = ("X", "Y", "DX", "DY", "CYC")
_ADDRESS: dict[int, str] = {X: "X", Y: "Y", DX: "DX", DY: "DY", CYC: "CYC"}
_ROW_OF: dict[str, int] = {"X": X, "Y": Y, "DX": DX, "DY": DY, "CYC": CYC}


class TapeError(Exception):
    """A tape image that breaks the code or the frame grammar.

    ``row`` is the 1-based row (byte) number, ``message`` says what was
    expected and what was found.
    """

    def __init__(self, row: int, message: str) -> None:
        super().__init__(row, message)
        self.row = row
        self.message = message

    def __str__(self) -> str:
        return f"row {self.row}: {self.message}"


@dataclass(frozen=True)
class Frame:
    """One frame: 0 means the field is absent (a zero is never punched).

    ``cyc`` is the total number of executions of this frame and the next
    one (0 = no cycle); ``k`` is the command 10, 20, 11 or 13.
    """

    x: int = 0
    y: int = 0
    dx: int = 0
    dy: int = 0
    cyc: int = 0
    k: int = 10


@dataclass
class Tape:
    """A decoded tape: the code variant, its frames, its length in rows;
    ``starts``: the 1-based row of each frame's first row, when the
    decoder noted them (None otherwise)."""

    code: str
    frames: list[Frame]
    rows: int
    starts: list[int] | None = field(default=None, compare=False, repr=False)


# ---------------------------------------------------------------------------
# Geometry shared by the decoder and the encoder.
# ---------------------------------------------------------------------------
def _sqrt_within(p: int, q: int, t: int) -> bool:
    """True if sqrt(q) <= sqrt(p) + t, exactly, for integers p, q, t >= 0.

    sqrt(q) <= sqrt(p) + t  <=>  q - p - t*t <= 2*t*sqrt(p)
    <=>  d <= 0  or  d*d <= 4*t*t*p,  with d = q - p - t*t.
    """
    d = q - p - t * t
    return d <= 0 or d * d <= 4 * t * t * p


def on_circle(x: int, y: int, dx: int, dy: int,
              tolerance: int = ARC_TOLERANCE) -> bool:
    """True if the arc end (x+dx, y+dy) is within ``tolerance`` of the start
    circle: | |(x+dx, y+dy)| - |(x, y)| | <= tolerance, in exact integer
    arithmetic (squared radii, no floating point)."""
    p = x * x + y * y
    q = (x + dx) ** 2 + (y + dy) ** 2
    return _sqrt_within(p, q, tolerance) and _sqrt_within(q, p, tolerance)


def frame_problems(frame: Frame) -> list[tuple[str, str]]:
    """The rules one frame breaks, as (field, message) pairs in tape order.

    ``field`` is the field the message belongs to ("X", "DX", "K", ...), so a
    decoder can name its row and an encoder its frame.
    """
    out: list[tuple[str, str]] = []
    f = frame
    for name in ("x", "y", "dx", "dy", "cyc", "k"):
        value = getattr(f, name)
        if not isinstance(value, int) or isinstance(value, bool):
            out.append((name.upper(), f"{name.upper()} must be an int, "
                                      f"not {type(value).__name__}"))
    if out:
        return out
    for name in ("x", "y", "dx", "dy", "cyc"):
        if abs(getattr(f, name)) >= 10 ** MAX_DIGITS:
            out.append((name.upper(), f"{name.upper()} has more than {MAX_DIGITS} digits "
                                      f"(the largest number is {10 ** MAX_DIGITS - 1})"))
    if out:
        return out
    circular = f.k in (11, 13)
    if f.x and not circular:
        out.append(("X", f"X/Y only with K11/K13 (this frame is K{f.k:02d})"))
    elif f.y and not circular:
        out.append(("Y", f"X/Y only with K11/K13 (this frame is K{f.k:02d})"))
    if circular and (f.x or f.y) and f.x * f.x + f.y * f.y > MAX_RADIUS ** 2:
        field = "X" if f.x else "Y"
        r = math.sqrt(f.x * f.x + f.y * f.y)
        out.append((field, f"radius {r:.1f} exceeds {MAX_RADIUS} units (10 m)"))
    if circular and (f.x or f.y) and (f.dx or f.dy) \
            and not on_circle(f.x, f.y, f.dx, f.dy):
        r0 = math.hypot(f.x, f.y)
        r1 = math.hypot(f.x + f.dx, f.y + f.dy)
        field = "DX" if f.dx else "DY"
        out.append((field, f"arc end point is not on the circle: start radius "
                           f"{r0:.1f}, end radius {r1:.1f} (tolerance "
                           f"{ARC_TOLERANCE} unit)"))
    if f.cyc < 0 or f.cyc == 1:
        out.append(("CYC", f"CYC {f.cyc}: a cycle runs its pair at least 2 times"))
    if f.k not in COMMANDS:
        out.append(("K", f"K {f.k:02d} is not a command (10, 20, 11, 13)"))
    elif circular and not (f.x or f.y):
        out.append(("K", f"K{f.k} needs X or Y (the radius must be > 0)"))
    return out


def sequence_problem(frames: Sequence[Frame]) -> tuple[int, str] | None:
    """The first rule a frame list breaks, as (0-based frame index, message),
    or None.  Besides :func:`frame_problems`: a CYC frame needs a following
    frame, and that partner frame must not carry CYC itself (a CYC frame right
    after a completed pair is fine)."""
    opener: int | None = None          # index of a CYC frame awaiting its partner
    for i, f in enumerate(frames):
        if not isinstance(f, Frame):
            return i, f"not a Frame: {f!r}"
        problems = frame_problems(f)
        if problems:
            return i, problems[0][1]
        if opener is not None:
            if f.cyc:
                return i, (f"CYC on the second frame of a cycle pair "
                           f"(CYC frame {opener + 1})")
            opener = None
        elif f.cyc:
            opener = i
    if opener is not None:
        return opener, "CYC needs a following frame"
    return None


def check_frames(frames: Sequence[Frame]) -> None:
    """Raise ValueError("frame N: ...") (N 1-based) for the first broken rule
    of :func:`sequence_problem`."""
    problem = sequence_problem(frames)
    if problem is not None:
        raise ValueError(f"frame {problem[0] + 1}: {problem[1]}")


# ---------------------------------------------------------------------------
# Encoder.
# ---------------------------------------------------------------------------
def _check_code(code: str) -> tuple[int, ...]:
    if code == "8":
        return DIGITS_8
    if code == "K":
        return DIGITS_K
    raise ValueError(f"code must be '8' or 'K', not {code!r}")


def frame_rows(frame: Frame, code: str = "8") -> list[int]:
    """The rows of one frame (no validation; see :func:`check_frames`)."""
    digits = _check_code(code)
    rows: list[int] = []
    for name, address in (("x", X), ("y", Y), ("dx", DX), ("dy", DY),
                          ("cyc", CYC)):
        value = getattr(frame, name)
        if value:
            rows.append(address)
            if value < 0:
                rows.append(MINUS)
            rows.extend(digits[int(c)] for c in str(abs(value)))
    rows.append(K)
    rows.extend(digits[int(c)] for c in f"{frame.k:02d}")
    rows.append(KK)
    return rows


def encode(frames: Iterable[Frame], code: str = "8", leader: int = 20) -> bytes:
    """A tape image: ``leader`` blank rows, GM, the frames, GM, ``leader``
    blank rows.  Raises ValueError for frames that break the rules."""
    frames = list(frames)
    _check_code(code)
    if not isinstance(leader, int) or leader < 0:
        raise ValueError(f"leader must be a non-negative int, not {leader!r}")
    check_frames(frames)
    rows = [BLANK] * leader + [GM]
    for f in frames:
        rows.extend(frame_rows(f, code))
    rows += [GM] + [BLANK] * leader
    return bytes(rows)


# ---------------------------------------------------------------------------
# Decoder.
# ---------------------------------------------------------------------------
def describe(value: int) -> str:
    """A row for a message, regardless of the code: "X (12)", "digit 3 (23)"."""
    if value in SERVICE:
        return f"{SERVICE[value]} ({value:02o})"
    if value in DIGITS_8:
        return f"digit {DIGITS_8.index(value)} ({value:02o})"
    if value in DIGITS_K:
        return f"digit {DIGITS_K.index(value)} ({value:02o})"
    return f"row {value:02o}"


def _scan_code(data: bytes) -> tuple[str, int | None]:
    """Variant shown by the first digit row that tells 8 from K, and its
    row (None if no row tells them apart: then both variants are equal)."""
    plain = {DIGITS_8[d] for d in (3, 5, 6, 9)}
    controlled = {DIGITS_K[d] for d in (3, 5, 6, 9)}
    for i, value in enumerate(data):
        if value in plain:
            return "8", i + 1
        if value in controlled:
            return "K", i + 1
    return "8", None


@dataclass(frozen=True)
class _Row:
    n: int            # row number, 1-based
    value: int        # 0..31
    kind: str         # "digit" or a SERVICE name
    digit: int        # the digit, for kind == "digit"


class _Reader:
    """Reads rows one at a time and classifies them in one code variant."""

    def __init__(self, data: bytes, code: str, evidence: int | None) -> None:
        self.data = data
        self.code = code
        self.evidence = evidence     # auto mode: the row that chose the code
        self.i = 0
        own = DIGITS_8 if code == "8" else DIGITS_K
        self.digit_of = {v: d for d, v in enumerate(own)}
        other = DIGITS_K if code == "8" else DIGITS_8
        self.foreign = {other[d]: d for d in (3, 5, 6, 9)}

    @property
    def end_row(self) -> int:
        """The row just past the data: where a missing row would be."""
        return len(self.data) + 1

    def raw(self) -> tuple[int, int] | None:
        """Next (row number, value) with only the 5-track check, or None."""
        if self.i >= len(self.data):
            return None
        n, value = self.i + 1, self.data[self.i]
        self.i += 1
        if value > 0o37:
            text = ("; the file begins as text, not as a tape image"
                    if n == 1 and 32 <= value <= 126 else "")
            raise TapeError(n, f"byte {value:03o} (octal) has bits above the low 5 "
                               f"set (not a 5-track row: a row is 00 to 37){text}")
        return n, value

    def classify(self, n: int, value: int) -> _Row:
        if value in self.digit_of:
            return _Row(n, value, "digit", self.digit_of[value])
        if value in SERVICE:
            return _Row(n, value, SERVICE[value], -1)
        if value in self.foreign:
            d = self.foreign[value]
            if self.evidence is not None:
                first = self.data[self.evidence - 1]
                raise TapeError(n, f"mixed code: digit {d} punched as "
                                   f"{value:02o} (octal), but row {self.evidence} has "
                                   f"{describe(first)} of code {self.code}; one of the "
                                   "two is wrong: --code 8 or --code K names it")
            if self.code == "K":
                raise TapeError(n, f"parity error: digit {d} punched as "
                                   f"{value:02o}, controlled code expects "
                                   f"{DIGITS_K[d]:02o} (octal)")
            raise TapeError(n, f"code {value:02o} (octal) is not valid in code 8 "
                               f"(digit {d} of the controlled code K)")
        raise TapeError(n, f"code {value:02o} (octal) is not an EM-703 code")

    def next(self) -> _Row | None:
        got = self.raw()
        return None if got is None else self.classify(*got)


def _found(row: _Row) -> str:
    return describe(row.value)


def _expect_list(items: Sequence[str]) -> str:
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " or " + items[-1]


def _after_field(last: int) -> str:
    """What may follow the digits of field number ``last``."""
    return _expect_list(["digit", *_FIELDS[last + 1:], "K"])


def _read_number(rd: _Reader, name: str, signed: bool) -> tuple[int, _Row]:
    """Digits after the address ``name``; returns (value, next row)."""
    row = rd.next()
    negative = False
    if row is not None and signed and row.kind == "minus":
        negative = True
        row = rd.next()
    label = name + ("-" if negative else "")
    if row is None:
        raise TapeError(rd.end_row, "missing GM at the end of the tape "
                                    f"(the tape ends after {label})")
    if row.kind != "digit":
        want = "minus or digit" if signed and not negative else "digit"
        raise TapeError(row.n, f"expected {want} after {label}, found {_found(row)}")
    if row.digit == 0:
        nxt = rd.data[rd.i] if rd.i < len(rd.data) else None
        if nxt is not None and nxt in rd.digit_of:
            raise TapeError(row.n, f"leading zero in {name} (a number is punched from its "
                                   "first digit that is not 0)")
        raise TapeError(row.n, f"{name} is 0: a zero value is never punched")
    value = digits = 0
    while row is not None and row.kind == "digit":
        digits += 1
        if digits > MAX_DIGITS:
            raise TapeError(row.n, f"{name} has more than {MAX_DIGITS} digits (the largest "
                                   f"number is {10 ** MAX_DIGITS - 1})")
        value = value * 10 + row.digit
        row = rd.next()
    if row is None:
        raise TapeError(rd.end_row, "missing GM at the end of the tape "
                                    "(the tape ends inside a frame)")
    return (-value if negative else value), row


def _read_frame(rd: _Reader, first: _Row) -> tuple[Frame, dict[str, int]]:
    """One frame starting at ``first`` (not GM); returns it with the row of
    each field's address code and of K."""
    values: dict[str, int] = {}
    rows: dict[str, int] = {}
    last = -1
    row = first
    while row.kind in _FIELDS:
        index = _FIELDS.index(row.kind)
        if index <= last:
            raise TapeError(row.n, f"expected {_after_field(last)} after "
                                   f"{_FIELDS[last]}, found {_found(row)}")
        name = row.kind
        rows[name] = row.n
        value, row = _read_number(rd, name, signed=(name != "CYC"))
        if name == "CYC" and value < 2:
            raise TapeError(rows[name], f"CYC {value}: a cycle runs its pair "
                                        "at least 2 times")
        values[name] = value
        last = index
        if row.kind not in _FIELDS and row.kind != "K":
            raise TapeError(row.n, f"expected {_after_field(last)} after "
                                   f"{name}, found {_found(row)}")
    if row.kind != "K":             # only at the start of a frame
        hint = " (a blank row: is the closing GM missing?)" if row.value == BLANK else ""
        raise TapeError(row.n, "expected X, Y, DX, DY, CYC, K or GM at the "
                               f"start of a frame, found {_found(row)}{hint}")
    rows["K"] = row.n
    digits: list[int] = []
    k = 0
    while True:
        nxt = rd.next()
        if nxt is None:
            raise TapeError(rd.end_row, "missing GM at the end of the tape "
                                        "(the tape ends inside a frame)")
        if nxt.kind != "digit" or len(digits) == 2:
            if nxt.kind == "digit" or len(digits) < 2:
                raise TapeError(nxt.n, "K must be followed by exactly two digits, found "
                                       f"{_found(nxt)}")
            break
        digits.append(nxt.digit)
        if len(digits) == 2:
            k = digits[0] * 10 + digits[1]
            if k not in COMMANDS:
                raise TapeError(rows["K"], f"K {k:02d} is not a command "
                                           "(10, 20, 11, 13)")
    if nxt.kind != "KK":
        raise TapeError(nxt.n, f"expected KK after K{k:02d}, found {_found(nxt)}")
    frame = Frame(x=values.get("X", 0), y=values.get("Y", 0),
                  dx=values.get("DX", 0), dy=values.get("DY", 0),
                  cyc=values.get("CYC", 0), k=k)
    problems = frame_problems(frame)
    if problems:
        field, message = min(problems, key=lambda p: rows.get(p[0], rows["K"]))
        raise TapeError(rows.get(field, rows["K"]), message)
    return frame, rows


#: A row as one character, per code: a digit, X, Y, D (DX), E (DY), C
#: (CYC), - (minus), K, ; (KK), G (GM); ? for a row that is neither.
_CHARS: dict[str, bytes] = {}
for _code, _digits in (("8", DIGITS_8), ("K", DIGITS_K)):
    _table = bytearray(b"?" * 256)
    for _d, _v in enumerate(_digits):
        _table[_v] = ord(str(_d))
    for _v, _c in ((MINUS, "-"), (X, "X"), (Y, "Y"), (DX, "D"), (DY, "E"), (CYC, "C"),
                   (K, "K"), (KK, ";"), (GM, "G")):
        _table[_v] = ord(_c)
    _CHARS[_code] = bytes(_table)
#: One well-formed frame in those characters: the fields in their order,
#: no zero value, no leading zero, no minus on CYC, at most MAX_DIGITS
#: digits, K and two digits, KK.
_NUMBER = rb"[1-9][0-9]{0,%d}" % (MAX_DIGITS - 1)
_FRAME = re.compile(rb"(?:X(-?%s))?(?:Y(-?%s))?(?:D(-?%s))?(?:E(-?%s))?(?:C(%s))?K([0-9][0-9]);"
                    % ((_NUMBER,) * 5))


def _decode_whole(data: bytes, code: str) -> Tape | None:
    """The decoded tape when ``data`` is a tape without fault in ``code``,
    else None (then :func:`decode` reads it row by row and names the first
    fault).  The whole tape at once, a frame a regular-expression match:
    the same frames as the row-by-row reader, many times faster.  Anything
    this does not accept as plainly well formed is left to that reader."""
    text = data.translate(_CHARS[code])
    open_gm = text.find(b"G")
    close_gm = text.rfind(b"G")
    if open_gm < 0 or close_gm == open_gm:
        return None
    if text.count(b"0", 0, open_gm) != open_gm or \
            text.count(b"0", close_gm + 1) != len(text) - close_gm - 1:
        return None
    first_row = open_gm + 2                 # 1-based row of the first frame
    frames: list[Frame] = []
    starts: list[int] = []
    pos = open_gm + 1
    opener = False
    match = _FRAME.match
    commands = COMMANDS
    while pos < close_gm:
        m = match(text, pos, close_gm)
        if m is None:
            return None
        x, y, dx, dy, cyc, k = m.groups()
        f = Frame(int(x) if x else 0, int(y) if y else 0, int(dx) if dx else 0,
                  int(dy) if dy else 0, int(cyc) if cyc else 0, int(k))
        if f.k not in commands or (cyc and f.cyc < 2):
            return None
        if f.k in (11, 13):
            if frame_problems(f):
                return None
        elif x or y:
            return None
        if opener:
            if cyc:
                return None
            opener = False
        elif cyc:
            opener = True
        starts.append(pos - open_gm - 1 + first_row)
        frames.append(f)
        pos = m.end()
    if opener:
        return None
    return Tape(code=code, frames=frames, rows=len(data), starts=starts)


def decode(data: bytes, code: str = "auto") -> Tape:
    """Decode a tape image; ``code`` is "8", "K" or "auto".

    In "auto" the variant is the one shown by the first digit row that tells
    them apart (a plain 3, 5, 6, 9 -> "8"; a controlled 23, 25, 26, 31 -> "K");
    a later row of the other variant is a "mixed code" error at that row.  A
    tape with no such row decodes the same either way and is reported as "8".
    Raises :class:`TapeError` for any deviation from docs/TAPE.md.
    """
    if code not in ("8", "K", "auto"):
        raise ValueError(f"code must be '8', 'K' or 'auto', not {code!r}")
    data = bytes(data)
    evidence: int | None = None
    if code == "auto":
        code, evidence = _scan_code(data)
    fast = _decode_whole(data, code)
    if fast is not None:
        return fast
    rd = _Reader(data, code, evidence)

    # Leader: blank rows up to the opening GM.
    while True:
        got = rd.raw()
        if got is None:
            what = "the tape is empty" if not data else "only blank rows"
            raise TapeError(rd.end_row, f"missing GM at the start of the tape ({what})")
        n, value = got
        if value == GM:
            break
        if value != BLANK:
            raise TapeError(n, f"data before the opening GM: found {describe(value)}")

    # The array: frames up to the closing GM.
    frames: list[Frame] = []
    opener: tuple[int, int] | None = None   # (frame index, CYC row) awaiting partner
    while True:
        row = rd.next()
        if row is None:
            raise TapeError(rd.end_row, "missing GM at the end of the tape")
        if row.kind == "GM":
            break
        frame, rows = _read_frame(rd, row)
        if opener is not None:
            if frame.cyc:
                raise TapeError(rows["CYC"], "CYC on the second frame of a cycle "
                                             f"pair (its CYC is at row {opener[1]})")
            opener = None
        elif frame.cyc:
            opener = (len(frames), rows["CYC"])
        frames.append(frame)
    if opener is not None:
        raise TapeError(opener[1], "CYC needs a following frame (CYC on the last frame)")

    # Trailer: blank rows only.
    while True:
        got = rd.raw()
        if got is None:
            break
        n, value = got
        if value != BLANK:
            raise TapeError(n, f"data after the closing GM: found {describe(value)}")
    return Tape(code=code, frames=frames, rows=len(data))


# ---------------------------------------------------------------------------
# Frame text (docs/FILES.md, NAME-*.txt): ASCII or the report's own symbols.
# ---------------------------------------------------------------------------
ASCII_NAMES: dict[str, str] = {"X": "X", "Y": "Y", "DX": "DX", "DY": "DY",
                               "CYC": "CYC", "K": "K", "KK": "KK", "GM": "GM"}
#: The report's symbols: Greek capital delta, Cyrillic Ц, К, КК, ГМ.
UTF8_NAMES: dict[str, str] = {"X": "X", "Y": "Y", "DX": "\u0394X", "DY": "\u0394Y",
                              "CYC": "\u0426", "K": "\u041a",
                              "KK": "\u041a\u041a", "GM": "\u0413\u041c"}


def frame_text(frame: Frame, utf8: bool = False) -> str:
    """One frame as text, e.g. ``DX300 DY400 CYC8 K10 KK``."""
    names = UTF8_NAMES if utf8 else ASCII_NAMES
    tokens = [f"{names[field]}{getattr(frame, field.lower())}"
              for field in _FIELDS if getattr(frame, field.lower())]
    tokens.append(f"{names['K']}{frame.k:02d}")
    tokens.append(names["KK"])
    return " ".join(tokens)


def tape_text(tape: Tape | Sequence[Frame], utf8: bool = False) -> str:
    """GM line, one line per frame, GM line; every line ends in a newline."""
    frames = tape.frames if isinstance(tape, Tape) else tape
    gm = (UTF8_NAMES if utf8 else ASCII_NAMES)["GM"]
    return "".join(f"{line}\n" for line in
                   [gm, *(frame_text(f, utf8) for f in frames), gm])


def _parse_tokens(line: str, names: dict[str, str], lineno: int) -> Frame:
    def fail(message: str) -> ValueError:
        return ValueError(f"line {lineno}: {message}")

    if not line:
        raise fail("empty line")
    tokens = line.split(" ")
    if "" in tokens:
        raise fail("tokens must be separated by single spaces")
    if tokens[-1] != names["KK"]:
        raise fail(f"a frame ends with {names['KK']}, found {tokens[-1]!r}")
    values: dict[str, int] = {}
    last = -1
    k: int | None = None
    for token in tokens[:-1]:
        if k is not None:
            raise fail(f"expected {names['KK']} after {names['K']}{k:02d}, "
                       f"found {token!r}")
        # Longest address first so that DX is not read as a malformed X.
        for field in sorted(_FIELDS + ("K",), key=lambda f: -len(names[f])):
            if token.startswith(names[field]):
                break
        else:
            raise fail(f"unknown token {token!r}")
        number = token[len(names[field]):]
        if field == "K":
            if len(number) != 2 or not number.isdigit() or not number.isascii():
                raise fail(f"{names['K']} must be followed by exactly two "
                           f"digits, found {token!r}")
            k = int(number)
            if k not in COMMANDS:
                raise fail(f"K {number} is not a command (10, 20, 11, 13)")
            continue
        index = _FIELDS.index(field)
        if index <= last:
            raise fail(f"{token!r} out of order (X, Y, DX, DY, CYC, K, KK)")
        digits = number[1:] if field != "CYC" and number.startswith("-") else number
        if not digits or not digits.isdigit() or not digits.isascii():
            raise fail(f"bad number in {token!r}")
        if digits[0] == "0":
            raise fail(f"leading zero or zero value in {token!r}")
        if len(digits) > MAX_DIGITS:
            raise fail(f"{names[field]} has more than {MAX_DIGITS} digits ({len(digits)}; "
                       f"the largest number is {10 ** MAX_DIGITS - 1})")
        value = int(number)
        if field == "CYC" and value < 2:
            raise fail(f"CYC {value}: a cycle runs its pair at least 2 times")
        values[field] = value
        last = index
    if k is None:
        raise fail(f"missing {names['K']} (the command is always written)")
    frame = Frame(x=values.get("X", 0), y=values.get("Y", 0),
                  dx=values.get("DX", 0), dy=values.get("DY", 0),
                  cyc=values.get("CYC", 0), k=k)
    problems = frame_problems(frame)
    if problems:
        raise fail(problems[0][1])
    return frame


def parse_frame_text(line: str, lineno: int = 1) -> Frame:
    """Inverse of :func:`frame_text` (either alphabet, not mixed).

    Strict: single spaces, fixed order, no leading zeros, no zero values, K
    with two digits, and the rules of :func:`frame_problems`.  Raises
    ValueError("line N: ...").
    """
    utf8 = line.endswith(UTF8_NAMES["KK"])
    return _parse_tokens(line, UTF8_NAMES if utf8 else ASCII_NAMES, lineno)


def parse_tape_text(text: str) -> list[Frame]:
    """Inverse of :func:`tape_text`: the alphabet is set by the first line
    (``GM`` or ``ГМ``) and every line must use it; every line ends in a
    newline; no blank lines.  Cycle rules are checked as in :func:`encode`.
    Raises ValueError("line N: ...")."""
    if not text.endswith("\n"):
        n = text.count("\n") + 1
        raise ValueError(f"line {n}: missing newline at the end of the text")
    lines = text[:-1].split("\n")
    if lines[0] == ASCII_NAMES["GM"]:
        names = ASCII_NAMES
    elif lines[0] == UTF8_NAMES["GM"]:
        names = UTF8_NAMES
    else:
        raise ValueError(f"line 1: expected GM, found {lines[0]!r}")
    if len(lines) < 2 or lines[-1] != names["GM"]:
        raise ValueError(f"line {len(lines)}: expected {names['GM']} as the last line")
    frames = [_parse_tokens(line, names, i + 2) for i, line in enumerate(lines[1:-1])]
    problem = sequence_problem(frames)
    if problem is not None:
        raise ValueError(f"line {problem[0] + 2}: {problem[1]}")
    return frames
