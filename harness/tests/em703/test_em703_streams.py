"""em703 reads what it is given, however it comes, and never crashes for want
of memory (docs/ROBUSTNESS.md, "em703").

A tape on a pipe, a FIFO or /dev/stdin is read to its end (its size is known
only there): the result is the same as from the file. A tape held by em703
is kept a byte a row. An allocation that fails, under a memory limit, ends
the run with one line on standard error and exit status 2, never with the
Fortran runtime's allocation error and its backtrace.
"""
from __future__ import annotations

import hashlib
import os
import resource
import subprocess
import threading
from pathlib import Path

import pytest


def run(*args, **kw) -> subprocess.CompletedProcess:
    return subprocess.run([str(a) for a in args], capture_output=True, timeout=120, **kw)


@pytest.fixture(scope="module")
def tape(example_tapes) -> Path:
    return max(example_tapes, key=lambda p: p.stat().st_size)


@pytest.mark.parametrize("sub", [["list"], ["list", "--code", "auto"], ["view"], ["sim"]])
def test_a_tape_on_a_pipe_reads_as_from_its_file(em703_exe, tape, sub):
    want = run(em703_exe, *sub, tape)
    assert want.returncode == 0, want.stderr
    got = run(em703_exe, *sub, "/dev/stdin", stdin=tape.open("rb"))
    assert (got.returncode, got.stdout) == (0, want.stdout), got.stderr
    # a real pipe, not a file opened as standard input
    proc = subprocess.Popen(["cat", str(tape)], stdout=subprocess.PIPE)
    got = run(em703_exe, *sub, "/dev/stdin", stdin=proc.stdout)
    proc.wait()
    assert (got.returncode, got.stdout) == (0, want.stdout), got.stderr


def test_a_tape_on_a_fifo_reads_as_from_its_file(em703_exe, tape, tmp_path):
    fifo = tmp_path / "tape.fifo"
    os.mkfifo(fifo)
    data = tape.read_bytes()

    def feed():
        with open(fifo, "wb") as f:
            # in pieces, as a slow writer would
            for i in range(0, len(data), 1000):
                f.write(data[i:i + 1000])
                f.flush()

    writer = threading.Thread(target=feed)
    writer.start()
    got = run(em703_exe, "list", fifo)
    writer.join()
    assert got.returncode == 0, got.stderr
    assert got.stdout == run(em703_exe, "list", tape).stdout


def test_an_empty_pipe_is_an_empty_tape_not_a_blank_one(em703_exe, tmp_path):
    got = run(em703_exe, "list", "/dev/stdin", stdin=subprocess.DEVNULL)
    assert got.returncode == 1
    assert "the tape is empty" in got.stderr.decode()


def test_a_directory_is_refused(em703_exe, tmp_path):
    got = run(em703_exe, "list", tmp_path)
    assert got.returncode == 2
    assert got.stderr.decode().strip() == f"{tmp_path}: cannot open: Is a directory"


def _limit(megabytes: int):
    def set_limit():
        resource.setrlimit(resource.RLIMIT_AS, (megabytes << 20, megabytes << 20))
    return set_limit


@pytest.fixture(scope="module")
def big_tape(tape, tmp_path_factory) -> Path:
    """About 30 MB: the frames of an example tape, over and over."""
    data = tape.read_bytes()
    a, b = data.index(b"\x1f"), data.rindex(b"\x1f")
    body = data[a + 1:b]
    path = tmp_path_factory.mktemp("big") / "big.ptp"
    path.write_bytes(data[:a + 1] + body * (30_000_000 // len(body)) + data[b:])
    return path


#: What each command is asked under the memory limit: a tape of about 30 MB
#: listed, simulated and drawn (view's rows limited to keep the test short),
#: and a split into 20 million frames (an array of them would need 320 MB).
BOUNDED = {
    "list": ["list", "BIG"],
    "sim": ["sim", "BIG"],
    "view": ["view", "BIG", "--rows", "1:200000"],
    "split": ["split", "--max", "1", "20000000", "1"],
}


@pytest.mark.parametrize("name", sorted(BOUNDED))
def test_big_inputs_and_outputs_take_bounded_memory(em703_exe, big_tape, name):
    """Under a 150 MB limit on the address space, the 30 MB tape lists, runs
    and draws, and a split writes 20 million frames, each exactly as without
    the limit: em703 holds the tape once (a byte a row), one decoded frame at
    a time, and a bounded output buffer."""
    args = [str(big_tape) if a == "BIG" else a for a in BOUNDED[name]]
    free = subprocess.run([str(em703_exe), *args], capture_output=True, timeout=120)
    limited = subprocess.run([str(em703_exe), *args], preexec_fn=_limit(150),
                             capture_output=True, timeout=120)
    assert (limited.returncode, limited.stderr) == (free.returncode, free.stderr)
    assert hashlib.sha256(limited.stdout).digest() == hashlib.sha256(free.stdout).digest()
    assert free.returncode == 0
    if name == "sim":          # millions of frames run, cycles unrolled
        assert int(free.stdout.split(b"executed = ")[1].split()[0]) > 5_000_000
    else:
        assert len(free.stdout) > 1_000_000


@pytest.mark.parametrize("command", ["list", "view", "sim"])
def test_memory_that_cannot_be_had_is_a_message_and_status_2(em703_exe, big_tape, command):
    """A tape bigger than the memory left: one line naming the tape, exit 2."""
    got = subprocess.run([str(em703_exe), command, str(big_tape)], preexec_fn=_limit(28),
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=120)
    err = got.stderr.decode()
    assert got.returncode == 2, err
    lines = err.strip().splitlines()
    assert lines == [f"{big_tape}: cannot read: not enough memory for "
                     f"{big_tape.stat().st_size} bytes"], err


def test_a_tape_to_check_that_fits_once_but_not_twice_is_a_message(em703_exe, big_tape):
    """em703 check holds a tape image and the program read from it: under a
    limit that holds the 30 MB tape but not both, one line saying so and exit
    2, not the Fortran runtime's allocation error."""
    got = subprocess.run([str(em703_exe), "check", str(big_tape)], preexec_fn=_limit(45),
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=120)
    assert (got.returncode, got.stderr.decode()) == (
        2, "em703: not enough memory for the program read from the tape (about 28 MB more); "
           "no half-made output is left\n")


def _million_pad_deck() -> str:
    """101 rows of 9999 pads of 0.50 mm (the small-pad tool: each pad a dot)
    at 0.10 mm steps, 5 mm apart: 1 009 899 pads."""
    cards = ["MILLION", "P" + " " * 9 + f"{10.0:10.2f}{10.0:10.2f}"]
    for r in range(101):
        cards.append("D" + " " * 9 + f"{0.0:10.2f}{r * 5.0:10.2f}{0.5:8.2f}{'':8}"
                     f"{9999:4d}{0.1:10.2f}{0.0:10.2f}")
    return "\n".join(cards + ["E"]) + "\n"


def test_a_tape_of_a_million_pads_in_rows_runs_and_draws(tenzor_exe, em703_exe, tmp_path):
    """em703 takes every tape TENZOR punches: a million pads in rows run two
    million frames once the cycles are unrolled (more than the simulator
    took before it counted cycle passes instead of unrolling them)."""
    deck = tmp_path / "million.crd"
    deck.write_text(_million_pad_deck())
    assert run(tenzor_exe, deck, "-o", tmp_path).returncode == 0
    job = {k.strip(): v.strip() for k, v in (line.split("=", 1) for line in
           (tmp_path / "MILLION.job").read_text().splitlines() if "=" in line)}
    sim = run(em703_exe, "sim", tmp_path / "MILLION-small.ptp")
    assert sim.returncode == 0, sim.stderr
    got = dict(line.split(" = ") for line in sim.stdout.decode().splitlines())
    assert int(got["executed"]) == 2 * 101 * 9999          # a dot and a move a pad
    assert got["travel_mm"] == job["small.travel_mm"]
    assert (got["end_x_mm"], got["end_y_mm"], got["tool_at_end"]) == ("0.00", "0.00", "up")
    gcode = run(em703_exe, "gcode", tmp_path / "MILLION.job", "-o", tmp_path / "m.ngc")
    assert gcode.returncode == 0, gcode.stderr
    blocks = (tmp_path / "m.ngc").read_bytes().split(b"\n")
    assert sum(1 for b in blocks if b.endswith(b" M03")) == 101 * 9999   # every pad drawn


def test_a_tape_too_long_to_write_is_refused_at_its_row(em703_exe, tmp_path):
    """A line drawn to and fro 999 999 999 times: sim runs it (cycle passes
    are counted), the writers, which write every executed frame, refuse it
    at the row of the cycle's first frame (row 22, after the leader and GM)
    and leave no file."""
    from harness.tape import Frame, encode
    tape = tmp_path / "saw.ptp"
    tape.write_bytes(encode([Frame(dx=300, dy=400, cyc=999_999_999, k=10),
                             Frame(dx=-300, dy=-400, k=10), Frame(k=20)]))
    sim = run(em703_exe, "sim", tape)
    assert b"executed = 1999999999\n" in sim.stdout, sim.stderr
    for sub in (["gcode", tape, "-o", tmp_path / "saw.ngc"],
                ["sim", tape, "--svg", tmp_path / "saw.svg"]):
        got = run(em703_exe, *sub)
        assert got.returncode == 1
        assert got.stderr.decode().startswith(f"{tape}: row 22: the tape runs 1999999999 frames"), \
            got.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["saw.ptp"]
