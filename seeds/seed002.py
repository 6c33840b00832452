"""Seed 002: the Ural-1 computation of milling programs.

Source: seed 002 (docs/SOURCES.md): I. N. Kosenko et al.,
"Расчет на ЭВМ «Урал-1» программы обработки деталей на станках с цифровым
программным управлением" (OCR text; figures lost).  What is re-created:

* The blade template (its Fig. 1): the profile D-E given by the measured
  points of Table 1, described by a line (equation 6, points 1-3) and two
  Lagrange quadratics (equation 8 through points 3, 5, 8; equation 10
  through points 8, 10, 13); Tables 2-4 compare them with the points.
  :func:`line_through`, :func:`lagrange_quadratic`, :data:`TABLE1`,
  :data:`PRINTED_EQUATIONS`; :func:`approximate_profile` does the same job
  for any table of points within a tolerance, greedily.
* Chord approximation: the step angle of an arc, equation
  ``Δφ = 2 arccos(1 - y/R0)`` (:func:`chord_step`), and the x step of a
  parabola (:func:`parabola_step`), so that no chord strays more than y from
  the curve.
* The flange (its Fig. 2, Table 5): a contour of lines and arcs
  (:func:`flange_contour`) and the cutter-centre equidistant of such a
  contour (:func:`equidistant`), written as TENZOR card decks.
* The 5121 code of Table 6 (:data:`CODE_5121`) in which the tape-code
  converter LKP-01F read decimal digits, and a tape image of frames in it
  (:func:`punch_5121`, :func:`read_5121`), laid out as the relay block of
  the paper's punch control punched them.

Lengths are millimetres (floats or Fractions) unless a name says units
(0.01 mm) or pulses.
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Union

from harness import cards
from harness.deck import parse_deck
from harness.files import ascii_text, write_whole

from .contour import (FIELD_MM, MAX_CHORDS, ArcEl, Element, Seg, contour_cards, equidistant,
                      package_contour, sample, units)

Point = tuple[float, float]
Number = Union[float, Fraction]

# ---------------------------------------------------------------------------
# Table 1 and the printed equations.
# ---------------------------------------------------------------------------
#: Table 1 as printed (OCR): point number -> (x, y), mm.
TABLE1_PRINTED: dict[int, tuple[str, str]] = {
    1: ("25.4", "-1.45"), 2: ("30.88", "1.7"), 3: ("35.5", "4.95"),
    4: ("39.93", "4.72"), 5: ("44.95", "10.52"), 6: ("47.39", "11.72"),
    7: ("49.51", "12.77"), 8: ("53.81", "14.57"), 9: ("57.83", "15.82"),
    10: ("61.65", "16.83"), 11: ("65.48", "17.72"), 12: ("69.48", "18.49"),
    13: ("70.85", "18.76")}

#: Table 1 as used here: the printed values with the two corrections that
#: Tables 2 and 3 prove (docs/SEED002-URAL1.md): point 2 is x = 30.38 (Table
#: 2, and equation 6 gives 1.70 there, 2.02 at 30.88) and point 4 is
#: y = 7.72 (4.72 is 3 mm off a smooth profile; equation 8 gives 7.72 at
#: x = 39.93, and Table 3's "+0.03" fits 7.72 at x = 39.99).
TABLE1: dict[int, tuple[Fraction, Fraction]] = {
    n: (Fraction(x), Fraction(y)) for n, (x, y) in TABLE1_PRINTED.items()}
TABLE1[2] = (Fraction("30.38"), Fraction("1.7"))
TABLE1[4] = (Fraction("39.93"), Fraction("7.72"))

#: The equations as printed: number -> (a, b, c) of y = a x^2 + b x + c.
#: Equation 10 is printed with +0.0046057 x^2; the paper's form (4),
#: y = -a x^2 + b x - c, and the points (a concave profile) say minus.
PRINTED_EQUATIONS: dict[int, tuple[str, str, str]] = {
    6: ("0", "0.633633", "-17.545"),
    8: ("-0.007226", "1.1707428", "-27.504968"),
    10: ("-0.0046057", "0.82004", "-16.182403")}

#: Nodes of each equation (Table 1 point numbers), as the paper says.
EQUATION_NODES: dict[int, tuple[int, ...]] = {6: (1, 3), 8: (3, 5, 8), 10: (8, 10, 13)}


def line_through(p0: tuple[Number, Number],
                 p1: tuple[Number, Number]) -> tuple[Number, Number]:
    """Slope and intercept of the line through two points: the paper's
    equation (5), (y - y1)/(y2 - y1) = (x - x1)/(x2 - x1), solved for y."""
    (x0, y0), (x1, y1) = p0, p1
    slope = (y1 - y0) / (x1 - x0)
    return slope, y0 - slope * x0


def lagrange_quadratic(points: Sequence[tuple[Number, Number]]) -> tuple[Number, Number, Number]:
    """(a, b, c) of y = a x^2 + b x + c through three points: the paper's
    Lagrange formula (1), (7), (9), multiplied out.  Exact for Fractions."""
    (x0, y0), (x1, y1), (x2, y2) = points
    a = b = c = 0 * x0
    for (xi, yi), xj, xk in (((x0, y0), x1, x2), ((x1, y1), x0, x2), ((x2, y2), x0, x1)):
        w = yi / ((xi - xj) * (xi - xk))
        a += w
        b -= (xj + xk) * w
        c += xj * xk * w
    return a, b, c


def equation(number: int, table: dict[int, tuple[Fraction, Fraction]] = TABLE1
             ) -> tuple[Fraction, Fraction, Fraction]:
    """Equation 6, 8 or 10 computed exactly from its nodes: (a, b, c)."""
    nodes = [table[n] for n in EQUATION_NODES[number]]
    if number == 6:
        slope, icpt = line_through(nodes[0], nodes[1])
        return Fraction(0), slope, icpt
    return lagrange_quadratic(nodes)


def poly(coef: Sequence[Number], x: Number) -> Number:
    """a x^2 + b x + c."""
    a, b, c = coef
    return (a * x + b) * x + c


def round2(v: Number) -> Fraction:
    """Round half away from zero to 0.01, as the paper's tables do."""
    q = Fraction(v) * 100
    n = math.floor(abs(q) + Fraction(1, 2))
    return Fraction(n if q >= 0 else -n, 100)


# ---------------------------------------------------------------------------
# Piecewise approximation of a tabulated profile, and chords.
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Piece:
    """One piece of a profile: points ``first``..``last`` (indices into the
    table), y = a x^2 + b x + c through ``nodes`` (two for a line)."""

    first: int
    last: int
    nodes: tuple[int, ...]
    coef: tuple[float, float, float]
    error: float

    @property
    def kind(self) -> str:
        return "line" if len(self.nodes) == 2 else "quadratic"


def _fit(pts: Sequence[Point], i: int, j: int) -> list[tuple[tuple[int, ...], tuple[float, float, float], float]]:
    """Candidate fits of points i..j: the chord through i and j, and the
    Lagrange quadratic through i, the point nearest the middle, and j.
    Each with its largest vertical error over i..j."""
    out = []
    slope, icpt = line_through(pts[i], pts[j])
    cands: list[tuple[tuple[int, ...], tuple[float, float, float]]] = [((i, j), (0.0, slope, icpt))]
    if j - i >= 2:
        xm = (pts[i][0] + pts[j][0]) / 2
        m = min(range(i + 1, j), key=lambda k: (abs(pts[k][0] - xm), k))
        cands.append(((i, m, j), lagrange_quadratic([pts[i], pts[m], pts[j]])))
    for nodes, coef in cands:
        err = max(abs(poly(coef, x) - y) for x, y in pts[i:j + 1])
        out.append((nodes, coef, err))
    return out


def approximate_profile(points: Sequence[Point], tol: float) -> list[Piece]:
    """Pieces of lines and Lagrange quadratics through the table's own
    points, each within ``tol`` (vertically) of every point it spans.

    As few pieces as possible (dynamic programming over the points; the
    paper needed three for Table 1 and found them by trial); among equally
    few, fewer quadratics, then the smaller largest error.  A piece is the
    chord through its end points or the quadratic through its ends and the
    point nearest its middle (the paper's choice of nodes).  Two
    neighbouring points always fit a chord, so the profile is covered;
    consecutive pieces share their end point, so it is continuous.
    """
    pts = [(float(x), float(y)) for x, y in points]
    if len(pts) < 2 or any(b[0] <= a[0] for a, b in zip(pts, pts[1:])):
        raise ValueError("a profile needs at least two points with increasing x")
    n = len(pts)
    # best[j]: (pieces, quadratics, worst error, previous index, fit) covering 0..j
    best: list[tuple | None] = [None] * n
    best[0] = (0, 0, 0.0, -1, None)
    for j in range(1, n):
        for i in range(j):
            if best[i] is None:
                continue
            ok = [f for f in _fit(pts, i, j) if f[2] <= tol + 1e-12]
            if not ok:
                continue
            nodes, coef, err = ok[0]
            pi, qi, ei = best[i][:3]
            cand = (pi + 1, qi + (len(nodes) == 3), max(ei, err), i, (nodes, coef, err))
            if best[j] is None or cand[:3] < best[j][:3]:
                best[j] = cand
    pieces: list[Piece] = []
    j = n - 1
    while j > 0:
        entry = best[j]
        if entry is None:           # only a non-finite value or tolerance gets here
            raise ValueError(f"no line or quadratic fits points {j} to {j + 1} within "
                             f"the tolerance {tol:g} mm")
        i, (nodes, coef, err) = entry[3], entry[4]
        pieces.append(Piece(i, j, nodes, coef, err))
        j = i
    return pieces[::-1]


def parabola_step(a: float, tol: float) -> float:
    """The x step of chords on y = a x^2 + b x + c that stray at most ``tol``
    from it (vertically): a chord of run h has sag |a| h^2 / 4."""
    if a == 0:
        return math.inf
    return 2.0 * math.sqrt(tol / abs(a))


def profile_chords(points: Sequence[Point], pieces: Sequence[Piece], tol: float) -> list[Point]:
    """The polyline of chords along the pieces (each piece cut into equal x
    steps of at most :func:`parabola_step`)."""
    pts = [(float(x), float(y)) for x, y in points]
    # each piece's run in steps, counted before any chord is made
    runs = [(pts[pc.last][0] - pts[pc.first][0]) / parabola_step(pc.coef[0], tol)
            for pc in pieces]
    if not (all(math.isfinite(q) for q in runs) and sum(max(q, 1) for q in runs) <= MAX_CHORDS):
        raise ValueError(f"the profile within --chord {tol:g} mm needs more than {MAX_CHORDS} "
                         f"chords: give a larger --chord")
    out = [pts[0]]
    for pc, run in zip(pieces, runs):
        x0, x1 = pts[pc.first][0], pts[pc.last][0]
        k = max(1, math.ceil(run - 1e-9))
        for s in range(1, k + 1):
            x = x1 if s == k else x0 + (x1 - x0) * s / k
            out.append((x, pts[pc.last][1] if s == k else float(poly(pc.coef, x))))
    return out


# ---------------------------------------------------------------------------
# The flange of Table 5.
# ---------------------------------------------------------------------------
#: Table 5 as printed (OCR): rows of (row, section, point, x, y).  Centres
#: are points "0_k" (O_k).
TABLE5_PRINTED: tuple[tuple[int, str, str, str, str], ...] = (
    (1, "0-1", "0", "5", "41"), (2, "", "1", "7.5", "61.5"),
    (3, "1-2", "2", "14.3", "71.3"), (4, "", "O2", "25.3", "59"),
    (5, "2-3", "3", "24.7", "91"), (6, "3-4", "4", "31.7", "103"),
    (7, "", "O4", "42.3", "88.7"), (8, "4-5", "5", "48", "115.3"),
    (9, "5-6", "6", "70.7", "115.3"), (10, "", "O5", "59.3", "100"),
    (11, "6-7", "7", "87", "103"), (12, "7-8", "8", "94", "91"),
    (13, "", "O6", "76.4", "88.7"), (14, "8-9", "9", "104.3", "71.3"),
    (15, "", "O7", "120", "101"), (16, "9-10", "10", "111.2", "61.5"),
    (17, "", "O8", "93.3", "59.3"), (18, "10-11", "11", "113.7", "41"),
    (19, "11-12", "12", "102.3", "21"), (20, "", "O9", "95", "38.6"),
    (21, "12-13", "13", "83.2", "13"), (22, "13-14", "14", "66.3", "13"),
    (23, "", "O10", "76.3", "16.6"), (24, "14-15", "15", "49.0", "13"),
    (25, "", "O11", "66", "-10.7"), (26, "14-15", "16", "35.5", "13"),
    (27, "", "O2", "42.3", "16.6"), (28, "16-17", "17", "16.3", "21"),
    (29, "17-0", "0", "5", "41"), (30, "", "O1", "23.8", "38.6"))

#: The flange contour used here: point -> (x, y) mm, after the corrections
#: of docs/SEED002-URAL1.md (points 2, 9 and 14).
FLANGE_POINTS: dict[int, Point] = {
    0: (5.0, 41.0), 1: (7.5, 61.5), 2: (14.3, 73.3), 3: (24.7, 91.0), 4: (31.7, 103.0),
    5: (48.0, 115.3), 6: (70.7, 115.3), 7: (87.0, 103.0), 8: (94.0, 91.0),
    9: (104.3, 73.3), 10: (111.2, 61.5), 11: (113.7, 41.0), 12: (102.3, 21.0),
    13: (83.2, 13.0), 14: (69.7, 13.0), 15: (49.0, 13.0), 16: (35.5, 13.0),
    17: (16.3, 21.0)}

#: Arcs of the flange: section (from point, to point) -> printed centre
#: (mm).  Sections not listed are straight.  O7 is dropped (section 8-9 is
#: the mirror image of the straight 2-3); O11 is moved to the axis of
#: symmetry; the last two centres are O12 and O13 (printed "O2", "O1").
FLANGE_CENTRES: dict[tuple[int, int], Point] = {
    (1, 2): (25.3, 59.0), (3, 4): (42.3, 88.7), (5, 6): (59.3, 100.0),
    (7, 8): (76.4, 88.7), (9, 10): (93.3, 59.3), (11, 12): (95.0, 38.6),
    (13, 14): (76.3, 16.6), (14, 15): (59.3, -10.7), (15, 16): (42.3, 16.6),
    (17, 0): (23.8, 38.6)}

#: The cutter of the paper: diameter 20 mm.
FLANGE_CUTTER_MM = 20.0


def fit_centre(p0: Point, p1: Point, c: Point) -> Point:
    """The point nearest c that is equally far from p0 and p1 (c moved onto
    the perpendicular bisector of p0 p1)."""
    mx, my = (p0[0] + p1[0]) / 2, (p0[1] + p1[1]) / 2
    ux, uy = p1[0] - p0[0], p1[1] - p0[1]
    norm = math.hypot(ux, uy)
    nx, ny = -uy / norm, ux / norm
    t = (c[0] - mx) * nx + (c[1] - my) * ny
    return mx + t * nx, my + t * ny


def flange_contour() -> list[Element]:
    """The flange of Table 5 as a closed clockwise contour: 0-1-2-...-17-0,
    arcs about their centres (each moved onto the bisector of its two end
    points, by at most 0.2 mm), each arc the short way round."""
    out: list[Element] = []
    for i in range(18):
        j = (i + 1) % 18
        p0, p1 = FLANGE_POINTS[i], FLANGE_POINTS[j]
        if (i, j) not in FLANGE_CENTRES:
            out.append(Seg(*p0, *p1))
            continue
        cx, cy = fit_centre(p0, p1, FLANGE_CENTRES[(i, j)])
        cross = (p0[0] - cx) * (p1[1] - cy) - (p0[1] - cy) * (p1[0] - cx)
        out.append(ArcEl(cx, cy, *p0, *p1, cw=cross < 0))
    return out


# ---------------------------------------------------------------------------
# The 5121 code (Table 6) and its tape.
# ---------------------------------------------------------------------------
#: Table 6: decimal digit -> its tetrad in the 5121 code, bits written as the
#: paper prints them (weights 5, 1, 2, 1 from the left).  Zero is 0000 (not
#: in the table: no weight is used).
CODE_5121: dict[int, str] = {0: "0000", 1: "0001", 2: "0101", 3: "0110", 4: "0111",
                             5: "1000", 6: "1001", 7: "1010", 8: "1011", 9: "1111"}
#: The weights of the tetrad's bits, left to right.
WEIGHTS_5121: tuple[int, int, int, int] = (5, 1, 2, 1)


def code_5121_weights(digit: int) -> tuple[int, int, int, int]:
    """The digit's 5121 tetrad as the gates of a decimal pulse multiplier's
    trains of 5, 2, 1 and 1 pulses (seed 004): (w5, w2, w1, w1'), each the
    weight or 0."""
    bits = CODE_5121[digit]
    return (5 if bits[0] == "1" else 0, 2 if bits[2] == "1" else 0,
            1 if bits[1] == "1" else 0, 1 if bits[3] == "1" else 0)


def tetrad(digit: int) -> int:
    """The 5121 tetrad of a digit as a 4-bit value (leftmost bit = bit 3)."""
    return int(CODE_5121[digit], 2)


def digit_of(value: int) -> int:
    """The digit of a 5121 tetrad; ValueError for one not in Table 6."""
    text = format(value & 15, "04b")
    for d, code in CODE_5121.items():
        if code == text:
            return d
    raise ValueError(f"tetrad {text} is not a digit of the 5121 code")


@dataclass(frozen=True)
class Frame5121:
    """One frame of the LKP-01F tape: increments in pulses, the speed code
    (one digit) and the auxiliary commands (three bits each for X and Y, two
    for Z: rows 12-14 are built "in the same way" as X's rows 2-5)."""

    dx: int
    dy: int
    dz: int = 0
    speed: int = 0
    aux_x: int = 0
    aux_y: int = 0
    aux_z: int = 0


#: Rows of one frame: X 4 digits, Y 4, Z 3, speed 1, then 3 blank rows.
ROWS_PER_FRAME = 15
LEADER_ROWS = 20
_MARK = 16            # track 5
#: The even frames' shift: two more blank rows before every even frame
#: (our reading of "сдвиг четных кадров на две единицы"; docs/SEED002-URAL1.md).
EVEN_SHIFT_ROWS = 2


def _number_rows(value: int, digits: int, aux: int) -> list[int]:
    """Rows of a signed number: its digits (most significant first) in the
    5121 code on tracks 1-4; track 5 is the sign on the first row (punched
    = minus) and the auxiliary command's bits on the next ones."""
    mag = abs(value)
    if mag >= 10 ** digits:
        raise ValueError(f"{value} does not fit {digits} decimal digits: split the move "
                         f"(python -m seeds split --max {10 ** digits - 1})")
    text = str(mag).rjust(digits, "0")
    rows = [tetrad(int(ch)) for ch in text]
    if value < 0:
        rows[0] |= _MARK
    for k in range(digits - 1):
        if aux >> (digits - 2 - k) & 1:
            rows[k + 1] |= _MARK
    return rows


def frame_rows_5121(f: Frame5121) -> list[int]:
    """The 15 rows of one frame (see the module doc and docs/SEED002-URAL1.md)."""
    if (not 0 <= f.speed <= 9 or not 0 <= f.aux_x <= 7 or not 0 <= f.aux_y <= 7
            or not 0 <= f.aux_z <= 3):
        raise ValueError(f"speed {f.speed} (0-9) or auxiliary command {f.aux_x}, "
                         f"{f.aux_y} (0-7), {f.aux_z} (0-3) out of range")
    rows = _number_rows(f.dx, 4, f.aux_x) + _number_rows(f.dy, 4, f.aux_y)
    rows += _number_rows(f.dz, 3, f.aux_z)
    rows.append(tetrad(f.speed) | _MARK)          # the frame's marker ("стоп")
    return rows + [0, 0, 0]


def punch_5121(frames: Iterable[Frame5121], leader: int = LEADER_ROWS,
               even_shift: bool = False) -> bytes:
    """A tape image (.ptp: one byte a row, tracks 1-5 in the low 5 bits);
    with ``even_shift`` every even frame (2nd, 4th, ...) is moved two rows
    along the tape (:data:`EVEN_SHIFT_ROWS` blank rows before it)."""
    rows = [0] * leader
    for n, f in enumerate(frames, 1):
        if even_shift and n % 2 == 0:
            rows += [0] * EVEN_SHIFT_ROWS
        rows += frame_rows_5121(f)
    rows += [0] * leader
    return bytes(rows)


def _read_number(rows: Sequence[int]) -> tuple[int, int]:
    value = int("".join(str(digit_of(r)) for r in rows))
    aux = 0
    for r in rows[1:]:
        aux = aux * 2 + (1 if r & _MARK else 0)
    return (-value if rows[0] & _MARK else value), aux


def read_5121(data: bytes) -> list[Frame5121]:
    """Frames of a 5121 tape image; ValueError naming the row (1-based).

    Frames are read from the end: the last row with a hole is the marker of
    the last frame, and each frame (12 rows and 3 blank ones, or 5 before a
    shifted even frame) follows the one before it; everything before the
    first is leader and must be blank.  (Reading forward would not do: a frame may begin with
    blank rows, its leading zero digits.)"""
    rows = list(data)
    for i, r in enumerate(rows):
        if r > 31:
            raise ValueError(f"row {i + 1}: value {r} has holes beyond track 5")
    end = max((i for i, r in enumerate(rows) if r), default=None)
    frames: list[Frame5121] = []
    while end is not None:
        start = end - 11
        if start < 0 or not rows[end] & _MARK:
            raise ValueError(f"row {end + 1}: expected a frame's marker row (track 5) "
                             f"with eleven rows before it")
        body = rows[start:end + 1]
        try:
            dx, ax = _read_number(body[0:4])
            dy, ay = _read_number(body[4:8])
            dz, az = _read_number(body[8:11])
            speed = digit_of(body[11])
        except ValueError as exc:
            raise ValueError(f"frame at row {start + 1}: {exc}") from None
        frames.append(Frame5121(dx, dy, dz, speed, ax, ay, az))
        for gap in (3, 3 + EVEN_SHIFT_ROWS):     # plain, or before a shifted even frame
            prev = start - gap - 1
            if prev >= 0 and rows[prev] & _MARK and not any(rows[start - gap:start]):
                end = prev
                break
        else:
            prev = -1
        if prev >= 0:
            continue
        stray = [i for i in range(start) if rows[i]]
        if stray:
            raise ValueError(f"row {stray[-1] + 1}: a hole in the leader, or a frame "
                             f"not followed by three blank rows")
        end = None
    return frames[::-1]


# ---------------------------------------------------------------------------
# A picture.
# ---------------------------------------------------------------------------
def contours_svg(layers: Sequence[tuple[Sequence[Element], str]], scale: float = 4.0,
                 margin: float = 12.0) -> str:
    """An SVG drawing of contours, each (elements, colour), y upwards, 1 mm
    = ``scale`` pixels; arcs as SVG arcs."""
    pts = [p for els, _ in layers for e in els for p in sample(e, 2.0)]
    x0, x1 = min(p[0] for p in pts) - margin, max(p[0] for p in pts) + margin
    y0, y1 = min(p[1] for p in pts) - margin, max(p[1] for p in pts) + margin

    def f(x: float, y: float) -> str:
        return f"{(x - x0) * scale:.2f} {(y1 - y) * scale:.2f}"

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{(x1 - x0) * scale:.0f}" '
           f'height="{(y1 - y0) * scale:.0f}">', '<rect width="100%" height="100%" fill="white"/>']
    for els, colour in layers:
        d = [f"M{f(els[0].x0, els[0].y0)}"]
        for e in els:
            if isinstance(e, Seg):
                d.append(f"L{f(e.x1, e.y1)}")
            else:
                big = 1 if e.sweep > math.pi else 0
                sweep_flag = 1 if e.cw else 0       # y flips: clockwise on paper is flag 1
                d.append(f"A{e.r * scale:.2f} {e.r * scale:.2f} 0 {big} {sweep_flag} "
                         f"{f(e.x1, e.y1)}")
        out.append(f'<path d="{" ".join(d)}" fill="none" stroke="{colour}" stroke-width="1.5"/>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------------------
# Decks.
# ---------------------------------------------------------------------------
#: Where the flange's origin goes on the coordinatograph's field (mm).
FLANGE_ORIGIN_MM = (100, 100)


def flange_deck() -> str:
    """examples/flange.crd: the flange contour of Table 5 (corrected) as a
    TENZOR deck, its origin at (100, 100) mm on the field, in deck order."""
    x0, y0 = (v * 100 for v in FLANGE_ORIGIN_MM)
    body = [cards.p_card(x0, y0, order="D")] + contour_cards(flange_contour())
    return cards.deck([cards.CardPackage("FLANGE-TABLE5", body)],
                      job="URAL-1 FLANGE, FIG. 2, TABLE 5")


def equidistant_deck(text: str, cutter_mm: float, outside: bool = True,
                     chord_tol: float | None = None) -> str:
    """For each package of a deck whose L/+ and A cards form one closed
    contour: a package NAME-EQ with the same P card and the cutter-centre
    path (:func:`equidistant`) as cards."""

    out = []
    for pkg in parse_deck(text):
        try:
            contour, labels = package_contour(pkg)
            path = equidistant(contour, cutter_mm / 2, outside, labels)
        except ValueError as exc:
            raise ValueError(f"package {pkg.name.strip()}: {exc}") from None
        x0, y0 = (cards.units(v) for v in pkg.start_mm)
        p = cards.p_card(x0, y0, *pkg.tools, pkg.dmax, pkg.scale, pkg.code, pkg.order)
        name = pkg.name.strip()[:15] + "-EQ"
        out.append(cards.CardPackage(name, [p] + contour_cards(path, chord_tol)))
    return cards.deck(out, job=f"EQUIDISTANT, CUTTER {cutter_mm:g} MM")


def profile_report(points: Sequence[Point], tol: float) -> str:
    """The greedy pieces of a profile, one a line, with their errors."""
    lines = [f"{len(points)} points, tolerance {tol:g} mm"]
    for pc in approximate_profile(points, tol):
        a, b, c = pc.coef
        nodes = ", ".join(str(n + 1) for n in pc.nodes)
        lines.append(f"points {pc.first + 1}-{pc.last + 1}: {pc.kind} through {nodes}: "
                     f"y = {a:.7f} x^2 + {b:.7f} x + {c:.6f}; largest error {pc.error:.4f} mm")
    return "\n".join(lines) + "\n"


def paper_report() -> str:
    """Equations 6, 8 and 10 recomputed from Table 1 beside the printed ones,
    and the values of Tables 2-4 (what ``profile --paper`` prints)."""
    out = []
    for n in (6, 8, 10):
        got = equation(n)
        printed = PRINTED_EQUATIONS[n]
        out.append(f"equation ({n}) through points {', '.join(map(str, EQUATION_NODES[n]))}:")
        out.append("  computed: y = " + " ".join(f"{float(v):+.7f}" for v in got) + "  (a b c)")
        out.append("  printed:  y = " + " ".join(f"{float(v):+.7f}" for v in printed))
    pieces = {6: range(1, 4), 8: range(3, 9), 10: range(8, 14)}
    for n, points in pieces.items():
        coef = equation(n)
        for k in points:
            x, y = TABLE1[k]
            v = poly(coef, x)
            out.append(f"  eq ({n}) point {k:2d}: x {float(x):6.2f} measured {float(y):6.2f} "
                       f"computed {float(round2(v)):6.2f} error {float(round2(v - y)):+.2f}")
    return "\n".join(out) + "\n"


def _read_points(path: str) -> list[Point]:
    """'x y' per line (mm), '#' comments, blank lines ignored."""
    text = sys.stdin.read() if path == "-" else ascii_text(Path(path).read_bytes())
    pts = []
    for no, line in enumerate(text.splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        parts = line.replace(",", " ").split()
        if len(parts) != 2:
            raise ValueError(f"line {no}: expected 'x y', got {line!r}")
        try:
            x, y = float(parts[0]), float(parts[1])
        except ValueError:
            raise ValueError(f"line {no}: expected two numbers, got {line!r}") from None
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ValueError(f"line {no}: {line!r} is not a finite point")
        if max(abs(x), abs(y)) > FIELD_MM:
            raise ValueError(f"line {no}: {line!r} is off the field (a point is at most "
                             f"{FIELD_MM:g} mm from 0 either way)")
        pts.append((x, y))
    return pts


def _run_profile(args: argparse.Namespace) -> int:
    for name, v in (("--tol", args.tol), ("--chord", args.chord)):
        if not (math.isfinite(v) and v > 0):
            print(f"profile: {name} {v:g}: a tolerance is a finite number of mm above 0",
                  file=sys.stderr)
            return 2
    try:
        if args.paper:
            sys.stdout.write(paper_report())
            return 0
        if args.points:
            try:
                pts = _read_points(args.points)
            except OSError as exc:
                print(f"profile: {args.points}: {exc.strerror or exc}", file=sys.stderr)
                return 2
            except ValueError as exc:
                print(f"profile: {args.points}: {exc}", file=sys.stderr)
                return 1
        else:
            pts = [(float(x), float(y)) for x, y in TABLE1.values()]
        sys.stdout.write(profile_report(pts, args.tol))
        if args.output:
            chords = profile_chords(pts, approximate_profile(pts, args.tol), args.chord)
            path: list[tuple[int, int]] = []
            for x, y in chords:
                u = (units(x), units(y))
                if not path or u != path[-1]:
                    path.append(u)
            body = [cards.p_card(10000, 10000, order="D"), cards.l_card(*path[0])]
            body += [cards.plus_card(*u) for u in path[1:]]
            text = cards.deck([cards.CardPackage("PROFILE", body)], job="URAL-1 PROFILE")
            write_whole(args.output, text, inputs=[args.points] if args.points else [])
    except OSError as exc:
        print(f"profile: {exc.filename or args.output}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    except ValueError as exc:
        print(f"profile: {exc}", file=sys.stderr)
        return 1
    return 0


def add_profile(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "profile", help="a tabulated profile as lines and Lagrange quadratics (seed 002)",
        description="Approximate a tabulated profile (default: Table 1 of the Ural-1 "
                    "paper, corrected) by lines and Lagrange quadratics through its own "
                    "points within TOL, print the pieces, and optionally write the chord "
                    "polyline (each chord within CHORD of its piece) as a TENZOR deck.")
    p.add_argument("points", nargs="?", metavar="POINTS",
                   help="file of 'x y' lines in mm ('-' = standard input)")
    p.add_argument("--tol", type=float, default=0.03, help="mm (default 0.03, the paper's)")
    p.add_argument("--chord", type=float, default=0.02,
                   help="chord tolerance, mm (default 0.02, the paper's y)")
    p.add_argument("--paper", action="store_true",
                   help="print equations 6, 8, 10 recomputed beside the printed ones")
    p.add_argument("-o", "--output", metavar="DECK", help="write the chords as a card deck")
    p.set_defaults(func=_run_profile)


def cutter_problem(cutter: float) -> str | None:
    """Why ``--cutter`` cannot be a cutter's diameter, or None."""
    if math.isfinite(cutter) and 0 < cutter <= FIELD_MM:
        return None
    return (f"--cutter {cutter:g}: a cutter's diameter is a number of mm above 0 and at "
            f"most {FIELD_MM:g} (the field)")


def _run_equidistant(args: argparse.Namespace) -> int:
    problem = cutter_problem(args.cutter)
    if problem is None and args.chords is not None and not (math.isfinite(args.chords)
                                                           and args.chords > 0):
        problem = f"--chords {args.chords:g}: a chord tolerance is a number of mm above 0"
    if problem:
        print(f"equidistant: {problem}", file=sys.stderr)
        return 2
    try:
        try:
            text = sys.stdin.read() if args.deck == "-" else ascii_text(Path(args.deck).read_bytes())
        except OSError as exc:
            print(f"equidistant: {args.deck}: {exc.strerror or exc}", file=sys.stderr)
            return 2
        out = equidistant_deck(text, args.cutter, not args.inside, args.chords)
        if args.svg:
            layers = []
            for pkg in parse_deck(text):
                contour = package_contour(pkg)[0]     # closed: equidistant_deck read it
                layers += [(contour, "black"),
                           (equidistant(contour, args.cutter / 2, not args.inside), "#c00")]
            write_whole(args.svg, contours_svg(layers), inputs=[args.deck])
        if args.output:
            write_whole(args.output, out, inputs=[args.deck])
        else:
            sys.stdout.write(out)
    except OSError as exc:                      # an output
        print(f"equidistant: {exc.filename or args.output}: {exc.strerror or exc}",
              file=sys.stderr)
        return 2
    except ValueError as exc:
        print(f"equidistant: {args.deck}: {exc}", file=sys.stderr)
        return 1
    return 0


def add_equidistant(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "equidistant", help="cutter-centre path of a contour of lines and arcs (seed 002)",
        description="Read a card deck whose L/+ and A cards form one closed contour per "
                    "package (in card order) and write a deck of the path of the centre "
                    "of a cutter of the given diameter running outside (or inside) it.")
    p.add_argument("deck", metavar="DECK", help="card deck ('-' = standard input)")
    p.add_argument("--cutter", type=float, default=FLANGE_CUTTER_MM,
                   help="cutter diameter, mm (default 20, the paper's)")
    p.add_argument("--inside", action="store_true", help="run inside the contour")
    p.add_argument("--chords", type=float, default=None, metavar="TOL",
                   help="write arcs as chords within TOL mm (line-only machines)")
    p.add_argument("-o", "--output", metavar="DECK", help="output deck (default stdout)")
    p.add_argument("--svg", metavar="FILE.svg", help="also draw the contour and the path")
    p.set_defaults(func=_run_equidistant)


def _read_frames_text(text: str) -> list[Frame5121]:
    """'DX DY [DZ [SPEED [AUX_X [AUX_Y [AUX_Z]]]]]' per line (pulses)."""
    frames = []
    for no, line in enumerate(text.splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        try:
            vals = [int(v) for v in line.split()]
        except ValueError:
            raise ValueError(f"line {no}: not whole numbers: {line!r}") from None
        if not 2 <= len(vals) <= 7:
            raise ValueError(f"line {no}: expected DX DY [DZ [SPEED [AUX_X [AUX_Y [AUX_Z]]]]]")
        try:
            frame = Frame5121(*vals)
            frame_rows_5121(frame)
        except ValueError as exc:
            raise ValueError(f"line {no}: {exc}") from None
        frames.append(frame)
    return frames


def _run_punch5121(args: argparse.Namespace) -> int:
    try:
        if args.decode:
            data = open(args.input, "rb").read()
            for f in read_5121(data):
                sys.stdout.write(f"{f.dx} {f.dy} {f.dz} {f.speed} {f.aux_x} {f.aux_y} "
                                 f"{f.aux_z}\n")
            return 0
        if not args.output:
            print("punch5121: -o TAPE.ptp is required to punch (or --decode a tape)",
                  file=sys.stderr)
            return 2
        text = sys.stdin.read() if args.input == "-" else ascii_text(Path(args.input).read_bytes())
        data = punch_5121(_read_frames_text(text), even_shift=args.even_shift)
        write_whole(args.output, data, inputs=[args.input])
    except OSError as exc:
        print(f"punch5121: {exc.filename or args.input}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    except ValueError as exc:
        print(f"punch5121: {args.input}: {exc}", file=sys.stderr)
        return 1
    return 0


def add_punch5121(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "punch5121", help="punch frames in the 5121 code of the LKP-01F (seed 002)",
        description="Punch frames 'DX DY [DZ [SPEED [AUX_X [AUX_Y [AUX_Z]]]]]' (pulses; DX, DY "
                    "at most 4 digits, DZ 3, SPEED one) as a 5-track tape image in the "
                    "5121 code of the Ural-1 paper's Table 6, or --decode one.  The "
                    "output of 'split --max 9999' is valid input.")
    p.add_argument("input", metavar="FRAMES", help="frame text ('-' = stdin), or a .ptp with --decode")
    p.add_argument("-o", "--output", metavar="TAPE.ptp",
                   help="the tape image to punch (required, but for --decode)")
    p.add_argument("--decode", action="store_true", help="print the frames of a tape image")
    p.add_argument("--even-shift", action="store_true",
                   help="move every even frame two rows along the tape (the reader "
                        "takes either layout)")
    p.set_defaults(func=_run_punch5121)
