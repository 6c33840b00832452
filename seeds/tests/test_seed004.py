"""Seed 004: the split of long moves (its table, exactly) and the
pulse-multiplier interpolators simulated pulse by pulse."""
from __future__ import annotations

import math
import subprocess
import sys
from fractions import Fraction
from itertools import accumulate
from pathlib import Path

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from seeds import seed004 as s4
from seeds.__main__ import main

ROOT = Path(__file__).resolve().parents[2]


def test_document_table_reproduced_exactly() -> None:
    """004, "Линейные интерполяторы": 98132, 87647 pulses in 10 frames."""
    frames = s4.split_move(*s4.DOCUMENT_MOVE, s4.DOCUMENT_MAX)
    assert frames == list(s4.DOCUMENT_TABLE)
    assert len(frames) == 10
    # the document's own description: last digit dropped, remainders 2 and 7
    assert sum(1 for f in frames if f[0] == 9814) == 2
    assert sum(1 for f in frames if f[1] == 8765) == 7
    assert all(f[0] in (9813, 9814) and f[1] in (8764, 8765) for f in frames)


def test_document_table_from_the_command_line(capsys) -> None:
    assert main(["split", "--max", "9999", "98132", "87647"]) == 0
    out = capsys.readouterr().out
    assert out == "".join(f"{a} {b}\n" for a, b in s4.DOCUMENT_TABLE)


def test_division_points_of_the_document() -> None:
    """The table's division points are the nearest pulses to k/10 of the
    move; the only tie (43823.5 on Y after 5 frames) goes to the start."""
    xs = [sum(f[0] for f in s4.DOCUMENT_TABLE[:k]) for k in range(11)]
    ys = [sum(f[1] for f in s4.DOCUMENT_TABLE[:k]) for k in range(11)]
    for k in range(11):
        assert abs(xs[k] - k * 98132 / 10) <= 0.5
        assert abs(ys[k] - k * 87647 / 10) <= 0.5
    assert ys[5] == 43823


@st.composite
def st_move(draw: st.DrawFn) -> tuple[int, int, int]:
    """A limit N and a move of at most 60 frames of it."""
    n = draw(st.integers(1, 20000))
    reach = 60 * n
    return draw(st.integers(-reach, reach)), draw(st.integers(-reach, reach)), n


@given(move=st_move())
@example(move=(98132, 87647, 9999))
@example(move=(-98132, 87647, 9999))
@example(move=(1, 0, 1))
@example(move=(0, 0, 5))
def test_split_properties(move: tuple[int, int, int]) -> None:
    dx, dy, n = move
    frames = s4.split_move(dx, dy, n)
    if (dx, dy) == (0, 0):
        assert frames == []
        return
    assert len(frames) == max(math.ceil(abs(dx) / n), math.ceil(abs(dy) / n))
    assert all(abs(a) <= n and abs(b) <= n for a, b in frames)
    assert sum(a for a, _ in frames) == dx and sum(b for _, b in frames) == dy
    # frames differ by at most one pulse per axis ("as evenly as possible")
    assert max(a for a, _ in frames) - min(a for a, _ in frames) <= 1
    assert max(b for _, b in frames) - min(b for _, b in frames) <= 1
    x = y = 0
    for a, b in frames:
        x, y = x + a, y + b
        assert abs(s4.line_distance(x, y, dx, dy)) < 1.0      # within one pulse
        assert abs(s4.line_distance(x, y, dx, dy)) <= math.sqrt(0.5) + 1e-9


def test_split_is_symmetric_in_sign() -> None:
    base = s4.split_move(98132, 87647)
    assert s4.split_move(-98132, -87647) == [(-a, -b) for a, b in base]
    assert s4.split_move(87647, 98132) == [(b, a) for a, b in base]


def test_binary_multiplier_gives_the_register_number() -> None:
    """"Dx = a1*2^0 + ... + an*2^(n-1)": the pulses of a cycle are the
    register's number, bit k giving 2^k pulses."""
    for bits in (1, 3, 8):
        for value in range(1 << bits):
            assert sum(s4.binary_pulses(value, bits)) == value
    # the most significant bit fires on every other input pulse
    assert s4.binary_pulses(0b100, 3) == [1, 0, 1, 0, 1, 0, 1, 0]
    assert s4.binary_pulses(0b001, 3) == [0, 0, 0, 1, 0, 0, 0, 0]
    with pytest.raises(ValueError):
        s4.binary_pulses(8, 3)                                 # DXmax = N - 1


def test_decimal_multiplier_and_the_5121_code() -> None:
    """A BCD decade yields trains of 5, 2, 1, 1 pulses: digits written in
    seed 002's 5121 code give exactly their value."""
    for value in (0, 1, 7, 9, 10, 99, 1234, 9999, 9813, 8765):
        decades = 4
        assert sum(s4.decimal_pulses(value, decades)) == value
    assert [w for w, _ in s4.DECADE_TRAINS] == [5, 2, 1, 1]
    assert sum(len(states) for _, states in s4.DECADE_TRAINS) == 9


@given(dx=st.integers(-3000, 3000), dy=st.integers(-3000, 3000),
       method=st.sampled_from(s4.METHODS))
@example(dx=4095, dy=4095, method="binary")
@example(dx=4095, dy=2730, method="binary")
def test_interpolators_end_on_the_point_within_their_bound(dx: int, dy: int, method: str) -> None:
    if (dx, dy) == (0, 0):
        return
    run = s4.interpolate(dx, dy, method)
    assert (run.xs[-1], run.ys[-1]) == (dx, dy)
    steps = list(zip(run.xs, run.ys))
    assert all(abs(x1 - x0) <= 1 and abs(y1 - y0) <= 1
               for (x0, y0), (x1, y1) in zip(steps, steps[1:]))
    assert len(run.xs) == run.volume + 1
    if method == "binary":
        assert run.max_deviation <= s4.binary_bound(dx, dy) + 1e-9
    if method in ("integrator", "counter"):
        # each axis 0 to 1 pulse behind its share, both the same way:
        # |dx*ey - dy*ex| / L < max(|dx|, |dy|) / L <= 1
        assert run.max_deviation <= max(abs(dx), abs(dy)) / math.hypot(dx, dy) < 1


def test_binary_deviation_grows_with_the_counter() -> None:
    """The document: the largest deviation grows like the logarithm of the
    longest move (the number of counter bits n) for a fixed pulse.  The
    registers 1010...10 and 0101...01 err in opposite senses on every bit:
    their deviation is n / sqrt(20) pulses, linear in n."""
    for n in (4, 8, 12, 16):
        dx, dy = int("10" * (n // 2), 2), int("01" * (n // 2), 2)
        run = s4.interpolate(dx, dy, "binary", n)
        assert run.max_deviation == pytest.approx(n / math.sqrt(20))
        assert run.max_deviation <= s4.binary_bound(dx, dy)


def test_splitting_keeps_the_deviation_small() -> None:
    """The document's advice: split the long move into 10 frames of the
    4-decade multiplier (volume 10000) instead of a 17-bit one."""
    whole = s4.interpolate(*s4.DOCUMENT_MOVE, "binary")
    split = s4.interpolate(*s4.DOCUMENT_MOVE, "decimal", max_pulses=9999)
    assert split.volume == 10000 and len(split.frames) == 10
    assert (split.xs[-1], split.ys[-1]) == s4.DOCUMENT_MOVE
    assert whole.max_deviation > 1.0
    assert split.max_deviation < whole.max_deviation + 1


def test_dda_command_and_plot(tmp_path: Path) -> None:
    svg = tmp_path / "dda.svg"
    proc = subprocess.run([sys.executable, "-m", "seeds", "dda", "9813", "8765",
                           "--plot", str(svg)], cwd=ROOT, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert "largest deviation from the line" in proc.stdout
    text = svg.read_text()
    assert text.startswith("<svg") and "<polyline" in text and text.rstrip().endswith("</svg>")
    run = s4.interpolate(9813, 8765)
    assert s4.svg_plot(run) == text                               # deterministic
    assert main(["dda", "0", "0"]) == 2
    assert main(["dda", "99999", "1", "--method", "decimal", "--size", "4"]) == 2


# ---------------------------------------------------------------------------
# Equal frames by continued fractions.
# ---------------------------------------------------------------------------
def test_equal_split_of_the_documents_move() -> None:
    """98132, 87647 at most 9999: 7841/8779 is a convergent of 87647/98132;
    11 such frames and the last (1563, 1396), the division points within
    0.0001 pulse of the line (the unequal table's are within 0.373)."""
    run = s4.split_equal(98132, 87647, 9999)
    assert run.frames == [(8779, 7841)] * 11 + [(1563, 1396)]
    assert (8779, 7841) in [(q, p) for p, q in s4.semiconvergents(87647, 98132)]
    assert run.deviation == pytest.approx(8.3603e-5, abs=1e-9)
    assert s4.split_deviation(98132, 87647, run.frames) == pytest.approx(run.deviation)
    assert s4.split_deviation(98132, 87647, s4.DOCUMENT_TABLE) == pytest.approx(0.37291, abs=1e-5)


def test_semiconvergents_of_a_known_fraction() -> None:
    """7/16 = [0; 2, 3, 2]: convergents 0/1, 1/2, 3/7, 7/16 and the
    semiconvergents between them."""
    got = list(s4.semiconvergents(7, 16))
    assert got == [(0, 1), (1, 1), (1, 2), (1, 3), (2, 5), (3, 7), (4, 9), (7, 16)]


@given(st.integers(-10**6, 10**6), st.integers(-10**6, 10**6), st.integers(1, 3000))
@example(98132, 87647, 9999)
@example(1, 98132, 9999)
def test_equal_split_properties(dx: int, dy: int, nmax: int) -> None:
    try:
        run = s4.split_equal(dx, dy, nmax)
    except ValueError:
        # the last frame cannot take up the error of the equal ones: only
        # for moves longer than the limit squared
        assert max(abs(dx), abs(dy)) > nmax * nmax
        return
    frames = run.frames
    assert sum(f[0] for f in frames) == dx and sum(f[1] for f in frames) == dy
    assert all(abs(a) <= nmax and abs(b) <= nmax for a, b in frames)
    assert all(f == frames[0] for f in frames[:run.count])
    assert all(a * dx >= 0 and b * dy >= 0 for a, b in frames)          # never backwards
    assert s4.split_deviation(dx, dy, frames) == pytest.approx(run.deviation, abs=1e-9)


def test_equal_split_command(capsys) -> None:
    assert main(["split", "--equal", "--max", "2", "7", "3"]) == 0
    assert capsys.readouterr().out == (
        "2 1\n2 1\n2 1\n1 0\n# 4 frames: 3 of 2 1, the last 1 0; largest distance of a "
        "division point from the line 0.393919 pulses\n")


def test_split_exit_status_tells_a_usage_error_from_a_refused_move(capsys) -> None:
    """--max below 1 is a usage error (2); a move the limit cannot split is
    refused (1: no equal frames fit, as docs/SEED004-TAPE-CODES.md says, or
    more than a million frames)."""
    for args in (["--max", "0", "5", "3"], ["--equal", "--max", "-1", "5", "3"]):
        assert main(["split", *args]) == 2
        assert capsys.readouterr().err.startswith(f"split: --max {args[-3]}: a frame's limit")
    assert main(["split", "--equal", "--max", "2", "9", "3"]) == 1
    assert capsys.readouterr().err == ("split: no equal frames of at most 2 pulses fit the "
                                       "move (9, 3)\n")
    assert main(["split", "--max", "1", "2000000", "0"]) == 1
    assert "needs 2000000 frames of at most 1 pulses, more than 1000000" in \
        capsys.readouterr().err


def test_equal_split_exists_exactly_when_some_split_does() -> None:
    """Every move of up to 40 pulses with limits 1-5: the convergents find
    equal frames whenever a search of all (k, a, b) does."""
    def exists(u: int, v: int, n: int) -> bool:
        return any(0 <= u - k * a <= n and 0 <= v - k * b <= n
                   for k in range(1, u + 2) for a in range(n + 1) for b in range(n + 1))
    for n in range(1, 6):
        for u in range(1, 41):
            for v in range(u + 1):
                try:
                    s4.split_equal(u, v, n)
                    found = True
                except ValueError:
                    found = False
                assert found == exists(u, v, n), (u, v, n)


# ---------------------------------------------------------------------------
# The interpolator with a master coordinate.
# ---------------------------------------------------------------------------
def test_master_interpolator_on_the_documents_frame() -> None:
    """The document's first frame, 9813, 8765 pulses, 14 bits.  Without lag
    the master interpolator is the binary multiplier pulse for pulse; with an
    X drive L generator periods late, independent axes fall behind (4.437
    pulses off the line at L = 8, 13.951 at L = 32) while the master's Y
    waits for X and stays within 1.772 pulses whatever L."""
    plain = s4.interpolate(9813, 8765, "binary")
    assert s4.interpolate(9813, 8765, "master").xs == plain.xs
    assert s4.interpolate(9813, 8765, "master").ys == plain.ys
    for lag, independent in ((8, 4.437), (32, 13.951)):
        assert s4.interpolate(9813, 8765, "binary", lag=lag).max_deviation == \
            pytest.approx(independent, abs=1e-3)
        run = s4.interpolate(9813, 8765, "master", lag=lag)
        assert run.max_deviation == pytest.approx(1.772, abs=1e-3)
        assert (run.xs[-1], run.ys[-1]) == (9813, 8765)
        # one axis at a time, one pulse at a time: Y never moves with X
        steps = {(b - a, d - c) for a, b, c, d in zip(run.xs, run.xs[1:], run.ys, run.ys[1:])}
        assert steps <= {(0, 0), (1, 0), (0, 1)}


def test_master_interpolators_lag_costs_one_x_pulse_as_the_page_says() -> None:
    """SEED004-TAPE-CODES.md said "one pulse more than without lag" for
    1.772 against 1.106: the worst point is one X pulse behind a point of
    the unlagged path, and one X pulse is dy/|(dx, dy)| across the line."""
    plain = s4.interpolate(9813, 8765, "binary")
    run = s4.interpolate(9813, 8765, "master", lag=8)
    k = run.worst
    ahead = next(i for i, (x, y) in enumerate(zip(plain.xs, plain.ys))
                 if (x, y) == (run.xs[k] + 1, run.ys[k]))
    one_x = 8765 / math.hypot(9813, 8765)
    assert run.deviation[k] == pytest.approx(plain.deviation[ahead] + one_x)
    assert plain.deviation[ahead] == pytest.approx(plain.max_deviation)
    page = " ".join((ROOT / "docs" / "SEED004-TAPE-CODES.md").read_text().split())
    assert (f"That is {run.max_deviation - plain.max_deviation:.3f} pulses more than without "
            f"lag") in page
    assert f"8765/√(9813² + 8765²) = {one_x:.3f} pulses across the line" in page
    assert "one pulse more than without lag" not in page


def test_master_command(capsys) -> None:
    assert main(["dda", "9813", "8765", "--method", "master", "--lag", "8"]) == 0
    out = capsys.readouterr().out
    assert "master interpolator, bits 14" in out and "+1.772 pulses" in out


# ---------------------------------------------------------------------------
# The interpolator on counters with a variable division ratio (named by the
# document, not described: our reconstruction, a divider per axis).
# ---------------------------------------------------------------------------
def reference_times(d: int, n: int) -> list[int]:
    """The rule, written apart from the simulated circuit: output pulse i
    (1..d) on generator pulse ceil(i*n/d) (1-based)."""
    return [math.ceil(Fraction(i * n, d)) for i in range(1, d + 1)]


def times(pulses: list[int]) -> list[int]:
    """1-based generator pulses that carry an output pulse."""
    return [m + 1 for m, p in enumerate(pulses) if p]


@st.composite
def st_ratio(draw: st.DrawFn) -> tuple[int, int]:
    """A counter volume N and a number of pulses 0 <= D < N."""
    n = draw(st.integers(1, 1 << 14))
    return draw(st.integers(0, n - 1)), n


@given(st_ratio())
@example((9813, 10000))
@example((8765, 10000))
@example((9813, 16384))
@example((8764, 16384))
@example((1, 2))
@example((0, 1))
@example((4999, 10000))
def test_counter_pulses_follow_the_ceiling_rule(dn: tuple[int, int]) -> None:
    """Pulse i on generator pulse ceil(i N / D): exactly D pulses a cycle,
    the last on the N-th, each period K = floor(N/D) or K + 1 with exactly
    r = N mod D long ones, the first long whenever r > 0."""
    d, n = dn
    got = times(s4.counter_pulses(d, n))
    assert got == reference_times(d, n)
    assert len(got) == d
    if d == 0:
        return
    assert got[-1] == n
    k, r = divmod(n, d)
    periods = [b - a for a, b in zip([0] + got, got)]
    assert set(periods) <= {k, k + 1}
    assert periods.count(k + 1) == r
    assert periods[0] == (k + 1 if r else k)


def test_counter_is_the_integrator_for_every_small_volume() -> None:
    """Two circuits, one pulse train: every N up to 64, every D < N."""
    for n in range(1, 65):
        for d in range(n):
            assert s4.counter_pulses(d, n) == s4.integrator_pulses(d, n), (d, n)


@given(st_ratio())
@example((9813, 10000))
@example((8765, 10000))
@example((9814, 16384))
@example((8764, 16384))
def test_counter_is_the_integrator_pulse_for_pulse(dn: tuple[int, int]) -> None:
    """After m generator pulses both have given floor(m D / N) pulses: the
    divider stores a period, the integrator an accumulated phase."""
    d, n = dn
    counter = s4.counter_pulses(d, n)
    assert counter == s4.integrator_pulses(d, n)
    assert list(accumulate(counter)) == [m * d // n for m in range(1, n + 1)]


@pytest.mark.parametrize("size,frames", [(None, False), (10000, False),
                                         (None, True), (10000, True)])
def test_counter_moves_as_the_integrator_on_the_documents_frames(size: int | None,
                                                                  frames: bool) -> None:
    """The first frame 9813, 8765 and the split move 98132, 87647 at most
    9999 a frame, in the smallest volume (16384) and in the document's
    10 000: the same path, position for position."""
    if frames:
        kw = {"max_pulses": 9999}
        dx, dy = s4.DOCUMENT_MOVE
    else:
        kw = {}
        dx, dy = s4.DOCUMENT_TABLE[0]
    counter = s4.interpolate(dx, dy, "counter", size, **kw)
    integrator = s4.interpolate(dx, dy, "integrator", size, **kw)
    assert counter.volume == integrator.volume == (size or 16384)
    assert (counter.xs, counter.ys) == (integrator.xs, integrator.ys)
    if frames:
        assert counter.frames == s4.DOCUMENT_TABLE


def compare(a: list[int], b: list[int]) -> tuple[int, int, int]:
    """Two trains of one cycle: pulses on the same generator pulse, the
    largest difference of their counts so far, the largest difference of
    the times of their i-th pulses."""
    same = sum(1 for p, q in zip(a, b) if p and q)
    count = max(abs(p - q) for p, q in zip(accumulate(a), accumulate(b)))
    when = max(abs(p - q) for p, q in zip(times(a), times(b)))
    return same, count, when


@pytest.mark.parametrize("d,binary,decimal", [
    (9813, (5877, 3, 5), (9629, 3, 3)),
    (9814, (5878, 3, 5), (9630, 2, 2)),
    (8765, (4689, 3, 4), (7675, 2, 3)),
    (8764, (4684, 2, 4), (7680, 3, 3))])
def test_counter_against_the_multipliers(d: int, binary: tuple[int, int, int],
                                         decimal: tuple[int, int, int]) -> None:
    """Every axis value of the document's frames: the counter interpolator
    and the binary multiplier in 16384 (14 bits), and the decimal one in
    10 000 (4 decades), do not give the same train: only part of the pulses
    fall on the same generator pulse, the counts drift up to 3 pulses apart
    and the i-th pulses up to 5 generator pulses.  The multiplier adds one
    evenly spaced train per register digit; the sum is not evenly spaced."""
    assert {f[0] for f in s4.DOCUMENT_TABLE} | {f[1] for f in s4.DOCUMENT_TABLE} == \
        {9813, 9814, 8765, 8764}
    assert compare(s4.binary_pulses(d, 14), s4.counter_pulses(d, 16384)) == binary
    assert compare(s4.decimal_pulses(d, 4), s4.counter_pulses(d, 10000)) == decimal
    assert compare(s4.integrator_pulses(d, 10000), s4.counter_pulses(d, 10000)) == (d, 0, 0)


@pytest.mark.parametrize("method,size,first,split", [
    ("binary", None, 1.1058, 1.7004),
    ("decimal", None, 1.7981, 1.9325),
    ("integrator", None, 0.7379, 1.0901),
    ("integrator", 10000, 0.7274, 1.0581),
    ("counter", None, 0.7379, 1.0901),
    ("counter", 10000, 0.7274, 1.0581)])
def test_deviations_on_the_documents_frames(method: str, size: int | None,
                                            first: float, split: float) -> None:
    """The table of the page: the largest distance from the line on the
    first frame 9813, 8765 and on the whole move split at 9999."""
    run = s4.interpolate(*s4.DOCUMENT_TABLE[0], method, size)
    assert run.max_deviation == pytest.approx(first, abs=1e-4)
    run = s4.interpolate(*s4.DOCUMENT_MOVE, method, size, max_pulses=9999)
    assert run.max_deviation == pytest.approx(split, abs=1e-4)


def test_fixed_ratio_on_the_documents_frame() -> None:
    """Without the remainder register, 9813 and 8765 pulses in 10 000 both
    divide by K = 1: free-running, each axis would give 10 000 pulses (187
    and 1235 too many); stopped after their own, they run together to
    (8765, 8765), 698.135 pulses off the line, and X goes on alone."""
    run = s4.interpolate(9813, 8765, "counter", 10000, fixed_ratio=True)
    assert run.fixed_ratio and (run.xs[-1], run.ys[-1]) == (9813, 8765)
    assert run.worst == 8765 and (run.xs[8765], run.ys[8765]) == (8765, 8765)
    assert run.max_deviation == pytest.approx(8765 * 1048 / math.hypot(9813, 8765))
    assert run.max_deviation == pytest.approx(698.135, abs=1e-3)
    assert s4.fixed_ratio_count(9813, 10000) == s4.fixed_ratio_count(8765, 10000) == 10000
    assert "X 187 and Y 1235 pulses too many" in s4.summary(run)
    # the line was cut short: "...; each axis was stopped after its own"
    assert s4.summary(run).endswith("X 187 and Y 1235 pulses too many; each axis was stopped "
                                    "after its own pulses (X 9813, Y 8765)\n")
    split = s4.summary(s4.interpolate(-98132, 87647, "counter", 10000, max_pulses=9999,
                                      fixed_ratio=True))
    assert split.endswith("each axis was stopped after its own pulses (X 98132, Y 87647)\n")


@given(st_ratio())
@example((5, 16))
@example((5, 15))
@example((9813, 10000))
def test_fixed_ratio_counts(dn: tuple[int, int]) -> None:
    """K = floor(N/D) fixed: a free-running divider gives N // K >= D
    pulses a cycle, exactly D only when K (D + 1) > N (D dividing N, or
    e.g. 5 in 16); stopped after D, pulse i is on i K; with D dividing N
    it is the variable divider's train."""
    d, n = dn
    free = sum(1 for m in range(1, n + 1) if d and m % (n // d) == 0)
    assert s4.fixed_ratio_count(d, n) == free >= d
    assert (free == d) == (d == 0 or (n // d) * (d + 1) > n)
    got = times(s4.counter_pulses(d, n, fixed_ratio=True))
    assert got == [i * (n // d) for i in range(1, d + 1)]
    if d and n % d == 0:
        assert s4.counter_pulses(d, n, fixed_ratio=True) == s4.counter_pulses(d, n)


def test_counter_command(tmp_path: Path, capsys) -> None:
    assert main(["dda", "9813", "8765", "--method", "counter", "--size", "10000"]) == 0
    out = capsys.readouterr().out
    assert out == ("move DX 9813 DY 8765 pulses, counter interpolator, volume 10000, "
                   "10000 input pulses per frame, 1 frame\n"
                   "largest deviation from the line: -0.727 pulses at input pulse 5401 "
                   "(x 5300, y 4733)\n"
                   "(our reconstruction of the document's named-only interpolator on "
                   "counters with a variable division ratio)\n"
                   "division coefficients: X K 1 r 187, Y K 1 r 1235\n")
    svg = tmp_path / "counter.svg"
    assert main(["dda", "98132", "87647", "--method", "counter", "--max", "9999",
                 "--plot", str(svg)]) == 0
    assert "counter interpolator, volume 16384" in capsys.readouterr().out
    run = s4.interpolate(98132, 87647, "counter", max_pulses=9999)
    assert svg.read_text() == s4.svg_plot(run)
    assert main(["dda", "--help"]) == 0
    assert "OUR reconstruction" in " ".join(capsys.readouterr().out.split())


@pytest.mark.parametrize("args,words", [
    ("0 0", "a move of (0, 0) has nothing to interpolate"),
    ("5 3 --size 5", "5 pulses do not fit a counter interpolator of volume 5"),
    ("5 3 --size 0", "5 pulses do not fit a counter interpolator of volume 0"),
    ("-5 -3 --size -8", "5 pulses do not fit a counter interpolator of volume -8"),
    ("5 3 --size 99999999999999999999", "more than 2097152"),
    ("99999999 1", "more than 2097152"),
    ("98132 87647 --max 9999 --size 300000", "would take 3000000 input pulses"),
    ("5 3 --lag -1", "the lag is a number of generator periods"),
])
def test_counter_refuses_bad_input(capsys, args: str, words: str) -> None:
    assert main(["dda", *args.split(), "--method", "counter"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("dda: ") and words in err and err.count("\n") == 1, err


def test_fixed_ratio_is_the_counters_only(capsys) -> None:
    for method in ("binary", "decimal", "integrator", "master"):
        assert main(["dda", "5", "3", "--method", method, "--fixed-ratio"]) == 2
        assert capsys.readouterr().err == (f"dda: a fixed ratio is the counter "
                                           f"interpolator's, not the {method}'s\n")
