"""`em703 list` against the harness's own decoder (harness/tape.py): frame for
frame on every tape TENZOR punches from examples/, on random tapes in both
codes, and on corrupted tapes, where both must stop at the same row."""

from __future__ import annotations

import random
import re
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from harness.tape import Frame, TapeError, decode, encode, tape_text

from harness.tests.helpers import run
from harness.tests.strategies import frame_lists

ERROR_LINE = re.compile(r"^(?P<file>.+): row (?P<row>\d+): (?P<message>.+)\n$")


def test_every_example_tape_lists_as_the_harness_decodes_it(em703_exe, example_tapes) -> None:
    for tape in example_tapes:
        expected = decode(tape.read_bytes())
        for utf8 in (False, True):
            flags = ["--utf8"] if utf8 else []
            proc = run(em703_exe, "list", tape, *flags, check=0)
            lines = proc.stdout.decode("utf-8").split("\n", 1)
            assert lines[0] == (f"# code {expected.code}"
                                + ("" if _told(tape.read_bytes()) else
                                   " (no digit row tells 8 from K)")
                                + f", {expected.rows} rows, {len(expected.frames)} frame"
                                + ("" if len(expected.frames) == 1 else "s"))
            assert lines[1] == tape_text(expected, utf8=utf8), tape
            bare = run(em703_exe, "list", "--bare", tape, *flags, check=0)
            assert bare.stdout.decode("utf-8") == tape_text(expected, utf8=utf8)
        # and the frame text TENZOR wrote beside the tape
        assert run(em703_exe, "list", "--bare", tape).stdout.decode() == \
            tape.with_suffix(".txt").read_text()


def _told(data: bytes) -> bool:
    """Does a digit row tell code 8 from code K?"""
    return any(b in (0o03, 0o05, 0o06, 0o11, 0o23, 0o25, 0o26, 0o31) for b in data)


@settings(max_examples=25, deadline=None)
@given(frames=frame_lists(), code=st.sampled_from(["8", "K"]))
def test_random_tapes_list_frame_for_frame(em703_exe, tmp_path_factory, frames: list[Frame],
                                           code: str) -> None:
    data = encode(frames, code)
    path = tmp_path_factory.mktemp("list") / "t.ptp"
    path.write_bytes(data)
    proc = run(em703_exe, "list", "--bare", path, check=0)
    assert proc.stdout.decode() == tape_text(frames)
    forced = run(em703_exe, "list", "--bare", "--code", code, path, check=0)
    assert forced.stdout == proc.stdout
    head = run(em703_exe, "list", path, check=0).stdout.decode().splitlines()[0]
    assert head.startswith(f"# code {decode(data).code}")


def _corrupt(data: bytes, rng: random.Random) -> bytes:
    bad = bytearray(data)
    for _ in range(rng.randint(1, 3)):
        i = rng.randrange(len(bad))
        op = rng.randint(0, 2)
        if op == 0:
            bad[i] = rng.randrange(32) if rng.random() < 0.9 else rng.randrange(256)
        elif op == 1 and len(bad) > 1:
            del bad[i]
        else:
            bad.insert(i, rng.randrange(32))
    return bytes(bad)


def _agree(em703_exe: Path, path: Path, data: bytes, code: str = "auto") -> None:
    """em703 list and harness decode agree on a tape: same frames, or an
    error at the same row (exit 1, one line `FILE: row N: message`)."""
    path.write_bytes(data)
    proc = run(em703_exe, "list", "--bare", "--code", code, path)
    try:
        expected = decode(data, code)
    except TapeError as exc:
        assert proc.returncode == 1, (proc.returncode, exc)
        err = proc.stderr.decode()
        match = ERROR_LINE.match(err)
        assert match and match["file"] == str(path), err
        assert int(match["row"]) == exc.row, f"em703: {err.strip()} | harness: {exc}"
        # the frames before the error, after the opening GM if there was one
        out = proc.stdout.decode()
        if exc.message.startswith(("missing GM at the start", "data before the opening GM")):
            assert out == "", out
        elif out:
            assert out.startswith("GM\n") and (out == "GM\n" or not out.endswith("\nGM\n"))
        return
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.decode() == tape_text(expected)


def test_corrupted_example_tapes_fail_at_the_same_row(em703_exe, example_tapes, tmp_path) -> None:
    rng = random.Random(703)
    path = tmp_path / "bad.ptp"
    for n in range(150):
        tape = example_tapes[n % len(example_tapes)]
        _agree(em703_exe, path, _corrupt(tape.read_bytes(), rng),
               rng.choice(["auto", "auto", "8", "K"]))


@settings(max_examples=20, deadline=None)
@given(frames=frame_lists(max_items=4), code=st.sampled_from(["8", "K"]), seed=st.integers(0, 10**6))
def test_corrupted_random_tapes_fail_at_the_same_row(em703_exe, tmp_path_factory, frames, code,
                                                     seed) -> None:
    data = _corrupt(encode(frames, code), random.Random(seed))
    _agree(em703_exe, tmp_path_factory.mktemp("bad") / "t.ptp", data)


# Each class of error the issue names, with its row and what was expected.
GM, X, DX, DY, CYC, K, KK, MINUS = 0o37, 0o12, 0o20, 0o21, 0o30, 0o16, 0o17, 0o14
LEAD = [0, 0, GM]


@pytest.mark.parametrize("rows, code, row, words", [
    (LEAD + [DX, 5, K, 1, 0, KK, 0o33, GM], "auto", 10, "not an EM-703 code"),
    (LEAD + [DX, 5, K, 1, 0, KK, 5, K, 2, 0, KK, GM], "auto", 10, "at the start of a frame"),
    (LEAD + [DX, 3, K, 1, 0, KK, GM], "K", 5, "parity error"),
    (LEAD + [DX, 5, K, 1, 0, KK], "auto", 10, "missing GM"),
    ([0, DX, 5, K, 1, 0, KK, GM], "auto", 2, "data before the opening GM"),
    (LEAD + [DX, 5, K, 1, 2, KK, GM], "auto", 6, "K 12 is not a command"),
    (LEAD + [X, 3, 0, 0, DX, MINUS, 3, 0, 0, DY, MINUS, 3, 1, 0, K, 1, 3, KK, GM], "auto", 8,
     "not on the circle"),
    (LEAD + [DX, 5, CYC, 2, K, 1, 0, KK, GM], "auto", 6, "CYC needs a following frame"),
    # a zero before a digit, the tape's last row, or the zero the last row itself
    (LEAD + [DX, 0, 5], "auto", 5, "leading zero in DX (a number is punched from its first"),
    (LEAD + [DX, 0], "auto", 5, "DX is 0: a zero value is never punched"),
])
def test_each_error_names_its_row(em703_exe, tmp_path, rows, code, row, words) -> None:
    path = tmp_path / "bad.ptp"
    path.write_bytes(bytes(rows))
    proc = run(em703_exe, "list", "--code", code, path, check=1)
    err = proc.stderr.decode()
    assert err.count("\n") == 1 and err.startswith(f"{path}: row {row}: ") and words in err, err
    with pytest.raises(TapeError) as exc:
        decode(bytes(rows), code)
    assert exc.value.row == row


@pytest.mark.parametrize("command", ["list", "sim", "gcode"])
def test_each_reader_says_what_the_decoder_says(em703_exe, tmp_path, command) -> None:
    """Every broken tape of the oracle's own table (harness/tests/oracle/
    test_tape.py: each fault, the mixed code, a tenth digit) is refused by
    `em703 list`, `sim` and `gcode` with the decoder's row and message, word
    for word: sim reads the tape again for each walk, and must not forget
    which row told the variant.  gcode has no --code: it reads as "auto"."""
    from harness.tests.oracle.test_tape import DECODE_ERRORS
    path = tmp_path / "bad.ptp"
    wrong = []
    for name, data, code, row, message in DECODE_ERRORS:
        path.write_bytes(data)
        if command == "gcode":
            try:
                decode(data, "auto")
                continue                    # a fault of code 8 or K alone
            except TapeError as exc:
                row, message = exc.row, exc.message
            proc = run(em703_exe, command, path, "-o", tmp_path / "bad.nc", check=1)
        else:
            proc = run(em703_exe, command, path, "--code", code, check=1)
        if proc.stderr.decode() != f"{path}: row {row}: {message}\n":
            wrong.append((name, proc.stderr.decode()))
    assert wrong == [] and len(DECODE_ERRORS) >= 45
