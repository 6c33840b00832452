"""gerber2deck on small boards written here: what it makes, and the errors a
user can cause (one line, no traceback, no deck)."""
from __future__ import annotations

import subprocess
import sys

BOARD = """%FSLAX46Y46*%
%MOMM*%
%ADD10C,1.600000*%
%ADD11R,2.000000X1.000000*%
%ADD12C,0.300000*%
D10*
X1000000Y1000000D03*
X3540000Y1000000D03*
X6080000Y1000000D03*
D11*
X1000000Y5000000D03*
D12*
X1000000Y1000000D02*
X6080000Y5000000D01*
G36*
X8000000Y0D02*
X12000000Y0D01*
X12000000Y4000000D01*
X8000000Y4000000D01*
X8000000Y0D01*
G37*
M02*
"""


def g2d(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "seeds", "gerber2deck", *map(str, args)],
                          capture_output=True, text=True, timeout=120, cwd=cwd)


def test_a_small_board_becomes_rows_tracks_and_strokes(tmp_path, run_tenzor):
    gbr = tmp_path / "tiny.gbr"
    gbr.write_text(BOARD)
    proc = g2d(gbr, "-o", tmp_path / "tiny.crd")
    assert proc.returncode == 0, proc.stderr
    assert "Traceback" not in proc.stderr
    deck = (tmp_path / "tiny.crd").read_text()
    cards = deck.splitlines()
    # the three round pads are one row of N = 3 at 25.40 mm
    assert any(c.startswith("D") and c[46:50].strip() == "3" for c in cards), deck
    assert any(c.startswith("L") for c in cards)
    assert "regions (G36/G37) filled by strokes" in proc.stderr
    result, out = run_tenzor(tmp_path / "tiny.crd")
    assert result.returncode == 0, result.stderr
    assert (out / "TINY.job").exists()


def test_errors_are_one_line_and_leave_no_deck(tmp_path):
    missing = g2d(tmp_path / "none.gbr", "-o", tmp_path / "x.crd")
    assert missing.returncode == 2 and "none.gbr" in missing.stderr
    assert "Traceback" not in missing.stderr
    gbr = tmp_path / "tiny.gbr"
    gbr.write_text(BOARD)
    far = g2d(gbr, "--start", "1190,1190", "-o", tmp_path / "far.crd")
    assert far.returncode == 1 and "field" in far.stderr and "no deck" in far.stderr
    assert not (tmp_path / "far.crd").exists()
    thin = tmp_path / "thin.gbr"
    thin.write_text(BOARD.replace("%ADD12C,0.300000*%", "%ADD12C,0.005000*%"))
    proc = g2d(thin, "-o", tmp_path / "thin.crd")
    assert proc.returncode == 1 and "narrower than 0.01 mm" in proc.stderr
    assert not (tmp_path / "thin.crd").exists()
    junk = tmp_path / "junk.gbr"
    junk.write_bytes(b"\x00\x01 not a gerber file at all")
    proc = g2d(junk, "-o", tmp_path / "junk.crd")
    assert proc.returncode in (1, 2) and "Traceback" not in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1, proc.stderr
