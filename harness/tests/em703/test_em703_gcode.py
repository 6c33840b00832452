"""`em703 gcode` against the harness's simulator: the program's moves trace
the harness's path within 0.01 mm, read twice, by a small reader of the
G-code subset written here and by LinuxCNC's standalone interpreter `rs274`
(its canonical moves), on every example tape and job and on random tapes;
with --chords no point of a chord is farther than TOL from the arc.

rs274 comes with Debian's linuxcnc-uspace, which `make rs274` installs (it
is large, so `make test` does not); without it the rs274 tests are skipped
with that reason, except under REQUIRE_RS274=1 (CI), where they fail."""

from __future__ import annotations

import math
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from harness.sim import Arc, Dot, Line, simulate, unroll
from harness.tape import Frame, decode, encode

from harness.tests.helpers import keys, run
from harness.tests.strategies import frame_lists


@pytest.fixture(scope="session")
def rs274() -> str:
    """The path of rs274; without it a skip, or a failure under REQUIRE_RS274=1."""
    path = shutil.which("rs274")
    if path is None:
        why = ("rs274 (LinuxCNC's standalone G-code interpreter, Debian package "
               "linuxcnc-uspace) is not on PATH: `make rs274` installs it")
        if os.environ.get("REQUIRE_RS274") == "1":
            pytest.fail(why + "; REQUIRE_RS274=1 says its cross-check must run", pytrace=False)
        pytest.skip(why + "; the G-code is checked by the harness's own reader only")
    return path


MM = 0.01
Event = tuple


# ---------------------------------------------------------------------------
# What the program must do: the harness's run as a list of events in
# execution order: ("down",), ("up",), ("travel", x, y), ("line", x, y),
# ("arc", x, y, cx, cy, clockwise); positions in mm.
# ---------------------------------------------------------------------------
def expected_events(frames: list[Frame], origin: tuple[int, int] = (0, 0)) -> list[Event]:
    run_ = simulate(frames)
    strokes, travel = iter(run_.strokes), iter(run_.travel)
    events: list[Event] = []
    down = False
    ox, oy = origin

    def mm(v: float, o: int) -> float:
        return (v + o) / 100

    for f in unroll(frames):
        if f.k == 20:
            if down:
                events.append(("up",))
                down = False
            if f.dx or f.dy:
                t = next(travel)
                events.append(("travel", mm(t.x1, ox), mm(t.y1, oy)))
            continue
        if not down:
            events.append(("down",))
            down = True
        if f.k == 10 and not (f.dx or f.dy):
            assert isinstance(next(strokes), Dot)
            continue
        s = next(strokes)
        if isinstance(s, Line):
            events.append(("line", mm(s.x1, ox), mm(s.y1, oy)))
        else:
            assert isinstance(s, Arc)
            events.append(("arc", mm(s.x1, ox), mm(s.y1, oy), mm(s.cx, ox), mm(s.cy, oy),
                           s.sweep < 0))
    return events


def job_events(job: Path) -> tuple[list[Event], list[tuple[list[Frame], tuple[int, int]]]]:
    """Events of a job's three tapes one after another (each from where the
    last ended; the tool change between them raises the tool), and each
    tape's frames with its origin."""
    sheet = keys(job.read_text())
    events: list[Event] = []
    tapes = []
    origin = (0, 0)
    for key in ("small", "large", "cond"):
        frames = decode((job.parent / sheet[f"{key}.tape"]).read_bytes(), sheet["code"]).frames
        tapes.append((frames, origin))
        events += [("up",), *expected_events(frames, origin)]
        end = simulate(frames).end
        origin = (origin[0] + end[0], origin[1] + end[1])
    return _normalise(events), tapes


def _normalise(events: list[Event]) -> list[Event]:
    """Drop tool changes that change nothing, and a final raise."""
    out: list[Event] = []
    down = False
    for e in events:
        if e[0] == "down":
            if down:
                continue
            down = True
        elif e[0] == "up":
            if not down:
                continue
            down = False
        out.append(e)
    while out and out[-1] == ("up",):
        out.pop()
    return out


# ---------------------------------------------------------------------------
# Reader 1: the harness's own reader of the subset em703 writes.
# ---------------------------------------------------------------------------
WORD = re.compile(r"([A-Z])([-+]?\d+(?:\.\d*)?)")


def read_gcode(text: str) -> list[Event]:
    lines = text.splitlines()
    assert lines[0] == "%" and lines[-1] == "%", "a program starts and ends with %"
    events: list[Event] = []
    x = y = 0.0
    z = None
    numbers: list[int] = []
    motion = None
    for line in lines[1:-1]:
        line = re.sub(r"\([^)]*\)", "", line).strip()
        if not line:
            continue
        words = WORD.findall(line)
        assert "".join(a + b for a, b in words) == line.replace(" ", ""), line
        values: dict[str, float] = {}
        for letter, number in words:
            if letter == "N":
                numbers.append(int(number))
            elif letter in "GM":
                code = int(float(number))
                if letter == "G" and code in (0, 1, 2, 3):
                    motion = code
                elif letter == "M" and code == 3:
                    events.append(("down",))
                elif letter == "M" and code == 5:
                    events.append(("up",))
            else:
                values[letter] = float(number)
        if "Z" in values:
            assert "X" not in values and motion in (0, 1)
            z = values["Z"]
            events.append(("down",) if z <= 0 else ("up",))
        if "X" in values or "Y" in values:
            nx, ny = values.get("X", x), values.get("Y", y)
            if motion == 0:
                events.append(("travel", nx, ny))
            elif motion == 1:
                events.append(("line", nx, ny))
            else:
                events.append(("arc", nx, ny, x + values["I"], y + values["J"], motion == 2))
            x, y = nx, ny
    assert numbers == sorted(numbers) and len(set(numbers)) == len(numbers), "N numbers rise"
    return _normalise(events)


# ---------------------------------------------------------------------------
# Reader 2: LinuxCNC's interpreter; its canonical moves as events.
# ---------------------------------------------------------------------------
CANON = re.compile(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|START_SPINDLE_CLOCKWISE|"
                   r"STOP_SPINDLE_TURNING)\(([^)]*)\)")


def rs274_events(rs274: str, program: Path) -> list[Event]:
    proc = subprocess.run([rs274, "-g", str(program)], capture_output=True, text=True,
                          timeout=120, stdin=subprocess.DEVNULL)
    assert proc.returncode == 0, proc.stdout[-1500:] + proc.stderr[-1500:]
    events: list[Event] = []
    x = y = 0.0
    for name, args in CANON.findall(proc.stdout):
        v = [float(a) for a in args.split(",")] if args.strip() else []
        if name == "START_SPINDLE_CLOCKWISE":
            events.append(("down",))
        elif name == "STOP_SPINDLE_TURNING":
            events.append(("up",))
        elif name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED"):
            if (v[0], v[1]) == (x, y):           # a Z move only: the tool goes down or up
                events.append(("down",) if v[2] <= 0 else ("up",))
                continue
            events.append(("travel" if name == "STRAIGHT_TRAVERSE" else "line", v[0], v[1]))
            x, y = v[0], v[1]
        else:   # ARC_FEED(first_end, second_end, first_axis, second_axis, rotation, ...)
            events.append(("arc", v[0], v[1], v[2], v[3], v[4] < 0))
            x, y = v[0], v[1]
    return _normalise(events)


def assert_same_path(got: list[Event], want: list[Event], what: str) -> None:
    assert [e[0] for e in got] == [e[0] for e in want], what
    for n, (g, w) in enumerate(zip(got, want)):
        for a, b in zip(g[1:], w[1:]):
            if isinstance(b, bool):
                assert a == b, (what, n, g, w)
            else:
                assert abs(a - b) <= MM + 1e-9, (what, n, g, w)


# ---------------------------------------------------------------------------
def test_example_tapes_trace_the_harness_path(em703_exe, example_tapes) -> None:
    for tape in example_tapes:
        frames = decode(tape.read_bytes()).frames
        want = _normalise(expected_events(frames))
        text = run(em703_exe, "gcode", tape, check=0).stdout.decode()
        assert_same_path(read_gcode(text), want, str(tape))
        zed = run(em703_exe, "gcode", "--z", tape, check=0).stdout.decode()
        assert "M03" not in zed and "M05" not in zed
        assert_same_path(read_gcode(zed), want, f"{tape} --z")


def test_rs274_traces_the_harness_path_of_every_example_tape(em703_exe, rs274, example_tapes,
                                                             tmp_path) -> None:
    program = tmp_path / "t.ngc"
    for tape in example_tapes:
        want = _normalise(expected_events(decode(tape.read_bytes()).frames))
        for extra in ([], ["--z"]):
            run(em703_exe, "gcode", tape, *extra, "-o", program, check=0)
            assert_same_path(rs274_events(rs274, program), want, f"{tape} {extra} (rs274)")


def test_example_jobs_trace_the_harness_path(em703_exe, example_jobs, tmp_path) -> None:
    for job in example_jobs:
        want, _ = job_events(job)
        out = tmp_path / "job.ngc"
        run(em703_exe, "gcode", job, "-o", out, check=0)
        text = out.read_text()
        assert [line.split(" ", 1)[1] for line in text.splitlines() if " M06" in line] == \
            ["T1 M06", "T2 M06", "T3 M06"]
        assert_same_path(read_gcode(text), want, str(job))
        # the same bytes on every run
        assert run(em703_exe, "gcode", job, check=0).stdout.decode() == text


@settings(max_examples=20, deadline=None)
@given(frames=frame_lists(), use_z=st.booleans())
def test_random_tapes_trace_the_harness_path(em703_exe, tmp_path_factory, frames, use_z) -> None:
    tmp = tmp_path_factory.mktemp("gcode")
    tape = tmp / "t.ptp"
    tape.write_bytes(encode(frames))
    text = run(em703_exe, "gcode", tape, *(["--z"] if use_z else []), check=0).stdout.decode()
    want = _normalise(expected_events(frames))
    assert_same_path(read_gcode(text), want, "random tape")


def test_rs274_traces_the_harness_path_of_every_example_job(em703_exe, rs274, example_jobs,
                                                            tmp_path) -> None:
    out = tmp_path / "job.ngc"
    for job in example_jobs:
        want, _ = job_events(job)
        for extra in ([], ["--z"]):
            run(em703_exe, "gcode", job, *extra, "-o", out, check=0)
            assert_same_path(rs274_events(rs274, out), want, f"{job} {extra} (rs274)")
        run(em703_exe, "gcode", job, "--chords", "0.01", "-o", out, check=0)
        assert all(e[0] != "arc" for e in rs274_events(rs274, out))


@settings(max_examples=20, deadline=None)
@given(frames=frame_lists(), use_z=st.booleans())
def test_rs274_traces_the_harness_path_of_random_tapes(em703_exe, rs274, tmp_path_factory,
                                                       frames, use_z) -> None:
    tmp = tmp_path_factory.mktemp("rs274")
    tape, program = tmp / "t.ptp", tmp / "t.ngc"
    tape.write_bytes(encode(frames))
    run(em703_exe, "gcode", tape, *(["--z"] if use_z else []), "-o", program, check=0)
    assert_same_path(rs274_events(rs274, program), _normalise(expected_events(frames)),
                     "random tape (rs274)")


# ---------------------------------------------------------------------------
# Chords for line-only machines (seed 002): step angle 2 arccos(1 - TOL/R).
# ---------------------------------------------------------------------------
def _points_of(events: list[Event]) -> list[tuple[float, float]]:
    return [(e[1], e[2]) for e in events if e[0] in ("line", "travel")]


class _Spiral:
    """The arc as the machine runs it from the tape's start to the tape's end
    point: the angle a0 + sweep * s and the radius going evenly from the
    start's to the end's (equal when the end is on the circle; at most 0.01 mm
    apart, docs/TAPE.md), for s from 0 to 1; in mm."""

    def __init__(self, arc: Arc) -> None:
        self.cx, self.cy = arc.cx / 100, arc.cy / 100
        self.r0 = arc.r / 100
        self.r1 = math.hypot(arc.x1 - arc.cx, arc.y1 - arc.cy) / 100
        self.a0, self.sweep = arc.a0, arc.sweep

    def at(self, s: np.ndarray) -> np.ndarray:
        r = self.r0 + (self.r1 - self.r0) * s
        a = self.a0 + self.sweep * s
        return np.stack([self.cx + r * np.cos(a), self.cy + r * np.sin(a)], -1)

    def param(self, q: np.ndarray, guess: np.ndarray) -> np.ndarray:
        """The parameter s of the spiral point in the direction of q, taking
        the turn nearest to ``guess``."""
        phi = np.arctan2(q[..., 1] - self.cy, q[..., 0] - self.cx)
        d = np.mod(phi - (self.a0 + self.sweep * guess) + math.pi, 2 * math.pi) - math.pi
        return guess + d / self.sweep

    def radial(self, q: np.ndarray, guess: np.ndarray) -> np.ndarray:
        """Distance of q from the spiral along its radius (never less than the
        true distance)."""
        s = self.param(q, guess)
        r = self.r0 + (self.r1 - self.r0) * s
        return np.abs(np.hypot(q[..., 0] - self.cx, q[..., 1] - self.cy) - r)


def _segment_distance(q: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance of points q [n, m, 2] from segments a-b [n, 2]."""
    seg = (b - a)[:, None, :]
    rel = q - a[:, None, :]
    lam = np.clip((rel * seg).sum(-1) / np.maximum((seg * seg).sum(-1), 1e-18), 0, 1)
    return np.hypot(*np.moveaxis(rel - lam[..., None] * seg, -1, 0))


def _check_chords(text: str, frames: list[Frame], tol: float, what: str) -> int:
    """Every chord lies within tol of its arc and every arc within tol of its
    chords; returns the number of chords."""
    got = read_gcode(text)
    assert all(e[0] != "arc" for e in got), what
    want = _normalise(expected_events(frames))
    run_ = simulate(frames)
    arcs = iter(s for s in run_.strokes if isinstance(s, Arc))
    i = 0
    x = y = 0.0
    chords = 0
    for w in want:
        if w[0] != "arc":
            assert got[i][0] == w[0], (what, got[i], w)
            if len(w) > 1:
                assert abs(got[i][1] - w[1]) <= MM and abs(got[i][2] - w[2]) <= MM
                x, y = got[i][1], got[i][2]
            i += 1
            continue
        arc = next(arcs)
        pts = [(x, y)]
        while True:
            g = got[i]
            assert g[0] == "line", (what, g)
            pts.append((g[1], g[2]))
            i += 1
            if abs(g[1] - w[1]) < 1e-9 and abs(g[2] - w[2]) < 1e-9:
                break
        chords += len(pts) - 1
        # the number of chords: the step angle of seed 002 for the larger radius
        r = max(arc.r, math.hypot(arc.x1 - arc.cx, arc.y1 - arc.cy)) / 100
        step = 2 * math.acos(max(-1.0, 1 - (tol - 0.0008) / r))
        assert len(pts) - 1 == max(1, math.ceil(abs(arc.sweep) / step - 1e-9)), what
        p = np.array(pts)
        n = len(pts) - 1
        spiral = _Spiral(arc)
        sv = spiral.param(p, np.arange(n + 1) / n)          # each vertex on the spiral
        t = np.linspace(0, 1, 17)
        # every point of a chord within tol of the arc (measured along the radius)
        q = p[:-1, None, :] + t[None, :, None] * (p[1:] - p[:-1])[:, None, :]
        guess = sv[:-1, None] + t[None, :] * (sv[1:] - sv[:-1])[:, None]
        off = spiral.radial(q, guess).max()
        assert off <= tol + 1e-6, (what, "a chord leaves the arc by", float(off))
        # every point of the arc within tol of its chord
        arc_pts = spiral.at(guess)
        off = _segment_distance(arc_pts, p[:-1], p[1:]).max()
        assert off <= tol + 1e-6, (what, "the arc leaves its chords by", float(off))
        assert abs(sv[0]) < 1e-6 and abs(sv[-1] - 1) < 1e-6, what
        x, y = pts[-1]
    assert i == len(got), what
    return chords


@pytest.mark.parametrize("tol", [0.005, 0.05, 0.5])
def test_chords_stay_within_the_tolerance_on_the_examples(em703_exe, example_tapes, tol) -> None:
    total = 0
    for tape in example_tapes:
        frames = decode(tape.read_bytes()).frames
        text = run(em703_exe, "gcode", "--chords", str(tol), tape, check=0).stdout.decode()
        total += _check_chords(text, frames, tol, f"{tape} --chords {tol}")
    assert total > 0


@settings(max_examples=20, deadline=None)
@given(frames=frame_lists(max_items=5), tol=st.sampled_from([0.002, 0.01, 0.1, 1.0]))
def test_chords_stay_within_the_tolerance_on_random_tapes(em703_exe, tmp_path_factory, frames,
                                                          tol) -> None:
    tape = tmp_path_factory.mktemp("chords") / "t.ptp"
    tape.write_bytes(encode(frames))
    text = run(em703_exe, "gcode", "--chords", str(tol), tape, check=0).stdout.decode()
    _check_chords(text, frames, tol, "random tape")


# ---------------------------------------------------------------------------
# Block numbers: N1, N2, ... and after N99999 again from N1.
# ---------------------------------------------------------------------------
def test_block_numbers_start_again_at_n1_after_n99999(em703_exe, tmp_path) -> None:
    # a cycle pair run 50000 times draws 100000 lines: with the two blocks of
    # the heading, the tool lowered, raised and M02, 100005 blocks
    tape = tmp_path / "long.ptp"
    tape.write_bytes(encode([Frame(dx=1, k=10, cyc=50000), Frame(dx=-1, k=10)]))
    lines = run(em703_exe, "gcode", tape, check=0).stdout.decode().splitlines()
    numbers = [int(line[1:].split(" ", 1)[0]) for line in lines if line.startswith("N")]
    assert numbers == [*range(1, 100000), *range(1, 7)]
    wrap = lines.index("N99999 G01 X0.000 Y0.000")
    assert lines[wrap - 1:wrap + 2] == ["N99998 G01 X0.010 Y0.000", "N99999 G01 X0.000 Y0.000",
                                        "N1 G01 X0.010 Y0.000"]
    assert lines[-4:] == ["N4 G01 X0.000 Y0.000", "N5 M05", "N6 M02", "%"]
