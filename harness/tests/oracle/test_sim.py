"""Unit tests of the coordinatograph simulator (harness/sim.py) on hand-made
frames: the report's Examples 1-5, cycles, dots, tool state, bbox, times."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from harness.sim import MAX_EXECUTED, Arc, Dot, Line, arc_sweep, simulate, unroll
from harness.tape import Frame


def test_example1_circle_minus_direction() -> None:
    """X-300 K11: R 3 mm, tool left of the centre, counter-clockwise."""
    run = simulate([Frame(x=-300, k=11)])
    (arc,) = run.strokes
    assert isinstance(arc, Arc)
    assert (arc.cx, arc.cy) == (300, 0)
    assert arc.r == 300
    assert arc.sweep == pytest.approx(2 * math.pi)     # full turn, counter-clockwise
    assert arc.a0 == pytest.approx(math.pi)            # the tool is left of the centre
    assert run.end == (0, 0)
    assert run.tool_down_at_end
    assert run.drawn_mm == pytest.approx(2 * math.pi * 3)
    assert run.bbox == pytest.approx((0.0, 6.0, -3.0, 3.0))


def test_example2_circle_plus_direction() -> None:
    """Y10000 K13: R 100 mm, tool above the centre, clockwise."""
    run = simulate([Frame(y=10000, k=13), Frame(k=20)])
    arc = run.strokes[0]
    assert isinstance(arc, Arc)
    assert (arc.cx, arc.cy, arc.r) == (0, -10000, 10000)
    assert arc.sweep == pytest.approx(-2 * math.pi)
    assert run.end == (0, 0) and not run.tool_down_at_end
    assert run.bbox == pytest.approx((-100.0, 100.0, -200.0, 0.0))
    assert run.travel == []


def test_example3_quarter_arc_clockwise() -> None:
    """X2000 DX-2000 DY-2000 K13: from (0,0) about (-20,0) to (-20,-20) mm."""
    run = simulate([Frame(x=2000, dx=-2000, dy=-2000, k=13)])
    (arc,) = run.strokes
    assert isinstance(arc, Arc)
    assert (arc.cx, arc.cy) == (-2000, 0)
    assert arc.r == 2000
    assert arc.a0 == pytest.approx(0.0)
    assert arc.sweep == pytest.approx(-math.pi / 2)    # clockwise quarter
    assert (arc.x1, arc.y1) == run.end == (-2000, -2000)
    assert run.drawn_mm == pytest.approx(10 * math.pi)
    assert run.bbox == pytest.approx((-20.0, 0.0, -20.0, 0.0))
    assert run.minutes == pytest.approx(10 * math.pi / 1500)


def test_example3_counter_clockwise_is_the_long_way() -> None:
    run = simulate([Frame(x=2000, dx=-2000, dy=-2000, k=11)])
    arc = run.strokes[0]
    assert arc.sweep == pytest.approx(1.5 * math.pi)
    assert run.drawn_mm == pytest.approx(30 * math.pi)
    assert run.bbox == pytest.approx((-40.0, 0.0, -20.0, 20.0))


def test_example4_line() -> None:
    """DX-500 DY-500 K10 from B(15,30) to A(10,25) mm (tape coordinates)."""
    run = simulate([Frame(dx=-500, dy=-500, k=10)])
    assert run.strokes == [Line(0, 0, -500, -500)]
    assert run.drawn_mm == pytest.approx(5 * math.sqrt(2))
    assert run.end == (-500, -500) and run.tool_down_at_end


def test_example5_saw() -> None:
    """DX300 DY400 CYC8 K10, DX100 DY-400 K10: 8 teeth."""
    run = simulate([Frame(dx=300, dy=400, cyc=8, k=10), Frame(dx=100, dy=-400, k=10)])
    assert run.executed == 16
    assert len(run.strokes) == 16
    assert run.end == (3200, 0)
    assert run.drawn_mm == pytest.approx(8 * (5 + math.sqrt(17)))
    assert run.strokes[2] == Line(400, 0, 700, 400)
    assert run.bbox == pytest.approx((0.0, 32.0, 0.0, 4.0))


def test_cycle_then_continues_after_the_pair() -> None:
    frames = [Frame(dx=100, k=20), Frame(dx=10, cyc=3, k=10), Frame(dy=10, k=20),
              Frame(dx=-5, k=10)]
    order = [f for f in unroll(frames)]
    assert order == [frames[0]] + [frames[1], frames[2]] * 3 + [frames[3]]
    run = simulate(frames)
    assert run.end == (100 + 30 - 5, 30)
    assert len(run.travel) == 4 and len(run.strokes) == 4


@pytest.mark.parametrize("frames", [
    [Frame(dx=1, cyc=2, k=10)],                                   # no partner
    [Frame(dx=1, cyc=2, k=10), Frame(dx=1, cyc=2, k=10)],         # partner with CYC
    [Frame(dx=1, cyc=1, k=10), Frame(dx=1, k=10)],                # CYC 1
    [Frame(dx=1, cyc=600_000, k=10), Frame(dx=1, k=10)],          # absurd count
    [Frame(dx=1, k=12)],                                          # not a command
    [Frame(x=100, dx=1, k=10)],                                   # X on a line
    [Frame(k=11)],                                                # circle without radius
])
def test_invalid_frames_raise(frames: list[Frame]) -> None:
    with pytest.raises(ValueError):
        simulate(frames)


def test_the_executed_frame_limit_is_inclusive() -> None:
    """At most MAX_EXECUTED frames run: a pair cycled to exactly that many
    is taken, one frame more is refused before anything runs."""
    assert MAX_EXECUTED == 10**6
    pair = [Frame(dx=1, cyc=500_000, k=10), Frame(dx=-1, k=10)]
    assert next(unroll(pair)) == pair[0]
    over = pair + [Frame(k=20)]                     # one frame more
    with pytest.raises(ValueError, match=r"^more than 1000000 executed frames$"):
        next(unroll(over))


def test_an_arc_ending_on_its_start_ray_is_a_full_turn() -> None:
    """X5 DX1: the end (6, 0) from the centre lies in the start direction,
    1 unit out (within the arc tolerance): the arc goes all the way round,
    in its own direction, not nowhere."""
    assert arc_sweep(5, 0, 6, 0, clockwise=False) == 2 * math.pi
    assert arc_sweep(5, 0, 6, 0, clockwise=True) == -2 * math.pi
    for k, sweep in ((11, 2 * math.pi), (13, -2 * math.pi)):
        run = simulate([Frame(x=5, dx=1, k=k)])
        (arc,) = run.strokes
        assert isinstance(arc, Arc)
        assert (arc.cx, arc.cy, arc.r, arc.sweep) == (-5, 0, 5, sweep)
        assert (arc.x1, arc.y1) == run.end == (1, 0)
        assert run.drawn_mm == pytest.approx(2 * math.pi * 5 / 100)


def test_dot_lowers_the_tool_where_it_stands() -> None:
    run = simulate([Frame(dx=250, dy=-100, k=20), Frame(k=10), Frame(dx=-250, dy=100, k=20)])
    assert run.strokes == [Dot(250, -100)]
    assert run.drawn_mm == 0
    assert [t.length for t in run.travel] == pytest.approx([math.hypot(250, 100)] * 2)
    assert run.travel_mm == pytest.approx(2 * math.hypot(2.5, 1.0))
    assert run.end == (0, 0) and not run.tool_down_at_end


def test_tool_state() -> None:
    assert not simulate([]).tool_down_at_end
    assert simulate([Frame(k=10)]).tool_down_at_end
    assert not simulate([Frame(k=10), Frame(k=20)]).tool_down_at_end
    assert simulate([Frame(k=20), Frame(y=5, k=13)]).tool_down_at_end
    run = simulate([Frame(k=20)])                   # a raise without a move
    assert run.travel == [] and run.strokes == []


def test_bbox_includes_arc_extremes_and_travel() -> None:
    # half circle clockwise from the right of the centre, through the bottom
    run = simulate([Frame(x=1000, dx=-2000, k=13)])
    assert run.bbox == pytest.approx((-20.0, 0.0, -10.0, 0.0))
    run = simulate([Frame(x=1000, dx=-2000, k=11)])  # ... or through the top
    assert run.bbox == pytest.approx((-20.0, 0.0, 0.0, 10.0))
    run = simulate([Frame(dx=-700, dy=900, k=20)])
    assert run.bbox == pytest.approx((-7.0, 0.0, 0.0, 9.0))


def test_times() -> None:
    line = simulate([Frame(dx=550000, k=10)])            # 5.5 m at 5.5 m/min
    assert line.minutes == pytest.approx(1.0)
    travel = simulate([Frame(dy=-550000, k=20)])
    assert travel.minutes == pytest.approx(1.0) and travel.travel_mm == pytest.approx(5500)
    circle = simulate([Frame(x=15000, k=13)])              # 2*pi*150 mm at 1.5 m/min
    assert circle.minutes == pytest.approx(2 * math.pi * 150 / 1500)
    both = simulate([Frame(dx=550000, k=10), Frame(x=15000, k=13), Frame(dy=-550000, k=20)])
    assert both.minutes == pytest.approx(2 + 2 * math.pi * 150 / 1500)
    assert both.drawn_mm == pytest.approx(5500 + 2 * math.pi * 150)


_step = st.integers(-5000, 5000)


@given(st.lists(st.tuples(_step, _step, st.sampled_from([10, 20]),
                          st.sampled_from([0, 0, 0, 2, 3, 7])), max_size=12))
def test_end_is_the_sum_of_the_increments(moves: list[tuple[int, int, int, int]]) -> None:
    frames = [Frame(dx=dx, dy=dy, k=k, cyc=cyc) for dx, dy, k, cyc in moves]
    # repair: a CYC frame needs a partner without CYC
    fixed: list[Frame] = []
    i = 0
    while i < len(frames):
        f = frames[i]
        if f.cyc:
            partner = frames[i + 1] if i + 1 < len(frames) else Frame(k=20)
            fixed += [f, Frame(dx=partner.dx, dy=partner.dy, k=partner.k)]
            i += 2
        else:
            fixed.append(f)
            i += 1
    run = simulate(fixed)
    ex = ey = 0
    i = 0
    while i < len(fixed):
        n = fixed[i].cyc or 1
        span = fixed[i:i + 2] if fixed[i].cyc else fixed[i:i + 1]
        ex += n * sum(f.dx for f in span)
        ey += n * sum(f.dy for f in span)
        i += len(span)
    assert run.end == (ex, ey)
    assert run.tool_down_at_end == (bool(fixed) and fixed[-1].k == 10)
    total = sum(s.length for s in run.strokes if isinstance(s, Line))
    assert run.drawn_mm == pytest.approx(total / 100)
