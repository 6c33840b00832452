"""Unit tests of the coverage comparison (harness/raster.py) on synthetic
runs against hand-made ideal layers."""

from __future__ import annotations

import math

import numpy as np
import pytest

from harness.deck import ArcBand, Disc, Layer, RoundRect, Stroke
from harness.raster import Grid, compare, make_grid, render_layer, render_run
from harness.sim import simulate
from harness.tape import Frame

TOOL = 50                                   # 0.50 mm
#: A 4 x 2 mm rectangular pad centred at (10, 10) mm, tool 0.50 mm.
RECT = Layer(TOOL, [RoundRect(1000, 1000, 400, 200, TOOL / 2)])


def rect_frames(skip_pass: bool = False, extra: bool = False) -> list[Frame]:
    """Outline inset by the tool radius, then two inner passes; back home."""
    f = [Frame(dx=825, dy=925, k=20),
         Frame(dx=350, k=10), Frame(dy=150, k=10), Frame(dx=-350, k=10), Frame(dy=-150, k=10)]
    if skip_pass:
        f += [Frame(dy=100, k=20), Frame(dx=350, k=10)]           # y = 9.75 mm pass missing
    else:
        f += [Frame(dy=50, k=10), Frame(dx=350, k=10), Frame(dy=50, k=10),
              Frame(dx=-350, k=10)]
    if extra:
        f += [Frame(dx=-300, k=10)]                               # runs off the pad
    return f + [Frame(dx=-(825 + (350 if skip_pass else 0) - (300 if extra else 0)),
                      dy=-1025, k=20)]


def ring_frames(radii: list[int], cx: int = 2000, cy: int = -1000) -> list[Frame]:
    """Concentric circles about (cx, cy), outermost first, joined by radial
    moves with the tool down; a radius 0 is a dot at the centre."""
    f = [Frame(dx=cx - radii[0], dy=cy, k=20)]
    at = radii[0]
    for r in radii:
        if r != at:
            f.append(Frame(dx=at - r, k=10))
            at = r
        f.append(Frame(x=-r, k=11) if r else Frame(k=10))
    return f + [Frame(dx=-(cx - at), dy=-cy, k=20)]


def test_exact_rectangle_fill_passes() -> None:
    run = simulate(rect_frames())
    assert run.end == (0, 0) and not run.tool_down_at_end
    report = compare(run, TOOL, RECT)
    assert report.ok, report.summary()
    assert report.drawn > 0 and report.pitch_mm == 0.02


def test_missing_pass_is_a_hole_at_the_right_place() -> None:
    run = simulate(rect_frames(skip_pass=True))
    assert run.end == (0, 0)
    report = compare(run, TOOL, RECT)
    assert report.holes > 0 and report.excess == 0, report.summary()
    # uncovered strip: 9.50 < y < 10.00 mm, well inside 8 < x < 12 mm
    for x, y, depth, gap in report.worst_holes:
        assert 8.0 < x < 12.0 and 9.5 < y < 10.0, report.summary()
        assert depth >= 0.05 and 0 < gap <= 0.25
    assert max(h[2] for h in report.worst_holes) > 0.4     # deep inside the pad
    # the strip is about 3 mm x 0.4 mm (ideal shrunk by 0.05 mm)
    area = report.holes * report.pitch_mm ** 2
    assert 0.5 < area < 2.0, report.summary()
    assert "FAILED" in report.summary()


def test_extra_stroke_is_excess_at_the_right_place() -> None:
    run = simulate(rect_frames(extra=True))
    assert run.end == (0, 0)
    report = compare(run, TOOL, RECT)
    assert report.excess > 0 and report.holes == 0, report.summary()
    x, y, dist = report.worst_excess[0]
    assert 4.99 < x < 5.5 and 10.0 <= y <= 10.5, report.summary()   # the stroke: y 10..10.5
    assert dist == pytest.approx(8.0 - x, abs=0.01)
    for x, y, dist in report.worst_excess:
        assert x < 7.95 and dist > 0.05


def test_round_pad_rings_pass_and_a_missing_ring_is_found() -> None:
    pad = Layer(TOOL, [Disc(2000, -1000, 100)])          # 2 mm pad
    good = simulate(ring_frames([75, 40, 0]))
    assert compare(good, TOOL, pad).ok
    bad = simulate(ring_frames([75, 0]))                  # 0.25..0.5 mm band not drawn
    report = compare(bad, TOOL, pad)
    assert report.holes > 0 and report.excess == 0
    for x, y, _, _ in report.worst_holes:
        r = math.hypot(x - 20, y + 10)
        assert 0.25 < r < 0.5, report.summary()


def test_dot_equals_a_pad_of_the_tool() -> None:
    run = simulate([Frame(dx=300, dy=300, k=20), Frame(k=10), Frame(dx=-300, dy=-300, k=20)])
    assert compare(run, TOOL, [Disc(300, 300, TOOL / 2)]).ok
    assert not compare(run, TOOL, [Disc(320, 300, TOOL / 2)]).ok


def test_arc_direction_matters() -> None:
    # quarter arc r 20 mm clockwise from (0,0) about (-20,0): Example 3
    ideal = [ArcBand(-2000, 0, 2000, 0.0, -math.pi / 2, TOOL / 2)]
    cw = simulate([Frame(x=2000, dx=-2000, dy=-2000, k=13)])
    ccw = simulate([Frame(x=2000, dx=-2000, dy=-2000, k=11)])
    assert compare(cw, TOOL, ideal).ok
    report = compare(ccw, TOOL, ideal)
    assert report.excess > 0 and report.holes > 0
    for x, y, _ in report.worst_excess:                 # the long way round
        assert y > -0.3 or x < -20.3, report.summary()


def test_tolerance_of_tool_width() -> None:
    ideal = [Stroke(((0, 0), (3000, 0)), TOOL / 2)]
    run = simulate([Frame(dx=3000, k=10)])
    assert compare(run, TOOL + 8, ideal).ok              # 0.04 mm wider: inside 0.05 mm
    assert compare(run, TOOL - 8, ideal).ok
    assert compare(run, TOOL + 14, ideal).excess > 0      # 0.07 mm wider
    assert compare(run, TOOL - 14, ideal).holes > 0


def test_the_finest_tolerance_is_checked_at_half_its_pitch() -> None:
    """verify takes 0.02 mm: no pitch of PITCHES is below it, so the check
    runs at 0.01 mm, and a tool 0.04 mm too wide is excess there."""
    ideal = [Stroke(((0, 0), (3000, 0)), TOOL / 2)]
    run = simulate([Frame(dx=3000, k=10)])
    report = compare(run, TOOL, ideal, tol=2)
    assert report.ok and report.pitch_mm == 0.01 and report.tol_mm == 0.02, report.summary()
    assert compare(run, TOOL + 8, ideal, tol=2).excess > 0
    assert compare(run, TOOL + 8, ideal, tol=5).ok


def test_empty_tape_against_empty_layer() -> None:
    report = compare(simulate([]), TOOL, Layer(TOOL))
    assert report.ok and report.pixels == 0


def test_missing_layer_is_all_holes() -> None:
    report = compare(simulate([]), TOOL, Layer(TOOL, [Disc(0, 0, 100)]))
    assert report.holes > 0 and not report.ok


def test_pixel_budget_and_adaptive_pitch() -> None:
    run = simulate([Frame(dx=20000, k=10)])                # 200 mm line
    ideal = [Stroke(((0, 0), (20000, 0)), TOOL / 2)]
    fine = compare(run, TOOL, ideal)
    assert fine.ok and fine.pitch_mm == 0.02
    coarse = compare(run, TOOL, ideal, max_pixels=fine.pixels * 7 // 10)
    assert coarse.ok and coarse.pitch_mm > 0.02
    # the budget only chooses the pitch: past it, the coarsest pitch, never a refusal
    tight = compare(run, TOOL, ideal, max_pixels=1000)
    assert tight.ok and tight.pitch_mm == 0.04 and tight.pixels > 1000
    with pytest.raises(ValueError):
        make_grid((0, 200000, 0, 200000), 2.0)             # 2 m square at 0.02 mm


def test_render_layer_offsets_and_render_run() -> None:
    grid = make_grid((-200, 200, -200, 200), 2.0, 20.0)
    disc = Layer(TOOL, [Disc(0, 0, 100)])
    area = {off: render_layer(disc, grid, off).sum() * 4 for off in (-20, 0, 30)}
    for off, a in area.items():
        assert a == pytest.approx(math.pi * (100 + off) ** 2, rel=0.02)
    drawn = render_run(simulate(ring_frames([75, 40, 0], 0, 0)), TOOL, grid)
    assert np.array_equal(drawn, render_layer(disc, grid) | drawn)
    assert drawn.sum() * 4 == pytest.approx(math.pi * 100 ** 2, rel=0.02)


def test_shapes_signed_distance() -> None:
    rr = RoundRect(0, 0, 400, 200, 25)
    x = np.array([0.0, 200, 300, 225, 0])
    y = np.array([0.0, 0, 0, 125, 150])
    d = rr.sdf(x, y)
    assert d == pytest.approx([-100, 0, 100, 50 * math.sqrt(2) - 25, 50])
    band = ArcBand(0, 0, 1000, 0.0, math.pi / 2, 25)         # counter-clockwise quarter
    d = band.sdf(np.array([1000.0, 0, -1000, 0, 500]), np.array([0.0, 1000, 0, -1000, 0]))
    assert d == pytest.approx([-25, -25, 1000 * math.sqrt(2) - 25,
                               1000 * math.sqrt(2) - 25, 475])
    grid = Grid(0, 0, 2.0, 3, 2)
    xs, ys = grid.centres()
    assert xs[0].tolist() == [1.0, 3.0, 5.0] and ys[:, 0].tolist() == [1.0, 3.0]


def _random_shapes(rng: np.random.Generator, integer: bool) -> list:
    """A dozen random shapes of every kind: discs, rounded rectangles,
    polylines (upright and slanted, some with repeated points), full and
    partial arcs, on whole units or anywhere."""
    def v(a: float, b: float) -> float:
        x = float(rng.uniform(a, b))
        return float(round(x)) if integer else x

    shapes: list = []
    for _ in range(int(rng.integers(1, 14))):
        k = int(rng.integers(0, 4))
        if k == 0:
            shapes.append(Disc(v(0, 1500), v(0, 1500), v(0, 150)))
        elif k == 1:
            w, h = v(2, 300), v(2, 300)
            shapes.append(RoundRect(v(0, 1500), v(0, 1500), w, h,
                                    min(w, h) / 2 * float(rng.uniform(0, 1))))
        elif k == 2:
            pts = tuple((v(0, 1500), v(0, 1500)) for _ in range(int(rng.integers(1, 5))))
            if len(pts) > 1 and rng.uniform() < 0.5:
                pts = (pts[0], (pts[0][0], pts[1][1]), pts[1], pts[1])
            shapes.append(Stroke(pts, v(1, 60)))
        else:
            sweep = float(rng.choice([2 * math.pi, -2 * math.pi, rng.uniform(-6, 6)]))
            shapes.append(ArcBand(v(0, 1500), v(0, 1500), v(0, 500),
                                  float(rng.uniform(-4, 4)), sweep, v(1, 60)))
    return shapes


@pytest.mark.parametrize("seed", range(24))
def test_span_fill_is_the_pairwise_evaluation(seed: int) -> None:
    """The boolean pass paints each shape's spans per pixel row; it must
    find exactly the pixels that evaluating every (pixel, shape) pair finds
    (Plan.distances), on pixel centres that fall exactly on outlines
    (whole units) and anywhere else."""
    from harness.raster import plan
    rng = np.random.default_rng(seed)
    shapes = _random_shapes(rng, integer=seed % 2 == 0)
    n_ideal = int(rng.integers(0, len(shapes) + 1))
    tol = float(rng.integers(2, 40))
    pitch = min(float(rng.choice([1.0, 2.0, 3.0, 4.0])), tol / 2)
    pl = plan(shapes[:n_ideal], shapes[n_ideal:], tol, pitch=pitch,
              reach=float(rng.choice([0.0, 50.0])))
    assert pl is not None
    for batch in pl.batches(None, 16):
        on, inner, near = pl.flags(batch, tol)
        ideal_d, _ = pl.distances(batch, True)
        drawn_d, _ = pl.distances(batch, False)
        assert np.array_equal(on, drawn_d <= 0)
        assert np.array_equal(inner, ideal_d <= -tol)
        assert np.array_equal(near, ideal_d <= tol)
