"""Seed 004: the split of long moves (its table, exactly) and the
pulse-multiplier interpolators simulated pulse by pulse."""
from __future__ import annotations

import math
import subprocess
import sys
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
    if method == "integrator":
        assert run.max_deviation < math.sqrt(2)   # each axis within one pulse


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


def test_master_command(capsys) -> None:
    assert main(["dda", "9813", "8765", "--method", "master", "--lag", "8"]) == 0
    out = capsys.readouterr().out
    assert "master interpolator, bits 14" in out and "+1.772 pulses" in out
