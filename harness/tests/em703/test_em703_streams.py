"""em703 reads what it is given, however it comes, and never crashes for want
of memory (docs/ROBUSTNESS.md, "em703").

A tape on a pipe, a FIFO or /dev/stdin is read to its end (its size is known
only there): the result is the same as from the file. A tape held by em703
is kept a byte a row. An allocation that fails, under a memory limit, ends
the run with one line on standard error and exit status 2, never with the
Fortran runtime's allocation error and its backtrace.
"""
from __future__ import annotations

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


@pytest.mark.parametrize("args", [
    ["list", "BIG"], ["view", "BIG"], ["sim", "BIG"],
    ["split", "--max", "1", "999999999", "1"],
], ids=["list", "view", "sim", "split"])
def test_memory_that_cannot_be_had_is_a_message_and_status_2(em703_exe, big_tape, args):
    args = [big_tape if a == "BIG" else a for a in args]
    got = subprocess.run([str(a) for a in (em703_exe, *args)], preexec_fn=_limit(150),
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=120)
    err = got.stderr.decode()
    assert got.returncode == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("em703: not enough memory for "), err
    assert lines[0].endswith("MB more); no half-made output is left"), err
