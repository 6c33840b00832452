"""Seed 004: long moves split into frames, and linear interpolators.

Source: seed 004 (docs/SOURCES.md) (a Russian textbook chapter
on NC tape codes and interpolators; OCR text, formulas and figures lost).
Sections used:

* "Линейные интерполяторы", the pulse multiplier ("импульсный умножитель"):
  a counter of n binary digits, a register a1..an, AND gates and one OR gate
  per axis.  One cycle of the counter is one frame; the number of output
  pulses equals the number in the register ("Dx = a1*2^0 + ... + an*2^(n-1)"),
  at most N - 1 for a counter of volume N ("DXmax = N - 1").  The path is a
  staircase whose largest deviation from the line grows with n, i.e. with
  the logarithm of the longest move.
* The split of a long move: "объем умножителя составляет 10000 ... 9999
  импульсов"; DX = 98132, DY = 87647 go into 10 frames, each the "last digit
  dropped" (9813, 8764) plus the remainders (2 and 7 pulses) "distributed
  over the frames as evenly as possible", so that every division point lies
  within one pulse of the line.  Its table is :data:`DOCUMENT_TABLE`.

Everything here is integer arithmetic on pulses, deterministic.  These
interpolators are simulated pulse by pulse (one input pulse of the common
counter at a time):

* ``binary``: the document's binary pulse multiplier (a binary rate
  multiplier): counter bit b rising from 0 to 1 is gated by register bit
  n-1-b, so register bit k yields 2^k pulses per cycle.
* ``decimal``: the same with decade counters (volume 10^D, the document's
  10000).  A BCD decade rising through its states gives trains of 5, 2, 1
  and 1 pulses per decade cycle on its four bits, so a register digit must be
  written in those weights: exactly the 5121 code of seed 002's Table 6
  (:data:`seeds.seed002.CODE_5121`), which is why its tape-code converter
  read digits in that code.
* ``integrator``: a digital differential analyser (the document's
  "интерполятор на числовых интеграторах с параллельным переносом"): each
  input pulse adds the register to an accumulator; an overflow is an output
  pulse.
* ``counter``: OUR RECONSTRUCTION of the third principle, which the document
  only names ("интерполятор на счетчиках с переменным коэффициентом
  деления") and does not describe: a programmable frequency divider per
  axis.  A down-counter fed by the common generator is loaded with
  K = floor(N/|D|) or K + 1; reaching zero it gives one output pulse and is
  loaded again; a remainder accumulator, preset to |D| - 1, gains
  r = N mod |D| at every load and, when it reaches |D|, loses |D| and makes
  that period K + 1.  Output pulse i comes on generator pulse
  ceil(i*N/|D|): the last on the N-th, so a cycle gives exactly |D|.  This
  is, pulse for pulse, the integrator's train (after m input pulses
  floor(m*|D|/N) pulses); the divider stores a period, the integrator an
  accumulated phase.  ``fixed_ratio`` shows the naive divider without the
  remainder (K fixed, each axis stopped after |D| pulses), which is why the
  ratio must vary.
"""

from __future__ import annotations

import argparse
import math
import sys
from collections import deque
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

from harness.files import write_whole

from .seed002 import code_5121_weights

#: The document's split of DX = 98132, DY = 87647 pulses at most 9999 per frame.
DOCUMENT_MOVE: tuple[int, int] = (98132, 87647)
DOCUMENT_MAX: int = 9999
#: The most frames a move may be split into, and the most input pulses the
#: interpolators may simulate: past them a hostile DX or --size would take
#: minutes and gigabytes (a list of 10^8 frames), so the move is refused.
MOST_FRAMES: int = 1_000_000
MOST_PULSES: int = 1 << 21
DOCUMENT_TABLE: tuple[tuple[int, int], ...] = (
    (9813, 8765), (9813, 8764), (9814, 8765), (9813, 8765), (9813, 8764),
    (9813, 8765), (9813, 8765), (9814, 8765), (9813, 8764), (9813, 8765))

METHODS: tuple[str, ...] = ("binary", "decimal", "integrator", "master", "counter")


# ---------------------------------------------------------------------------
# Splitting a long move.
# ---------------------------------------------------------------------------
def _sign(v: int) -> int:
    return (v > 0) - (v < 0)


def frames_needed(dx: int, dy: int, max_pulses: int) -> int:
    """The fewest frames of at most ``max_pulses`` per axis for (dx, dy)."""
    if max_pulses < 1:
        raise ValueError(f"--max {max_pulses}: a frame's limit is at least 1 pulse")
    return max(-(-abs(dx) // max_pulses), -(-abs(dy) // max_pulses))


def division_point(d: int, k: int, n: int) -> int:
    """k/n of the way along an axis of d pulses, to the nearest pulse; a tie
    (exactly half a pulse) goes toward the start point.

    This is what reproduces the document's table: for DY = 87647 in ten
    frames the fifth point 43823.5 is 43823, so frame 5 gets 8764 pulses."""
    mag = (2 * k * abs(d) + n - 1) // (2 * n)
    return mag if d >= 0 else -mag


def split_move(dx: int, dy: int, max_pulses: int = DOCUMENT_MAX) -> list[tuple[int, int]]:
    """Split a straight move of (dx, dy) pulses into as few frames as the
    limit allows, every frame at most ``max_pulses`` on each axis.

    Frame k ends at the point nearest to k/n of the move (see
    :func:`division_point`), so each division point is within half a pulse
    of the line on each axis (within 0.71 pulse of it), and the frames differ
    by at most one pulse per axis: the document's "base value plus the
    remainder spread as evenly as possible".  A move of (0, 0) has no frame.
    """
    n = frames_needed(dx, dy, max_pulses)
    if n == 0:
        return []
    if n > MOST_FRAMES:
        raise ValueError(f"the move ({dx}, {dy}) needs {n} frames of at most {max_pulses} "
                         f"pulses, more than {MOST_FRAMES}")
    points = [(division_point(dx, k, n), division_point(dy, k, n)) for k in range(n + 1)]
    return [(x1 - x0, y1 - y0) for (x0, y0), (x1, y1) in zip(points, points[1:])]


def line_distance(x: float, y: float, dx: int, dy: int) -> float:
    """Signed distance (pulses, + = left) of (x, y) from the line through the
    origin and (dx, dy)."""
    return (dx * y - dy * x) / math.hypot(dx, dy)


# ---------------------------------------------------------------------------
# Equal frames by continued fractions.
# ---------------------------------------------------------------------------
def semiconvergents(num: int, den: int) -> Iterator[tuple[int, int]]:
    """The convergents and semiconvergents p/q of num/den (0 <= num <= den,
    den > 0), q never decreasing: 0/1, then (p_{k-2} + t p_{k-1}) /
    (q_{k-2} + t q_{k-1}) for t = 1 .. a_k of each partial quotient a_k
    (t = a_k is the convergent).  The candidates for the best rational
    approximation with a bounded denominator (the document's "аппарат
    цепных дробей")."""
    yield 0, 1
    p0, q0, p1, q1 = 1, 0, 0, 1          # convergents k-2 and k-1
    a, b = den, num                      # num/den = [0; a1, a2, ...]
    while b:
        quot = a // b
        for t in range(1, quot + 1):
            yield p0 + t * p1, q0 + t * q1
        p0, q0, p1, q1 = p1, q1, p0 + quot * p1, q0 + quot * q1
        a, b = b, a - quot * b


@dataclass(frozen=True)
class EqualSplit:
    """A move split into ``count`` equal frames ``frame`` and, unless it is
    (0, 0), one ``last`` frame that takes up the error; ``deviation``: the
    largest distance (pulses) of a division point from the line."""

    dx: int
    dy: int
    frame: tuple[int, int]
    count: int
    last: tuple[int, int]
    deviation: float

    @property
    def frames(self) -> list[tuple[int, int]]:
        out = [self.frame] * self.count
        return out + ([self.last] if self.last != (0, 0) else [])


def split_equal(dx: int, dy: int, max_pulses: int = DOCUMENT_MAX) -> EqualSplit:
    """Split a straight move into equal frames, all but the last, which
    takes up the error (seed 004: the tangent of the move approximated by
    continued fractions).

    Along the longer axis u and the shorter v: the frame's tangent is a
    convergent or semiconvergent p/q of v/u with q <= max_pulses, the frame
    (m q, m p) with the largest m that lets the last frame fit (both of its
    components between 0 and max_pulses, same direction as the move); of all
    candidates the one whose division points stray least from the line
    (exactly: k m |q v - p u| / L for k equal frames, the last division point
    being the farthest), then the fewest frames, then the smallest q.  Sums
    are exact by construction.  ValueError when no candidate fits: the last
    frame cannot take up the error of so many equal ones (possible only when
    the move is longer than max_pulses squared; for every move of up to 79
    pulses and limits 1-7 a split exists exactly when a search of all equal
    frames finds one)."""
    if max_pulses < 1:
        raise ValueError(f"--max {max_pulses}: a frame's limit is at least 1 pulse")
    u, v = abs(dx), abs(dy)
    swap = v > u
    if swap:
        u, v = v, u
    if u == 0:
        return EqualSplit(dx, dy, (0, 0), 0, (0, 0), 0.0)
    best: tuple | None = None
    for p, q in semiconvergents(v, u):
        if q > max_pulses:
            break
        # the total multiplier c = k m: both remainders u - c q, v - c p in 0..max
        clo = max(1, -(-(u - max_pulses) // q))
        chi = u // q
        if p:
            clo, chi = max(clo, -(-(v - max_pulses) // p)), min(chi, v // p)
        elif v > max_pulses:
            continue
        if clo > chi:
            continue
        for m in range(max_pulses // q, 0, -1):
            k = chi // m
            if k * m < clo:
                continue
            ru, rv = u - k * m * q, v - k * m * p
            err = k * m * abs(q * v - p * u)
            key = (err, k + (1 if (ru, rv) != (0, 0) else 0), q)
            if best is None or key < best[0]:
                best = (key, (m * q, m * p), k, (ru, rv), err)
            break
    if best is None:
        raise ValueError(f"no equal frames of at most {max_pulses} pulses fit the move "
                         f"({dx}, {dy})")
    _, (a, b), k, (ru, rv), err = best
    if k + ((ru, rv) != (0, 0)) > MOST_FRAMES:
        raise ValueError(f"the move ({dx}, {dy}) needs {k + ((ru, rv) != (0, 0))} equal frames "
                         f"of at most {max_pulses} pulses, more than {MOST_FRAMES}")
    dev = err / math.hypot(u, v)

    def orient(x: int, y: int) -> tuple[int, int]:
        if swap:
            x, y = y, x
        return (x if dx >= 0 else -x, y if dy >= 0 else -y)

    return EqualSplit(dx, dy, orient(a, b), k, orient(ru, rv), dev)


def split_deviation(dx: int, dy: int, frames: Sequence[tuple[int, int]]) -> float:
    """The largest distance (pulses) of a division point of the frames from
    the line of the move."""
    x = y = 0
    worst = 0.0
    for fx, fy in frames:
        x, y = x + fx, y + fy
        worst = max(worst, abs(line_distance(x, y, dx, dy)))
    return worst


# ---------------------------------------------------------------------------
# Interpolators.
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Interpolation:
    """A simulated frame (or chain of frames) pulse by pulse.

    ``xs``, ``ys``: the tool position after every input pulse of the common
    counter (index 0 is the start); ``deviation``: the signed distance of
    each position from the line (pulses); ``volume``: input pulses per frame
    (the counter's volume N); ``frames``: the frames interpolated;
    ``fixed_ratio``: the counter interpolator without its remainder register
    (see :func:`counter_pulses`).
    """

    method: str
    dx: int
    dy: int
    volume: int
    frames: tuple[tuple[int, int], ...]
    xs: tuple[int, ...]
    ys: tuple[int, ...]
    deviation: tuple[float, ...]
    fixed_ratio: bool = False

    @property
    def worst(self) -> int:
        """Index of the input pulse with the largest |deviation|."""
        return max(range(len(self.deviation)), key=lambda i: abs(self.deviation[i]))

    @property
    def max_deviation(self) -> float:
        return abs(self.deviation[self.worst])


def binary_bits(dx: int, dy: int) -> int:
    """Fewest counter bits n with 2^n - 1 >= max(|dx|, |dy|) (at least 1)."""
    return max(1, max(abs(dx), abs(dy)).bit_length())


def _ctz(m: int) -> int:
    return (m & -m).bit_length() - 1


def binary_pulses(value: int, bits: int) -> list[int]:
    """Output pulses (0 or 1) of one axis of a binary pulse multiplier over
    one cycle of 2^bits input pulses, for register ``value`` (0..2^bits-1).

    Input pulse m (1-based) raises counter bit b = ctz(m) from 0 to 1 (the
    last pulse of the cycle only overflows the counter); that bit is gated
    by register bit bits-1-b, which therefore yields 2^(bits-1-b) pulses.
    """
    if not 0 <= value < 1 << bits:
        raise ValueError(f"{value} pulses do not fit a {bits}-bit multiplier "
                         f"(at most {(1 << bits) - 1})")
    out = [0] * (1 << bits)
    for m in range(1, 1 << bits):
        out[m - 1] = (value >> (bits - 1 - _ctz(m))) & 1
    return out


#: Input states (1..9, 0 after the carry) at which each bit of a BCD decade
#: counter rises from 0 to 1, and the weight of that bit's pulse train.
DECADE_TRAINS: tuple[tuple[int, tuple[int, ...]], ...] = (
    (5, (1, 3, 5, 7, 9)),   # bit 1 (weight 1 of 8421) rises on odd states
    (2, (2, 6)),            # bit 2
    (1, (4,)),              # bit 4
    (1, (8,)))              # bit 8


def decimal_pulses(value: int, decades: int) -> list[int]:
    """Output pulses of one axis of a decimal pulse multiplier of
    ``decades`` BCD decades (volume 10^decades) over one cycle.

    Register digit j (weight 10^j) is written in the 5121 code (seed 002,
    Table 6); its bits of weights 5, 2, 1, 1 gate the four trains of
    :data:`DECADE_TRAINS` of counter decade ``decades-1-j``, which runs
    through 10^j cycles per cycle of the whole counter."""

    volume = 10 ** decades
    if not 0 <= value < volume:
        raise ValueError(f"{value} pulses do not fit a {decades}-decade multiplier "
                         f"(at most {volume - 1})")
    out = [0] * volume
    for j in range(decades):
        digit = value // 10 ** j % 10
        if digit == 0:
            continue
        decade = decades - 1 - j
        period = 10 ** decade          # input pulses per state of that decade
        weights = code_5121_weights(digit)   # (5, 2, 1, 1) subset summing to digit
        for (w, states), on in zip(DECADE_TRAINS, weights):
            if not on:
                continue
            assert w == on
            for cycle in range(10 ** j):
                for s in states:
                    # the decade enters state s on input pulse
                    # (cycle*10 + s) * period; its own carries come first
                    out[(cycle * 10 + s) * period - 1] = 1
    return out


def integrator_pulses(value: int, volume: int) -> list[int]:
    """Output pulses of a DDA integrator: the accumulator (starting empty)
    gains ``value`` per input pulse and emits one pulse per overflow of
    ``volume``: after m input pulses, floor(m * value / volume) pulses."""
    if not 0 <= value < volume:
        raise ValueError(f"{value} pulses do not fit an integrator of volume {volume}")
    out, acc = [0] * volume, 0
    for m in range(volume):
        acc += value
        if acc >= volume:
            acc -= volume
            out[m] = 1
    return out


def counter_pulses(value: int, volume: int, fixed_ratio: bool = False) -> list[int]:
    """Output pulses of one axis of the counter interpolator over one cycle
    of ``volume`` (N) generator pulses, for ``value`` (D) pulses.

    OUR RECONSTRUCTION: the document names the "интерполятор на счетчиках с
    переменным коэффициентом деления" and no more.  A presettable
    down-counter is loaded with a division coefficient; each generator pulse
    counts it down; at zero it gives one output pulse and is loaded again.
    The coefficient is K = floor(N/D) or K + 1: a remainder register holds
    r = N mod D and a remainder accumulator, preset to D - 1, gains r at
    every load (the first at the start of the cycle); when it reaches D it
    loses D and that load is K + 1.  The load before period i then holds
    ceil(i*r/D) - ceil((i-1)*r/D) extra, so output pulse i comes on
    generator pulse ceil(i*N/D) (1-based): every pulse within one generator
    pulse after its ideal time i*N/D, the r long periods spread as evenly as
    they can be, and the D-th pulse on the N-th generator pulse, so the
    cycle gives exactly D pulses with nothing to stop the divider.

    ``fixed_ratio``: the naive divider with no remainder register, K fixed.
    It would give N // K pulses a cycle, more than D unless K*(D+1) > N
    (see :func:`fixed_ratio_count`), so here each axis is stopped after its
    D pulses (on generator pulse D*K, early) and the axes' rates are off.
    """
    if not 0 <= value < volume:
        raise ValueError(f"{value} pulses do not fit a counter interpolator of volume "
                         f"{volume}")
    out = [0] * volume
    if value == 0:
        return out                       # the divider is never started
    k, r = divmod(volume, value)
    if fixed_ratio:
        r = 0
    rest = value - 1                     # the remainder accumulator
    given = 0

    def load() -> int:
        nonlocal rest
        rest += r
        if rest >= value:
            rest -= value
            return k + 1
        return k

    count = load()
    for m in range(volume):
        count -= 1
        if count == 0:
            out[m] = 1
            given += 1
            if fixed_ratio and given == value:
                break                    # the naive divider must be stopped
            count = load()
    return out


def fixed_ratio_count(value: int, volume: int) -> int:
    """Pulses a free-running divider of fixed coefficient K = floor(N/D)
    gives in a cycle of N = ``volume`` generator pulses (0 for D = 0)."""
    return volume // (volume // value) if value else 0


def _axis_pulses(method: str, value: int, size: int, fixed_ratio: bool = False) -> list[int]:
    if method in ("binary", "master"):
        return binary_pulses(value, size)
    if method == "decimal":
        return decimal_pulses(value, size)
    if method == "integrator":
        return integrator_pulses(value, size)
    if method == "counter":
        return counter_pulses(value, size, fixed_ratio)
    raise ValueError(f"unknown method {method!r}; one of {', '.join(METHODS)}")


def counter_size(method: str, frames: Sequence[tuple[int, int]]) -> int:
    """The smallest counter (bits, decades, or volume for the integrator
    and the counter interpolator) that holds every frame of ``frames``."""
    big = max([max(abs(a), abs(b)) for a, b in frames] + [1])
    if method in ("binary", "master"):
        return big.bit_length()
    if method == "decimal":
        return len(str(big))
    return 1 << big.bit_length()


def interpolate(dx: int, dy: int, method: str = "binary", size: int | None = None,
                max_pulses: int | None = None, lag: int = 0,
                fixed_ratio: bool = False) -> Interpolation:
    """Simulate the move (dx, dy) pulse by pulse.

    ``size``: counter bits (binary, master), decades (decimal) or volume
    (integrator, counter); default the smallest that holds the frames.
    ``max_pulses``: split the move first (:func:`split_move`) and
    interpolate frame after frame, as the document advises for long moves.
    ``lag``: the X drive (heavy, inertial: the document's long-travel axis
    of a large milling machine) carries out each of its pulses ``lag``
    generator periods late.  With independent axes (binary, decimal,
    integrator) X simply falls behind; with ``master`` (the document's
    "интерполятор с задающей координатой") X is the master: each pulse the
    multiplier gives X closes the valve between the generator and the
    multiplier ("запрет"), and the master's position sensor opens it again
    once X has moved ("разрешение"), so Y waits for X.  The positions are
    recorded once a generator period.
    ``fixed_ratio``: only with ``counter``, its naive divider
    (:func:`counter_pulses`).
    """
    if (dx, dy) == (0, 0):
        raise ValueError("a move of (0, 0) has nothing to interpolate")
    if lag < 0:
        raise ValueError(f"the lag is a number of generator periods, not {lag}")
    if fixed_ratio and method != "counter":
        raise ValueError(f"a fixed ratio is the counter interpolator's, not the {method}'s")
    frames = split_move(dx, dy, max_pulses) if max_pulses is not None else [(dx, dy)]
    given = size is not None
    if size is None:
        size = counter_size(method, frames)
    if method not in ("integrator", "counter") and not 1 <= size <= 64:
        if given:
            raise ValueError(f"--size {size}: the counter size is 1 to 64 (bits or decades)")
        raise ValueError(f"a frame of {max(max(abs(a), abs(b)) for a, b in frames)} pulses "
                         f"needs a counter of {size} bits or decades, more than 64: give "
                         f"--max to split the move")
    # (not a dict of the methods: that would compute 10 ** size for an integrator's
    # volume of 2^32, which takes minutes)
    volume = (1 << size if method in ("binary", "master") else 10 ** size if method == "decimal"
              else size)
    if volume * len(frames) > MOST_PULSES:
        raise ValueError(f"the simulation would take {volume * len(frames)} input pulses, "
                         f"more than {MOST_PULSES}; split the move with --max or give a "
                         f"smaller --size")
    if method == "master" and volume * len(frames) + lag * abs(dx) > MOST_PULSES:
        # the valve holds the generator lag periods for each of X's pulses
        raise ValueError(f"the simulation would take {volume * len(frames) + lag * abs(dx)} "
                         f"generator periods with the lag, more than {MOST_PULSES}")
    xs, ys = [0], [0]
    pending: deque[int] = deque()       # X pulses on their way (independent axes)
    for fx, fy in frames:
        px = _axis_pulses(method, abs(fx), size, fixed_ratio)
        py = _axis_pulses(method, abs(fy), size, fixed_ratio)
        sx, sy = _sign(fx), _sign(fy)
        for a, b in zip(px, py):
            if method == "master":
                ys.append(ys[-1] + sy * b)
                xs.append(xs[-1] + (sx * a if lag == 0 else 0))
                if a and lag:
                    # the valve is shut until the master's sensor reports the move
                    for t in range(lag):
                        xs.append(xs[-1] + (sx if t == lag - 1 else 0))
                        ys.append(ys[-1])
                continue
            pending.append(sx * a)
            moved = pending.popleft() if len(pending) > lag else 0
            xs.append(xs[-1] + moved)
            ys.append(ys[-1] + sy * b)
    while pending:                       # the X drive catches up
        xs.append(xs[-1] + pending.popleft())
        ys.append(ys[-1])
    if (xs[-1], ys[-1]) != (dx, dy):
        raise AssertionError(f"interpolator ended at {(xs[-1], ys[-1])}, not {(dx, dy)}")
    dev = tuple(line_distance(x, y, dx, dy) for x, y in zip(xs, ys))
    return Interpolation(method, dx, dy, volume, tuple(frames), tuple(xs), tuple(ys), dev,
                         fixed_ratio)


def binary_bound(dx: int, dy: int) -> float:
    """Upper bound (pulses) of the binary multiplier's deviation on one
    frame: after m input pulses register bit k has given
    floor(m/2^b) - floor(m/2^(b+1)) = floor(m/2^(b+1) + 1/2) pulses
    (b = n-1-k), within half a pulse of its share m*2^k/2^n; so an axis is
    off by at most popcount(|d|)/2 pulses, and the distance from the line
    by at most (popcount(dx)*|dy| + popcount(dy)*|dx|) / (2 L).  Since
    popcount <= n, this grows like log2 of the move: the document's point."""
    px, py = bin(abs(dx)).count("1"), bin(abs(dy)).count("1")
    return (px * abs(dy) + py * abs(dx)) / (2 * math.hypot(dx, dy))


# ---------------------------------------------------------------------------
# Text and SVG.
# ---------------------------------------------------------------------------
def summary(run: Interpolation) -> str:
    """A few lines describing a simulation (what ``python -m seeds dda``
    prints)."""
    i = run.worst
    unit = {"binary": "bits", "master": "bits", "decimal": "decades",
            "integrator": "volume", "counter": "volume"}[run.method]
    size = {"binary": run.volume.bit_length() - 1, "master": run.volume.bit_length() - 1,
            "decimal": len(str(run.volume)) - 1}.get(run.method, run.volume)
    name = "counter (fixed ratio)" if run.fixed_ratio else run.method
    lines = [f"move DX {run.dx} DY {run.dy} pulses, {name} interpolator, "
             f"{unit} {size}, {run.volume} input pulses per frame, "
             f"{len(run.frames)} frame{'s' if len(run.frames) != 1 else ''}",
             f"largest deviation from the line: {run.deviation[i]:+.3f} pulses "
             f"at input pulse {i} (x {run.xs[i]}, y {run.ys[i]})"]
    if run.method == "binary" and len(run.frames) == 1:
        lines.append(f"bound (popcount rule): {binary_bound(run.dx, run.dy):.3f} pulses")
    if run.method == "counter":
        lines.append("(our reconstruction of the document's named-only interpolator on "
                     "counters with a variable division ratio)")
    if run.method == "counter" and len(run.frames) == 1:
        parts = []
        for axis, d in (("X", abs(run.dx)), ("Y", abs(run.dy))):
            if d:
                k, r = divmod(run.volume, d)
                parts.append(f"{axis} K {k}" + ("" if run.fixed_ratio else f" r {r}"))
        lines.append("division coefficients: " + ", ".join(parts))
    if run.fixed_ratio:
        extra = [sum(fixed_ratio_count(abs(f[a]), run.volume) - abs(f[a]) for f in run.frames)
                 for a in (0, 1)]
        own = [sum(abs(f[a]) for f in run.frames) for a in (0, 1)]
        lines.append(f"free-running, the fixed ratio would give X {extra[0]} and Y {extra[1]} "
                     f"pulses too many; each axis was stopped after its own pulses (X {own[0]}, "
                     f"Y {own[1]})")
    return "\n".join(lines) + "\n"


def _fmt(v: float) -> str:
    return f"{v:.2f}".rstrip("0").rstrip(".")


def svg_plot(run: Interpolation, width: int = 720) -> str:
    """An SVG picture: on top the path (staircase) and the line, below the
    signed deviation from the line for every input pulse (per pixel column
    its minimum and maximum), with the largest one marked."""
    pad, h1, h2 = 40, 360, 200
    inner = width - 2 * pad
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" '
           f'height="{h1 + h2 + 3 * pad}" font-family="monospace" font-size="12">',
           '<rect width="100%" height="100%" fill="white"/>',
           f'<text x="{pad}" y="20">{run.method} interpolator: DX {run.dx}, DY {run.dy}, '
           f'{len(run.frames)} frame(s); largest deviation '
           f'{run.max_deviation:.3f} pulses</text>']
    # Panel 1: the staircase near the largest deviation, one pulse a cell.
    w = run.worst
    half = 12
    cx, cy = run.xs[w], run.ys[w]
    scale = min(inner, h1) / (2 * half)

    def px(x: float) -> float:
        return pad + (x - cx + half) * scale

    def py(y: float) -> float:
        return pad + h1 - (y - cy + half) * scale

    lo = w
    while lo > 0 and abs(run.xs[lo - 1] - cx) <= half and abs(run.ys[lo - 1] - cy) <= half:
        lo -= 1
    hi = w
    while (hi < len(run.xs) - 1 and abs(run.xs[hi + 1] - cx) <= half
           and abs(run.ys[hi + 1] - cy) <= half):
        hi += 1
    out.append(f'<text x="{pad}" y="{pad - 6}">path near the largest deviation, '
               f'one pulse a cell, x {cx - half}..{cx + half}, y {cy - half}..{cy + half}</text>')
    grid = " ".join(f"M{_fmt(px(cx - half + k))} {_fmt(py(cy - half))}V{_fmt(py(cy + half))}"
                    f" M{_fmt(px(cx - half))} {_fmt(py(cy - half + k))}H{_fmt(px(cx + half))}"
                    for k in range(2 * half + 1))
    out.append(f'<path d="{grid}" stroke="#ddd" stroke-width="1"/>')
    # the line, clipped to the window by sampling its parameter
    ts = [(cx - half) / run.dx, (cx + half) / run.dx] if run.dx else []
    ts += [(cy - half) / run.dy, (cy + half) / run.dy] if run.dy else []
    inside = sorted(t for t in ts + [0.0, 1.0] if 0.0 <= t <= 1.0
                    and abs(t * run.dx - cx) <= half + 1e-9 and abs(t * run.dy - cy) <= half + 1e-9)
    if len(inside) >= 2:
        a, b = inside[0], inside[-1]
        out.append(f'<line x1="{_fmt(px(a * run.dx))}" y1="{_fmt(py(a * run.dy))}" '
                   f'x2="{_fmt(px(b * run.dx))}" y2="{_fmt(py(b * run.dy))}" '
                   f'stroke="#c00" stroke-width="1.5"/>')
    pts = " ".join(f"{_fmt(px(x))},{_fmt(py(y))}" for x, y in
                   zip(run.xs[lo:hi + 1], run.ys[lo:hi + 1]))
    out.append(f'<polyline points="{pts}" fill="none" stroke="black" stroke-width="2"/>')
    out.append(f'<circle cx="{_fmt(px(cx))}" cy="{_fmt(py(cy))}" r="5" fill="none" '
               f'stroke="#00c" stroke-width="2"/>')
    # Panel 2: deviation per input pulse.
    top = 2 * pad + h1
    dev = run.deviation
    lim = max(max(abs(d) for d in dev), 0.5)
    n = len(dev)
    cols = min(inner, n)
    out.append(f'<rect x="{pad}" y="{top}" width="{inner}" height="{h2}" fill="none" '
               f'stroke="#888"/>')
    mid = top + h2 / 2
    out.append(f'<line x1="{pad}" y1="{_fmt(mid)}" x2="{pad + inner}" y2="{_fmt(mid)}" '
               f'stroke="#c00"/>')
    segs = []
    for c in range(cols):
        lo, hi = c * n // cols, max((c + 1) * n // cols, c * n // cols + 1)
        chunk = dev[lo:hi]
        x = pad + (c + 0.5) * inner / cols
        y0 = mid - min(chunk) / lim * (h2 / 2 - 4)
        y1 = mid - max(chunk) / lim * (h2 / 2 - 4)
        segs.append(f"M{_fmt(x)} {_fmt(y0)}V{_fmt(min(y1, y0 - 0.5))}")
    out.append(f'<path d="{" ".join(segs)}" stroke="black" stroke-width="1" fill="none"/>')
    wx = pad + (w + 0.5) * inner / n
    wy = mid - dev[w] / lim * (h2 / 2 - 4)
    out.append(f'<circle cx="{_fmt(wx)}" cy="{_fmt(wy)}" r="4" fill="none" stroke="#00c"/>')
    out.append(f'<text x="{pad}" y="{top - 6}">deviation from the line, pulses '
               f'(+{_fmt(lim)} .. -{_fmt(lim)}), input pulse 0 .. {n - 1}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------------------
# Command line: python -m seeds split / dda.
# ---------------------------------------------------------------------------
def equal_summary(run: EqualSplit) -> str:
    """The comment line that ``split --equal`` prints after the frames."""
    n = len(run.frames)
    head = (f"# {n} frame{'s' if n != 1 else ''}: {run.count} of {run.frame[0]} {run.frame[1]}"
            if run.count else "# no frame")
    if run.last != (0, 0):
        head += f", the last {run.last[0]} {run.last[1]}"
    return head + (f"; largest distance of a division point from the line "
                   f"{run.deviation:.6f} pulses\n")


def _run_split(args: argparse.Namespace) -> int:
    try:
        if args.equal:
            run = split_equal(args.dx, args.dy, args.max)
            frames = run.frames
        else:
            frames = split_move(args.dx, args.dy, args.max)
    except ValueError as exc:
        print(f"split: {exc}", file=sys.stderr)
        return 2 if args.max < 1 else 1
    sys.stdout.write("".join(f"{a} {b}\n" for a, b in frames))
    if args.equal:
        sys.stdout.write(equal_summary(run))
    return 0


def add_split(sub: argparse._SubParsersAction) -> None:
    """``split --max N DX DY``: one frame a line."""
    p = sub.add_parser(
        "split", help="split a long move into frames of at most N pulses (seed 004)",
        description="Print the frames (one 'DX DY' pair a line) of a straight move of "
                    "DX, DY pulses split into as few frames of at most N pulses per axis "
                    "as possible, every division point within one pulse of the line "
                    "(the nearest point to k/n of the move; a tie goes toward the start). "
                    "The document's example: --max 9999 98132 87647.")
    p.add_argument("--max", type=int, default=DOCUMENT_MAX, metavar="N",
                   help=f"most pulses per axis in one frame (default {DOCUMENT_MAX})")
    p.add_argument("--equal", action="store_true",
                   help="equal frames but the last, which takes up the error (continued "
                        "fractions); a last '#' line gives the largest distance of a "
                        "division point from the line")
    p.add_argument("dx", type=int, metavar="DX")
    p.add_argument("dy", type=int, metavar="DY")
    p.set_defaults(func=_run_split)


def _run_dda(args: argparse.Namespace) -> int:
    try:
        run = interpolate(args.dx, args.dy, args.method, args.size, args.max, args.lag,
                          args.fixed_ratio)
    except ValueError as exc:
        print(f"dda: {exc}", file=sys.stderr)
        return 2
    sys.stdout.write(summary(run))
    if args.plot:
        try:
            write_whole(args.plot, svg_plot(run))
        except OSError as exc:
            print(f"dda: {args.plot}: {exc.strerror or exc}", file=sys.stderr)
            return 2
    return 0


def add_dda(sub: argparse._SubParsersAction) -> None:
    """``dda DX DY [--method M] [--size S] [--max N] [--lag L] [--fixed-ratio]
    [--plot FILE.svg]``."""
    p = sub.add_parser(
        "dda", help="simulate a linear interpolator pulse by pulse (seed 004)",
        description="Simulate a linear interpolator pulse by pulse on a move of DX, DY "
                    "pulses and print its largest deviation from the line: the "
                    "document's binary pulse multiplier (default), a decimal one whose "
                    "register digits are in the 5121 code, a DDA integrator, the "
                    "interpolator with a master coordinate, or the interpolator on "
                    "counters with a variable division ratio, which the document only "
                    "names: the counter method is our reconstruction (a programmable "
                    "divider per axis).")
    p.add_argument("dx", type=int, metavar="DX")
    p.add_argument("dy", type=int, metavar="DY")
    p.add_argument("--method", choices=METHODS, default="binary",
                   help="binary pulse multiplier (default), decimal (5121) pulse "
                        "multiplier, integrator (DDA), master (a binary multiplier "
                        "slaved to the X axis's position sensor), or counter (OUR "
                        "reconstruction of the named-only interpolator on counters "
                        "with a variable division ratio: per axis a down-counter "
                        "loaded with floor(N/D) or one more, pulse i on generator "
                        "pulse ceil(i*N/D))")
    p.add_argument("--size", type=int, default=None, metavar="S",
                   help="counter bits (binary, master), decades (decimal) or volume "
                        "(integrator, counter); default the smallest that holds the "
                        "move")
    p.add_argument("--max", type=int, default=None, metavar="N",
                   help="split the move into frames of at most N pulses first "
                        "(as 'split --max N') and interpolate frame by frame")
    p.add_argument("--lag", type=int, default=0, metavar="L",
                   help="the X drive moves L generator periods after its pulse (an "
                        "inertial axis); with --method master Y waits for it")
    p.add_argument("--fixed-ratio", action="store_true",
                   help="with --method counter: the naive divider, K = floor(N/D) "
                        "fixed and each axis stopped after its D pulses, to show why "
                        "the ratio must vary")
    p.add_argument("--plot", metavar="FILE.svg", help="write an SVG picture")
    p.set_defaults(func=_run_dda)
