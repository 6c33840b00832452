"""gerber2deck on small boards written here: what it makes, and the errors a
user can cause (one line, no traceback, no deck)."""
from __future__ import annotations

import subprocess
import sys

import pytest

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


OBROUNDS = """%FSLAX46Y46*%
%MOMM*%
%ADD13O,3.000000X1.000000*%
%ADD14O,1.000000X3.000000*%
%ADD10C,2.000000*%
D13*
X20000000Y20000000D03*
D14*
X30000000Y20000000D03*
D10*
X40000000Y20000000D03*
M02*
"""


def test_obrounds_are_conductors_along_their_long_side(tmp_path):
    """An obround 3 x 1 mm is a conductor 1 mm wide from end to end along x,
    one 1 x 3 mm along y; the start point is the copper's lower-left corner
    (18.50, 18.50 mm); the 2 mm round pad a D card."""
    gbr = tmp_path / "ob.gbr"
    gbr.write_text(OBROUNDS)
    proc = g2d(gbr)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines()[4:11] == [
        "P              10.00     10.00    1.00    1.00    1.00    2.00",
        "D              21.50      1.50    2.00",
        "L               0.50      1.50    1.00",
        "+               2.50      1.50",
        "L              11.50      0.50    1.00",
        "+              11.50      2.50",
        "E"]
    assert "2 obround pads drawn as short conductors of their width" in proc.stderr


def test_a_pad_of_dmax_is_drawn_with_the_small_pad_tool(tmp_path):
    """A pad of exactly DMAX (2.00 mm) is the small-pad tape's, so W1 must
    fit it: --tools 2.5,0.5,0.3 is refused for it, though W2 would fit."""
    gbr = tmp_path / "ob.gbr"
    gbr.write_text(OBROUNDS)
    proc = g2d(gbr, "--tools", "2.5,0.5,0.3", "-o", tmp_path / "ob.crd")
    assert proc.returncode == 1
    assert proc.stderr.splitlines()[-1] == (
        f"gerber2deck: {gbr}: a pad of 2.00 mm at board 40.00, 20.00 mm is smaller than its "
        f"tool (2.50 mm): give smaller tools with --tools; no deck written")
    assert not (tmp_path / "ob.crd").exists()
    assert g2d(gbr, "--tools", "2,2.5,0.3").returncode == 0


def test_a_board_must_fit_the_field_on_each_axis(tmp_path):
    """A board 100 mm wide and 10 mm high placed at 1150, 10 mm does not fit
    the field (1250 mm on x); placed at 10, 1150 it does."""
    gbr = tmp_path / "long.gbr"
    gbr.write_text("%FSLAX46Y46*%\n%MOMM*%\n%ADD10C,0.2*%\nD10*\nG36*\nX0Y0D02*\n"
                   "X100000000Y0D01*\nX100000000Y10000000D01*\nX0Y10000000D01*\nX0Y0D01*\n"
                   "G37*\nM02*\n")
    far = g2d(gbr, "--start", "1150,10", "-o", tmp_path / "far.crd")
    assert far.returncode == 1 and not (tmp_path / "far.crd").exists()
    assert (f"{gbr}: the board is 100.00 x 10.00 mm; placed at 1150, 10 mm it does not fit "
            f"the 1200 x 1200 mm field of the coordinatograph; no deck written") in far.stderr
    assert g2d(gbr, "--start", "10,1150", "-o", tmp_path / "up.crd").returncode == 0


def test_drill_tool_and_rows_of_two() -> None:
    """The drill package's tool is the smallest hole rounded down (0.807 mm:
    0.80, never larger than a hole); two equal pads at a step are one row of
    N = 2."""
    from seeds import gerber
    holes = [gerber.Hole(1.0, 1.0, 0.807), gerber.Hole(3.0, 1.0, 1.0)]
    assert gerber.drill_tool(holes) == 80
    assert gerber.drill_cards(holes, (0.0, 0.0)) == (
        ["D               1.00      1.00    0.81", "D               3.00      1.00    1.00"], 80)
    pads = [gerber.Pad(0, 0, 160, None), gerber.Pad(254, 0, 160, None),
            gerber.Pad(0, 500, 160, None)]
    assert gerber.pad_cards(pads) == [
        "D               0.00      0.00    1.60           2      2.54      0.00",
        "D               0.00      5.00    1.60"]


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


# ---- what the batch fuzz found (seeds/tests/test_fuzz_seeds_batch.py) -------
HEAD = "%FSLAX46Y46*%\n%MOMM*%\n"


def refused(tmp_path, gerber: str, drill: str | None = None) -> subprocess.CompletedProcess:
    """gerber2deck on the files given; it must say why in one line and
    leave no deck."""
    (tmp_path / "c.gbr").write_text(gerber)
    args = [tmp_path / "c.gbr", "-o", tmp_path / "c.crd"]
    if drill is not None:
        (tmp_path / "d.drl").write_text(drill)
        args += ["--drill", tmp_path / "d.drl"]
    proc = g2d(*args)
    assert proc.returncode in (1, 2), proc.stderr
    assert "Traceback" not in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1, proc.stderr
    assert not (tmp_path / "c.crd").exists()
    return proc


def test_a_board_wider_than_the_field_is_refused_before_it_is_filled(tmp_path):
    # a region 2 km square: hatched band by band before the board's size was
    # checked, it took hours and all the memory
    proc = refused(tmp_path, HEAD + "%ADD10C,0.2*%\nD10*\nG36*\nX0Y0D02*\nX2000000000000Y0D01*\n"
                   "X2000000000000Y2000000000000D01*\nX0Y2000000000000D01*\nX0Y0D01*\n"
                   "G37*\nM02*\n")
    assert proc.returncode == 1
    assert "the copper spans 2000000.00 x 2000000.00 mm, more than the 1200 x 1200 mm field" \
        in proc.stderr


def test_a_flash_with_no_aperture_is_refused(tmp_path):
    proc = refused(tmp_path, HEAD + "%ADD10C,1*%\nX1000000Y2000000D03*\nM02*\n")
    assert proc.returncode == 1
    assert "a flash (D03) at 1.000, 2.000 mm with no aperture selected before it" in proc.stderr


@pytest.mark.parametrize("aperture, words", [
    ("%ADD10C,nan*%", "the flash of D10 at 1.000, 2.000 mm: a coordinate or an aperture's "
                      "size is not a finite number"),
    # found by the batch with another seed: shapely's arithmetic overflowed
    # (GEOSException "Scale factor must be non-zero")
    ("%ADD10C,1e308*%", "the flash of D10 at 1.000, 2.000 mm: a coordinate or an aperture's "
                        "size is not a finite number of at most 10000000 mm (10 km)"),
    ("%AMOC8*5,1,8,0,0,1.08239X$1,22.5*%\n%ADD10OC8,*%",
     "the flash of D10 at 1.000, 2.000 mm cannot be drawn (Cannot fully resolve expression"),
])
def test_an_aperture_that_cannot_be_drawn_is_named(tmp_path, aperture, words):
    proc = refused(tmp_path, HEAD + aperture + "\nD10*\nX1000000Y2000000D03*\nM02*\n")
    assert proc.returncode == 1
    assert words in proc.stderr


def test_a_layer_of_clear_polarity_only_has_no_copper(tmp_path):
    proc = refused(tmp_path, HEAD + "%ADD10C,1*%\n%LPC*%\nD10*\nX0Y0D03*\nX3000000Y0D03*\nM02*\n")
    assert proc.returncode == 1 and "no dark copper in it" in proc.stderr


@pytest.mark.parametrize("body, words", [
    ("X1.0Y1.0\nX2.0Y2.0\nT1\nX5.0Y5.0\nM30\n",
     'd.drl:5 "X1.0Y1.0": a hit before any tool is selected (a T line with the tool\'s number); '
     'gerbonara leaves such hits out (2 in this file)'),
    ("T1\nX1.0Y1.0\nM30\nX7.0Y7.0\n",
     'd.drl:8 "X7.0Y7.0": a hit after the end of the program (M30); gerbonara leaves such '
     'hits out (1 in this file)'),
])
def test_a_drill_hit_gerbonara_would_leave_out_is_named(tmp_path, body, words):
    # gerbonara reads past such a hit with a warning only: the hole was
    # missing from the deck without a word
    proc = refused(tmp_path, BOARD, "M48\nMETRIC\nT1C0.8\n%\n" + body)
    assert proc.returncode == 2
    assert words in proc.stderr


def test_a_drill_file_without_a_unit_is_named(tmp_path):
    proc = refused(tmp_path, BOARD, "M48\nT1C0.8\n%\nT1\nX1.0Y1.0\nM30\n")
    assert proc.returncode == 2
    assert "d.drl: no unit: its header says neither METRIC nor INCH" in proc.stderr


def test_objects_that_draw_nothing_are_left_out_and_said(tmp_path, run_tenzor):
    # a rectangle of no width flashed, and the same board's copper around it
    gbr = tmp_path / "nothing.gbr"
    gbr.write_text(BOARD.replace("%ADD12C,0.300000*%", "%ADD12C,0.300000*%\n%ADD13R,0X3.6*%")
                   .replace("M02*", "D13*\nX3000000Y3000000D03*\nM02*"))
    proc = g2d(gbr, "-o", tmp_path / "nothing.crd")
    assert proc.returncode == 0, proc.stderr
    assert ("1 objects that draw nothing (an aperture of no size, a region of no area) left out"
            in proc.stderr)
    result, _ = run_tenzor(tmp_path / "nothing.crd")
    assert result.returncode == 0, result.stderr


def test_copper_wider_than_the_widest_tool_takes_a_20_mm_tool(tmp_path, run_tenzor):
    # tracks 30 mm wide: TENZOR's tools are 0.01 to 20 mm, so W3 is 20 mm
    gbr = tmp_path / "wide.gbr"
    gbr.write_text(HEAD + "%ADD10C,30*%\nD10*\nX0Y0D02*\nX200000000Y0D01*\nM02*\n")
    proc = g2d(gbr, "-o", tmp_path / "wide.crd")
    assert proc.returncode == 0, proc.stderr
    assert "tools W1 20.00, W2 20.00, W3 20.00 mm" in proc.stderr
    result, _ = run_tenzor(tmp_path / "wide.crd")
    assert result.returncode == 0, result.stderr


@pytest.mark.parametrize("tools", ["0.25,0.25,0.255", "0.25,0.25,x", "0.005,0.25,0.25",
                                   "0.25,0.25,20.01", "0.25,0.25"])
def test_tools_off_the_cards_grid_or_range_are_a_usage_error(tmp_path, tools):
    # 0.255 mm was rounded to 0.26 without a word
    (tmp_path / "c.gbr").write_text(BOARD)
    proc = g2d(tmp_path / "c.gbr", "--tools", tools, "-o", tmp_path / "c.crd")
    assert proc.returncode == 2 and "--tools" in proc.stderr, proc.stderr
    assert "0.01 to 20.00 mm" in proc.stderr or "3 finite numbers of mm" in proc.stderr
    assert not (tmp_path / "c.crd").exists()


def test_a_package_is_never_named_a_bare_c_or_e(tmp_path, run_tenzor):
    """A bare C or E card ends a package: --name C is refused, and a file
    named e.gbr makes the package E_, which TENZOR punches."""
    gbr = tmp_path / "e.gbr"
    gbr.write_text(BOARD)
    proc = g2d(gbr, "--name", "C", "-o", tmp_path / "c.crd")
    assert proc.returncode == 2 and "not a bare C or E (they end a package)" in proc.stderr
    proc = g2d(gbr, "-o", tmp_path / "e.crd")
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "e.crd").read_text().splitlines()[3] == "E_"
    tapes, out = run_tenzor(tmp_path / "e.crd")
    assert tapes.returncode == 0, tapes.stderr.decode()
    assert (out / "E_-cond.ptp").exists()


def test_g85_slots_are_left_out_and_named_by_their_line(tmp_path):
    # KiCad writes an oval hole as a G85 slot; gerbonara refused the whole
    # file at that line ("Unknown excellon statement"), exit 2
    (tmp_path / "c.gbr").write_text(BOARD)
    (tmp_path / "d.drl").write_text("M48\nMETRIC\nT1C0.8\n%\nT1\nX10.0Y10.0\n"
                                    "X5.0Y0.0G85X8.0Y0.0\nX35.4Y10.0\nM30\n")
    proc = g2d(tmp_path / "c.gbr", "--drill", tmp_path / "d.drl", "-o", tmp_path / "c.crd")
    assert proc.returncode == 0, proc.stderr
    assert "d.drl:7: a slot (G85, a routed hole) left out" in proc.stderr
    assert "d.drl: 2 holes -> package C_-DRILL" in proc.stderr, proc.stderr
    drill = (tmp_path / "c.crd").read_text().split("C_-DRILL", 1)[1]
    assert sum(c.startswith("D") for c in drill.splitlines()) == 2, drill


@pytest.mark.parametrize("after, hole", [
    ("Y2.0", (8.0, 2.0)),                 # X left out: the slot's end X
    ("X3.0", (3.0, 0.0)),                 # Y left out: the slot's end Y
    ("X3.0Y4.0", (3.0, 4.0)),
    ("T2\nY2.0", (8.0, 2.0)),             # a tool change between
])
def test_a_hit_after_a_slot_leaving_out_a_coordinate_takes_the_slots_end(tmp_path, after,
                                                                          hole):
    """Excellon's coordinates are modal and a slot leaves the drill at its
    end: the hit after it that leaves out X or Y is there, not at the hit
    before the slot. Before, the slot's line was only blanked, and such a
    hole moved to the last hit's coordinate without a word."""
    from seeds.gerber import read_drill
    drl = tmp_path / "d.drl"
    drl.write_text("M48\nMETRIC\nT1C0.8\nT2C0.8\n%\nT1\nX10.0Y10.0\n"
                   f"X5.0Y0.0G85X8.0Y0.0\n{after}\nY6.0\nM30\n")
    holes, slots, g85 = read_drill(drl)
    assert (slots, g85) == (0, [8])
    assert [(h.x, h.y) for h in holes] == [(10.0, 10.0), hole, (hole[0], 6.0)]


def test_a_slot_whose_end_leaves_out_a_coordinate_ends_on_its_start_line(tmp_path):
    """X5Y1G85X8: the slot runs along Y = 1 and the hit after it at Y2 is at X = 8."""
    from seeds.gerber import read_drill
    drl = tmp_path / "d.drl"
    drl.write_text("M48\nMETRIC\nT1C0.8\n%\nT1\nX10.0Y10.0\nX5.0Y1.0G85X8.0\nY2.0\n"
                   "X9.0\nM30\n")
    holes, _, _ = read_drill(drl)
    assert [(h.x, h.y) for h in holes] == [(10.0, 10.0), (8.0, 2.0), (9.0, 2.0)]


def test_a_drill_file_of_slots_only_gives_no_drill_package(tmp_path):
    (tmp_path / "c.gbr").write_text(BOARD)
    (tmp_path / "d.drl").write_text("M48\nMETRIC\nT1C0.8\n%\nT1\nX5.0Y0.0G85X8.0Y0.0\nM30\n")
    proc = g2d(tmp_path / "c.gbr", "--drill", tmp_path / "d.drl", "-o", tmp_path / "c.crd")
    assert proc.returncode == 0, proc.stderr
    assert "d.drl:6: a slot (G85, a routed hole) left out" in proc.stderr
    assert "no round holes, only slots: no package C_-DRILL" in proc.stderr
    assert "-DRILL" not in (tmp_path / "c.crd").read_text()


def test_a_gerber_file_cut_short_is_said(tmp_path):
    # a file without its M02 was converted as far as it went, without a word
    gbr = tmp_path / "cut.gbr"
    gbr.write_text(BOARD[:BOARD.index("G36*")])
    proc = g2d(gbr, "-o", tmp_path / "cut.crd")
    assert proc.returncode == 0, proc.stderr
    assert "cut.gbr: the file ends without M02 (end of file): it may be cut short" \
        in proc.stderr
    whole = tmp_path / "whole.gbr"
    whole.write_text(BOARD)
    proc = g2d(whole, "-o", tmp_path / "whole.crd")
    assert proc.returncode == 0 and "M02" not in proc.stderr, proc.stderr


def test_a_file_with_no_copper_is_exit_2_as_the_page_says(tmp_path):
    from pathlib import Path
    page = " ".join((Path(__file__).resolve().parents[2] / "docs" / "GERBER.md")
                    .read_text().split())
    assert "Exit status 2: a file gerbonara cannot read (its error in one line), a copper " \
           "file with no copper in it" in page
    proc = refused(tmp_path, HEAD + "M02*\n")
    assert proc.returncode == 2 and "c.gbr: no copper in it" in proc.stderr
