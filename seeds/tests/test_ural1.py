"""Seed 002 end to end (``python -m seeds ural1``): the flange of Table 5
through the equidistant, chords, frames and speed codes to a 5121 tape, the
Ural-1's mask-and-shift translation, and both readings of Table 5."""
from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import pytest

from seeds import contour as cn
from seeds import seed002 as s2
from seeds import ural1 as u1

ROOT = Path(__file__).resolve().parents[2]
FLANGE = (ROOT / "examples" / "flange.crd").read_text()


def test_translation_by_masks_and_shifts_is_table_6() -> None:
    """Every four-digit number: the counter-and-mask translation gives the
    tetrads of Table 6's lookup."""
    for v in range(10000):
        assert u1.translate_5121(v, 4) == [s2.tetrad(int(c)) for c in f"{v:04d}"]


def test_explain_shows_each_tetrad() -> None:
    lines: list[str] = []
    u1.translate_5121(2050, 4, lines)
    assert lines[0] == "  number 2050: BCD word 0,0010 0000 0101 0000 ..."
    assert lines[1].startswith("    tetrad 1: mask 0,1111 0000 0000 0000 ... picks "
                               "0,0010 0000 0000 0000 ...; x = 0010 at count 2, y = 0101")
    assert lines[-1] == "    5121: 0101 0000 1000 0000 (Table 6: 2 0 5 0)"


def test_section_0_1_read_as_the_path() -> None:
    """Table 5 read as the cutter's path (the reading the text supports):
    section 0-1 is y = 8.2x (equation 12), 20.65 mm, t = l/s*60 = 20.65 s at
    60 mm/min; one frame of 250, 2050 pulses, speed code 6 (a 32 s cycle)."""
    run, = u1.ural1_runs(FLANGE, path_given=True)
    first = run.sections[0]
    assert first.kind == "line" and first.length == pytest.approx(math.hypot(2.5, 20.5))
    assert first.time_s(60) == pytest.approx(20.652, abs=1e-3)
    assert first.frames == (s2.Frame5121(250, 2050, 0, 6),)
    # section 1-2: the arc about O2, radius 18 (the text's r), in chords
    arc = run.sections[1]
    assert arc.kind == "arc" and arc.element.r == pytest.approx(18.0, abs=0.05)
    assert arc.chords == math.ceil(arc.element.sweep / cn.chord_step(arc.element.r, 0.02) - 1e-9)


def test_both_readings_of_table_5() -> None:
    """As the contour, the path is offset 10 mm (section 0-1 becomes
    y = 8.2x + 82.61) and runs 411.33 mm; as the path, 349.28 mm."""
    contour, = u1.ural1_runs(FLANGE)
    path, = u1.ural1_runs(FLANGE, path_given=True)
    assert sum(s.length for s in contour.sections) == pytest.approx(411.33, abs=0.01)
    assert sum(s.length for s in path.sections) == pytest.approx(349.28, abs=0.01)
    e = contour.sections[0].element
    slope = (e.y1 - e.y0) / (e.x1 - e.x0)
    assert slope == pytest.approx(8.2) and e.y0 - slope * e.x0 == pytest.approx(82.61, abs=0.01)
    assert 10 * math.sqrt(1 + 8.2 ** 2) == pytest.approx(82.61, abs=0.01)


def test_paper_step_angle_is_the_parts_radius() -> None:
    """The paper's R0 = 8 = 18 - 10: the part's radius under the path's arc
    of radius 18 (Δφ = 0.1415 rad with y = 0.02)."""
    assert cn.chord_step(18 - 10, 0.02) == pytest.approx(0.14145, abs=1e-5)


def test_tape_closes_and_reads_back() -> None:
    for given in (False, True):
        run, = u1.ural1_runs(FLANGE, path_given=given)
        frames = run.frames
        assert sum(f.dx for f in frames) == 0 and sum(f.dy for f in frames) == 0
        assert all(abs(f.dx) <= 9999 and abs(f.dy) <= 9999 for f in frames)
        assert s2.read_5121(run.tape) == frames
        # every frame within its cycle: the feed never above 60 mm/min
        for f in frames:
            assert math.hypot(f.dx, f.dy) / 100 / 60 * 60 <= u1.CYCLE_S[f.speed] + 1e-9
        n = len(frames)
        assert len(run.tape) == 2 * s2.LEADER_ROWS + run.frame_rows
        assert run.frame_rows == 15 * n + 2 * (n // 2)


def test_even_frames_shifted_two_rows() -> None:
    frames = [s2.Frame5121(1, 2), s2.Frame5121(3, 4), s2.Frame5121(5, 6)]
    plain = s2.punch_5121(frames)
    shifted = s2.punch_5121(frames, even_shift=True)
    lead = s2.LEADER_ROWS
    assert shifted[lead:lead + 15] == plain[lead:lead + 15]
    assert shifted[lead + 15:lead + 17] == bytes(2)
    assert shifted[lead + 17:lead + 32] == plain[lead + 15:lead + 30]
    assert s2.read_5121(shifted) == s2.read_5121(plain) == frames


def test_z_auxiliary_bits_like_x_and_y() -> None:
    """Rows 12-14 (Z) are built "in the same way": sign on the first row's
    track 5, the auxiliary command's two bits on the others."""
    f = s2.Frame5121(0, 0, -12, 3, 0, 0, 0b10)
    rows = s2.frame_rows_5121(f)
    assert rows[8:11] == [0 | 16, s2.tetrad(1) | 16, s2.tetrad(2)]
    assert s2.read_5121(s2.punch_5121([f])) == [f]


def test_speed_code_is_the_shortest_cycle_not_shorter_than_the_frame() -> None:
    """A frame as long as a cycle takes that cycle: at 60 mm/min, 1 mm is
    1 s (code 1), 32 mm is 32 s (code 6), a pulse more is code 7; a 3-4-5
    frame of 5 mm takes the 8 s cycle (code 4)."""
    assert u1.speed_code(100, 0, 60) == 1
    assert u1.speed_code(0, -3200, 60) == 6
    assert u1.speed_code(3201, 0, 60) == 7
    assert u1.speed_code(300, 400, 60) == 4
    assert u1.speed_code(25600, 0, 60) == 9
    with pytest.raises(ValueError, match="longer than the longest cycle"):
        u1.speed_code(25601, 0, 60)


def test_punching_time_and_tape_length() -> None:
    run, = u1.ural1_runs(FLANGE, path_given=True)
    text = u1.report(run, 60, 0.02)
    rows = run.frame_rows
    assert f"{rows} rows" in text and f"{rows / 300:.1f} min" in text
    assert f"{rows * 2.54 / 1000:.2f} m" in text


#: a 40 mm square with a slot 1 mm wide down to y = 20
NOTCH = "NOTCH\n" + "".join(f"{c:<10}{x:>10}{y:>10}\n" for c, x, y in [
    ("L", "0.00", "0.00"), ("+", "40.00", "0.00"), ("+", "40.00", "40.00"),
    ("+", "21.00", "40.00"), ("+", "21.00", "20.00"), ("+", "20.00", "20.00"),
    ("+", "20.00", "40.00"), ("+", "0.00", "40.00"), ("+", "0.00", "0.00")]) + "E\n"


def test_a_section_shorter_than_half_a_pulse_has_no_frame(tmp_path: Path) -> None:
    """A 0.999 mm cutter in the 1 mm slot leaves the slot's floor 0.001 mm
    long: both its ends round to one pulse, so it has no frame, and its
    report line no speed code ("-"); it was an IndexError's traceback."""
    run, = u1.ural1_runs(NOTCH, cutter_mm=0.999)
    assert [len(s.frames) for s in run.sections].count(0) == 1
    assert s2.read_5121(run.tape) == run.frames
    assert "      8  line       0.00       1       0      -           0.0        0" \
        in u1.report(run, 60, 0.02).splitlines()
    deck = tmp_path / "notch.crd"
    deck.write_text(NOTCH)
    proc = subprocess.run([sys.executable, "-m", "seeds", "ural1", "--cutter", "0.999",
                           str(deck)], cwd=ROOT, capture_output=True, text=True)
    assert proc.returncode == 0 and proc.stderr == ""
    assert proc.stdout.splitlines()[0] == ("NOTCH: 14 sections, feed 60 mm/min, chords "
                                           "within 0.02 mm")


def test_command(tmp_path: Path) -> None:
    tape = tmp_path / "flange.5121"
    cmd = [sys.executable, "-m", "seeds", "ural1", "examples/flange.crd", "--path", "-o", str(tape)]
    one = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    assert one.returncode == 0, one.stderr
    first = tape.read_bytes()
    two = subprocess.run(cmd + ["--explain"], cwd=ROOT, capture_output=True, text=True)
    assert two.returncode == 0 and tape.read_bytes() == first
    assert two.stdout.startswith(one.stdout)
    assert "the first frame through the Ural-1's translation into 5121:" in two.stdout
    assert one.stdout.splitlines()[2].split() == ["1", "line", "20.65", "1", "1", "6", "20.7", "32"]
    bad = tmp_path / "bad.crd"
    bad.write_text(FLANGE.replace("+             104.30     73.30", "+             104.30     75.30"))
    proc = subprocess.run([sys.executable, "-m", "seeds", "ural1", str(bad)], cwd=ROOT,
                          capture_output=True, text=True)
    assert proc.returncode == 1 and proc.stderr.startswith("ural1: ")
