"""`em703 gerber` rendered by an independent tool, gerbv (Debian package
gerbv), against the harness's raster of the same tapes (harness/raster.py):
on every example job and on random jobs, the two bitmaps agree within a band
of BAND pixels (every pixel one of them sets has a pixel of the other within
BAND pixels, diagonals included). The Gerber text is also checked for its form
and for being the same bytes from run to run.

Why two pixels, not one: gerbv's PNG export moves every coordinate to the
pixel grid before it draws (measured: a 0.5 mm flash at x = -1.155 mm, 0.225
pixel from a pixel corner, is drawn centred on that corner; the same in y),
and draws strokes whole pixels wide (a 0.5 mm stroke at 127 dpi, 2.5 pixels,
comes out 3 pixels wide). The harness samples the exact geometry at pixel
centres. Each side is then within a pixel of the truth, but not within one
pixel of each other: at the corner where a 0.5 mm stroke meets a circle's
band (hypothesis found it: the example below), gerbv's stroke stands 1.25
pixels right of the exact one, and the pixel in the corner is 2 pixels from
the harness's nearest. With -a (antialiasing, used here) the snapping stays;
only the edges are smoother. So the band is gerbv's half pixel of snapping
and half pixel of width on top of the two samplings' pixel."""

from __future__ import annotations

import shutil
import struct
import subprocess
import zlib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from harness.deck import run_shapes
from harness.raster import Grid, render_run, union_box
from harness.sim import simulate
from harness.tape import Frame, decode, encode

from harness.tests.helpers import keys, run, write_job
from harness.tests.strategies import frame_lists

GERBV = shutil.which("gerbv")
needs_gerbv = pytest.mark.skipif(
    GERBV is None, reason="gerbv is not on PATH (Debian package gerbv): the Gerber output "
                          "cannot be rendered by an independent tool here")
#: gerbv's resolutions (dots per inch) and the pitch of a pixel in 0.01 mm.
DPIS = (508, 254, 127, 50)
MAX_SIDE = 2000          # gerbv exports at most 2000 x 2000 pixels


# ---------------------------------------------------------------------------
# A PNG reader (zlib and numpy only): 8-bit grey, RGB or RGBA, no interlace.
# ---------------------------------------------------------------------------
def read_png(path: Path) -> np.ndarray:
    """The first channel of a PNG image, as [row from the top, column]."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    i, idat = 8, b""
    while i < len(data):
        n, kind = struct.unpack(">I4s", data[i:i + 8])
        chunk = data[i + 8:i + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
        i += 12 + n
    assert depth == 8 and interlace == 0, (depth, interlace)
    ch = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
    raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(h, 1 + w * ch)
    filters = raw[:, 0].astype(np.int16)
    # The filters work byte by byte with the byte one pixel to the left, so
    # each channel decodes alone; only the first (red, or grey) is needed.
    res = raw[:, 1::ch].astype(np.int16)
    out = np.zeros((h + 1, w + 1), np.int16)             # row 0 and column 0: zeros
    # A byte depends on its left, upper and upper-left neighbours, so the
    # bytes of one anti-diagonal are decoded together, whatever the filters.
    for d in range(w + h - 1):
        ys = np.arange(max(0, d - w + 1), min(h - 1, d) + 1)
        xs = d - ys
        a = out[ys + 1, xs]
        b = out[ys, xs + 1]
        c = out[ys, xs]
        f = filters[ys]
        pa, pb, pc = np.abs(b - c), np.abs(a - c), np.abs(a + b - 2 * c)
        pred = np.where((pa <= pb) & (pa <= pc), a, np.where(pb <= pc, b, c))   # Paeth
        pred = np.where(f == 3, (a + b) >> 1, pred)
        pred = np.where(f == 2, b, pred)
        pred = np.where(f == 1, a, pred)
        pred = np.where(f == 0, 0, pred)
        out[ys + 1, xs + 1] = (res[ys, xs] + pred) & 255
    return out[1:, 1:].astype(np.uint8)


#: How far apart, in pixels, gerbv's picture and the harness's may be (see above).
BAND = 2


def dilate(a: np.ndarray, n: int = BAND) -> np.ndarray:
    """a grown by n pixels in the 8 directions."""
    p = np.pad(a, n)
    out = np.zeros_like(a)
    h, w = a.shape
    for dy in range(2 * n + 1):
        for dx in range(2 * n + 1):
            out |= p[dy:dy + h, dx:dx + w]
    return out


def _render_both(em703_exe: Path, job: Path, tmp: Path) -> tuple[np.ndarray, np.ndarray, float]:
    """(gerbv's bitmap, the harness's bitmap, pitch in mm) of a job, both
    [row from the bottom, column], True = dark (drawn)."""
    sheet = keys(job.read_text())
    gerber = tmp / "job.gbr"
    run(em703_exe, "gerber", job, "-o", gerber, check=0)
    runs = []
    for key in ("small", "large", "cond"):
        frames = decode((job.parent / sheet[f"{key}.tape"]).read_bytes()).frames
        runs.append((simulate(frames), round(float(sheet[f"{key}.tool_mm"]) * 100)))
    box = union_box([s.bbox() for r, tool in runs for s in run_shapes(r, tool)])
    assert box is not None
    extent = max(box[1] - box[0], box[3] - box[2])
    dpi = next((d for d in DPIS if extent / (2540 / d) + 20 <= MAX_SIDE), DPIS[-1])
    pitch = 2540 / dpi                       # units per pixel
    x0 = np.floor(box[0] / pitch - 4) * pitch
    y0 = np.floor(box[2] / pitch - 4) * pitch
    nx = int(np.ceil((box[1] - x0) / pitch)) + 4
    ny = int(np.ceil((box[3] - y0) / pitch)) + 4
    png = tmp / "job.png"
    # gerbv's origin (lower left corner) in mm; it reads at most about 20 characters
    origin = f"{x0 / 100:.4f}x{y0 / 100:.4f}"
    assert len(origin) < 20 and abs(float(origin.split("x")[0]) * 100 - x0) < 1e-6, origin
    proc = subprocess.run(
        [GERBV, "-a", "-x", "png", "-u", "mm", "-D", str(dpi), "-O", origin,
         "-w", f"{nx}x{ny}", "-B", "0", "-b", "#000000", "-f", "#ffffffff", "-o", str(png),
         str(gerber)], capture_output=True, timeout=120)
    assert proc.returncode == 0 and png.exists(), proc.stderr.decode("latin-1")
    image = read_png(png)
    assert image.shape == (ny, nx), (image.shape, nx, ny)
    theirs = image[::-1, :] > 127
    grid = Grid(x0, y0, pitch, nx, ny)
    ours = np.zeros((ny, nx), bool)
    for r, tool in runs:
        ours |= render_run(r, tool, grid)
    return theirs, ours, pitch / 100


def _assert_one_pixel_band(theirs: np.ndarray, ours: np.ndarray, pitch_mm: float,
                           what: str) -> None:
    extra = theirs & ~dilate(ours)
    missing = ours & ~dilate(theirs)
    def where(mask: np.ndarray) -> str:
        js, is_ = np.nonzero(mask)
        return ", ".join(f"({i * pitch_mm:.2f}, {j * pitch_mm:.2f})" for j, i in
                         list(zip(js, is_))[:5])
    assert not extra.any() and not missing.any(), (
        f"{what}: gerbv and the harness differ by more than {BAND} pixels "
        f"({BAND * pitch_mm:.3f} mm): "
        f"{int(extra.sum())} pixels only gerbv draws, e.g. at {where(extra)}; "
        f"{int(missing.sum())} pixels only the harness draws, e.g. at {where(missing)} "
        "(mm from the raster's corner)")
    assert theirs.any() == ours.any(), what


@needs_gerbv
def test_gerbv_renders_every_example_job_as_the_harness_rasters_it(em703_exe, example_jobs,
                                                                   tmp_path) -> None:
    for job in example_jobs:
        theirs, ours, pitch = _render_both(em703_exe, job, tmp_path)
        _assert_one_pixel_band(theirs, ours, pitch, str(job.name))


@needs_gerbv
@settings(max_examples=10, deadline=None)
@given(small=frame_lists(max_items=4), cond=frame_lists(max_items=4),
       tools=st.tuples(st.sampled_from(["0.30", "0.50", "1.20"]),
                       st.sampled_from(["0.20", "0.50", "2.00"])))
@example(small=[Frame(dx=-11, dy=-862, cyc=12, k=10), Frame(x=0, y=2824, k=11)],
         cond=[Frame(dy=3684, k=10)], tools=("0.50", "2.00"))
def test_gerbv_renders_random_jobs_as_the_harness_rasters_them(em703_exe, tmp_path_factory,
                                                               small, cond, tools) -> None:
    tapes = []
    for frames in (small, cond):
        r = simulate(frames)
        # at most 190 mm across, so the raster is at 254 dpi or finer: a 0.2 mm
        # tool is then 2 pixels wide. (On a coarser raster gerbv's antialiasing
        # leaves a dot of 1-1.5 pixels below the threshold and it vanishes,
        # which hypothesis found with a 0.3 mm dot at 127 dpi.)
        assume(max(r.bbox[1] - r.bbox[0], r.bbox[3] - r.bbox[2]) < 190)
        if r.end != (0, 0):             # back to the start point, as TENZOR's tapes end
            frames = [*frames, Frame(dx=-r.end[0], dy=-r.end[1], k=20)]
        tapes.append(frames)
    small, cond = tapes
    tmp = tmp_path_factory.mktemp("gerber")
    job = write_job(tmp, "RANDOM", {"small": encode(small), "cond": encode(cond, "8")},
                    {"small": tools[0], "cond": tools[1]})
    theirs, ours, pitch = _render_both(em703_exe, job, tmp)
    _assert_one_pixel_band(theirs, ours, pitch, "random job")


def test_gerber_form_and_apertures(em703_exe, example_jobs, tmp_path) -> None:
    for job in example_jobs:
        sheet = keys(job.read_text())
        first = run(em703_exe, "gerber", job, check=0).stdout.decode()
        lines = first.splitlines()
        assert lines[2:5] == ["%FSLAX66Y66*%", "%MOMM*%", "%LPD*%"]
        for n, key in enumerate(("small", "large", "cond")):
            tool = float(sheet[f"{key}.tool_mm"])
            assert f"%ADD{10 + n}C,{tool:.4f}*%" in lines
        assert lines[-1] == "M02*" and "G75*" in lines
        assert all(line.endswith("*") or line.endswith("*%") for line in lines)
        # dots are flashes, one per Dot stroke of the harness run
        flashes = sum(line.endswith("D03*") for line in lines)
        dots = 0
        for key in ("small", "large", "cond"):
            run_ = simulate(decode((job.parent / sheet[f"{key}.tape"]).read_bytes()).frames)
            dots += sum(type(s).__name__ == "Dot" for s in run_.strokes)
        assert flashes == dots
        out = tmp_path / "again.gbr"
        run(em703_exe, "gerber", job, "-o", out, check=0)
        assert out.read_text() == first


def test_a_job_name_cannot_end_a_gerber_word(em703_exe, tmp_path) -> None:
    """* ends a Gerber word and % a command: in the title's G04 comment
    they become _, so the comment stays one word."""
    job = write_job(tmp_path, "STAR", {}, {})
    job.write_text(job.read_text().replace("name = STAR", "name = CARD *1* 50%"))
    lines = run(em703_exe, "gerber", job, check=0).stdout.decode().splitlines()
    assert lines[0] == "G04 EM-703 job CARD _1_ 50_, code 8*"
    assert lines[2:5] == ["%FSLAX66Y66*%", "%MOMM*%", "%LPD*%"]


@pytest.mark.parametrize("dx, status", [(99_999_999, 0), (100_000_000, 1)])
def test_the_gerber_format_holds_up_to_its_last_digit(em703_exe, tmp_path, dx, status) -> None:
    """Format 6.6 holds 999 999.999999 mm: a line to 999 999.99 mm is
    written, one to 1 000 000.00 mm is refused, naming how far it reaches."""
    job = write_job(tmp_path, "FAR", {"cond": encode([Frame(dx=dx, k=10), Frame(dx=-dx, k=20)])},
                    {})
    proc = run(em703_exe, "gerber", job, check=status)
    if status == 0:
        assert "X999999990000Y0D01*" in proc.stdout.decode()
    else:
        assert proc.stderr.decode() == (
            f"{tmp_path / 'FAR-cond.ptp'}: the drawing reaches 1000000.00 mm from the start "
            "point, beyond the 999999.999999 mm that the Gerber 6.6 format holds\n")


@pytest.mark.parametrize("codes, heading", [
    ({"cond": "K"}, "K"), ({"small": "8"}, "8"), ({"small": "8", "cond": "K"}, "8 and K"),
    ({}, "8 or K")])
def test_a_job_sheet_without_a_code_line_is_headed_with_the_tapes_code(em703_exe, tmp_path,
                                                                      codes, heading):
    """Each tape is read in the code it tells (a digit 3, 5, 6 or 9); the
    empty tapes of write_job tell neither."""
    tapes = {key: encode([Frame(dx=300, k=10), Frame(dx=-300, k=20)], code)
             for key, code in codes.items()}
    job = write_job(tmp_path, "NOCODE", tapes, {})
    job.write_text("".join(l for l in job.read_text().splitlines(True)
                           if not l.startswith("code")))
    first = run(em703_exe, "gerber", job, check=None).stdout.decode().splitlines()[0]
    assert first == f"G04 EM-703 job NOCODE, code {heading}*"
