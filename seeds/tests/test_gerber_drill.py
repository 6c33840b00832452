"""A board's holes through the 1977 chain: `gerber2deck --drill` -> `tenzor`
-> `em703 drill` on the NAME-DRILL job gives back every round hole of the
board's own drill file once, its centre within 0.01 mm, and nothing else.
Its diameter comes back within 0.015 mm: the deck holds it to 0.01 mm
(0.005 mm of rounding), and TENZOR's circles have radii of whole units, so a
hole whose diameter less the tool is an odd number of units is drawn, and
found again, one unit (0.01 mm) smaller; the drill file em703 writes and the
board's own are both read by gerbonara, independently of the project's
readers. The tour's drilling travel against the file's own order is
reported by seeds/tapereport.py (docs/GERBER.md)."""

from __future__ import annotations

import math
import re
import subprocess
import warnings
from pathlib import Path

import pytest

from seeds.tests.test_gerber_roundtrip import BOARDS, board_run, realboards


def holes_of(path: Path) -> list[tuple[float, float, float]]:
    """(x, y, diameter) in mm of every round hit of an Excellon file, by gerbonara."""
    from gerbonara import ExcellonFile
    from gerbonara.graphic_objects import Flash
    from gerbonara.utils import MM
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drill = ExcellonFile.open(path)
    out = []
    for o in drill.objects:
        if isinstance(o, Flash):
            o = o.converted(MM)
            out.append((float(o.x), float(o.y), float(o.aperture.equivalent_width(MM))))
    return out


@pytest.mark.parametrize("board", BOARDS, ids=[b[0] for b in BOARDS])
def test_em703_drill_gives_back_the_boards_holes(board, tenzor_exe, em703_exe, tmp_path,
                                                 tmp_path_factory):
    folder = realboards() / board[0]
    run = board_run(board, tenzor_exe, tmp_path_factory)
    m = re.search(r"start point at board (\S+), (\S+) mm", run.said)
    assert m, run.said
    ox, oy = (float(v.rstrip(",;")) for v in m.groups())
    job = next(run.tapes.glob("*-DRILL.job"))
    drl = tmp_path / "tour.drl"
    em = subprocess.run([str(em703_exe), "drill", str(job), "-o", str(drl)], capture_output=True,
                        timeout=300)
    assert em.returncode == 0, em.stderr.decode("latin-1")
    got = [(x + ox, y + oy, d) for x, y, d in holes_of(drl)]
    want = holes_of(folder / board[2])
    assert len(got) == len(want), (len(got), len(want))
    # every hole of the board matched to one hit within 0.01 mm
    cells: dict[tuple[int, int], list[int]] = {}
    for k, (x, y, _) in enumerate(got):
        cells.setdefault((math.floor(x / 0.05), math.floor(y / 0.05)), []).append(k)
    used = set()
    for wx, wy, wd in want:
        cx, cy = math.floor(wx / 0.05), math.floor(wy / 0.05)
        near = [k for i in (-1, 0, 1) for j in (-1, 0, 1) for k in cells.get((cx + i, cy + j), [])
                if k not in used and math.hypot(got[k][0] - wx, got[k][1] - wy) <= 0.01 + 1e-9]
        assert near, f"no hit within 0.01 mm of the hole at ({wx:.3f}, {wy:.3f}) mm"
        k = min(near, key=lambda k: (math.hypot(got[k][0] - wx, got[k][1] - wy), k))
        used.add(k)
        assert abs(got[k][2] - wd) <= 0.015 + 1e-9, (got[k], (wx, wy, wd))
    assert len(used) == len(got)
