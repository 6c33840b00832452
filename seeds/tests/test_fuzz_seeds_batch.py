"""The neighbouring systems' tools on hostile files, in-process, in bulk
(docs/ROBUSTNESS.md): dxf2deck's DXF drawings, profile's points, equidistant's
decks, punch5121's frame text and tape images, cnclink's polylines and decks,
split's and dda's numbers, ural1's contour decks and options, dxf2dmc's
drawings and options, gerber2deck's copper layers and drill files (whose
decks TENZOR must then punch).

Each tool's ``main`` is called directly (no process start; ~1 ms a call for
most), on inputs from ``random.Random(seed)`` with fixed seeds. Whatever it
is given, a tool must return 0, 1 or 2 and raise nothing (an exception here
is a traceback for the user); when it returns non-zero it says why on
standard error, naming the tool (and the line, row or entity where the input
says where); it leaves no temporary file, and an output it refuses to write
is not there.
"""
from __future__ import annotations

import contextlib
import io
import random
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from harness.tests import hostile
from seeds.__main__ import main

ROOT = Path(__file__).resolve().parents[2]
BOARD_DXF = (ROOT / "examples" / "dxf" / "board.dxf").read_text(encoding="ascii")
CONTOURS = [(ROOT / "examples" / n).read_text(encoding="ascii")
            for n in ("flange.crd", "flange-path.crd", "blade-profile.crd",
                      "report/saw-polyline.crd", "demo.crd")]
NUMS = ["0", "-0", "1", "-1", "0.5", "nan", "inf", "-inf", "1e308", "-1e308", "1e-320",
        "1e12", "-1e12", "99999", "2147483648", "x", "", "1,5", "0x10", "1_000"]


def call(argv: list[str], here: Path, where: str) -> tuple[int, str]:
    """main(argv) in ``here``'s files: (status, standard error), after every
    promise of the module doc."""
    before = {p.name for p in here.iterdir()}
    out, err = io.StringIO(), io.StringIO()
    stdin, sys.stdin = sys.stdin, io.StringIO("")
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            status = main(argv)
    except BaseException as exc:                   # noqa: BLE001: any escape is the failure
        raise AssertionError(f"{where}: {argv} raised {type(exc).__name__}: {exc}") from exc
    finally:
        sys.stdin = stdin
    text = err.getvalue()
    assert status in (0, 1, 2), f"{where}: {argv} returned {status!r}"
    if status:
        assert text.strip(), f"{where}: {argv} returned {status} without a message"
        # (cnclink's refused transfer ends with the paper's own message)
        assert text.startswith((f"{argv[0]}: ", "usage:")) or "ошибка вывода" in text, \
            f"{where}: {argv}: the message does not name the tool: {text[:300]!r}"
    new = {p.name for p in here.iterdir()} - before
    assert not [n for n in new if n.endswith(".tmp")], f"{where}: {argv} left {new}"
    return status, text


def _dxf_number(r: random.Random) -> str:
    return r.choice(NUMS) if r.random() < 0.3 else f"{r.uniform(-300, 300):.3f}"


def _entity(r: random.Random) -> list[str]:
    layer = r.choice(["0", "PADS", "PAD", "RING", "COND_W0.5", "X_Wnan", "X_W-1", "X_W1e9",
                      "TEXT", ""])
    kind = r.choice(["CIRCLE", "LINE", "ARC", "LWPOLYLINE", "TEXT", "POINT", "INSERT",
                     "SPLINE"])
    tags = ["0", kind, "8", layer, "10", _dxf_number(r), "20", _dxf_number(r)]
    if kind in ("CIRCLE", "ARC"):
        tags += ["40", _dxf_number(r)]
    if kind == "ARC":
        tags += ["50", _dxf_number(r), "51", _dxf_number(r)]
    if kind == "LINE":
        tags += ["11", _dxf_number(r), "21", _dxf_number(r)]
    if kind == "LWPOLYLINE":
        n = r.randint(0, 6)
        tags = ["0", kind, "8", layer, "90", str(n), "70", r.choice(["0", "1", "x"])]
        if r.random() < 0.5:
            tags += ["43", _dxf_number(r)]
        for _ in range(n):
            tags += ["10", _dxf_number(r), "20", _dxf_number(r)]
            if r.random() < 0.3:
                tags += ["42", _dxf_number(r)]
    if kind == "TEXT":
        tags += ["40", "1", "1", r.choice(["FIRST", "LAST", "1", "2", "3", "99", "", "0",
                                           "-1", "\u0416"])]
    if kind == "INSERT":
        tags += ["2", r.choice(["NOWHERE", "*MODEL_SPACE", ""])]
    return tags


def hostile_dxf(r: random.Random) -> str:
    if r.random() < 0.5:                           # entities of hostile values
        tags = ["0", "SECTION", "2", "ENTITIES"]
        for _ in range(r.randint(0, 12)):
            tags += _entity(r)
        tags += ["0", "ENDSEC", "0", "EOF"]
        return "\n".join(tags) + "\n"
    lines = BOARD_DXF.splitlines()                  # the example drawing, mutated
    for _ in range(r.randint(1, 4)):
        i = r.randrange(len(lines))
        what = r.choice(["value", "value", "drop", "dup", "swap", "cut", "junk"])
        if what == "value":
            i |= 1                                  # a value line (codes are even lines)
            if i < len(lines):
                lines[i] = r.choice(NUMS + ["CIRCLE", "EOF", "ENDSEC", "SECTION"])
        elif what == "drop":
            del lines[i]
        elif what == "dup":
            lines.insert(i, lines[i])
        elif what == "swap":
            j = r.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
        elif what == "cut":
            del lines[i:]
        else:
            lines[i] = hostile.random_text(r, 20)
        lines = lines or [""]
    return "\n".join(lines) + "\n"


def points_text(r: random.Random, ints: bool = False) -> str:
    rows = []
    x = 0.0
    for _ in range(r.randint(0, 30)):
        x += r.uniform(0.1, 20)
        row = (f"{int(x)} {r.randint(-2000, 2000)}" if ints
               else f"{x:.2f} {r.uniform(-50, 50):.3f}")
        if r.random() < 0.15:
            row = " ".join(r.choice(NUMS) for _ in range(r.randint(0, 3)))
        elif r.random() < 0.05:
            row = hostile.random_text(r, 20)
        elif r.random() < 0.05:
            row = ""
        rows.append(row)
    return "\n".join(rows) + r.choice(["\n", "", "\r\n"])


def contour_deck(r: random.Random) -> str:
    """An example deck of contours, whole (a fifth of the time) or with
    one package's cards mutated."""
    text = r.choice(CONTOURS)
    if r.random() < 0.2:
        return text
    lines = text.splitlines()
    head = [ln for ln in lines if ln[:1] in "*#"][:3]
    data = [ln for ln in lines if ln[:1] not in "*#CE"][1:]     # less the first name card
    body = hostile.guard(hostile.mutated_body(r, data))
    return "\n".join(head + ["EQ"] + body + ["E"]) + "\n"


#: RS-274X apertures: D10 is always round (the tracks' and arcs'), the
#: others of any kind; OC8 and RR are macros the file defines
APERTURES = ["C", "R", "O", "P", "OC8", "RR"]


def _gnum(r: random.Random) -> str:
    """A coordinate in 4.6 format: mostly on a board of +-200 mm, sometimes hostile."""
    if r.random() < 0.1:
        return r.choice(NUMS + ["99999999", "-99999999", "00", "2000000000000"])
    return str(r.randint(-200, 200) * 10000 + r.randint(0, 9999))


def _gsize(r: random.Random) -> str:
    """An aperture size in mm: mostly 0.005 to 5 mm, sometimes hostile."""
    return r.choice(NUMS) if r.random() < 0.1 else f"{r.uniform(0.005, 5):.4f}"


def hostile_gerber(r: random.Random) -> str:
    """A copper layer: apertures of every kind, flashes, tracks, arcs,
    regions, polarity and transforms, a quarter of the files then mutated
    line by line."""
    lines = [r.choice(["%FSLAX46Y46*%"] * 3 + ["%FSLAX24Y24*%", "%FSTAX36Y36*%"]),
             r.choice(["%MOMM*%", "%MOMM*%", "%MOIN*%"]),
             "%AMOC8*5,1,8,0,0,1.08239X$1,22.5*%", "%AMRR*21,1,$1,$2,0,0,$3*1,1,$4,0,0*%"]
    nap = r.randint(1, 6)
    for k in range(nap):
        kind = "C" if k == 0 else r.choice(APERTURES)
        if kind == "C":
            params = _gsize(r)
        elif kind in "RO":
            params = f"{_gsize(r)}X{_gsize(r)}"
        elif kind == "P":
            params = f"{_gsize(r)}X{r.choice(['3', '4', '8', '12', '0', '2'])}X{r.choice(['0', '45'])}"
        elif kind == "OC8":
            params = _gsize(r)
        else:
            params = f"{_gsize(r)}X{_gsize(r)}X{r.choice(['0', '90', '45'])}X{_gsize(r)}"
        lines.append(f"%ADD{10 + k}{kind},{params}*%")
    lines.append("D10*")
    for _ in range(r.randint(1, 30)):
        what = r.random()
        if what < 0.15:                         # now and then an aperture not defined
            lines.append(f"D{10 + r.randint(0, nap if r.random() < 0.1 else nap - 1)}*")
        elif what < 0.4:
            lines.append(f"X{_gnum(r)}Y{_gnum(r)}D03*")
        elif what < 0.65:
            lines += ["D10*"] if r.random() < 0.8 else []
            lines += [f"X{_gnum(r)}Y{_gnum(r)}D02*", f"X{_gnum(r)}Y{_gnum(r)}D01*"]
        elif what < 0.75:
            lines += ["D10*"] if r.random() < 0.8 else []
            lines += ["G75*", r.choice(["G02*", "G03*"]), f"X{_gnum(r)}Y{_gnum(r)}D02*",
                      f"X{_gnum(r)}Y{_gnum(r)}I{_gnum(r)}J{_gnum(r)}D01*", "G01*"]
        elif what < 0.85:
            lines += ["G36*", f"X{_gnum(r)}Y{_gnum(r)}D02*"]
            lines += [f"X{_gnum(r)}Y{_gnum(r)}D01*" for _ in range(r.randint(0, 6))]
            lines.append("G37*")
        elif what < 0.92:
            lines.append(r.choice(["%LPC*%", "%LPD*%"]))
        else:
            lines.append(r.choice(["G04 a comment*", "%LMX*%", "%LR45*%", "%LS2*%", "%LR0*%"]))
    lines.append("M02*")
    if r.random() < 0.25:
        for _ in range(r.randint(1, 4)):
            i = r.randrange(len(lines))
            how = r.random()
            if how < 0.3:
                del lines[i]
            elif how < 0.5:
                lines.insert(i, lines[i])
            elif how < 0.8:
                j = r.randrange(len(lines[i]) + 1)
                lines[i] = lines[i][:j] + r.choice("9-.*%XD,") + lines[i][j:]
            else:
                lines[i] = "".join(chr(r.randint(32, 126)) for _ in range(r.randint(0, 12)))
    return "\n".join(lines) + "\n"


def hostile_drill(r: random.Random) -> str:
    """An Excellon drill file: tools, hits (some before any tool, some of
    hostile numbers), slots, a line now and then replaced by random text."""
    tools = r.randint(1, 4)
    lines = ["M48", r.choice(["METRIC", "INCH", "METRIC,TZ", "INCH,LZ", "METRIC,000.000"])]
    lines += [f"T{k}C{_gsize(r)}" for k in range(1, tools + 1)]
    lines.append(r.choice(["%", "M95"]))
    for _ in range(r.randint(0, 15)):
        what = r.random()
        if what < 0.2:
            lines.append(f"T{r.randint(0, tools + 1)}")
        elif what < 0.75:
            lines.append(f"X{r.uniform(-100, 200):.3f}Y{r.uniform(-100, 200):.3f}"
                         if r.random() < 0.9 else f"X{r.choice(NUMS)}Y{r.choice(NUMS)}")
        elif what < 0.85:                 # a coordinate left out: the last one's
            lines.append(r.choice("XY") + f"{r.uniform(-100, 200):.3f}")
        else:
            lines.append(r.choice([f"G85X{r.uniform(0, 50):.3f}Y{r.uniform(0, 50):.3f}",
                                   "G00X1Y1\nM15\nG01X5Y5\nM16"]))
    lines.append("M30")
    if r.random() < 0.3:
        lines[r.randrange(len(lines))] = "".join(chr(r.randint(32, 126))
                                                 for _ in range(r.randint(0, 12)))
    return "\n".join(lines) + "\n"


KINDS = {"dxf2deck": 6, "profile": 3, "equidistant": 3, "punch5121": 3, "punch5121-decode": 3,
         "cnclink": 3, "split": 2, "dda": 2, "ural1": 2, "dxf2dmc": 2}
CHUNK = 100
PLAN = [(kind, n) for kind, k in KINDS.items() for n in range(k)]
PROGRAM = {"split": "seeds split", "punch5121-decode": "punch5121"}


@pytest.mark.hostile
@pytest.mark.parametrize("kind,n", PLAN, ids=[f"{k}-{n}" for k, n in PLAN])
def test_hostile_files(tmp_path, kind, n):
    seed = 3000 + 100 * list(KINDS).index(kind) + n
    r = random.Random(seed)
    for i in range(CHUNK):
        here = tmp_path / f"case{i}"
        here.mkdir()
        where = f"seed {seed}, input {i}"
        if kind == "dxf2deck":
            (here / "in.dxf").write_text(hostile_dxf(r), encoding="utf-8")
            argv = ["dxf2deck", str(here / "in.dxf"), "-o", str(here / "out.crd")]
            if r.random() < 0.2:
                argv += [r.choice(["--origin", "--start", "--tools", "--name"]),
                         ",".join(r.choice(NUMS) for _ in range(r.randint(1, 3)))]
            status, err = call(argv, here, where)
            if status == 2:
                assert not (here / "out.crd").exists(), f"{where}: a deck written with status 2"
        elif kind == "dxf2dmc":
            (here / "in.dxf").write_text(hostile_dxf(r), encoding="utf-8")
            argv = ["dxf2dmc", str(here / "in.dxf"), "-o", str(here / "out.dmc")]
            for opt in ("--mode", "--tolerance", "--counts-per-mm", "--speed", "--tool-bit"):
                if r.random() < 0.15:
                    argv += [opt, r.choice(NUMS + ["continuous", "intermittent"])]
            status, err = call(argv, here, where)
            if status == 2:
                assert not (here / "out.dmc").exists(), f"{where}: a program written with 2"
        elif kind == "ural1":
            (here / "in.crd").write_text(contour_deck(r), encoding="utf-8")
            argv = ["ural1", str(here / "in.crd"), "-o", str(here / "out.ptp")]
            for opt in ("--cutter", "--tolerance", "--feed", "--max"):
                if r.random() < 0.2:
                    argv += [opt, r.choice(NUMS + ["20", "0.02", "60", "9999"])]
            if r.random() < 0.2:
                argv += ["--path"]
            call(argv, here, where)
        elif kind == "profile":
            (here / "pts.txt").write_text(points_text(r), encoding="utf-8")
            argv = ["profile", str(here / "pts.txt"), "-o", str(here / "out.crd")]
            if r.random() < 0.3:
                argv += [r.choice(["--tol", "--chord"]), r.choice(NUMS[:12])]
            call(argv, here, where)
        elif kind == "equidistant":
            (here / "in.crd").write_text(contour_deck(r), encoding="utf-8")
            argv = ["equidistant", str(here / "in.crd"), "-o", str(here / "out.crd")]
            if r.random() < 0.3:
                argv += ["--cutter", r.choice(NUMS[:12])]
            if r.random() < 0.3:
                argv += ["--chords", r.choice(["0.01", "0.5", "nan", "-1", "0", "1e-6"])]
            if r.random() < 0.3:
                argv += ["--inside"]
            call(argv, here, where)
        elif kind == "punch5121":
            text = "\n".join(" ".join(hostile.number_word(r) for _ in range(r.randint(0, 7)))
                             for _ in range(r.randint(0, 20)))
            (here / "f.txt").write_text(text, encoding="utf-8")
            call(["punch5121", str(here / "f.txt"), "-o", str(here / "t.ptp")], here, where)
        elif kind == "punch5121-decode":
            data = hostile.random_bytes(r, 400)
            if r.random() < 0.7:
                data = bytes(b & 31 for b in data)
            (here / "t.ptp").write_bytes(data)
            call(["punch5121", "--decode", str(here / "t.ptp")], here, where)
        elif kind == "cnclink":
            if r.random() < 0.3:
                name, text = "in.crd", contour_deck(r)
            else:
                name, text = "in.txt", points_text(r, ints=True)
            (here / name).write_text(text, encoding="utf-8")
            argv = ["cnclink", str(here / name)]
            if r.random() < 0.3:
                argv += ["--corrupt", ",".join(hostile.number_word(r) for _ in range(2))]
            if r.random() < 0.2:
                argv += ["--resend", r.choice(["0", "1", "3", "-1", "x"])]
            call(argv, here, where)
        elif kind == "split":
            args = [hostile.number_word(r) for _ in range(r.randint(0, 3))]
            if r.random() < 0.6:
                args = ["--max", hostile.number_word(r)] + args
            call(["split", *args], here, where)
        else:
            args = [hostile.number_word(r) for _ in range(r.randint(1, 3))]
            if r.random() < 0.5:
                args += ["--method", r.choice(["binary", "decimal", "integrator", "master",
                                               "counter", "x"])]
            if r.random() < 0.3:
                args += ["--size", hostile.number_word(r)]
            if r.random() < 0.3:
                args += ["--max", hostile.number_word(r)]
            if r.random() < 0.2:
                args += ["--lag", hostile.number_word(r)]
            if r.random() < 0.2:
                args += ["--fixed-ratio"]
            call(["dda", *args], here, where)
    hostile.count(PROGRAM.get(kind, kind), CHUNK)


GERBER_CHUNKS = 4


@pytest.mark.hostile
@pytest.mark.parametrize("n", range(GERBER_CHUNKS))
def test_hostile_gerber_files(tmp_path, tenzor_exe, n):
    """gerber2deck on hostile copper layers and drill files: besides the
    promises of ``call``, a refused board leaves no deck, and every deck it
    writes is one TENZOR punches without an error."""
    seed = 5000 + n
    r = random.Random(seed)
    for i in range(CHUNK):
        here = tmp_path / f"case{i}"
        here.mkdir()
        where = f"seed {seed}, input {i}"
        (here / "c.gbr").write_text(hostile_gerber(r), encoding="ascii")
        argv = ["gerber2deck", str(here / "c.gbr"), "-o", str(here / "out.crd")]
        if r.random() < 0.5:
            (here / "d.drl").write_text(hostile_drill(r), encoding="ascii")
            argv += ["--drill", str(here / "d.drl")]
        if r.random() < 0.1:
            argv += [r.choice(["--tools", "--start"]),
                     ",".join(r.choice(NUMS + ["0.1", "0.5", "5"]) for _ in range(r.randint(1, 3)))]
        status, err = call(argv, here, where)
        deck = here / "out.crd"
        assert status != 0 or deck.exists(), f"{where}: status 0 and no deck"
        if status:
            assert not deck.exists(), f"{where}: a deck written with status {status}"
            continue
        tz = subprocess.run([str(tenzor_exe), str(deck), "-o", str(here / "tapes")],
                            capture_output=True, text=True, timeout=120)
        assert tz.returncode == 0, f"{where}: TENZOR refused gerber2deck's deck: {tz.stderr[:500]}"
    hostile.count("gerber2deck", CHUNK)


TAPEREPORT_CHUNKS = 2


@pytest.mark.hostile
@pytest.mark.parametrize("n", range(TAPEREPORT_CHUNKS))
def test_hostile_job_sheets(tmp_path, tenzor_exe, n):
    """tapereport on a board's job sheets, tapes and deck (TENZOR's, for
    seeds/tests/test_tapereport.py's deck), broken one to three ways: lines
    of a job sheet, a tape's rows, the deck's cards, files missing or made
    folders; the promises of ``call``."""
    from seeds.tests.test_tapereport import DECK
    seed = 6000 + n
    r = random.Random(seed)
    base = tmp_path / "base"
    base.mkdir()
    (base / "board.crd").write_text(DECK, encoding="ascii")
    tz = subprocess.run([str(tenzor_exe), "board.crd", "-o", "out"], cwd=base,
                        capture_output=True, text=True, timeout=120)
    assert tz.returncode == 0, tz.stderr
    files = sorted(p.name for p in (base / "out").iterdir())
    tapes = [f for f in files if f.endswith(".ptp")]
    for i in range(CHUNK):
        here = tmp_path / f"case{i}"
        shutil.copytree(base, here)
        where = f"seed {seed}, input {i}"
        out = here / "out"
        for _ in range(r.randint(1, 3)):
            what = r.random()
            if what < 0.35:
                job = out / r.choice(["BOARD.job", "BOARD-DRILL.job"])
                if job.is_file():
                    job.write_bytes(hostile.mutated_job(r, job.read_text(encoding="latin-1")))
            elif what < 0.65:
                tape = out / r.choice(tapes)
                if tape.is_dir():
                    continue
                data = tape.read_bytes() if tape.is_file() else b""
                tape.write_bytes(r.choice([hostile.mutated_tape(r, data),
                                           hostile.random_bytes(r, 300), data[:r.randint(0, 40)],
                                           hostile.valid_tape(r)]))
                if r.random() < 0.7:             # the sheet no longer records it
                    for job in filter(Path.is_file, out.glob("*.job")):
                        text = job.read_text(encoding="latin-1")
                        job.write_text("\n".join(ln for ln in text.splitlines()
                                                 if "sha256" not in ln and ".bytes" not in ln),
                                       encoding="latin-1")
            elif what < 0.9:
                deck = here / "board.crd"
                if not deck.is_file():
                    continue
                lines = deck.read_bytes().split(b"\n")
                k = r.randrange(len(lines))
                lines[k] = r.choice([hostile.random_bytes(r, 30).replace(b"\n", b" "),
                                     hostile.random_text(r, 40).encode("utf-8", "surrogatepass"),
                                     b"", lines[r.randrange(len(lines))], lines[k][:r.randint(0, 20)],
                                     b"E", b"C", b"BOARD-DRILL"])
                deck.write_bytes(b"\n".join(lines))
            else:
                victim = r.choice([here / "board.crd", out / "BOARD-DRILL.job",
                                   out / r.choice(tapes), out / "BOARD.job"])
                if victim.is_file():
                    victim.unlink()
                    if r.random() < 0.3:
                        victim.mkdir()
        argv = ["tapereport", str(out / r.choice(["BOARD.job", "BOARD.job", "BOARD-DRILL.job"]))]
        if r.random() < 0.7:
            argv += ["--deck", str(here / "board.crd")]
        status, err = call(argv, here, where)
        if status:
            named = [str(p) for p in (*here.rglob("*"), here / "board.crd", *out.glob("*"))]
            assert any(name in err for name in named), f"{where}: no file named: {err[:300]!r}"
        shutil.rmtree(here)
    hostile.count("tapereport", CHUNK)


# ---------------------------------------------------------------------------
# Faults the batch found, kept as their smallest inputs (docs/ROBUSTNESS.md).
# Each was a traceback or a run of minutes; each is now a message and 1 or 2.
# ---------------------------------------------------------------------------
FOUND = [
    # ezdxf's tag loader: a group code with no value at the end; a value not a number
    ("dxf2deck", "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n", 2, "not a DXF drawing"),
    ("dxf2deck", "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n1,5\n20\n0\n0\nENDSEC\n0\nEOF\n", 2,
     "not a DXF drawing"),
    # a point that is not finite: an AssertionError deep in the fit
    ("profile", "nan 1\n2 2\n3 inf\n", 1, "line 1: 'nan 1' is not a finite point"),
    ("profile --tol nan", "1 1\n2 2\n3 4\n", 2, "--tol nan"),
    ("profile --chord 0", "1 1\n2 2\n3 4\n", 2, "--chord 0"),      # ZeroDivisionError
    ("cnclink --corrupt x", "0 0\n5 5\n", 2, "--corrupt 'x'"),      # ValueError
    ("cnclink --resend -1", "0 0\n5 5\n", 2, "--resend -1"),        # "after 0 transmissions"
    # 99999999999 pulses: 3 million frames, 286112 blocks and a time-out
    ("cnclink", "0 0\n99999999999 0\n", 1, "more than the machine's largest"),
    ("split --max 1 99999999 1", None, 1, "more than 1000000"),      # two minutes, 10 GB
    ("dda 999999999 1", None, 2, "more than 2097152"),               # 2^30 pulses
    ("dda -1957 0 --size 99999999999999999999", None, 2, "1 to 64"),  # OverflowError
    ("dda -1862 2147483648 --method integrator", None, 2, "more than 2097152"),  # 10 ** 2^32
    # the valve held 2^31 generator periods for each of X's pulses: gigabytes
    ("dda 3 0 --method master --lag 2147483647", None, 2, "generator periods with the lag"),
    # ezdxf's tag loader on inf where an integer belongs: an OverflowError
    ("dxf2deck", "0\nSECTION\n2\nENTITIES\n0\nLINE\n62\ninf\n0\nENDSEC\n0\nEOF\n", 2,
     "not a DXF drawing: OverflowError"),
    # a chord tolerance of 1e-320 mm: a step angle of 0 (ZeroDivisionError);
    # profile's chords: test_a_profile_of_endless_chords_is_refused
    ("equidistant --chords 1e-320", CONTOURS[0], 1, "more than 1000000 chords"),
    # a cutter of 1e308, 0 or -1 mm, a feed of 0: a ZeroDivisionError, or a
    # path of a cutter of no size
    ("equidistant --cutter 1e308", CONTOURS[0], 2, "--cutter 1e+308: a cutter's diameter"),
    ("equidistant --cutter -1", CONTOURS[0], 2, "--cutter -1: a cutter's diameter"),
    ("ural1 --cutter 0", CONTOURS[0], 2, "--cutter 0: a cutter's diameter"),
    ("ural1 --feed 0", CONTOURS[0], 2, "--feed 0: a feed is a number of mm/min above 0"),
    # dxf2deck's options were read but not checked: a ValueError or an
    # OverflowError when the cards were written
    ("dxf2deck --tools 0.5,nan,1e308", BOARD_DXF, 2, "--tools 0.5,nan,1e308: 3 finite numbers of mm"),
    ("dxf2deck --start 2147483648,1", BOARD_DXF, 2, "--start 2147483648,1: the start point's"),
    ("dxf2deck --start inf,0", BOARD_DXF, 2, "--start inf,0: 2 finite numbers of mm"),
    ("dxf2deck --origin nan,0", BOARD_DXF, 2, "--origin nan,0: 2 finite numbers of mm"),
    # a point of 1e308 mm: an OverflowError when its chords became cards
    ("profile", "-1e308 0\n33.14 -18.495\n35.88 47.374\n", 1, "line 1: '-1e308 0' is off"),
    # found by reading the pages against the tools: a traceback (a name the
    # card writer refuses; 10^17 equal frames, a MemoryError), a message
    # that garbled or named nothing, blamed the deck for an option, or an
    # option that changed nothing
    ("dxf2deck --name ABCDEFGHIJKLMNOPQRSTU", BOARD_DXF, 2, "--name 'ABCDEFGHIJKLMNOPQRSTU': 1 to"),
    ("dxf2deck --name *X", BOARD_DXF, 2, "--name '*X': 1 to 18 letters"),
    ("dxf2deck --name E", BOARD_DXF, 2, "not a bare C or E (they end a package)"),
    ("split --equal 1000000000000000000000 1", None, 1, "equal frames of at most 9999 pulses, "
                                                       "more than 1000000"),
    ("dxf2deck --tools a,b,c", BOARD_DXF, 2, "--tools a,b,c: 3 finite numbers of mm"),
    ("dxf2deck --origin 1", BOARD_DXF, 2, "--origin 1: 2 finite numbers of mm"),
    ("dxf2dmc --origin inf,0", BOARD_DXF, 2, "--origin inf,0: 2 finite numbers of mm"),
    ("equidistant --chords 0", CONTOURS[0], 2, "--chords 0: a chord tolerance is a number"),
    ("ural1 --tolerance -1", CONTOURS[0], 2, "--tolerance -1: a chord tolerance is a number"),
    ("profile", "1 1\n2 \xe9\n", 1, "in.txt: line 2, column 3: byte 0xe9 is not ASCII"),
    ("equidistant", "\xe9\n", 1, "in.txt: line 1, column 1: byte 0xe9 is not ASCII"),
    ("dda 1000000000000000000000 1", None, 2, "needs a counter of 70 bits or decades, more "
                                              "than 64: give --max"),
    ("dda 10 5 --max 0", None, 2, "--max 0: a frame's limit is at least 1 pulse"),
    ("cnclink --stop-at 3", "0 0\n5 5\n", 2, "--stop-at is an option of --run"),
]


@pytest.mark.parametrize("command,text,status,words", FOUND, ids=[c for c, *_ in FOUND])
def test_found_by_the_batch(tmp_path, command, text, status, words):
    argv = command.split()
    if text is not None:
        path = tmp_path / ("in.dxf" if argv[0] in ("dxf2deck", "dxf2dmc") else "in.txt")
        path.write_bytes(text.encode("latin-1"))
        argv.insert(1, str(path))
    got, err = call(argv, tmp_path, command)
    assert got == status and words in err, (got, err)


def test_a_profile_of_endless_chords_is_refused(tmp_path):
    """profile -o --chord 1e-320 cut the profile into chords without end and
    took all the memory there is (the batch's process was killed at 23 GB)."""
    (tmp_path / "pts.txt").write_text("1 1\n2 2\n3 4\n4 7\n", encoding="ascii")
    status, err = call(["profile", str(tmp_path / "pts.txt"), "--chord", "1e-320", "-o",
                        str(tmp_path / "out.crd")], tmp_path, "profile --chord 1e-320")
    assert status == 1 and "more than 1000000 chords: give a larger --chord" in err, err
    assert not (tmp_path / "out.crd").exists()
