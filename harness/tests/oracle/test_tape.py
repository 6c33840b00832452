"""Tests of harness.tape: report goldens, round trips, corruptions, errors."""

from __future__ import annotations

import math

import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from harness.__main__ import main
from harness.report import EXAMPLES, OCR_TEXT, example_text
from harness.tape import (
    Frame, Tape, TapeError, decode, encode, frame_text, on_circle,
    parse_frame_text, parse_tape_text, tape_text,
)

# ---------------------------------------------------------------------------
# The report's examples punched by hand from Table I (octal rows between the
# GMs), once per variant.  Written out, not computed from harness.tape.
# ---------------------------------------------------------------------------
HAND_ROWS: dict[int, dict[str, list[int]]] = {
    1: {  # X - 3 0 0 K 1 1 KK
        "8": [0o12, 0o14, 0o03, 0o00, 0o00, 0o16, 0o01, 0o01, 0o17],
        "K": [0o12, 0o14, 0o23, 0o00, 0o00, 0o16, 0o01, 0o01, 0o17],
    },
    2: {  # Y 1 0 0 0 0 K 1 3 KK
        "8": [0o13, 0o01, 0o00, 0o00, 0o00, 0o00, 0o16, 0o01, 0o03, 0o17],
        "K": [0o13, 0o01, 0o00, 0o00, 0o00, 0o00, 0o16, 0o01, 0o23, 0o17],
    },
    3: {  # X 2 0 0 0 DX - 2 0 0 0 DY - 2 0 0 0 K 1 3 KK
        "8": [0o12, 0o02, 0o00, 0o00, 0o00,
              0o20, 0o14, 0o02, 0o00, 0o00, 0o00,
              0o21, 0o14, 0o02, 0o00, 0o00, 0o00,
              0o16, 0o01, 0o03, 0o17],
        "K": [0o12, 0o02, 0o00, 0o00, 0o00,
              0o20, 0o14, 0o02, 0o00, 0o00, 0o00,
              0o21, 0o14, 0o02, 0o00, 0o00, 0o00,
              0o16, 0o01, 0o23, 0o17],
    },
    4: {  # DX - 5 0 0 DY - 5 0 0 K 1 0 KK
        "8": [0o20, 0o14, 0o05, 0o00, 0o00, 0o21, 0o14, 0o05, 0o00, 0o00,
              0o16, 0o01, 0o00, 0o17],
        "K": [0o20, 0o14, 0o25, 0o00, 0o00, 0o21, 0o14, 0o25, 0o00, 0o00,
              0o16, 0o01, 0o00, 0o17],
    },
    5: {  # DX 3 0 0 DY 4 0 0 CYC 8 K 1 0 KK / DX 1 0 0 DY - 4 0 0 K 1 0 KK
        "8": [0o20, 0o03, 0o00, 0o00, 0o21, 0o04, 0o00, 0o00, 0o30, 0o10,
              0o16, 0o01, 0o00, 0o17,
              0o20, 0o01, 0o00, 0o00, 0o21, 0o14, 0o04, 0o00, 0o00,
              0o16, 0o01, 0o00, 0o17],
        "K": [0o20, 0o23, 0o00, 0o00, 0o21, 0o04, 0o00, 0o00, 0o30, 0o10,
              0o16, 0o01, 0o00, 0o17,
              0o20, 0o01, 0o00, 0o00, 0o21, 0o14, 0o04, 0o00, 0o00,
              0o16, 0o01, 0o00, 0o17],
    },
}

#: The frames of each example, written as Python values by hand.
HAND_FRAMES: dict[int, list[Frame]] = {
    1: [Frame(x=-300, k=11)],
    2: [Frame(y=10000, k=13)],
    3: [Frame(x=2000, dx=-2000, dy=-2000, k=13)],
    4: [Frame(dx=-500, dy=-500, k=10)],
    5: [Frame(dx=300, dy=400, cyc=8, k=10), Frame(dx=100, dy=-400, k=10)],
}

REPORT_FRAMES = [HAND_FRAMES[n] for n in sorted(HAND_FRAMES)]


def image(body: list[int], leader: int = 20) -> bytes:
    """A full tape image around hand rows: leader, GM, body, GM, trailer."""
    return bytes([0] * leader + [0o37] + body + [0o37] + [0] * leader)


def with_gm(*rows: int) -> bytes:
    """Rows framed by GM with a 2-row leader: row 3 is GM, row 4 the first."""
    return bytes([0, 0, 0o37, *rows, 0o37, 0, 0])


# ---------------------------------------------------------------------------
# Report goldens.
# ---------------------------------------------------------------------------
def test_examples_table_is_complete() -> None:
    assert [n for n, _ref, _lines in EXAMPLES] == [1, 2, 3, 4, 5]
    for n, ref, lines in EXAMPLES:
        assert ref == f"report, section Состав кадра, Пример {n}"
        assert lines and all(line.endswith(" KK") for line in lines)
        assert n in OCR_TEXT


@pytest.mark.parametrize("number", sorted(HAND_FRAMES))
def test_example_text_golden(number: int) -> None:
    assert parse_tape_text(example_text(number)) == HAND_FRAMES[number]
    assert tape_text(HAND_FRAMES[number]) == example_text(number)


@pytest.mark.parametrize("code", ["8", "K"])
@pytest.mark.parametrize("number", sorted(HAND_ROWS))
def test_example_encode_matches_hand_rows(number: int, code: str) -> None:
    frames = parse_tape_text(example_text(number))
    assert encode(frames, code) == image(HAND_ROWS[number][code])
    assert encode(frames, code, leader=0) == image(HAND_ROWS[number][code], 0)


@pytest.mark.parametrize("code", ["8", "K"])
@pytest.mark.parametrize("number", sorted(HAND_ROWS))
def test_example_decode_hand_rows(number: int, code: str) -> None:
    data = image(HAND_ROWS[number][code])
    for mode in (code, "auto"):
        tape = decode(data, mode)
        assert tape == Tape(code=code, frames=HAND_FRAMES[number], rows=len(data))
        assert tape_text(tape) == example_text(number)


def test_example_5_utf8_text() -> None:
    text = tape_text(HAND_FRAMES[5], utf8=True)
    assert text == ("ГМ\n"
                    "ΔX300 ΔY400 Ц8 К10 КК\n"
                    "ΔX100 ΔY-400 К10 КК\n"
                    "ГМ\n")
    assert parse_tape_text(text) == HAND_FRAMES[5]
    assert frame_text(HAND_FRAMES[1][0], utf8=True) == "X-300 К11 КК"


def test_frame_text_forms() -> None:
    assert frame_text(Frame(x=-300, k=11)) == "X-300 K11 KK"
    assert frame_text(Frame(dx=300, dy=400, cyc=8, k=10)) == "DX300 DY400 CYC8 K10 KK"
    assert frame_text(Frame(k=20)) == "K20 KK"
    assert frame_text(Frame()) == "K10 KK"


def test_controlled_digits_have_odd_parity() -> None:
    """Table I: in code K every non-zero digit has an odd number of holes."""
    for digit in range(1, 10):
        rows = HAND_ROWS_DIGITS[digit]
        assert bin(rows).count("1") % 2 == 1
        assert encode([Frame(dx=digit, k=10)], "K", leader=0)[2] == rows


HAND_ROWS_DIGITS = {1: 0o01, 2: 0o02, 3: 0o23, 4: 0o04, 5: 0o25, 6: 0o26,
                    7: 0o07, 8: 0o10, 9: 0o31}


def test_auto_without_distinguishing_digits_is_code_8() -> None:
    data = encode([Frame(dx=100, dy=-200, k=20), Frame(k=10)], "K")
    assert data == encode([Frame(dx=100, dy=-200, k=20), Frame(k=10)], "8")
    assert decode(data).code == "8"
    assert decode(data, "K").code == "K"


def test_empty_array_decodes() -> None:
    assert decode(bytes([0o37, 0o37])) == Tape("8", [], 2)
    assert encode([], "K", leader=1) == bytes([0, 0o37, 0o37, 0])


# ---------------------------------------------------------------------------
# Strategies: valid frames and frame lists.
# ---------------------------------------------------------------------------
FIELD = 120_000                                   # 1200 mm in 0.01 mm
coords = st.integers(-FIELD, FIELD)


@st.composite
def circle_start(draw: st.DrawFn) -> tuple[int, int]:
    x = draw(st.integers(-1_000_000, 1_000_000))
    limit = math.isqrt(1_000_000 ** 2 - x * x)
    y = draw(st.integers(-limit, limit))
    assume(x or y)
    return x, y


@st.composite
def arc_frames(draw: st.DrawFn) -> Frame:
    x, y = draw(circle_start())
    k = draw(st.sampled_from([11, 13]))
    if draw(st.booleans()):
        # exact lattice symmetries of the circle
        ex, ey = draw(st.sampled_from([(-y, x), (y, -x), (-x, -y), (x, -y),
                                       (-x, y), (y, x), (-y, -x)]))
    else:
        r, a0 = math.hypot(x, y), math.atan2(y, x)
        theta = draw(st.floats(0, 2 * math.pi))
        ex, ey = round(r * math.cos(a0 + theta)), round(r * math.sin(a0 + theta))
    assume(on_circle(x, y, ex - x, ey - y))
    return Frame(x=x, y=y, dx=ex - x, dy=ey - y, k=k)


def single_frames() -> st.SearchStrategy[Frame]:
    lines = st.builds(Frame, dx=coords, dy=coords, k=st.sampled_from([10, 20]))
    circles = st.builds(lambda xy, k: Frame(x=xy[0], y=xy[1], k=k),
                        circle_start(), st.sampled_from([11, 13]))
    return st.one_of(lines, circles, arc_frames())


@st.composite
def frame_lists(draw: st.DrawFn, max_items: int = 5) -> list[Frame]:
    frames: list[Frame] = []
    for _ in range(draw(st.integers(0, max_items))):
        first = draw(single_frames())
        if draw(st.booleans()):                   # a cycle pair
            cyc = draw(st.integers(2, 999))
            frames += [Frame(first.x, first.y, first.dx, first.dy, cyc, first.k),
                       draw(single_frames())]
        else:
            frames.append(first)
    return frames


codes = st.sampled_from(["8", "K"])


def _pin_report(test):  # type: ignore[no-untyped-def]
    """Pin every report example, in both codes, with @example."""
    for frames in REPORT_FRAMES:
        for code in ("8", "K"):
            test = example(frames=frames, code=code)(test)
    return test


# ---------------------------------------------------------------------------
# Round trips.
# ---------------------------------------------------------------------------
@_pin_report
@given(frames=frame_lists(), code=codes)
def test_round_trip_bytes(frames: list[Frame], code: str) -> None:
    data = encode(frames, code)
    assert decode(data, code).frames == frames
    auto = decode(data)
    assert auto.frames == frames
    assert encode(auto.frames, auto.code) == data
    assert decode(data, code).rows == len(data)


@_pin_report
@given(frames=frame_lists(), code=codes)
def test_round_trip_text(frames: list[Frame], code: str) -> None:
    for utf8 in (False, True):
        text = tape_text(frames, utf8=utf8)
        assert parse_tape_text(text) == frames
        for line, frame in zip(text.splitlines()[1:-1], frames):
            assert parse_frame_text(line) == frame
    assert tape_text(decode(encode(frames, code))) == tape_text(frames)


def _check_corruption(data: bytes, index: int, value: int, code: str) -> None:
    bad = bytearray(data)
    bad[index] = value
    for mode in (code, "auto"):
        try:
            tape = decode(bytes(bad), mode)
        except TapeError as exc:
            assert 1 <= exc.row <= len(bad), str(exc)
            assert str(exc) == f"row {exc.row}: {exc.message}"
        else:
            assert value <= 0o37
            assert encode(tape.frames, tape.code, leader=2) == bytes(bad)


@given(frames=frame_lists(max_items=3), code=codes, data=st.data())
@settings(max_examples=300)
def test_single_row_corruption(frames: list[Frame], code: str,
                               data: st.DataObject) -> None:
    tape = encode(frames, code, leader=2)
    index = data.draw(st.integers(0, len(tape) - 1), label="index")
    value = data.draw(st.integers(0, 255).filter(lambda v: v != tape[index]),
                      label="value")
    _check_corruption(tape, index, value, code)


@pytest.mark.parametrize("code", ["8", "K"])
@pytest.mark.parametrize("number", sorted(HAND_FRAMES))
def test_every_corruption_of_report_examples(number: int, code: str) -> None:
    tape = encode(HAND_FRAMES[number], code, leader=2)
    for index in range(len(tape)):
        for value in range(256):
            if value != tape[index]:
                _check_corruption(tape, index, value, code)


# ---------------------------------------------------------------------------
# Decoder errors: row number and message.
# ---------------------------------------------------------------------------
DX3_K10 = [0o20, 0o03, 0o16, 0o01, 0o00, 0o17]           # DX3 K10 KK

DECODE_ERRORS: list[tuple[str, bytes, str, int, str]] = [
    ("field out of order", with_gm(0o20, 0o03, 0o13, 0o03, 0o16, 0o01, 0o03, 0o17),
     "8", 6, "expected digit, DY, CYC or K after DX, found Y (13)"),
    ("field twice", with_gm(0o12, 0o03, 0o12, 0o03, 0o16, 0o01, 0o03, 0o17),
     "8", 6, "expected digit, Y, DX, DY, CYC or K after X, found X (12)"),
    ("KK without K", with_gm(0o20, 0o03, 0o17),
     "8", 6, "expected digit, DY, CYC or K after DX, found KK (17)"),
    ("after CYC digits", with_gm(0o20, 0o03, 0o30, 0o02, 0o21, 0o01, 0o16, 0o01,
                                 0o00, 0o17, *DX3_K10),
     "8", 8, "expected digit or K after CYC, found DY (21)"),
    ("frame starts with KK", with_gm(0o17),
     "8", 4, "expected X, Y, DX, DY, CYC, K or GM at the start of a frame, found KK (17)"),
    ("frame starts with digit", with_gm(0o01, *DX3_K10),
     "8", 4, "expected X, Y, DX, DY, CYC, K or GM at the start of a frame, "
             "found digit 1 (01)"),
    ("K one digit", with_gm(0o16, 0o01, 0o17),
     "8", 6, "K must be followed by exactly two digits, found KK (17)"),
    ("K three digits", with_gm(0o16, 0o01, 0o00, 0o00, 0o17),
     "8", 7, "K must be followed by exactly two digits, found digit 0 (00)"),
    ("K no digit", with_gm(0o16, 0o17),
     "8", 5, "K must be followed by exactly two digits, found KK (17)"),
    ("K not a command", with_gm(0o20, 0o03, 0o16, 0o01, 0o05, 0o17),
     "8", 6, "K 15 is not a command (10, 20, 11, 13)"),
    ("K 00", with_gm(0o16, 0o00, 0o00, 0o17),
     "8", 4, "K 00 is not a command (10, 20, 11, 13)"),
    ("K then not KK", with_gm(0o20, 0o03, 0o16, 0o01, 0o00, 0o12),
     "8", 9, "expected KK after K10, found X (12)"),
    ("leading zero", with_gm(0o20, 0o00, 0o03, 0o16, 0o01, 0o00, 0o17),
     "8", 5, "leading zero in DX (a number is punched from its first digit that is not 0)"),
    ("leading zero after minus", with_gm(0o21, 0o14, 0o00, 0o03, 0o16, 0o01, 0o00, 0o17),
     "8", 6, "leading zero in DY (a number is punched from its first digit that is not 0)"),
    ("zero value", with_gm(0o20, 0o00, 0o16, 0o01, 0o00, 0o17),
     "8", 5, "DX is 0: a zero value is never punched"),
    ("minus without digits", with_gm(0o20, 0o14, 0o16, 0o01, 0o00, 0o17),
     "8", 6, "expected digit after DX-, found K (16)"),
    ("address without number", with_gm(0o20, 0o21, 0o01, 0o16, 0o01, 0o00, 0o17),
     "8", 5, "expected minus or digit after DX, found DY (21)"),
    ("negative CYC", with_gm(0o20, 0o03, 0o30, 0o14, 0o02, 0o16, 0o01, 0o00, 0o17),
     "8", 7, "expected digit after CYC, found minus (14)"),
    ("CYC 1", with_gm(0o20, 0o03, 0o30, 0o01, 0o16, 0o01, 0o00, 0o17, *DX3_K10),
     "8", 6, "CYC 1: a cycle runs its pair at least 2 times"),
    ("leading zero in CYC", with_gm(0o30, 0o00, 0o02, 0o16, 0o01, 0o00, 0o17, *DX3_K10),
     "8", 5, "leading zero in CYC (a number is punched from its first digit that is not 0)"),
    ("missing closing GM", bytes([0o37, *DX3_K10]),
     "8", 8, "missing GM at the end of the tape"),
    ("closing GM missing before the trailer", bytes([0, 0, 0o37, *DX3_K10, 0, 0]),
     "8", 10, "expected X, Y, DX, DY, CYC, K or GM at the start of a frame, found digit 0 (00)"
              " (a blank row: is the closing GM missing?)"),
    ("tape ends inside a frame", bytes([0o37, 0o20, 0o03]),
     "8", 4, "missing GM at the end of the tape (the tape ends inside a frame)"),
    ("missing opening GM", bytes([0, 0, 0]),
     "8", 4, "missing GM at the start of the tape (only blank rows)"),
    ("empty file", b"",
     "8", 1, "missing GM at the start of the tape (the tape is empty)"),
    ("data before GM", bytes([0, 0, 0o12, 0o37, *DX3_K10, 0o37]),
     "8", 3, "data before the opening GM: found X (12)"),
    ("data after GM", bytes([0o37, *DX3_K10, 0o37, 0, 0o01, 0]),
     "8", 10, "data after the closing GM: found digit 1 (01)"),
    ("GM after GM pair", bytes([0o37, 0o37, 0o37]),
     "8", 3, "data after the closing GM: found GM (37)"),
    ("high bits", bytes([0, 0o37, 0x43, 0o37]),
     "8", 3, "byte 103 (octal) has bits above the low 5 set (not a 5-track row: a row "
            "is 00 to 37)"),
    ("high bits in leader", bytes([0x20, 0o37, 0o37]),
     "auto", 1, "byte 040 (octal) has bits above the low 5 set (not a 5-track row: a "
               "row is 00 to 37); the file begins as text, not as a tape image"),
    ("a text for a tape", b"name = DEMO\n",
     "auto", 1, "byte 156 (octal) has bits above the low 5 set (not a 5-track row: a "
               "row is 00 to 37); the file begins as text, not as a tape image"),
    ("a byte of 8 tracks first", bytes([0o200, 0o37, 0o37]),
     "auto", 1, "byte 200 (octal) has bits above the low 5 set (not a 5-track row: a "
               "row is 00 to 37)"),
    ("not a code", with_gm(0o20, 0o03, 0o15),
     "8", 6, "code 15 (octal) is not an EM-703 code"),
    ("controlled digit in code 8", with_gm(0o20, 0o23, 0o16, 0o01, 0o00, 0o17),
     "8", 5, "code 23 (octal) is not valid in code 8 (digit 3 of the controlled code K)"),
    ("parity error", with_gm(0o20, 0o03, 0o16, 0o01, 0o00, 0o17),
     "K", 5, "parity error: digit 3 punched as 03, controlled code expects 23 (octal)"),
    ("parity error 9", with_gm(0o20, 0o11, 0o16, 0o01, 0o00, 0o17),
     "K", 5, "parity error: digit 9 punched as 11, controlled code expects 31 (octal)"),
    ("mixed code", with_gm(0o20, 0o25, 0o21, 0o05, 0o16, 0o01, 0o00, 0o17),
     "auto", 7, "mixed code: digit 5 punched as 05 (octal), but row 5 has digit 5 (25) of code K;"
                " one of the two is wrong: --code 8 or --code K names it"),
    ("X with K10", with_gm(0o12, 0o03, 0o16, 0o01, 0o00, 0o17),
     "8", 4, "X/Y only with K11/K13 (this frame is K10)"),
    ("Y with K20", with_gm(0o13, 0o03, 0o20, 0o01, 0o16, 0o02, 0o00, 0o17),
     "8", 4, "X/Y only with K11/K13 (this frame is K20)"),
    ("circle without radius", with_gm(0o16, 0o01, 0o03, 0o17),
     "8", 4, "K13 needs X or Y (the radius must be > 0)"),
    ("arc without radius", with_gm(0o20, 0o01, 0o16, 0o01, 0o01, 0o17),
     "8", 6, "K11 needs X or Y (the radius must be > 0)"),
    ("arc end off the circle", with_gm(0o12, 0o03, 0o20, 0o03, 0o16, 0o01, 0o03, 0o17),
     "8", 6, "arc end point is not on the circle: start radius 3.0, end radius 6.0 "
             "(tolerance 1 unit)"),
    ("radius over 10 m", with_gm(0o12, 0o01, 0o00, 0o00, 0o00, 0o00, 0o00, 0o01,
                                 0o16, 0o01, 0o01, 0o17),
     "8", 4, "radius 1000001.0 exceeds 1000000 units (10 m)"),
    ("ten digits", with_gm(0o20, 0o01, *[0] * 9, 0o16, 0o02, 0o00, 0o17),
     "8", 14, "DX has more than 9 digits (the largest number is 999999999)"),
    ("ten digits after a minus", with_gm(0o21, 0o14, *[0o01] * 10, 0o16, 0o02, 0o00, 0o17),
     "8", 15, "DY has more than 9 digits (the largest number is 999999999)"),
    ("ten digits of CYC", with_gm(0o20, 0o03, 0o30, *[0o07] * 10, 0o16, 0o01, 0o00, 0o17,
                                  *DX3_K10),
     "8", 16, "CYC has more than 9 digits (the largest number is 999999999)"),
    ("a radius of 156 digits", with_gm(0o12, 0o01, *[0] * 155, 0o16, 0o01, 0o01, 0o17),
     "8", 14, "X has more than 9 digits (the largest number is 999999999)"),
    ("a number of 4301 digits", with_gm(0o20, *[0o01] * 4301, 0o16, 0o02, 0o00, 0o17),
     "8", 14, "DX has more than 9 digits (the largest number is 999999999)"),
    ("CYC on the last frame", with_gm(*DX3_K10[:2], 0o30, 0o02, *DX3_K10[2:]),
     "8", 6, "CYC needs a following frame (CYC on the last frame)"),
    ("CYC on the partner frame",
     with_gm(*DX3_K10[:2], 0o30, 0o02, *DX3_K10[2:],
             *DX3_K10[:2], 0o30, 0o03, *DX3_K10[2:], *DX3_K10),
     "8", 14, "CYC on the second frame of a cycle pair (its CYC is at row 6)"),
]


@pytest.mark.parametrize("data,code,row,message",
                         [case[1:] for case in DECODE_ERRORS],
                         ids=[case[0] for case in DECODE_ERRORS])
def test_decode_error(data: bytes, code: str, row: int, message: str) -> None:
    with pytest.raises(TapeError) as info:
        decode(data, code)
    assert (info.value.row, info.value.message) == (row, message)
    assert str(info.value) == f"row {row}: {message}"


def test_nine_digits_is_the_largest_number() -> None:
    """999 999 999 in every field reads back, by the whole-tape reader and the
    row reader; a tenth digit is refused by the encoder and the text reader."""
    frames = [Frame(dx=999_999_999, dy=-999_999_999, cyc=999_999_999), Frame(dx=-1)]
    data = encode(frames)
    assert decode(data).frames == frames
    # a fault in the trailer: the row reader reads every frame, then names it
    with pytest.raises(TapeError) as info:
        decode(data[:-20] + b"\x00\x01")
    assert (info.value.row, info.value.message[:25]) == (len(data) - 18,
                                                         "data after the closing GM")
    with pytest.raises(ValueError, match="frame 1: DX has more than 9 digits"):
        encode([Frame(dx=10 ** 9)])
    with pytest.raises(ValueError, match=r"line 1: DX has more than 9 digits \(10; the"):
        parse_frame_text("DX1000000000 K10 KK")


def test_arc_tolerance_is_exactly_one_unit() -> None:
    assert on_circle(5, 0, 1, 0)            # end (6, 0): radius 6, off by exactly 1
    assert not on_circle(5, 0, 1, 1)        # end (6, 1): sqrt(37) = 6.08, off by 1.08
    assert on_circle(3, 4, -9, -4)          # end (-6, 0): off by exactly 1
    assert not on_circle(3, 4, -9, -3)      # end (-6, 1): off by 1.08
    assert not on_circle(3, 4, -3, -4)      # end (0, 0): radius 5 to 0
    assert on_circle(0, 1, 0, -1)           # radius 1 to 0: off by exactly 1
    assert not on_circle(0, 2, 0, -2)       # radius 2 to 0
    assert on_circle(4, 0, -4, 3)           # (0, 3): 1 unit in
    assert not on_circle(10**6, 0, -10**6, 10**6 - 2)   # 2 units in, at 10 m


def test_cycle_after_completed_pair_is_fine() -> None:
    frames = [Frame(dx=1, cyc=2), Frame(dy=1), Frame(dx=2, cyc=3), Frame(dy=2)]
    assert decode(encode(frames)).frames == frames


@pytest.mark.parametrize("frames,message", [
    ([Frame(k=15)], "frame 1: K 15 is not a command (10, 20, 11, 13)"),
    ([Frame(dx=1, cyc=1), Frame()], "frame 1: CYC 1: a cycle runs its pair at least 2 times"),
    ([Frame(dx=1, cyc=-2), Frame()], "frame 1: CYC -2: a cycle runs its pair at least 2 times"),
    ([Frame(x=5, k=10)], "frame 1: X/Y only with K11/K13 (this frame is K10)"),
    ([Frame(k=13)], "frame 1: K13 needs X or Y (the radius must be > 0)"),
    ([Frame(), Frame(dx=1, cyc=2)], "frame 2: CYC needs a following frame"),
    ([Frame(dx=1, cyc=2), Frame(dx=1, cyc=2), Frame()],
     "frame 2: CYC on the second frame of a cycle pair (CYC frame 1)"),
    ([Frame(x=3, dx=3, k=11)], "frame 1: arc end point is not on the circle: start "
                               "radius 3.0, end radius 6.0 (tolerance 1 unit)"),
    ([Frame(x=1_000_001, k=11)], "frame 1: radius 1000001.0 exceeds 1000000 units (10 m)"),
    ([Frame(dx=True)], "frame 1: DX must be an int, not bool"),
    (["DX3 K10 KK"], "frame 1: not a Frame: 'DX3 K10 KK'"),
])
def test_encode_rejects(frames: list, message: str) -> None:
    with pytest.raises(ValueError) as info:
        encode(frames)
    assert str(info.value) == message


def test_encode_bad_arguments() -> None:
    with pytest.raises(ValueError, match="code must be"):
        encode([], "auto")
    with pytest.raises(ValueError, match="leader"):
        encode([], "8", leader=-1)
    with pytest.raises(ValueError, match="code must be"):
        decode(b"", "9")


# ---------------------------------------------------------------------------
# Frame text parser errors.
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("line,message", [
    ("X-300  K11 KK", "line 1: tokens must be separated by single spaces"),
    (" X-300 K11 KK", "line 1: tokens must be separated by single spaces"),
    ("X-300 K11", "line 1: a frame ends with KK, found 'K11'"),
    ("X-0300 K11 KK", "line 1: leading zero or zero value in 'X-0300'"),
    ("DX0 K10 KK", "line 1: leading zero or zero value in 'DX0'"),
    ("K11 X-300 KK", "line 1: expected KK after K11, found 'X-300'"),
    ("DY5 DX5 K10 KK", "line 1: 'DX5' out of order (X, Y, DX, DY, CYC, K, KK)"),
    ("X-300 K5 KK", "line 1: K must be followed by exactly two digits, found 'K5'"),
    ("DX5 K15 KK", "line 1: K 15 is not a command (10, 20, 11, 13)"),
    ("DX5 KK", "line 1: missing K (the command is always written)"),
    ("DX5 CYC1 K10 KK", "line 1: CYC 1: a cycle runs its pair at least 2 times"),
    ("DX5 CYC-2 K10 KK", "line 1: bad number in 'CYC-2'"),
    ("DX+5 K10 KK", "line 1: bad number in 'DX+5'"),
    ("Z5 K10 KK", "line 1: unknown token 'Z5'"),
    ("ΔX5 K10 KK", "line 1: unknown token 'ΔX5'"),
    ("X5 K10 KK", "line 1: X/Y only with K11/K13 (this frame is K10)"),
    ("K11 KK", "line 1: K11 needs X or Y (the radius must be > 0)"),
    ("dx5 K10 KK", "line 1: unknown token 'dx5'"),
])
def test_parse_frame_text_errors(line: str, message: str) -> None:
    with pytest.raises(ValueError) as info:
        parse_frame_text(line)
    assert str(info.value) == message


@pytest.mark.parametrize("text,message", [
    ("GM\nDX5 K10 KK\nGM", "line 3: missing newline at the end of the text"),
    ("DX5 K10 KK\nGM\n", "line 1: expected GM, found 'DX5 K10 KK'"),
    ("GM\nDX5 K10 KK\n", "line 2: expected GM as the last line"),
    ("GM\n\nGM\n", "line 2: empty line"),
    ("GM\nDX5 K10 KK\nDX5 CYC2 K10 KK\nGM\n", "line 3: CYC needs a following frame"),
    ("GM\nΔX5 К10 КК\nGM\n", "line 2: a frame ends with KK, found 'КК'"),
    ("ГМ\nDX5 K10 KK\nГМ\n", "line 2: a frame ends with КК, found 'KK'"),
    ("GM\r\nDX5 K10 KK\r\nGM\r\n", "line 1: expected GM, found 'GM\\r'"),
])
def test_parse_tape_text_errors(text: str, message: str) -> None:
    with pytest.raises(ValueError) as info:
        parse_tape_text(text)
    assert str(info.value) == message


# ---------------------------------------------------------------------------
# Command line.
# ---------------------------------------------------------------------------
def test_cli_decode(tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    path = tmp_path / "saw.ptp"
    path.write_bytes(image(HAND_ROWS[5]["K"]))
    assert main(["decode", str(path)]) == 0
    assert capsys.readouterr().out == example_text(5)
    assert main(["decode", str(path), "--code", "K", "--utf8"]) == 0
    assert capsys.readouterr().out == tape_text(HAND_FRAMES[5], utf8=True)


def test_cli_decode_error(tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    path = tmp_path / "saw.ptp"
    path.write_bytes(image(HAND_ROWS[5]["K"]))
    assert main(["decode", str(path), "--code", "8"]) == 1
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err == (f"{path}: row 23: code 23 (octal) is not valid in code 8 "
                            "(digit 3 of the controlled code K)\n")


def test_cli_usage_errors(tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    assert main([]) == 2
    assert main(["decode"]) == 2
    assert main(["decode", "x.ptp", "--code", "9"]) == 2
    assert main(["decode", str(tmp_path / "missing.ptp")]) == 2
    assert "missing.ptp" in capsys.readouterr().err


def _row_by_row(data: bytes, mode: str) -> Tape | TapeError:
    """decode() with the whole-tape decoder switched off: the row reader."""
    import harness.tape as tape_module
    whole = tape_module._decode_whole
    tape_module._decode_whole = lambda data, code: None
    try:
        return decode(data, mode)
    except TapeError as exc:
        return exc
    finally:
        tape_module._decode_whole = whole


@given(frames=frame_lists(max_items=6), code=codes, data=st.data())
@settings(max_examples=200)
def test_whole_tape_decoder_is_the_row_reader(frames: list[Frame], code: str,
                                              data: st.DataObject) -> None:
    """A tape decoded whole gives the frames, code, rows and frame starts
    the row-by-row reader gives; a tape with a fault in any row is left to
    that reader, so decode() raises its error."""
    good = encode(frames, code, leader=data.draw(st.integers(0, 3), label="leader"))
    bad = bytearray(good)
    corrupt = data.draw(st.booleans(), label="corrupt")
    if corrupt:
        index = data.draw(st.integers(0, len(bad) - 1), label="index")
        bad[index] = data.draw(st.integers(0, 255), label="value")
    for mode in (code, "auto"):
        slow = _row_by_row(bytes(bad), mode)
        try:
            fast: Tape | TapeError = decode(bytes(bad), mode)
        except TapeError as exc:
            fast = exc
        if isinstance(slow, TapeError):
            assert isinstance(fast, TapeError) and str(fast) == str(slow)
        else:
            assert isinstance(fast, Tape)
            assert (fast.code, fast.frames, fast.rows) == (slow.code, slow.frames, slow.rows)
            assert fast.starts is not None or corrupt      # every good tape is read whole
            if fast.starts is not None:
                from harness.tape import frame_rows
                row = next(i for i, v in enumerate(bad) if v != 0) + 2
                for start, f in zip(fast.starts, fast.frames):
                    assert start == row
                    row += len(frame_rows(f, fast.code))
