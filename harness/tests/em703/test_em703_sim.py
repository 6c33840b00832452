"""`em703 sim` against the harness's simulator (harness/sim.py): the same
lengths, time, end point and bounding box within 0.01 mm on every example
tape and on random tapes; the same verdict on the field at every machine
scale; `--svg` and `em703 svg` draw every stroke, the same bytes each run."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from decimal import Decimal
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from harness.sim import Arc, Dot, Line, simulate
from harness.tape import Frame, decode, encode

from harness.tests.helpers import keys, run
from harness.tests.strategies import frame_lists

MM = 0.01            # tolerance on lengths and positions, mm
SCALES = ["1:100", "1:10", "1:5", "1:2", "1:1", "2:1", "5:1", "50:1", "100:1"]
SVG = "{http://www.w3.org/2000/svg}"


def _compare(em703_exe: Path, path: Path, *args: str) -> dict[str, str]:
    """Run em703 sim and check every key against harness.sim."""
    data = path.read_bytes()
    tape = decode(data)
    expected = simulate(tape.frames)
    proc = run(em703_exe, "sim", path, *args)
    assert proc.returncode in (0, 1), proc.stderr
    got = keys(proc.stdout.decode())
    assert got["code"] == tape.code
    assert int(got["frames"]) == len(tape.frames)
    assert int(got["executed"]) == expected.executed
    assert int(got["rows"]) == len(data)
    assert float(got["tape_m"]) == pytest.approx(len(data) * 2.54 / 1000, abs=0.00051)
    assert float(got["drawn_mm"]) == pytest.approx(expected.drawn_mm, abs=MM)
    assert float(got["line_mm"]) == pytest.approx(expected.line_mm, abs=MM)
    assert float(got["arc_mm"]) == pytest.approx(expected.arc_mm, abs=MM)
    assert float(got["travel_mm"]) == pytest.approx(expected.travel_mm, abs=MM)
    assert float(got["minutes"]) == pytest.approx(expected.minutes, abs=0.0005)
    assert (float(got["end_x_mm"]), float(got["end_y_mm"])) == \
        pytest.approx((expected.end[0] / 100, expected.end[1] / 100), abs=1e-9)
    assert got["tool_at_end"] == ("down" if expected.tool_down_at_end else "up")
    box = tuple(float(got[k]) for k in ("xmin_mm", "xmax_mm", "ymin_mm", "ymax_mm"))
    assert box == pytest.approx(expected.bbox, abs=MM)
    return got


def _field_ok(tape_bbox: tuple[float, float, float, float], start: tuple[str, str],
              scale: str) -> bool:
    """The harness's rule (as in test_layers.py): the scaled box from the start
    point stays within 0..1200 mm."""
    num, den = map(int, scale.split(":"))
    s = Decimal(num) / Decimal(den)
    x0, y0 = Decimal(start[0]), Decimal(start[1])
    xmin, xmax, ymin, ymax = (Decimal(repr(v)) for v in tape_bbox)
    return (x0 + xmin * s >= 0 and y0 + ymin * s >= 0
            and x0 + xmax * s <= 1200 and y0 + ymax * s <= 1200)


def test_every_example_tape_runs_as_the_harness_runs_it(em703_exe, examples) -> None:
    for ex in examples:
        job = keys(ex.jobs[0].read_text())
        start = (job["start_x_mm"], job["start_y_mm"])
        for tape in ex.tapes:
            got = _compare(em703_exe, tape, "--start", ",".join(start), "--scale", job["scale"])
            # TENZOR punched it for this start point and scale: it fits, and
            # the job sheet's statistics agree.
            assert got["field"] == "inside", tape
            key = tape.stem.rsplit("-", 1)[1]
            assert got["frames"] == job[f"{key}.frames"] and got["rows"] == job[f"{key}.rows"]
            assert float(got["drawn_mm"]) == pytest.approx(float(job[f"{key}.drawn_mm"]), abs=MM)
            assert float(got["travel_mm"]) == pytest.approx(float(job[f"{key}.travel_mm"]), abs=MM)


@settings(max_examples=25, deadline=None)
@given(frames=frame_lists(), code=st.sampled_from(["8", "K"]),
       scale=st.sampled_from(SCALES), start=st.sampled_from([("0", "0"), ("600", "600"),
                                                             ("1150.5", "20.25")]))
def test_random_tapes_run_as_the_harness_runs_them(em703_exe, tmp_path_factory, frames, code,
                                                   scale, start) -> None:
    path = tmp_path_factory.mktemp("sim") / "t.ptp"
    path.write_bytes(encode(frames, code))
    proc = run(em703_exe, "sim", path, "--scale", scale, "--start", ",".join(start))
    got = _compare(em703_exe, path, "--scale", scale, "--start", ",".join(start))
    inside = _field_ok(simulate(frames).bbox, start, scale)
    assert got["field"] == ("inside" if inside else "left")
    assert proc.returncode == (0 if inside else 1)
    if not inside:
        err = proc.stderr.decode()
        assert re.fullmatch(rf"{re.escape(str(path))}: row \d+: frame \d+ leaves the field .*\n",
                            err), err


def test_leaving_the_field_names_the_frame_and_its_row(em703_exe, tmp_path) -> None:
    # GM DX1000 K20 KK DX-5000 K10 KK ...: the second frame (row 31) goes 40 mm left of its start
    frames = [Frame(dx=1000, k=20), Frame(dx=-5000, k=10), Frame(dx=4000, k=20)]
    path = tmp_path / "left.ptp"
    path.write_bytes(encode(frames, "8"))
    proc = run(em703_exe, "sim", path, "--start", "30,30", check=1)
    assert keys(proc.stdout.decode())["field"] == "left"
    assert proc.stderr.decode() == (
        f"{path}: row 31: frame 2 leaves the field (0..1200 mm) at scale 1:1 from the start "
        "point (30.00, 30.00) mm: the carriage reaches x = -10.00 mm\n")
    run(em703_exe, "sim", path, "--start", "30,30", "--scale", "1:2", check=0)


def _drawn_elements(svg: Path) -> tuple[list[ET.Element], ET.Element]:
    root = ET.parse(svg).getroot()
    assert root.tag == SVG + "svg"
    return list(root.iter()), root


def test_sim_svg_draws_each_stroke_and_travel(em703_exe, example_tapes, tmp_path) -> None:
    for tape in example_tapes:
        frames = decode(tape.read_bytes()).frames
        expected = simulate(frames)
        svg = tmp_path / "run.svg"
        # the SVG is written whether or not the run stays on the field
        assert run(em703_exe, "sim", tape, "--tool", "0.40", "--svg", svg).returncode in (0, 1)
        _, root = _drawn_elements(svg)
        groups = {g.get("id"): g for g in root.iter(SVG + "g")}
        down = list(groups["tool-down"])
        assert groups["tool-down"].get("stroke-width") == "0.40"
        assert len(down) == len(expected.strokes), tape
        for element, stroke in zip(down, expected.strokes):
            if isinstance(stroke, Line):
                assert element.tag == SVG + "line"
                assert float(element.get("x2")) == pytest.approx(stroke.x1 / 100)
                assert float(element.get("y2")) == pytest.approx(-stroke.y1 / 100)
            elif isinstance(stroke, Dot):
                assert element.tag == SVG + "circle" and element.get("r") == "0.200"
            elif isinstance(stroke, Arc) and stroke.full:
                assert element.tag == SVG + "circle"
                assert float(element.get("cx")) == pytest.approx(stroke.cx / 100)
                assert float(element.get("r")) == pytest.approx(stroke.r / 100, abs=1e-4)
            else:
                assert element.tag == SVG + "path" and " A " in element.get("d")
        assert len(list(groups["travel"])) == len(expected.travel)
        again = tmp_path / "again.svg"
        run(em703_exe, "sim", tape, "--tool", "0.40", "--svg", again)
        assert again.read_bytes() == svg.read_bytes()


def test_job_svg_has_a_layer_per_tape_and_a_grid(em703_exe, example_jobs, tmp_path) -> None:
    for job in example_jobs:
        sheet = keys(job.read_text())
        out = tmp_path / "job.svg"
        run(em703_exe, "svg", job, "-o", out, check=0)
        _, root = _drawn_elements(out)
        groups = {g.get("id"): g for g in root.iter(SVG + "g")}
        assert {"grid", "grid-10", "small", "large", "cond"} <= set(groups)
        colours = set()
        for key in ("small", "large", "cond"):
            tape = job.parent / sheet[f"{key}.tape"]
            strokes = simulate(decode(tape.read_bytes()).frames).strokes
            assert len(list(groups[key])) == len(strokes), (job, key)
            assert float(groups[key].get("stroke-width")) == float(sheet[f"{key}.tool_mm"])
            colours.add(groups[key].get("stroke"))
        assert len(colours) == 3
        # the grid lines fall on whole millimetres
        for line in groups["grid"]:
            assert float(line.get("x1")) == int(float(line.get("x1")))
        stdout = run(em703_exe, "svg", job, check=0).stdout
        assert stdout == out.read_bytes()
