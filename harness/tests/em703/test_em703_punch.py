"""`em703 punch` and `em703 view`: text on ISO 7-bit and EIA RS-244 tape as
seed 004 describes the codes, checked against tables written here from the
seed's rules (not from the Fortran), round trips of G-code programs, and the
picture of a punched tape for all three codes, including docs/TAPE.md's."""

from __future__ import annotations

import re
import string

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from harness.tests.helpers import ROOT

from harness.tests.helpers import run

LEADER = 20
EOB_EIA = 0x80


def bits(*tracks: int) -> int:
    """A row from its punched tracks (track k = bit k-1)."""
    return sum(1 << (t - 1) for t in tracks)


def iso(ch: str) -> int:
    """seed 004: ISO 7-bit, the code on tracks 1-7, track 8 makes the holes even."""
    c = ord(ch)
    return c | (0x80 if bin(c).count("1") % 2 else 0)


def _odd(row: int) -> int:
    """Track 5 added when the holes are even (EIA: always an odd number)."""
    return row if bin(row).count("1") % 2 else row | bits(5)


#: seed 004: "digits in 8-4-2-1 on tracks 4-3-2-1; letters a-i, j-r, s-z coded
#: like the digits with group marks on tracks 6 and 7; track 8 only for the
#: end of block; track 5 makes the count odd".  Zero and the signs as RS-244.
EIA: dict[str, int] = {"0": _odd(bits(6))}
for d in range(1, 10):
    EIA[str(d)] = _odd(d)
for i, ch in enumerate("abcdefghi", 1):
    EIA[ch] = _odd(i | bits(6, 7))
for i, ch in enumerate("jklmnopqr", 1):
    EIA[ch] = _odd(i | bits(7))
for i, ch in enumerate("stuvwxyz", 2):
    EIA[ch] = _odd(i | bits(6))
EIA.update({" ": bits(5), "-": bits(7), "+": bits(5, 6, 7), ".": bits(1, 2, 4, 6, 7),
            ",": bits(1, 2, 4, 5, 6), "/": bits(1, 5, 6), "\t": bits(2, 3, 4, 5, 6),
            "(": bits(2, 4, 5), ")": bits(2, 4, 7), "%": bits(1, 2, 4), "\n": EOB_EIA})


def eia(ch: str) -> int:
    return EIA[ch.lower()]


def test_the_eia_table_is_a_code() -> None:
    assert len(set(EIA.values())) == len(EIA)
    assert all(bin(v).count("1") % 2 == 1 for v in EIA.values())
    assert EIA["3"] == bits(1, 2, 5) and EIA["g"] == bits(1, 2, 3, 6, 7) and EIA["x"] == \
        bits(1, 2, 3, 5, 6)


iso_text = st.text(alphabet=string.printable.replace("\x0b", "").replace("\x0c", ""), max_size=200)
eia_text = st.text(alphabet="".join(EIA) + string.ascii_uppercase, max_size=200)


@settings(max_examples=25, deadline=None)
@given(text=iso_text)
def test_iso_tapes_are_the_ascii_codes_with_even_parity(em703_exe, tmp_path_factory, text) -> None:
    tmp = tmp_path_factory.mktemp("iso")
    (tmp / "p.ngc").write_bytes(text.encode("ascii"))
    run(em703_exe, "punch", "--code", "iso", tmp / "p.ngc", check=0)
    tape = (tmp / "p.iso.ptp").read_bytes()
    body = [iso(c) for c in text.replace("\r", "")]
    assert tape == bytes([0] * LEADER + body + [0] * LEADER)
    assert all(bin(b).count("1") % 2 == 0 for b in tape)


@settings(max_examples=25, deadline=None)
@given(text=eia_text)
def test_eia_tapes_follow_seed_004(em703_exe, tmp_path_factory, text) -> None:
    tmp = tmp_path_factory.mktemp("eia")
    (tmp / "p.ngc").write_text(text)
    run(em703_exe, "punch", "--code", "eia", "-o", tmp / "out.ptp", tmp / "p.ngc", check=0)
    tape = (tmp / "out.ptp").read_bytes()
    assert tape == bytes([0] * LEADER + [eia(c) for c in text] + [0] * LEADER)
    inverse = {v: k for k, v in EIA.items()}
    body = tape[LEADER:len(tape) - LEADER]
    assert "".join(inverse[b] for b in body) == text.lower()
    for b in body:                               # odd parity, or the end of block alone
        assert b == EOB_EIA or (bin(b).count("1") % 2 == 1 and not b & 0x80)


def test_a_gcode_program_punches_and_views_in_both_codes(em703_exe, example_tapes,
                                                         tmp_path) -> None:
    tape = next(t for t in example_tapes if t.name == "EXAMPLE3-cond.ptp")
    program = tmp_path / "ex3.ngc"
    run(em703_exe, "gcode", tape, "-o", program, check=0)
    text = program.read_text()
    run(em703_exe, "punch", "--code", "iso", program, check=0)
    iso_tape = (tmp_path / "ex3.iso.ptp").read_bytes()
    assert bytes(b & 0x7F for b in iso_tape[LEADER:-LEADER]).decode() == text
    # EIA has no #, :, _ ... but every character of em703's programs
    run(em703_exe, "punch", "--code", "eia", program, check=0)
    eia_tape = (tmp_path / "ex3.eia.ptp").read_bytes()
    assert eia_tape[LEADER:-LEADER] == bytes(eia(c) for c in text)

    for path, code, meaning in ((tmp_path / "ex3.iso.ptp", "iso", iso_meaning),
                                (tmp_path / "ex3.eia.ptp", "eia", eia_meaning)):
        data = path.read_bytes()
        lines = run(em703_exe, "view", path, check=0).stdout.decode().splitlines()
        assert lines[0] == "  row  8 7 6 5 4   3 2 1   code  meaning"
        assert lines[1] == lines[-1] == "      +" + "-" * 21 + "+"
        assert len(lines) == len(data) + 3
        for n, (line, row) in enumerate(zip(lines[2:-1], data), 1):
            assert line == picture(n, row, 8) + f"| {row:03o}   " + meaning(row, n, data), line
        forced = run(em703_exe, "view", "--code", code, path, check=0).stdout.decode()
        assert forced.splitlines() == lines


def picture(n: int, row: int, tracks: int) -> str:
    """'   21 |o o o . o o    ': row number, holes from the highest track,
    the feed hole after track 3 (5 tracks) or 4 (8 tracks)."""
    feed = 3 if tracks == 5 else 4
    cells = []
    for t in range(tracks, 0, -1):
        cells.append("o" if row >> (t - 1) & 1 else " ")
        if t == feed:
            cells.append(".")
    return f"{n:5d} |" + " ".join(cells).ljust(2 * tracks + 5)


def _blank(n: int, data: bytes) -> str:
    if not any(data[:n - 1]):
        return "leader"
    if not any(data[n:]):
        return "trailer"
    return "blank"


def iso_meaning(row: int, n: int, data: bytes) -> str:
    if row == 0:
        return _blank(n, data)
    c = chr(row & 0x7F)
    return {"\n": "end of block (LF)", " ": "space", "\t": "tab"}.get(c, c)


def eia_meaning(row: int, n: int, data: bytes) -> str:
    if row == 0:
        return _blank(n, data)
    c = {v: k for k, v in EIA.items()}[row]
    return {"\n": "end of block", " ": "space", "\t": "tab", "%": "% (rewind stop)",
            "(": "( (control out)", ")": ") (control in)"}.get(c, c.upper())


def test_view_draws_the_picture_of_docs_tape_md(em703_exe, example_tapes) -> None:
    """docs/TAPE.md's picture of Example 3 is what em703 view draws."""
    doc = (ROOT / "docs" / "TAPE.md").read_text()
    block = doc.split("## A picture of a punched tape", 1)[1].split("```")[1].strip("\n")
    tape = next(t for t in example_tapes if t.name == "EXAMPLE3-cond.ptp")
    got = run(em703_exe, "view", tape, "--rows", "19:59", check=0).stdout.decode()
    assert got.strip("\n") == block


def test_view_of_em703_tapes_shows_each_row(em703_exe, example_tapes) -> None:
    names = {0o12: "X", 0o13: "Y", 0o14: "-", 0o16: "K", 0o17: "KK", 0o20: "DX", 0o21: "DY",
             0o30: "CYC", 0o37: "GM"}
    for tape in example_tapes:
        data = tape.read_bytes()
        lines = run(em703_exe, "view", tape, check=0).stdout.decode().splitlines()
        assert len(lines) == len(data) + 3 and lines[1] == "      +---------------+"
        first, last = data.index(0o37), len(data) - 1 - data[::-1].index(0o37)
        for n, (line, row) in enumerate(zip(lines[2:-1], data), 1):
            assert line.startswith(picture(n, row, 5) + f"| {row:03o}   "), line
            what = line[len(picture(n, row, 5)) + 8:]
            if row in names:
                assert what == names[row]
            elif n - 1 < first:
                assert what == "leader"
            elif n - 1 > last:
                assert what == "trailer"
            else:
                assert re.fullmatch(r"digit \d", what), line


def test_view_names_the_row_of_a_tape_that_is_not_em703s(em703_exe, example_tapes,
                                                       tmp_path) -> None:
    """--code em703 on a tape with a row beyond track 5: the file, that row
    (the first such), its code, and what would read it; a bad row the code
    merely has not is drawn and named, exit 0 (docs/TOOLS.md)."""
    data = bytearray(next(t for t in example_tapes if t.name == "EXAMPLE3-cond.ptp").read_bytes())
    data[30], data[40] = 0o245, 0o377
    tape = tmp_path / "t.ptp"
    tape.write_bytes(bytes(data))
    proc = run(em703_exe, "view", "--code", "em703", tape, check=1)
    assert proc.stderr.decode() == (f"{tape}: row 31: holes beyond track 5 (octal 245): not an "
                                    "EM-703 tape (--code iso or eia for a tape of 7 or 8 "
                                    "tracks)\n")
    assert not proc.stdout
    data[30], data[40] = 0o25, 0o26        # rows of 5 tracks the code has not
    tape.write_bytes(bytes(data))
    proc = run(em703_exe, "view", tape, check=0)
    assert not proc.stderr and len(proc.stdout.decode().splitlines()) == len(data) + 3


def test_view_names_digit_rows_in_the_variant_of_the_tape(em703_exe, tmp_path) -> None:
    """DX35 K10 KK DX-35 K20 KK in code 8 (digits 3 and 5 are rows 03, 05).
    A K row 25 (digit 5 with track 5) inside the GM makes the tape K: its 25
    is digit 5, and a 03 or 05 a digit without its track 5; before the
    opening GM it tells nothing, and is named digit 5 of code K."""
    from harness.tape import Frame, encode
    data = bytearray(encode([Frame(dx=35, k=10), Frame(dx=-35, k=20)], "8"))
    tape = tmp_path / "t.ptp"

    def meanings() -> dict[int, str]:
        tape.write_bytes(bytes(data))
        lines = run(em703_exe, "view", tape, check=0).stdout.decode().splitlines()[2:-1]
        return {n: line.rsplit("| ", 1)[1][6:] for n, line in enumerate(lines, 1)}

    assert [meanings()[n] for n in (23, 24, 31, 32)] == ["digit 3", "digit 5", "digit 3",
                                                         "digit 5"]
    data[0] = 0o25
    got = meanings()
    assert [got[n] for n in (1, 2, 23, 24)] == ["digit 5 of code K", "leader", "digit 3",
                                                "digit 5"]
    data[0], data[23] = 0, 0o25
    got = meanings()
    assert [got[n] for n in (23, 24, 31, 32)] == [
        "parity error (digit 3 without track 5)", "digit 5",
        "parity error (digit 3 without track 5)", "parity error (digit 5 without track 5)"]


@pytest.mark.parametrize("text, line, column, code", [
    ("G01 X1\nG00 #1=2\n", 2, 5, "eia"),
    ("G01 X1\r\nG00 X2 Y3 ;\n", 2, 11, "eia"),
    ("G01\rX1 ;\n", 1, 8, "eia"),            # a CR inside a line is dropped, but is a column
    ("G01\nX\u00e9\n", 2, 2, "iso"),
    ("G01\x07\n", 1, 4, "iso"),
])
def test_a_character_outside_the_code_names_its_line_and_column(em703_exe, tmp_path, text, line,
                                                                column, code) -> None:
    src = tmp_path / "p.ngc"
    src.write_bytes(text.encode("utf-8"))
    proc = run(em703_exe, "punch", "--code", code, src, check=1)
    err = proc.stderr.decode()
    assert err.startswith(f"{src}: line {line}, column {column}: ") and err.count("\n") == 1, err
    assert not (tmp_path / f"p.{code}.ptp").exists()


def test_the_tape_is_named_after_the_file_with_its_extension_replaced(em703_exe,
                                                                     tmp_path) -> None:
    """prog.ngc -> prog.iso.ptp; a name without an extension keeps it whole:
    a dot in a directory's name, or a dot file's leading dot, is none."""
    (tmp_path / "a.b").mkdir()
    for name, tape in (("prog.ngc", "prog.iso.ptp"), ("noext", "noext.iso.ptp"),
                       ("a.b/prog", "a.b/prog.iso.ptp"), (".hidden", ".hidden.iso.ptp"),
                       ("a.b/.hidden", "a.b/.hidden.iso.ptp")):
        (tmp_path / name).write_text("N1 G00\n")
        run(em703_exe, "punch", "--code", "iso", tmp_path / name, check=0)
        assert (tmp_path / tape).read_bytes() == bytes(LEADER) + bytes(
            iso(c) for c in "N1 G00\n") + bytes(LEADER), name
    assert sorted(p.name for p in tmp_path.rglob("*.ptp")) == [
        ".hidden.iso.ptp", ".hidden.iso.ptp", "noext.iso.ptp", "prog.iso.ptp", "prog.iso.ptp"]


@pytest.mark.parametrize("code, chars", [
    ("iso", "ASCII letters, digits, signs, tab, newline"),
    ("eia", "letters, digits, space - + . , / ( ) %, tab, newline")])
def test_a_control_byte_names_the_characters_of_its_code(em703_exe, tmp_path, code, chars):
    src = tmp_path / "soh.txt"
    src.write_bytes(b"ab\001c\n")
    proc = run(em703_exe, "punch", "--code", code, src, check=1)
    assert proc.stderr.decode() == (f"{src}: line 1, column 3: byte 001 (octal) is not a "
                                    f"character of the {code.upper()} code ({chars})\n")
