"""`em703 gcode --dialect grbl` against GRBL 1.1's documented rules: a
checker written from GRBL 1.1's list of supported G and M codes and its
error codes (the ones a program of this kind can run into) reads every line
the way GRBL's parser does and names the error GRBL would answer with; the
program must give none, and must still trace the harness's path.

The GRBL 1.1 error codes checked (from its documentation):

* error:1  a line must start with a command letter ("%" is not one);
* error:11 a line of more than 80 characters (GRBL's line buffer);
* error:20 an unsupported G or M code (M06 among them: no tool changer);
* error:22 a feed motion (G1, G2, G3) before any feed rate is set;
* error:25 a G-code word repeated in a block (two of one modal group);
* error:33 an arc whose end is off its circle: the radii from the centre to
  the start and to the end differ by more than 0.005 mm and by more than
  0.5 mm or 0.1 % of the radius;
* error:35 a G2/G3 arc in I, J form without an offset word.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from harness.tape import decode, encode

from harness.tests.em703.test_em703_gcode import (_normalise, assert_same_path, expected_events,
                                                  job_events, read_gcode)
from harness.tests.helpers import run
from harness.tests.strategies import frame_lists

#: GRBL 1.1's G and M codes (its wiki, "Supported G-codes"), as numbers.
GRBL_G = {0, 1, 2, 3, 4, 10, 17, 18, 19, 20, 21, 28, 30, 38.2, 38.3, 38.4, 38.5, 40, 43.1, 49,
          53, 54, 55, 56, 57, 58, 59, 61, 80, 90, 91, 91.1, 92, 92.1, 93, 94}
GRBL_M = {0, 1, 2, 30, 3, 4, 5, 7, 8, 9, 56}
#: GRBL's modal groups of the codes a program of em703 uses.
GROUP = {0: "motion", 1: "motion", 2: "motion", 3: "motion", 17: "plane", 18: "plane",
         19: "plane", 20: "units", 21: "units", 90: "distance", 91: "distance",
         93: "feed", 94: "feed"}
WORD = re.compile(r"([A-Z])([-+]?(?:\d+\.?\d*|\.\d+))")


def grbl_errors(program: str) -> list[str]:
    """Every line GRBL 1.1 would answer with an error, as "line N: error:E ..."."""
    errors: list[str] = []
    x = y = 0.0
    feed = None
    motion = 0
    for n, raw in enumerate(program.splitlines(), 1):
        if len(raw) > 80:
            errors.append(f"line {n}: error:11 {len(raw)} characters")
        line = re.sub(r"\([^)]*\)", "", raw).replace(" ", "").upper()
        if not line:
            continue
        if not line[0].isalpha():
            errors.append(f"line {n}: error:1 {raw!r}")
            continue
        words = WORD.findall(line)
        if "".join(a + b for a, b in words) != line:
            errors.append(f"line {n}: error:1 {raw!r}")
            continue
        groups: set[str] = set()
        values: dict[str, float] = {}
        for letter, number in words:
            v = float(number)
            if letter == "G":
                if v not in GRBL_G:
                    errors.append(f"line {n}: error:20 G{number}")
                group = GROUP.get(v, f"G{v}")
                if group in groups:
                    errors.append(f"line {n}: error:25 two G words of group {group}")
                groups.add(group)
                if group == "motion":
                    motion = int(v)
            elif letter == "M":
                if v not in GRBL_M:
                    errors.append(f"line {n}: error:20 M{number}")
            elif letter == "T":
                errors.append(f"line {n}: error:20 T{number} (no tool changer)")
            else:
                values[letter] = v
        if "F" in values:
            feed = values["F"]
        if ("X" in values or "Y" in values) and motion in (1, 2, 3) and feed is None:
            errors.append(f"line {n}: error:22 feed motion without a feed rate")
        if "X" in values or "Y" in values:
            nx, ny = values.get("X", x), values.get("Y", y)
            if motion in (2, 3):
                if "I" not in values and "J" not in values:
                    errors.append(f"line {n}: error:35 arc without I, J")
                cx, cy = x + values.get("I", 0.0), y + values.get("J", 0.0)
                r0 = math.hypot(x - cx, y - cy)
                r1 = math.hypot(nx - cx, ny - cy)
                delta = abs(r1 - r0)
                if delta > 0.005 and (delta > 0.5 or delta > 0.001 * r0):
                    errors.append(f"line {n}: error:33 arc end {delta:.4f} mm off its circle")
            x, y = nx, ny
    return errors


def test_the_checker_finds_what_grbl_refuses() -> None:
    """The linuxcnc program of a job is refused where GRBL refuses it."""
    assert grbl_errors("%\nN1 G21 G90\n%\n")[0].startswith("line 1: error:1")
    assert "error:20" in grbl_errors("N1 T1 M06\n")[0]
    assert "error:22" in grbl_errors("N1 G21\nN2 G01 X1.000 Y0.000\n")[0]
    assert "error:33" in grbl_errors("N1 F1500\nN2 G02 X0.000 Y-0.110 I0.050 J0.000\n")[0]
    assert grbl_errors("N1 F1500\nN2 G02 X0.000 Y-0.100 I0.050 J-0.050\n") == []
    assert "error:25" in grbl_errors("N1 G01 G00 X1\n")[0]
    assert "error:11" in grbl_errors("(" + "x" * 90 + ")\n")[0]


def _grbl_events(text: str):
    """The moves of a GRBL program, read by the harness's reader (which
    wants the % lines GRBL's dialect leaves out)."""
    return read_gcode("%\n" + text + "%\n")


def _same_path_grbl(got, want, what: str) -> None:
    """As assert_same_path, but an arc's centre may have moved along the
    bisector of its chord: its ends must be the same, and its middle within
    0.01 mm of the harness arc's middle."""
    assert [e[0] for e in got] == [e[0] for e in want], what
    x = y = 0.0
    for g, w in zip(got, want):
        if g[0] != "arc":
            assert_same_path([g], [w], what)
        else:
            assert abs(g[1] - w[1]) < 1e-9 and abs(g[2] - w[2]) < 1e-9 and g[5] == w[5], \
                (what, g, w)
            gm, wm = _middle((x, y), g), _middle((x, y), w)
            assert math.dist(gm, wm) <= 0.01, (what, g, w, gm, wm)
        if len(g) > 1:
            x, y = g[1], g[2]


def _middle(start: tuple[float, float], arc) -> tuple[float, float]:
    """The middle of an arc event from start: ("arc", x, y, cx, cy, clockwise)."""
    _, ex, ey, cx, cy, clockwise = arc
    a0 = math.atan2(start[1] - cy, start[0] - cx)
    a1 = math.atan2(ey - cy, ex - cx)
    turn = ((a0 - a1) if clockwise else (a1 - a0)) % (2 * math.pi) or 2 * math.pi
    mid = a0 - turn / 2 if clockwise else a0 + turn / 2
    r = (math.hypot(start[0] - cx, start[1] - cy) + math.hypot(ex - cx, ey - cy)) / 2
    return cx + r * math.cos(mid), cy + r * math.sin(mid)


def test_example_jobs_and_tapes_are_grbl_programs(em703_exe, example_jobs, example_tapes,
                                                  tmp_path) -> None:
    for job in example_jobs:
        out = tmp_path / "job.nc"
        got = run(em703_exe, "gcode", "--dialect", "grbl", job, "-o", out, check=0)
        text = out.read_text()
        assert grbl_errors(text) == [], job
        assert "%" not in text and "M06" not in text
        assert [ln.split(" ", 1)[1] for ln in text.splitlines() if ln.endswith(" M0")] == \
            ["M0"] * 3, "a pause before each tape"
        want, _ = job_events(job)
        _same_path_grbl(_grbl_events(text), want, str(job))
        # without --dialect the program is LinuxCNC's, which GRBL refuses at its first line
        linuxcnc = run(em703_exe, "gcode", job, check=0).stdout.decode()
        assert grbl_errors(linuxcnc)[0].startswith("line 1: error:1")
        assert run(em703_exe, "gcode", "--dialect", "linuxcnc", job, check=0).stdout.decode() \
            == linuxcnc
        assert got.returncode == run(em703_exe, "gcode", job, check=0).returncode
    for tape in example_tapes:
        for extra in ([], ["--z"], ["--chords", "0.01"]):
            text = run(em703_exe, "gcode", "--dialect", "grbl", *extra, tape,
                       check=0).stdout.decode()
            assert grbl_errors(text) == [], (tape, extra)


@settings(max_examples=30, deadline=None)
@given(frames=frame_lists(), use_z=st.booleans())
def test_random_tapes_are_grbl_programs(em703_exe, tmp_path_factory, frames, use_z) -> None:
    """Random tapes: arcs that end up to one unit off their circle (the tape
    allows it) come out within GRBL's check, from the same start to the same
    end, and the rest of the path is the harness's."""
    path = tmp_path_factory.mktemp("grbl") / "t.ptp"
    path.write_bytes(encode(frames))
    args = ["gcode", "--dialect", "grbl", path] + (["--z"] if use_z else [])
    text = run(em703_exe, *args, check=0).stdout.decode()
    assert grbl_errors(text) == [], text
    _same_path_grbl(_grbl_events(text), _normalise(expected_events(frames)), str(frames))


@pytest.mark.parametrize("frame, linuxcnc_arc, grbl_arc", [
    # X50 DX-50 DY-49 K13: the end is 0.01 mm inside the 0.5 mm circle
    (dict(x=50, dx=-50, dy=-49, k=13), "G02 X-0.500 Y-0.490 I-0.500 J0.000",
     "G02 X-0.500 Y-0.490"),
    # X300 DX-88 DY213 K11: the end (2.12, 2.13) mm from the centre lies
    # 0.0052 mm outside the 3 mm circle, less than a unit but more than both
    # of GRBL's limits (0.005 mm, and 0.1 % of the radius, 0.003 mm); the
    # centre on the bisector is rounded to 0.001 mm
    (dict(x=300, dx=-88, dy=213, k=11), "N4 G03 X-0.880 Y2.130 I-3.000 J0.000 F1500\n",
     "N4 G03 X-0.880 Y2.130 I-3.003 J0.006 F1500\n"),
])
def test_an_arc_off_its_circle_gets_a_centre_grbl_takes(em703_exe, tmp_path, frame,
                                                        linuxcnc_arc, grbl_arc) -> None:
    """An arc whose end is off its circle by less than a unit: LinuxCNC takes
    the tape's centre, GRBL would refuse it (error:33), so the GRBL program
    moves the centre onto the chord's bisector."""
    from harness.tape import Frame
    path = tmp_path / "off.ptp"
    path.write_bytes(encode([Frame(**frame), Frame(k=20)]))
    linuxcnc = run(em703_exe, "gcode", path, check=0).stdout.decode()
    assert linuxcnc_arc in linuxcnc
    assert "error:33" in " ".join(grbl_errors(linuxcnc.replace("%\n", "")))
    grbl = run(em703_exe, "gcode", "--dialect", "grbl", path, check=0).stdout.decode()
    assert grbl_errors(grbl) == []
    assert grbl_arc in grbl
