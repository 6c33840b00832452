"""bench.kicks: the traced copy of TENZOR and the arithmetic of its traces.

The traced copy must search exactly as TENZOR does when no variable is set
(else its traces would measure another program), its trace must end at the
tour the tape holds, and the instrumentation must still fit CMKICK: a
change there that moves one of the lines it replaces fails here, not in the
middle of a long measurement.
"""
from __future__ import annotations

import filecmp
import os
import shutil
import subprocess
from pathlib import Path

import pytest

from bench import kicks, measure, tsplib, variants

ROOT = Path(__file__).resolve().parents[2]
CMKICK = ROOT / "legacy" / "cmkick.f"


def test_the_trace_fits_cmkick_and_compiles(tmp_path: Path) -> None:
    text = kicks.traced_source(CMKICK.read_text(encoding="ascii"))
    assert "GETENV('TZTRACE'" in text and "NBASE = MAX(NWIN * NITM / 4, NLEAST)" in text
    src = tmp_path / "cmkick.f"
    src.write_text(text, encoding="ascii")
    gfortran = shutil.which("gfortran")
    if gfortran is None:
        pytest.skip("gfortran is not on PATH")
    proc = subprocess.run([gfortran, "-fsyntax-only", "-ffixed-form", "-fimplicit-none",
                           str(src)], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr


def test_a_moved_line_is_named() -> None:
    text = CMKICK.read_text(encoding="ascii").replace(
        "      IF (MODE .EQ. 2) NBASE = MAX(NITM / 4, NLEAST)\n",
        "      IF (MODE .EQ. 2) NBASE = MAX(NITM / 2, NLEAST)\n")
    with pytest.raises(kicks.KicksError,
                       match=r"0 copies of the line 'IF \(MODE \.EQ\. 2\) NBASE = MAX\(NITM / 4, NLEAST\)'"):
        kicks.traced_source(text)


def _trace(least: int = 1) -> kicks.Trace:
    # 10 items; kicks kept at 3 and 40, which take off less than half a per
    # cent of the first tour (the window does not grow); the kicks stopped
    # after 100; the program's CPU 23 ms, 3 of them after the kicks; 0.1 ms
    # a kick. The windows' arithmetic is read without CMKICK's least window
    # (least=1) but where a test says so
    return kicks.Trace(10, [(0, 0.010, 1.3), (3, 0.011, 1.05), (40, 0.015, 0.9),
                            (100, 0.020, 0.9)], 0.023, least)


def test_reading_a_trace() -> None:
    tr = _trace()
    assert tr.kicks == 100 and tr.per_kick() == pytest.approx(1e-4)
    assert tr.after() == pytest.approx(0.003)
    assert tr.at(5) == 1.3 and tr.at(12) == 1.05 and tr.at(400) == 0.9
    assert tr.kicks_to(1.0) == 40 and tr.kicks_to(1.1) == 3 and tr.kicks_to(0.5) is None


def test_shorter_windows_read_off_a_trace() -> None:
    tr = _trace()
    # window 1 (a quarter kick an item: 10 // 4 = 2 kicks): the first kick
    # kept, at 3, comes after 2 failed ones: stop at kick 2, still at 1.3 %
    assert tr.window(1) == pytest.approx((0.010 + 2e-4 + 0.003, 1.3))
    # window 4 (10 kicks): stop at kick 13
    assert tr.window(4) == pytest.approx((0.010 + 13e-4 + 0.003, 1.05))
    # window 20 (50 kicks): stop 50 kicks after kick 40, at 90
    assert tr.window(20) == pytest.approx((0.010 + 90e-4 + 0.003, 0.9))
    # window 40: the run ended first, at kick 100: the whole program
    assert tr.window(40) == pytest.approx((0.023, 0.9))


def test_a_window_is_at_least_the_least_one() -> None:
    # with CMKICK's least window (160 kicks, where the tour comes back from
    # a far start point) every window of a 10-item trace is 160 failed
    # kicks: longer than the run, which ends as it did
    tr = _trace(160)
    assert tr.window(1) == tr.window(40) == pytest.approx((0.023, 0.9))
    # a least window of 40: kick 40 comes 37 after kick 3, and the kicks
    # stop 40 failed kicks after it, at kick 80; of 30, at kick 33
    assert _trace(40).window(1) == pytest.approx((0.010 + 80e-4 + 0.003, 0.9))
    assert _trace(30).window(1) == pytest.approx((0.010 + 33e-4 + 0.003, 1.05))


def test_the_window_grows_with_what_the_kicks_gain() -> None:
    # 100 items, window 4: 100 failed kicks. Kick 5 takes the tour from 3 %
    # to 2 % over the optimum, 100/103 per cent of the first tour's length:
    # 0.47 beyond the first half, so the window grows to 100 + 141 and kick
    # 200 (195 after kick 5) is reached; at 1.5 % the kicks have taken off
    # 1.456 per cent, and the window is 100 + 286: the stop is at kick 586
    # (0.01 ms a kick), not at kick 105, as the window alone would put it
    tr = kicks.Trace(100, [(0, 0.010, 3.0), (5, 0.011, 2.0), (200, 0.015, 1.5),
                           (1000, 0.020, 1.5)], 0.023, 1)
    assert tr.window(4) == pytest.approx((0.010 + 586e-5 + 0.003, 1.5))
    # a small gain leaves the window as it is: stop 100 after kick 5
    small = kicks.Trace(100, [(0, 0.010, 3.0), (5, 0.011, 2.6), (200, 0.015, 1.5),
                              (1000, 0.020, 1.5)], 0.023, 1)
    assert small.window(4) == pytest.approx((0.010 + 105e-5 + 0.003, 2.6))
    # a gain of 3 % of the first tour (2.5 beyond the first half) would make
    # it 100 + 750; it stops at eight times itself, 800, after kick 5
    big = kicks.Trace(100, [(0, 0.010, 4.0), (5, 0.011, 0.88), (1000, 0.020, 0.88)], 0.023, 1)
    assert big.window(4) == pytest.approx((0.010 + 805e-5 + 0.003, 0.88))


def test_a_larger_tape_waits_longer() -> None:
    # 1 400 items, window 1: a quarter of a kick an item, 350, times the
    # square root of 1400/700: 494 failed kicks. Kick 400 is kept, kick 850
    # comes 450 after it, and the kicks stop 494 after that, at 1 344 (0.001
    # ms a kick; a window of 350 would have stopped them at kick 350)
    tr = kicks.Trace(1400, [(0, 0.010, 2.0), (400, 0.011, 1.9), (850, 0.015, 1.8),
                            (10000, 0.020, 1.8)], 0.023, 1)
    assert tr.window(1) == pytest.approx((0.010 + 1344e-6 + 0.003, 1.8))
    # the growth with the gain still stops at two kicks an item, 2 800
    big = kicks.Trace(1400, [(0, 0.010, 9.0), (10, 0.011, 0.9), (10000, 0.020, 0.9)],
                      0.023, 1)
    assert big.window(1) == pytest.approx((0.010 + 2810e-6 + 0.003, 0.9))


def test_lengths_are_scaled_to_the_tapes_per_cent(tmp_path: Path) -> None:
    f = tmp_path / "x.trc"
    f.write_text("  0  1.0E-02  1100.0\n  7  1.2E-02  1050.0\n  -9  1.5E-02  1020.0\n")
    tr = kicks.read_trace(f, 5, 2.0, 0.02)
    assert [k for k, _, _ in tr.points] == [0, 7, 9]
    assert tr.points[-1][2] == pytest.approx(2.0)
    assert tr.points[0][2] == pytest.approx(100 * (1100 * 1.02 / 1020 - 1))
    assert tr.least == 1
    # the first line's fourth number is the least window CMKICK took
    f.write_text("  0  1.0E-02  1100.0  160\n  -9  1.5E-02  1020.0\n")
    assert kicks.read_trace(f, 5, 2.0, 0.02).least == 160
    (tmp_path / "y.trc").write_text("  0  1.0E-02  1100.0\n")
    with pytest.raises(kicks.KicksError, match="no trace"):
        kicks.read_trace(tmp_path / "y.trc", 5, 2.0, 0.02)


@pytest.fixture(scope="module")
def traced(tmp_path_factory) -> Path:
    """The traced copy of this tree's TENZOR, built once for the module."""
    if shutil.which("fpm") is None:
        pytest.skip("fpm is not on PATH")
    return kicks.build_traced(ROOT, tmp_path_factory.mktemp("traced") / "tree")


def test_the_traced_copy_searches_as_tenzor_does(traced: Path, tmp_path: Path) -> None:
    """No variable set: the traced copy punches d198's tapes byte for byte
    as this tree's TENZOR does. Traced, its last point is the tape's tour."""
    plain = measure.release_binary(ROOT)
    deck = tsplib.write_deck(tsplib.load("d198"), tmp_path)
    env = {k: v for k, v in os.environ.items() if not k.startswith("TZ")}
    for exe_, out in ((traced, "a"), (plain, "b")):
        subprocess.run([str(exe_), str(deck), "-o", str(tmp_path / out)], env=env, check=True,
                       capture_output=True)
    names = sorted(p.name for p in (tmp_path / "a").iterdir())
    assert names and names == sorted(p.name for p in (tmp_path / "b").iterdir())
    _, mismatch, errors = filecmp.cmpfiles(tmp_path / "a", tmp_path / "b", names,
                                               shallow=False)
    assert not mismatch and not errors
    tr = kicks.run_traced(traced, "d198", 1977, 40, tmp_path)
    assert tr.items == 198 and tr.kicks > 10 * 198
    pcts = [p for _, _, p in tr.points]
    assert all(b <= a + 1e-9 for a, b in zip(pcts, pcts[1:]))   # kept kicks only shorten
    assert tr.window(40)[1] == pytest.approx(pcts[-1])


def test_window_one_read_off_a_trace_is_tenzors_own_stop(traced: Path, tmp_path: Path) -> None:
    """pcb1173 (1 173 items, over the 700 beyond which the window grows with
    the tape): the stop that TENZOR's own window (1) puts on a long trace
    comes after the kick that TENZOR's own run kept last. (A trace's per
    cents are its lengths scaled to its own end, so two traces are compared
    by their kicks.)"""
    own = kicks.run_traced(traced, "pcb1173", 1977, 1, tmp_path)
    last_kept = own.points[-2][0]
    assert last_kept > 0
    long = kicks.run_traced(traced, "pcb1173", 1977, 40, tmp_path)
    pct = {k: p for k, _, p in long.points}
    assert long.window(1)[1] == pct[last_kept]
    assert long.points[-2][0] > last_kept    # the long window goes on to keep more


@pytest.mark.parametrize("argv, says", [
    (["--names", "x"], "--names 'x': the instances are of bench/tsplib/: d198"),
    (["--seeds", "a,b"], "--seeds 'a,b': give whole numbers"),
    (["--window", "3"], "--window 3: at least 20"),
])
def test_a_bad_option_is_named(argv, says, capsys) -> None:
    assert kicks.main(argv) == 2
    assert says in capsys.readouterr().err


def test_the_report_names_a_run_that_never_came_within_1_per_cent() -> None:
    never = kicks.Trace(10, [(0, 0.010, 5.0), (100, 0.020, 2.0)], 0.023)
    text = kicks.report({"d198": [never, _trace()]}, [1977, 12345], {"d198": 0.5})
    row = next(line for line in text.splitlines() if line.startswith("d198"))
    assert row.split()[2] == "never" and "40" in row.split()[3]
    assert "1 of 2" in text.splitlines()[-1]          # window 20: only the second run


@pytest.mark.tenzor            # it runs a TENZOR (the traced copy): mutation runs select it
@pytest.mark.parametrize("name, tag, window", [("d657", "as", 657 // 4),
                                               ("pcb1173", "as", 379),  # 293 * sqrt(1173/700)
                                               ("u1060", "sh1", 326 + 410),  # 3 * 326 * 0.42
                                               ("d1291", "mx", 8 * (1291 // 4))])
def test_the_kicks_stop_where_their_window_says(traced: Path, tmp_path: Path, name: str,
                                                 tag: str, window: int) -> None:
    """CMKICK's window, read off a traced run with the fixed seed: the kicks
    stop when the window's failed kicks in a row follow the last kept one.
    d657's kicks take off 0.29 % of its first tour, less than half a per
    cent, so its window stays a quarter of a kick an item; pcb1173's take
    off less too, but its tape has more than 700 items, so its window is a
    quarter of a kick an item times the square root of 1173/700, 379 kicks;
    u1060's, its pads in bench.variants' first shuffled order (sh1), take
    off 0.92 %, between the half per cent and the per cent, so its window
    of 326 kicks (265 times the root of 1060/700) grows by three times
    itself for the 0.42 beyond the half, to 736; d1291's, mirrored
    (bench.variants' mx), take off 3.6 %, far past what grows the window to
    its cap, two kicks an item, and stop there before their work bound
    (fl1400's, which pinned the cap before, now stop at the work bound).
    None of the tours comes back from a far start point (no least
    window)."""
    deck = next(v for v in variants.variants(tsplib.load(name)) if v.tag == tag)
    tr = kicks.run_traced(traced, deck.instance, 1977, 1, tmp_path)
    p0, last = tr.points[0][2], tr.points[-2][2]
    gained = 100 * (p0 - last) / (100 + p0)
    assert (gained < 0.5) == (tag == "as"), gained
    assert tr.least == 1
    assert tr.kicks - tr.points[-2][0] == window


@pytest.mark.tenzor            # it runs a TENZOR (the traced copy): mutation runs select it
def test_a_tour_back_from_a_far_start_point_takes_the_least_window(traced: Path,
                                                                   tmp_path: Path) -> None:
    """d198 with its pads in bench.variants' first shuffled order: the first
    tour comes back to the far start point from the far side, so CMKICK
    takes its least window, 160 failed kicks, and says so on the trace's
    first line; a kick mends the tour (5.6 % over the optimum before it,
    0.13 % at the end), which grows the window to its cap, eight times
    itself: the kicks stop 1 280 after the last one kept."""
    deck = next(v for v in variants.variants(tsplib.load("d198")) if v.tag == "sh1")
    tr = kicks.run_traced(traced, deck.instance, 1977, 1, tmp_path)
    assert tr.least == 160
    assert tr.points[0][2] > 5.0 and tr.points[-1][2] < 1.0
    assert tr.kicks - tr.points[-2][0] == 8 * 160
    assert tr.window(1) == pytest.approx((tr.cpu, tr.points[-1][2]))


def test_the_budgets_come_from_the_recorded_run() -> None:
    """The kicks a hundredth of LKH-3 allows are read from the recorded
    run's tsplib.csv by default; a default path that named nothing would
    leave that column empty without a word."""
    default = kicks.build_parser().parse_args([]).lkh
    assert default == ROOT / "bench" / "results" / "tsplib.csv"
    seconds = kicks.lkh_seconds(default)
    assert sorted(seconds) == sorted(tsplib.NAMES) and min(seconds.values()) > 0
