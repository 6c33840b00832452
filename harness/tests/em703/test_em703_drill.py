"""`em703 drill`: the pads of a job's pad tapes as an Excellon drill file.

The hits are checked against the deck, read by the harness's own parser:
every pad of every D card (rows expanded) is one hit at its centre, with a
tool of its diameter (a rectangular pad's shorter side), and nothing else;
the hits come in the order the tapes first reach the pads (the harness's
simulator of the same tapes says which stroke reaches which pad first);
gerbv, an independent reader, renders the file.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from harness.deck import parse_deck
from harness.sim import Dot, simulate
from harness.tape import Frame, decode, encode

from harness.tests.helpers import keys, run, write_job

GERBV = shutil.which("gerbv")


def read_drill(text: str) -> list[tuple[int, int, int]]:
    """The hits (x, y in half units of 0.005 mm, tool diameter in units) of
    a METRIC Excellon file with decimal points, read by this test."""
    lines = text.splitlines()
    assert lines[0] == "M48" and "METRIC,TZ" in lines and lines[-1] == "M30"
    tools = {}
    hits = []
    tool = None
    body = False
    for line in lines[1:-1]:
        if line.startswith(";"):
            assert not body
            continue
        if line == "%":
            body = True
            continue
        if m := re.fullmatch(r"T(\d\d)C(\d+\.\d{3})", line):
            assert not body
            tools[m.group(1)] = round(float(m.group(2)) * 100)
        elif m := re.fullmatch(r"T(\d\d)", line):
            assert body and m.group(1) in tools
            tool = tools[m.group(1)]
        elif m := re.fullmatch(r"X(-?\d+\.\d{3})Y(-?\d+\.\d{3})", line):
            assert body and tool is not None
            hits.append((round(float(m.group(1)) * 200), round(float(m.group(2)) * 200), tool))
        else:
            assert line in ("METRIC,TZ", "G90", "G05"), line
    assert sorted(tools.values()) == [tools[k] for k in sorted(tools)], "tools by size"
    return hits


def deck_pads(pkg, layer: str | None = None, size: bool = False) -> list[tuple[int, ...]]:
    """Every pad of the package (of one pad tape: a pad's size, the larger
    of W and H, up to Dmax is small): centre in half units, hole in units
    (and with size, the pad's size)."""
    pads = []
    for p in pkg.pads:
        big = max(p.w, p.h or 0)
        if layer is not None and (big <= pkg.dmax) != (layer == "small"):
            continue
        for i in range(p.n):
            d = p.w if p.h is None else min(p.w, p.h)
            pads.append((2 * (p.x + i * p.sx), 2 * (p.y + i * p.sy), d) + ((big,) if size else ()))
    return pads


def first_reached(tape: Path, pads: list[tuple[int, ...]]) -> list[int]:
    """The pads of one tape in the order its strokes first reach them (a
    stroke starting within a pad's size of its centre)."""
    order: list[int] = []
    seen = set()
    for s in simulate(decode(tape.read_bytes()).frames).strokes:
        x, y = (s.x, s.y) if isinstance(s, Dot) else (s.x0, s.y0)
        for k, (px, py, _, big) in enumerate(pads):
            if k not in seen and (2 * x - px) ** 2 + (2 * y - py) ** 2 <= big ** 2:
                seen.add(k)
                order.append(k)
                break
    return order


def test_every_pad_of_every_example_is_a_hit_in_tour_order(em703_exe, examples, tmp_path) -> None:
    checked = 0
    for example in examples:
        for pkg in parse_deck(example.deck.read_text()):
            job = example.out / f"{pkg.file_name}.job"
            out = tmp_path / f"{pkg.file_name}.drl"
            got = run(em703_exe, "drill", job, "-o", out, check=0)
            assert got.returncode == 0, got.stderr
            hits = read_drill(out.read_text())
            pads = deck_pads(pkg)
            assert sorted(hits) == sorted(pads), job
            # the order: the small-pad tape's first reach, then the large's
            sheet = keys(job.read_text())
            order = []
            for layer in ("small", "large"):
                on = deck_pads(pkg, layer, size=True)
                reached = first_reached(job.parent / sheet[f"{layer}.tape"], on)
                order += [on[k][:3] for k in reached]
            assert hits == order, job
            # the same bytes on every run, to a file or to standard output
            assert run(em703_exe, "drill", job, check=0).stdout == out.read_bytes()
            checked += len(hits)
    assert checked > 100


@pytest.mark.skipif(GERBV is None, reason="gerbv (Debian package gerbv) is not on PATH")
def test_gerbv_reads_the_drill_file(em703_exe, examples, tmp_path) -> None:
    """gerbv renders the demo board's drill file: at 0.05 mm a pixel every hit
    is a dark disc of its tool's diameter (its centre dark, a point just
    outside it light, unless another hole is there), and nothing is dark
    outside the holes."""
    from harness.tests.em703.test_em703_gerber import read_png
    demo = next(e for e in examples if e.deck.name == "demo.crd")
    job = next(iter(demo.jobs))
    drl = tmp_path / "demo.drl"
    run(em703_exe, "drill", job, "-o", drl, check=0)
    hits = read_drill(drl.read_text())
    pitch = 0.05                                             # mm a pixel: 508 dpi
    x0 = min(x - d for x, _, d in hits) / 200 - 1
    y0 = min(y - d for _, y, d in hits) / 200 - 1
    nx = int((max(x + d for x, _, d in hits) / 200 + 1 - x0) / pitch)
    ny = int((max(y + d for _, y, d in hits) / 200 + 1 - y0) / pitch)
    png = tmp_path / "demo.png"
    got = subprocess.run([GERBV, "-a", "-x", "png", "-u", "mm", "-D", "508",
                          "-O", f"{x0:.2f}x{y0:.2f}", "-w", f"{nx}x{ny}", "-B", "0",
                          "-b", "#000000", "-f", "#ffffffff", "-o", str(png), str(drl)],
                         capture_output=True, timeout=60)
    assert got.returncode == 0 and png.exists(), got.stderr
    dark = read_png(png)[::-1, :] > 127                      # rows from the bottom

    def pixel(x_mm: float, y_mm: float) -> bool:
        return bool(dark[int((y_mm - y0) / pitch), int((x_mm - x0) / pitch)])

    def in_a_hole(x_mm: float, y_mm: float) -> bool:
        return any((x_mm - hx / 200) ** 2 + (y_mm - hy / 200) ** 2 <= (hd / 200 + 0.1) ** 2
                   for hx, hy, hd in hits)

    for x, y, d in hits:
        cx, cy, r = x / 200, y / 200, d / 200
        assert pixel(cx, cy), (cx, cy)
        for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            assert pixel(cx + dx * (r - 0.15), cy + dy * (r - 0.15)), (cx, cy, d)
            out = (cx + dx * (r + 0.15), cy + dy * (r + 0.15))
            if not in_a_hole(out[0] + dx * 0.1, out[1] + dy * 0.1):
                assert not pixel(*out), (cx, cy, d, out)
    ys, xs = np.nonzero(dark)
    assert all(in_a_hole(x0 + (i + 0.5) * pitch, y0 + (j + 0.5) * pitch)
               for i, j in zip(xs[::97], ys[::97]))


def test_bad_input_to_drill(em703_exe, examples, tmp_path) -> None:
    job = next(iter(examples[0].jobs))
    got = run(em703_exe, "drill", job, "-o", job, check=2)
    assert b"will not write" in got.stderr
    missing = run(em703_exe, "drill", tmp_path / "none.job", check=2)
    assert missing.stderr.count(b"\n") == 1
    usage = run(em703_exe, "drill", check=2)
    assert b"missing JOB" in usage.stderr


@pytest.mark.parametrize("gap, hits", [
    # the boxes 0..1 mm and 1.5..2.5 mm, widened by half the 0.5 mm tool,
    # touch at 1.25 mm: two pads, two holes of the shorter side plus the tool
    (150, ["X0.500Y0.500", "X2.000Y0.500"]),
    # 0.01 mm nearer they overlap: one pad, 0..2.49 mm, one hole at its centre
    (149, ["X1.245Y0.500"]),
])
def test_pads_of_strokes_that_only_touch_are_two_holes(em703_exe, tmp_path, gap, hits) -> None:
    square = [Frame(dx=100, k=10), Frame(dy=100, k=10), Frame(dx=-100, k=10),
              Frame(dy=-100, k=10)]
    frames = square + [Frame(dx=gap, k=20)] + square + [Frame(dx=-gap, k=20)]
    job = write_job(tmp_path, "touch", {"small": encode(frames)}, {})
    text = run(em703_exe, "drill", job, check=0).stdout.decode()
    assert text.splitlines()[4:] == ["T01C1.500", "%", "G90", "G05", "T01", *hits, "M30"]
    many = "1 hole" if len(hits) == 1 else f"{len(hits)} holes"
    assert text.splitlines()[1] == f"; EM-703 job touch: {many} of the small- and large-pad tapes"


def test_holes_at_and_left_of_the_start_point(em703_exe, tmp_path) -> None:
    """Dots (holes of the tool's 0.5 mm) at the start point and at (-1.5,
    -0.05) mm: the centres in mm with their signs, and no "-0.000"."""
    frames = [Frame(k=10), Frame(dx=-150, dy=-5, k=20), Frame(k=10), Frame(dx=150, dy=5, k=20)]
    job = write_job(tmp_path, "dots", {"large": encode(frames)}, {})
    text = run(em703_exe, "drill", job, check=0).stdout.decode()
    assert text.splitlines()[4:] == ["T01C0.500", "%", "G90", "G05", "T01", "X0.000Y0.000",
                                     "X-1.500Y-0.050", "M30"]
