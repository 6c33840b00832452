"""em703 split (Fortran) against the harness's seed 004 reference split and the
document's own table."""
from __future__ import annotations

import subprocess

from hypothesis import example, given
from hypothesis import strategies as st

from seeds.seed004 import split_move


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
