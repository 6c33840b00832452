"""em703 split (Fortran) against the harness's seed 004 reference split and the
document's own table."""
from __future__ import annotations

import subprocess

from hypothesis import example, given
from hypothesis import strategies as st

from seeds.seed004 import equal_summary, split_equal, split_move


def _split(exe, *args: str) -> list[tuple[int, int]]:
    proc = subprocess.run([exe, "split", *args], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    return [tuple(map(int, line.split())) for line in proc.stdout.splitlines()]


def test_the_documents_table(em703_exe):
    assert _split(em703_exe, "--max", "9999", "98132", "87647") == [
        (9813, 8765), (9813, 8764), (9814, 8765), (9813, 8765), (9813, 8764),
        (9813, 8765), (9813, 8765), (9814, 8765), (9813, 8764), (9813, 8765)]


@given(st.integers(-10**7, 10**7), st.integers(-10**7, 10**7), st.integers(1, 200))
@example(98132, 87647, 10)
def test_same_frames_as_the_harness(em703_exe, dx, dy, frames):
    # a limit that gives at most 200 frames, so the output stays small
    nmax = max(1, -(-max(abs(dx), abs(dy)) // frames))
    got = _split(em703_exe, "--max", str(nmax), str(dx), str(dy))
    assert got == split_move(dx, dy, nmax)


def test_usage_errors(em703_exe):
    for args in (["1"], ["1", "2", "3"], ["--max", "0", "1", "2"], ["x", "2"]):
        proc = subprocess.run([em703_exe, "split", *args], capture_output=True, text=True)
        assert proc.returncode == 2 and proc.stderr.startswith("em703 split: ")


def test_equal_frames_of_the_documents_move(em703_exe):
    """Seed 004's continued-fraction split of its own move: 11 equal frames
    and the last one, the same from em703 and from the harness."""
    proc = subprocess.run([em703_exe, "split", "--equal", "--max", "9999", "98132", "87647"],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert lines[:-1] == ["8779 7841"] * 11 + ["1563 1396"]
    assert lines[-1] == ("# 12 frames: 11 of 8779 7841, the last 1563 1396; largest distance "
                         "of a division point from the line 0.000084 pulses")


@given(st.integers(-10**7, 10**7), st.integers(-10**7, 10**7), st.integers(10, 60))
@example(98132, 87647, 10)
@example(1, 98132, 10)
@example(-803163, 23109, 6865)
@example(0, 0, 1)
def test_equal_frames_same_as_the_harness(em703_exe, dx, dy, frames):
    nmax = max(1, -(-max(abs(dx), abs(dy)) // frames))
    proc = subprocess.run([em703_exe, "split", "--equal", "--max", str(nmax), str(dx), str(dy)],
                          capture_output=True, text=True)
    try:
        run = split_equal(dx, dy, nmax)
    except ValueError:
        assert proc.returncode == 1 and proc.stdout == ""
        assert proc.stderr.startswith("em703 split: no equal frames of at most ")
        return
    assert proc.returncode == 0, proc.stderr
    want = "".join(f"{a} {b}\n" for a, b in run.frames) + equal_summary(run)
    assert proc.stdout == want
