"""Seed 001's own output, dxf2dmc: a DXF drawing to a Galil DMC program.

The program is read back by a small reader of the Galil subset dxf2dmc
writes (written here, from the command reference, not from dxf2dmc): it
runs the program's vector sequences (VP, CR, VE, BGS, AV, AMS), absolute
moves (PA, BG, AM) and outputs (SB, CB, WT), and gives what the tool drew
while its output bit was set, piece by piece, and the other outputs in the
order they were switched.  The pieces must be the drawing's entities, in
the labels' order, within the tolerance of ezdxf's own evaluation of them.
"""
from __future__ import annotations

import math
import re
from pathlib import Path

import ezdxf
import numpy as np
import pytest
import shapely

from seeds import seed001, seed001_dmc
from seeds.__main__ import main

TOL = 0.005
CPM = 1000.0


# ---------------------------------------------------------------------------
# A reader of the Galil subset.
# ---------------------------------------------------------------------------
class Trace:
    """Run a program: ``pieces`` (what the tool drew, mm, one polyline for
    each time the tool bit was set), ``events`` (("tool", on), ("out", bit,
    on), ("wait", ms)) in program order."""

    CMD = re.compile(r"^(#[A-Z]{1,7}|NO( .*)?|BGS|AMS|[A-Z]{2}( [-0-9.,A-Z]+)?)$")

    def __init__(self, text: str, cpm: float = CPM, tool: int = 1) -> None:
        self.cpm, self.tool = cpm, tool
        self.pos = (0.0, 0.0)
        self.on: bool | None = None          # unknown until the program says
        self.pieces: list[list[tuple[float, float]]] = []
        self.events: list[tuple] = []
        self.collect: list | None = None
        self.motion: list[tuple[float, float, float]] | None = None   # x, y, distance
        self.done = 0.0
        self.sequences: list[int] = []
        assert text.endswith("\n") and "\r" not in text
        lines = text[:-1].split("\n")
        assert lines[0] == "#DXF" and lines[-1] == "EN"
        pending_pa = None
        for line in lines:
            assert len(line) <= 80 and self.CMD.match(line), line
            op, _, arg = line.partition(" ")
            nums = [float(v) for v in arg.split(",")] if arg and op not in ("NO", "BG", "AM", "VM") else []
            if op in ("#DXF", "NO", "EN"):
                continue
            if op == "DP":
                assert nums == [0, 0] and self.motion is None
                self.pos = (0.0, 0.0)
            elif op in ("SB", "CB"):
                self._switch(int(nums[0]), op == "SB")
            elif op == "WT":
                self.events.append(("wait", int(nums[0])))
            elif op in ("VS", "SP"):
                assert all(v > 0 and v == int(v) for v in nums)
            elif op == "PA":
                assert self.motion is None and all(v == int(v) for v in nums)
                pending_pa = (nums[0], nums[1])
            elif op == "BG":
                assert arg == "XY" and pending_pa is not None
                assert not self.on, "an absolute move with the tool on"
                self.pos, pending_pa = pending_pa, None
            elif op == "AM":
                assert arg == "XY"
            elif op == "VM":
                assert arg == "XY" and self.collect is None and self.motion is None
                self.collect, self.origin = [], self.pos
            elif op == "VP":
                assert all(v == int(v) for v in nums)
                self.collect.append(("VP", self.origin[0] + nums[0], self.origin[1] + nums[1]))
            elif op == "CR":
                r, t, d = nums
                assert r == int(r) and r > 0 and (t * 256) % 1 == 0 and (d * 256) % 1 == 0
                self.collect.append(("CR", r, t, d))
            elif op == "VE":
                assert len(self.collect) <= 511, "more segments than a sequence holds"
                self.sequences.append(len(self.collect))
                self.ready, self.collect = self.collect, None
            elif op == "BGS":
                self._begin(self.ready)
            elif op == "AV":
                assert self.motion is not None and nums[0] == int(nums[0])
                self._advance(nums[0])
            elif op == "AMS":
                self._advance(math.inf)
                self.motion = None
            else:
                raise AssertionError(f"not in the subset: {line}")
        assert self.motion is None and not self.on
        self.pieces_mm = [[(x / cpm, y / cpm) for x, y in p] for p in self.pieces]

    def _switch(self, bit: int, on: bool) -> None:
        if bit != self.tool:
            self.events.append(("out", bit, on))
            return
        if self.on is None and not on:        # the program starts with the tool off
            self.on = False
            return
        assert on != self.on, "the tool switched twice the same way"
        self.on = on
        self.events.append(("tool", on))
        if on:
            self.pieces.append([self.pos])

    def _begin(self, segs: list) -> None:
        x, y = self.pos
        d = 0.0
        pts = [(x, y, 0.0)]
        for s in segs:
            if s[0] == "VP":
                d += math.hypot(s[1] - x, s[2] - y)
                x, y = s[1], s[2]
                pts.append((x, y, d))
            else:
                _, r, t, dt = s
                cx, cy = x - r * math.cos(math.radians(t)), y - r * math.sin(math.radians(t))
                n = max(2, int(abs(dt) * 4))
                for k in range(1, n + 1):
                    a = math.radians(t + dt * k / n)
                    x, y = cx + r * math.cos(a), cy + r * math.sin(a)
                    pts.append((x, y, d + r * math.radians(abs(dt)) * k / n))
                d += r * math.radians(abs(dt))
        self.motion, self.done = pts, 0.0

    def _advance(self, dist: float) -> None:
        for k in range(1, len(self.motion)):
            x0, y0, d0 = self.motion[k - 1]
            x1, y1, d1 = self.motion[k]
            if d1 <= self.done or d0 >= dist:
                continue
            f = min(1.0, (dist - d0) / (d1 - d0)) if d1 > d0 else 1.0
            self._to((x0 + (x1 - x0) * f, y0 + (y1 - y0) * f))
        self.done = max(self.done, min(dist, self.motion[-1][2]))

    def _to(self, p: tuple[float, float]) -> None:
        self.pos = p
        if self.on:
            self.pieces[-1].append(p)


# ---------------------------------------------------------------------------
# Drawings and ezdxf's own geometry of them.
# ---------------------------------------------------------------------------
def _truth(e) -> shapely.LineString:
    """An entity's curve as ezdxf evaluates it, densely (mm)."""
    if e.dxftype() == "SPLINE":
        bs = e.construction_tool()
        pts = bs.points(np.linspace(0, bs.max_t, 20001))
    else:
        pts = ezdxf.path.make_path(e).flattening(1e-5)
    return shapely.LineString([(p.x, p.y) for p in pts])


def _hausdorff(piece, truth: shapely.LineString) -> float:
    """The larger of the two directed distances: from every point of the
    drawn piece (each chord cut in 4) to the curve, from every point of the
    dense curve to the piece."""
    a = np.asarray(piece, dtype=float)
    f = np.linspace(0, 1, 5)[:-1, None, None]
    dense = (a[:-1] + f * (a[1:] - a[:-1])).transpose(1, 0, 2).reshape(-1, 2)
    dense = np.vstack([dense, a[-1:]])
    there = shapely.distance(shapely.points(dense), truth).max()
    back = shapely.distance(shapely.points(shapely.get_coordinates(truth)),
                            shapely.LineString(a)).max()
    return float(max(there, back))


def _drawing():
    """Labelled entities: FIRST the spline, 1 the bulged polyline, 2 the
    small arc, 3 the wide arc (drawn as chords), 4 the line, LAST the
    circle; a START macro by the line, a WRITING macro by the small arc, an
    END and a STOP macro by the polyline."""
    doc = ezdxf.new("R2000")
    msp = doc.modelspace()
    ents = {}
    ents["spline"] = msp.add_spline(fit_points=[(0, 0), (10, 8), (20, -3), (35, 5)])
    ents["poly"] = msp.add_lwpolyline([(0, 20, 0), (10, 20, 0.6), (20, 20, 0), (20, 30, 0)],
                                      format="xyb")
    ents["arc"] = msp.add_arc((40, 40), 5, 30, 200)
    ents["wide"] = msp.add_arc((-100, 20), 150, -10, 10)
    ents["line"] = msp.add_line((0, 60), (30, 60))
    ents["circle"] = msp.add_circle((60, 10), 4)
    for text, at in [("FIRST OUT 4", (20, 2)), ("1", (5, 21)), ("2", (40, 46)),
                     ("3", (50, 20)), ("4", (15, 61)), ("LAST OUT 4 OFF", (60, 15)),
                     ("START OUT 2 WAIT 20", (25, 59)), ("WRITING OUT 3", (36, 41)),
                     ("END OUT 2 OFF OUT 3 OFF", (20, 28)), ("STOP WAIT 100", (1, 19)),
                     ("MIND THE GAP", (80, 80))]:
        msp.add_text(text, dxfattribs={"insert": at, "layer": "NOTES"})
    return doc, ents


ORDER = ["spline", "poly", "arc", "wide", "line", "circle"]


def _convert(tmp_path: Path, doc, *args: str) -> tuple[int, str, str]:
    src = tmp_path / "d.dxf"
    doc.saveas(src)
    out = tmp_path / "d.dmc"
    status = main(["dxf2dmc", str(src), "-o", str(out), *args])
    return status, out.read_text() if out.exists() else "", str(src)


@pytest.mark.parametrize("mode", ["continuous", "intermittent"])
def test_the_program_draws_the_drawing_in_the_labels_order(tmp_path, capsys, mode):
    doc, ents = _drawing()
    status, text, _ = _convert(tmp_path, doc, "--mode", mode)
    err = capsys.readouterr().err
    assert status == 0, err
    assert "1 SPLINE flattened into chords within 0.004 mm" in err
    assert "'MIND THE GAP' is a hint" in err and "Traceback" not in err
    tr = Trace(text)
    assert len(tr.pieces_mm) == len(ORDER)
    for name, piece in zip(ORDER, tr.pieces_mm):
        assert _hausdorff(piece, _truth(ents[name])) <= TOL + 1e-9, name
    assert any(line.startswith("CR 5000,") for line in text.splitlines())   # the small arc
    assert not any(line.startswith("CR 150000,") for line in text.splitlines())  # the wide: chords
    if mode == "continuous":
        assert text.count("BGS") == 1 and "AV " in text and "PA " not in text
        assert "STOP macro works in intermittent mode only" in err
    else:
        assert text.count("BGS") == len(ORDER) and "AV " not in text


def test_macros_land_on_their_nearest_segment(tmp_path, capsys):
    doc, _ = _drawing()
    status, text, _ = _convert(tmp_path, doc, "--mode", "intermittent")
    ev = Trace(text).events
    # FIRST's body first, LAST's last
    assert ev[0] == ("out", 4, True) and ev[-1] == ("out", 4, False)
    tools = [k for k, e in enumerate(ev) if e[0] == "tool"]
    on = tools[0::2]
    off = tools[1::2]
    # segment 2 (the polyline, ordered 1): END after its tool-off, then STOP
    assert ev[off[1] + 1:off[1] + 4] == [("out", 2, False), ("out", 3, False), ("wait", 100)]
    # the small arc (3rd): WRITING right after the tool goes on
    assert ev[on[2] + 1] == ("out", 3, True)
    # the line (5th): START before the tool goes on
    assert ev[on[4] - 2:on[4]] == [("out", 2, True), ("wait", 20)]
    assert len(on) == len(ORDER)


def test_a_stop_macro_on_the_last_segment_runs_after_its_end(tmp_path, capsys):
    # the STOP of the last segment was dropped without a word
    doc = ezdxf.new("R2000")
    msp = doc.modelspace()
    msp.add_line((0, 0), (10, 0))
    msp.add_line((0, 20), (10, 20))
    for text, at in [("1", (5, 1)), ("2", (5, 21)), ("END OUT 2", (9, 21)),
                     ("STOP WAIT 50", (1, 21))]:
        msp.add_text(text, dxfattribs={"insert": at, "layer": "NOTES"})
    status, text, _ = _convert(tmp_path, doc, "--mode", "intermittent")
    assert status == 0, capsys.readouterr().err
    ev = Trace(text).events
    assert ev[-3:] == [("tool", False), ("out", 2, True), ("wait", 50)], ev


def test_the_drawings_mode_text_and_the_command_line(tmp_path, capsys):
    doc, _ = _drawing()
    doc.modelspace().add_text("MODE INTERMITTENT", dxfattribs={"insert": (90, 90)})
    _, text, _ = _convert(tmp_path, doc)
    assert "NO intermittent mode" in text
    _, text, _ = _convert(tmp_path, doc, "--mode", "continuous")
    assert "NO continuous mode" in text


def test_splines_within_tolerance_of_ezdxfs_evaluation(tmp_path, capsys):
    """Open, closed, rational and control-point splines, both commands: every
    chord within the tolerance of ezdxf's evaluation, and back."""
    doc = ezdxf.new("R2000")
    msp = doc.modelspace()
    ents = [msp.add_open_spline([(0, 0), (10, 30), (40, -20), (60, 10), (80, 0)], degree=3),
            msp.add_spline([(0, 50), (20, 70), (40, 50), (20, 30), (0, 50)]),
            msp.add_rational_spline([(0, 90), (10, 110), (30, 90)], weights=[1, 3, 1], degree=2),
            msp.add_spline(fit_points=[(50, 50), (52, 51), (55, 49), (90, 80)])]
    status, text, src = _convert(tmp_path, doc, "--tolerance", "0.01")
    assert status == 0
    assert "4 SPLINEs flattened into chords within 0.009 mm" in capsys.readouterr().err
    for e, piece in zip(ents, Trace(text).pieces_mm):
        assert _hausdorff(piece, _truth(e)) <= 0.01 + 1e-9
    # dxf2deck: a conductor of chords each, rounded to its 0.01 mm unit
    conv = seed001.convert(ezdxf.readfile(src), tolerance=0.005)
    assert conv.splines == 4 and conv.problems == []
    for e, it in zip(ents, conv.items):
        pts = [(float(c[10:20]), float(c[20:30])) for c in it.cards]
        assert it.cards[0].startswith("L") and len(pts) > 10
        assert _hausdorff(pts, _truth(e)) <= 0.005 + 0.005 * math.sqrt(2) + 1e-9
    assert main(["dxf2deck", src, "-o", str(tmp_path / "d.crd")]) == 0
    assert "4 SPLINEs flattened into chords within 0.005 mm" in capsys.readouterr().err


def test_a_long_path_is_cut_into_sequences_the_controller_holds(tmp_path, capsys):
    doc = ezdxf.new("R2000")
    pts = [(k * 0.1, 5 * math.sin(k / 10)) for k in range(1300)]
    e = doc.modelspace().add_lwpolyline(pts)
    for mode in ("continuous", "intermittent"):
        status, text, _ = _convert(tmp_path, doc, "--mode", mode)
        tr = Trace(text)
        assert status == 0 and max(tr.sequences) <= 511 and len(tr.sequences) == 3
        drawn = [p for piece in tr.pieces_mm for p in piece]
        assert _hausdorff(drawn, _truth(e)) <= TOL


def test_the_travel_to_a_long_path_counts_in_its_sequence(tmp_path, capsys):
    """A long path that starts away from the origin: the travel VP to it and
    its first 510 moves fill the first sequence (511), not 511 moves and the
    travel (512, more than the controller holds)."""
    doc = ezdxf.new("R2000")
    pts = [(5 + k * 0.1, 5 + 5 * math.sin(k / 10)) for k in range(1300)]
    e = doc.modelspace().add_lwpolyline(pts)
    status, text, _ = _convert(tmp_path, doc, "--mode", "continuous")
    tr = Trace(text)
    assert status == 0 and tr.sequences == [511, 510, 279]
    drawn = [p for piece in tr.pieces_mm for p in piece]
    assert _hausdorff(drawn, _truth(e)) <= TOL


def test_an_arc_is_a_cr_while_its_rounding_stays_within_the_tolerance(tmp_path, capsys):
    """SEED001-DXF.md: a CR's own rounding (a count of radius and start
    point, 1/256 degree of each angle) must stay within the tolerance: at
    1000 counts/mm and 0.005 mm, radii up to about 58 mm.  A 58 mm arc is a
    CR, a 59 mm one chords."""
    doc = ezdxf.new("R2000")
    msp = doc.modelspace()
    small = msp.add_arc((0, 0), 58, 0, 30)
    wide = msp.add_arc((0, 200), 59, 0, 30)
    status, text, _ = _convert(tmp_path, doc)
    assert status == 0, capsys.readouterr().err
    crs = [line for line in text.splitlines() if line.startswith("CR ")]
    assert crs == ["CR 58000,0,30"]
    pieces = Trace(text).pieces_mm
    assert _hausdorff(pieces[0], _truth(small)) <= TOL
    assert len(pieces[1]) > 10 and _hausdorff(pieces[1], _truth(wide)) <= TOL


def test_a_small_program_exactly(tmp_path, capsys):
    """Every line of two small programs: the speeds in counts per second
    (2.5 mm/s at 1000 counts/mm is VS 2500), the AV distances along the path
    (no AV where the tool goes on at the path's start), the VPs relative to
    the sequence's start, the tool bit."""
    doc = ezdxf.new("R2000")
    msp = doc.modelspace()
    line = msp.add_line((0, 0), (10, 0))
    arc = msp.add_arc((20, 0), 5, 180, 270)
    msp.add_text("1", dxfattribs={"insert": (5, 1)})
    msp.add_text("2", dxfattribs={"insert": (16, -4)})
    status, text, _ = _convert(tmp_path, doc, "--speed", "2.5")
    assert status == 0, capsys.readouterr().err
    assert text == f"""\
#DXF
NO dxf2dmc d.dxf
NO continuous mode, 1000 counts/mm, tolerance 0.005 mm, tool bit 1
DP 0,0
CB 1
VS 2500
SP 2500,2500
VM XY
VP 10000,0
VP 15000,0
CR 5000,180,90
VE
BGS
NO segment 1: #{line.dxf.handle} on layer 0
SB 1
AV 10000
CB 1
AV 15000
NO segment 2: #{arc.dxf.handle} on layer 0
SB 1
AV 22854
CB 1
AMS
EN
"""
    status, text, _ = _convert(tmp_path, doc, "--mode", "intermittent", "--counts-per-mm",
                               "400", "--tool-bit", "3")
    assert status == 0, capsys.readouterr().err
    assert text == f"""\
#DXF
NO dxf2dmc d.dxf
NO intermittent mode, 400 counts/mm, tolerance 0.005 mm, tool bit 3
DP 0,0
CB 3
VS 4000
SP 4000,4000
NO segment 1: #{line.dxf.handle} on layer 0
SB 3
VM XY
VP 4000,0
VE
BGS
AMS
CB 3
NO segment 2: #{arc.dxf.handle} on layer 0
PA 6000,0
BG XY
AM XY
SB 3
VM XY
CR 2000,180,90
VE
BGS
AMS
CB 3
EN
"""


@pytest.mark.parametrize("make, words", [
    (lambda m: m.add_text("BEGIN OUT 1", dxfattribs={"insert": (1, 1), "layer": "MAC"}),
     "unknown macro 'BEGIN' in 'BEGIN OUT 1'"),
    (lambda m: m.add_text("START OUT 9", dxfattribs={"insert": (1, 1), "layer": "MAC"}),
     "output 9 is not one of 1-8"),
    (lambda m: m.add_text("END BLINK 3", dxfattribs={"insert": (1, 1), "layer": "MAC"}),
     "unknown macro command 'BLINK 3'"),
    (lambda m: m.add_text("START WAIT 1", dxfattribs={"insert": (1, 1), "layer": "MAC"}),
     "WAIT 1 ms is not 2 to 2147483646 ms"),
    (lambda m: m.add_open_spline([(0, 0), (1, 1)], degree=3, dxfattribs={"layer": "CURVES"}),
     "cannot be flattened (DXFValueError: got 2 control points, need 4 or more"),
    (lambda m: m.add_open_spline([(0, 0), (1, float("nan")), (2, 0), (3, 1)],
                                 dxfattribs={"layer": "CURVES"}),
     "a coordinate is nan, not a number"),
    (lambda m: m.add_spline(dxfattribs={"layer": "CURVES"}),
     "cannot be flattened (ValueError: Construction tool requires control- or fit points."),
    (lambda m: m.add_line((0, 0), (1e12, 0), dxfattribs={"layer": "HOSTILE"}),
     "coordinate 1e+12 mm is off the 1200 mm field"),
    (lambda m: m.add_arc((0, 0), float("inf"), 0, 90, dxfattribs={"layer": "HOSTILE"}),
     "radius inf mm is not a size"),
])
def test_bad_input_is_one_line_naming_handle_and_layer(tmp_path, capsys, make, words):
    doc = ezdxf.new("R2000")
    msp = doc.modelspace()
    msp.add_line((0, 0), (10, 0))
    bad = make(msp)
    status, text, _ = _convert(tmp_path, doc)
    err = capsys.readouterr().err
    lines = [line for line in err.splitlines() if f"#{bad.dxf.handle} on layer {bad.dxf.layer}" in line]
    assert len(lines) == 1 and words in lines[0], err
    assert status == 1 and "Traceback" not in err
    assert len(Trace(text).pieces) == 1                   # the line is still drawn


def test_output_is_byte_identical_and_written_whole(tmp_path, capsys):
    doc, _ = _drawing()
    src = tmp_path / "d.dxf"
    doc.saveas(src)
    a, b = tmp_path / "a.dmc", tmp_path / "b.dmc"
    assert main(["dxf2dmc", str(src), "-o", str(a)]) == 0
    assert main(["dxf2dmc", str(src), "-o", str(b)]) == 0
    assert a.read_bytes() == b.read_bytes()
    assert seed001_dmc.main([str(src), "-o", str(b), "--mode", "continuous"]) == 0
    assert a.read_bytes() == b.read_bytes()
    # whole-file writes: never over the drawing, no stray temporary file
    assert main(["dxf2dmc", str(src), "-o", str(tmp_path / "." / "d.dxf")]) == 2
    assert "will not write over its own input" in capsys.readouterr().err
    assert main(["dxf2dmc", str(src), "-o", str(tmp_path / "nodir" / "x.dmc")]) == 2
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.dmc", "b.dmc", "d.dxf"]


def test_usage_errors(tmp_path, capsys):
    doc, _ = _drawing()
    src = tmp_path / "d.dxf"
    doc.saveas(src)
    for args in (["--tolerance", "nan"], ["--counts-per-mm", "100"], ["--tool-bit", "9"],
                 ["--speed", "-1"]):
        assert main(["dxf2dmc", str(src), *args]) == 2
    assert main(["dxf2dmc", str(tmp_path / "missing.dxf")]) == 2
    assert main(["dxf2dmc", "--help"]) == 0
    assert "Traceback" not in capsys.readouterr().err


@pytest.mark.parametrize("args, words", [
    # printed "1e+06 is not 1 to 1000000"
    (["--counts-per-mm", "1000001"], "dxf2dmc: --counts-per-mm 1000001 is not 1 to 1000000"),
    (["--counts-per-mm", "100"],
     "a count (0.01 mm) must be at most half the tolerance (0.005 mm): --counts-per-mm 100 "
     "with --tolerance 0.005 mm, where at least 400 counts a mm would do"),
    (["--counts-per-mm", "1000", "--tolerance", "0.0001"], "at least 20000 counts a mm"),
    # a count must be at most half the tolerance, not merely within it
    (["--counts-per-mm", "399"], "--counts-per-mm 399 with --tolerance 0.005 mm, where at "
                                 "least 400 counts a mm would do"),
])
def test_counts_per_mm_out_of_range_is_said_as_given(tmp_path, capsys, args, words):
    doc, _ = _drawing()
    src = tmp_path / "d.dxf"
    doc.saveas(src)
    assert main(["dxf2dmc", str(src), *args]) == 2
    assert words in capsys.readouterr().err
