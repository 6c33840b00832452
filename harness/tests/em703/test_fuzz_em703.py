"""Fuzzing em703 (docs/ROBUSTNESS.md): malformed tape images, job sheets, texts to punch
and arguments.

Whatever it is given, ``em703`` must exit with 0, 1 or 2 (never by a
signal), print no Fortran run-time error or backtrace, say why on standard
error when it exits non-zero, and leave no partial or corrupt output file
and no temporary file.  An output file (``-o``, ``--svg``) written by a run
that exits non-zero must be complete: em703 writes a whole drawing or
program for a tape it could read but found at fault (``sim`` of a tape that
leaves the field, ``gcode`` of a job whose tape does not return to its
start), and it must end as its format ends (``</svg>``, ``M02``/``%``,
``M02*``).

CI runs the default profile; ``HYPOTHESIS_PROFILE=long`` runs 2500 examples
per property (docs/ROBUSTNESS.md).
"""
from __future__ import annotations

import os
import subprocess
from pathlib import Path

from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from harness.tape import encode

from harness.tests.helpers import write_job
from harness.tests.strategies import frame_lists
from harness.tests.helpers import FORBIDDEN

LONG = os.environ.get("HYPOTHESIS_PROFILE") == "long"
N = 2500 if LONG else 100
FUZZ = settings(max_examples=N, deadline=None,
                suppress_health_check=[HealthCheck.function_scoped_fixture,
                                       HealthCheck.too_slow, HealthCheck.data_too_large])

_counter = iter(range(10**9))

#: How each output format ends.
ENDINGS = {".svg": b"</svg>\n", ".ngc": b"%\n", ".gbr": b"M02*\n"}


def fresh(tmp_path: Path) -> Path:
    here = tmp_path / f"case{next(_counter)}"
    here.mkdir(parents=True)
    return here


def em(exe: Path, here: Path, *args: str, out: str | None = None) -> subprocess.CompletedProcess:
    """Run em703 in ``here``; ``out`` names its output file (relative to
    ``here``), checked against the promises of the module doc."""
    before = {p.name: p.read_bytes() for p in here.iterdir() if p.is_file()}
    proc = subprocess.run([str(exe), *args], cwd=here, capture_output=True, timeout=120,
                          stdin=subprocess.DEVNULL)
    err = proc.stderr.decode("latin-1")
    text = err + proc.stdout.decode("latin-1", "replace")[-20000:]
    rc = proc.returncode
    assert rc in (0, 1, 2), f"em703 {args}: exit status {rc} (negative: a signal)\n{err[-2000:]}"
    for word in FORBIDDEN:
        assert word not in text, f"em703 {args}: {word!r} printed:\n{err[-2000:]}"
    if rc:
        assert err.strip(), f"em703 {args}: exit {rc} without a message"
    after = {p.name: p for p in here.iterdir()}
    new = sorted(set(after) - set(before))
    if out is not None:
        if rc == 0 and not out.startswith("/"):
            assert out in after, f"em703 {args}: done, but {out} not written"
        if rc != 0 and out in after:
            data = after[out].read_bytes()
            if data != before.get(out):
                ending = ENDINGS[Path(out).suffix]
                assert data.endswith(ending), \
                    f"em703 {args}: exit {rc}, and {out} is cut short: ...{data[-200:]!r}"
    stray = [n for n in new if n != out]
    assert not stray, f"em703 {args}: left {stray}"
    return proc


# ---------------------------------------------------------------------------
# Tape images.
# ---------------------------------------------------------------------------
def tape_users(exe: Path, here: Path, data: bytes) -> None:
    (here / "t.ptp").write_bytes(data)
    for args in (["list", "t.ptp"], ["list", "--code", "K", "t.ptp"], ["view", "t.ptp"]):
        em(exe, here, *args)
    em(exe, here, "sim", "t.ptp", "--svg", "t.svg", out="t.svg")
    em(exe, here, "gcode", "t.ptp", "-o", "t.ngc", out="t.ngc")
    (here / "keep.ngc").write_bytes(b"an earlier good file\n")
    em(exe, here, "gcode", "t.ptp", "-o", "keep.ngc", out="keep.ngc")


@FUZZ
@given(data=st.binary(max_size=1500))
@example(data=b"")
@example(data=b"\x1f\x1f")
@example(data=bytes([0o37] + [0o20] + [9] * 400 + [0o16, 1, 0, 0o17, 0o37]))
@example(data=bytes([0o37, 0o12, 1, 0o16, 1, 3, 0o17, 0o37]))
def test_random_tape_bytes(em703_exe, tmp_path, data):
    tape_users(em703_exe, fresh(tmp_path), data)


@st.composite
def st_mutated_tape(draw: st.DrawFn) -> bytes:
    """A valid tape, then rows flipped, dropped, duplicated, inserted, swapped
    or the tape cut short."""
    rows = bytearray(encode(draw(frame_lists()), draw(st.sampled_from(["8", "K"]))))
    for _ in range(draw(st.integers(1, 4))):
        what = draw(st.sampled_from(["flip", "drop", "dup", "insert", "swap", "cut", "high"]))
        i = draw(st.integers(0, len(rows) - 1)) if rows else 0
        if not rows:
            rows.append(0)
        if what == "flip":
            rows[i] = draw(st.integers(0, 31))
        elif what == "high":
            rows[i] = draw(st.integers(32, 255))
        elif what == "drop":
            del rows[i]
        elif what == "dup":
            rows.insert(i, rows[i])
        elif what == "insert":
            rows.insert(i, draw(st.integers(0, 31)))
        elif what == "swap":
            j = draw(st.integers(0, len(rows) - 1))
            rows[i], rows[j] = rows[j], rows[i]
        else:
            del rows[draw(st.integers(0, len(rows))):]
    return bytes(rows)


@FUZZ
@given(data=st_mutated_tape())
def test_mutated_tapes(em703_exe, tmp_path, data):
    tape_users(em703_exe, fresh(tmp_path), data)


# ---------------------------------------------------------------------------
# Job sheets.
# ---------------------------------------------------------------------------
VALUES = ["", " ", "-1", "0", "0.00", "1e309", "nan", "inf", "999999999999", "-999999999999",
          "1:0", "0:1", "a:b", "1:1:1", "100:1", "1:100", "8", "K", "Q", "x" * 3000, "\x00",
          "../nowhere.ptp", "/", ".", "t-small.ptp", "\u0416", "0.001", "20.00", "1200.01"]


@st.composite
def st_job_text(draw: st.DrawFn, base: str) -> bytes:
    lines = base.splitlines()
    for _ in range(draw(st.integers(1, 5))):
        what = draw(st.sampled_from(["value", "value", "drop", "dup", "key", "raw", "blank"]))
        i = draw(st.integers(0, len(lines) - 1))
        if what == "value" and " = " in lines[i]:
            key = lines[i].split(" = ", 1)[0]
            lines[i] = f"{key} = {draw(st.sampled_from(VALUES))}"
        elif what == "drop":
            del lines[i]
            if not lines:
                lines = [""]
        elif what == "dup":
            lines.insert(i, lines[i])
        elif what == "key":
            lines.insert(i, f"{draw(st.sampled_from(['small.x', 'zz', '', 'scale ', '=']))} = 1")
        elif what == "raw":
            lines[i] = draw(st.text(max_size=60))
        else:
            lines.insert(i, "")
    return ("\n".join(lines) + draw(st.sampled_from(["\n", "", "\r\n"]))).encode("utf-8",
                                                                              "surrogatepass")


@FUZZ
@given(data=st.data())
def test_hostile_job_sheets(em703_exe, tmp_path, data):
    here = fresh(tmp_path)
    tapes = {k: encode(data.draw(frame_lists(max_items=3))) for k in ("small", "cond")}
    job = write_job(here, "T", tapes, {"small": "0.40"})
    job.write_bytes(data.draw(st_job_text(job.read_text())))
    for sub, ext in (("svg", "svg"), ("gerber", "gbr"), ("gcode", "ngc")):
        em(em703_exe, here, sub, "T.job", "-o", f"out.{ext}", out=f"out.{ext}")


# ---------------------------------------------------------------------------
# Punching text, splitting moves, arguments.
# ---------------------------------------------------------------------------
@FUZZ
@given(text=st.binary(max_size=2000), code=st.sampled_from(["iso", "eia"]))
@example(text=b"", code="iso")
@example(text=b"G00 X1\x00\xff\n" * 3, code="eia")
def test_punch_any_bytes(em703_exe, tmp_path, text, code):
    here = fresh(tmp_path)
    (here / "p.txt").write_bytes(text)
    em(em703_exe, here, "punch", "--code", code, "-o", "p.ptp", "p.txt", out="p.ptp")


#: Pieces of seed 004's programs in all three frames, to build hostile ones from.
PIECES = ["%\n", "\n", "\t", "\t\t\t", "001", "999", "000", "N001 ", "N", "G01", "G17 ", "01",
          "17", "45", "+000000", "-123456", "+", "-", "  ", " ", "X+000100 ", "M06", "07", "(", ")",
          "(a, b)\n", "\r\n", "\x00", "\x80", "\xff", "9" * 60]


@FUZZ
@given(text=st.one_of(st.binary(max_size=1500),
                      st.lists(st.sampled_from(PIECES), max_size=60).map(
                          lambda p: "".join(p).encode("latin-1"))),
       frame=st.sampled_from(["address", "fixed", "variable"]))
@example(text=b"%\n001\t\t\t\t\t\t\t\t\t\t\t\t\n%\n", frame="variable")
@example(text=b"%\n001" + b"9" * 45 + b"\n%\n", frame="fixed")
@example(text=b"%\n\t\n001\t01\t\t+\n%", frame="variable")
@example(text=b"%\nN001 G17\x7f\x1b\rX\n001\x7f\n%\n", frame="address")
def test_check_any_program(em703_exe, tmp_path, text, frame):
    """em703 check in every frame of anything, as text and punched on either
    tape; its messages are short and carry no control character raw."""
    here = fresh(tmp_path)
    (here / "p.iso").write_bytes(text)
    checks = [em(em703_exe, here, "check", "--frame", frame, "p.iso")]
    for code in ("iso", "eia"):
        tape = f"p.{code}.ptp"
        if em(em703_exe, here, "punch", "--code", code, "-o", tape, "p.iso", out=tape).returncode == 0:
            checks.append(em(em703_exe, here, "check", "--frame", frame, tape))
    for proc in checks:
        for line in proc.stderr.split(b"\n")[:-1]:
            assert len(line) < 400 and not any(b < 32 or b == 127 for b in line), line


NUMBERS = ["0", "1", "-1", "9999", "10000", "99999999", "2147483647", "2147483648",
           "-2147483648", "-2147483649", "99999999999999999999", "1e9", "1.5", "", "-", "x",
           "--max", "0x10"]


@FUZZ
@given(args=st.lists(st.sampled_from(NUMBERS), max_size=5))
def test_split_any_numbers(em703_exe, tmp_path, args):
    em(em703_exe, fresh(tmp_path), "split", *args)


WORDS = ["list", "sim", "svg", "gcode", "gerber", "punch", "view", "split", "--help", "-h",
         "-o", "--svg", "--code", "iso", "eia", "8", "K", "auto", "--scale", "1:1", "0:0",
         "--start", "1,2", "x,", "--chords", "0.01", "--rows", "5:2", "--utf8", "--bare",
         "--z", "t.ptp", "T.job", "nothing", "", "-", "/", "\x01", "check", "--frame", "fixed",
         "variable", "address", "--dialect", "iso-1970s"]


@FUZZ
@given(args=st.lists(st.sampled_from(WORDS), max_size=6))
def test_random_arguments(em703_exe, tmp_path, args):
    here = fresh(tmp_path)
    (here / "t.ptp").write_bytes(encode([]))
    write_job(here, "T", {}, {})
    before = sorted(p.name for p in here.iterdir())
    proc = subprocess.run([str(em703_exe), *args], cwd=here, capture_output=True, timeout=60,
                          stdin=subprocess.DEVNULL)
    err = proc.stderr.decode("latin-1")
    assert proc.returncode in (0, 1, 2), err
    for word in FORBIDDEN:
        assert word not in err
    if proc.returncode:
        assert err.strip()
        # a failed run leaves no new file, unless a whole drawing or program
        for p in here.iterdir():
            if p.name not in before:
                assert any(p.read_bytes().endswith(e) for e in ENDINGS.values()), p.name
