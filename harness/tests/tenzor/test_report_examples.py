"""The report's five hand-coded tapes, punched by TENZOR from M-card decks.

Each deck in examples/report/ reproduces one example of the report (section
"Состав кадра"); the tape TENZOR punches must hold exactly the report's frames
(as corrected in docs/RECONSTRUCTION.md), then the frame that takes the tool back to the
start point raised. Bytes are compared with the harness's own encoding.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from harness import tape
from harness.report import EXAMPLES
from harness.tests.helpers import read_job

ROOT = Path(__file__).resolve().parents[3]
REPORT = ROOT / "examples" / "report"


def _return_frame(frames: list[tape.Frame]) -> list[tape.Frame]:
    """The frame that ends a tape raised at its start (docs/TAPE.md), found by
    summing the moves by hand: every report example ends with the tool down."""
    x = y = 0
    i = 0
    while i < len(frames):
        f = frames[i]
        if f.cyc:
            g = frames[i + 1]
            x += f.cyc * (f.dx + g.dx)
            y += f.cyc * (f.dy + g.dy)
            i += 2
        else:
            x += f.dx
            y += f.dy
            i += 1
    return [tape.Frame(dx=-x, dy=-y, k=20)]


@pytest.mark.parametrize("number,ref,lines", EXAMPLES, ids=[f"example{n}" for n, _, _ in EXAMPLES])
@pytest.mark.parametrize("code", ["8", "K"])
def test_example_tape_is_the_reports(run_tenzor, number, ref, lines, code):
    proc, out = run_tenzor(REPORT / f"example{number}.crd", "--code", code)
    assert proc.returncode == 0, proc.stderr.decode()
    want = [tape.parse_frame_text(line) for line in lines]
    want += _return_frame(want)
    data = (out / f"EXAMPLE{number}-cond.ptp").read_bytes()
    got = tape.decode(data, code=code)
    assert got.frames == want, f"{ref}: {tape.tape_text(got)}"
    assert data == tape.encode(want, code=code), "bytes differ from the harness's own encoding"
    text = (out / f"EXAMPLE{number}-cond.txt").read_text()
    assert text == tape.tape_text(want)
    # the pad tapes are empty but present: leader, GM GM, trailer
    for name in ("small", "large"):
        assert (out / f"EXAMPLE{number}-{name}.ptp").read_bytes() == tape.encode([], code=code)
    job = read_job(out / f"EXAMPLE{number}.job")
    assert job["code"] == code
    assert job["cond.frames"] == str(len(want))
    assert job["cond.rows"] == str(len(data))


def test_saw_polyline_folds_into_the_reports_cycle(run_tenzor):
    """An L card at 0,0 and sixteen + cards give Example 5's two frames."""
    proc, out = run_tenzor(REPORT / "saw-polyline.crd")
    assert proc.returncode == 0, proc.stderr.decode()
    got = tape.decode((out / "SAWLINE-cond.ptp").read_bytes()).frames
    saw = [tape.parse_frame_text(line) for line in EXAMPLES[4][2]]
    assert got == saw + [tape.Frame(dx=-3200, k=20)]


def test_code_override_changes_only_the_digits(run_tenzor):
    _, out8 = run_tenzor(REPORT / "example5.crd", "--code", "8")
    _, outk = run_tenzor(REPORT / "example5.crd", "--code", "K")
    plain = (out8 / "EXAMPLE5-cond.ptp").read_bytes()
    ctl = (outk / "EXAMPLE5-cond.ptp").read_bytes()
    assert len(plain) == len(ctl)
    swap = {0o03: 0o23, 0o05: 0o25, 0o06: 0o26, 0o11: 0o31}
    inside = False
    for a, b in zip(plain, ctl):
        if a == tape.GM:
            inside = not inside
        # a service code is never 3, 5, 6 or 9, so only digits are swapped
        assert b == (swap.get(a, a) if inside else a)
    assert plain != ctl
