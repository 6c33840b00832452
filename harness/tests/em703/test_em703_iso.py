"""`em703 gcode --dialect iso-1970s` (seed 004's block format) and
`em703 check` (its reader's check): every example job and tape gives a
program of numbered blocks of at most 999 a program that passes the check,
whose increments trace the same points as the LinuxCNC program, punched on
ISO and EIA tape; the check finds two codes of one group in a block."""

from __future__ import annotations

import math
import re
import subprocess
from pathlib import Path

from harness.tests.helpers import iso_programs

BLOCK = re.compile(r"N\d{3}( [GXYZIJFSTM][+-]?\d+)*$")


def _em(exe, *args, cwd=None):
    return subprocess.run([str(exe), *map(str, args)], capture_output=True, cwd=cwd)


def iso_points(text: str) -> list[tuple[int, int]]:
    """Absolute positions (0.001 mm) after every move block of an ISO program."""
    x = y = 0
    out = []
    for line in text.splitlines():
        if not line.startswith("N"):
            continue
        words = dict((w[0], w[1:]) for w in line.split()[1:])
        if "X" in words:
            x += int(words["X"])
            y += int(words["Y"])
            out.append((x, y))
    return out


def linuxcnc_points(text: str) -> list[tuple[int, int]]:
    out = []
    for line in text.splitlines():
        m = re.search(r"X(-?\d+\.\d+) Y(-?\d+\.\d+)", line)
        if m and line.startswith("N"):
            out.append((round(float(m.group(1)) * 1000), round(float(m.group(2)) * 1000)))
    return out


def test_example_programs(em703_exe, example_jobs, example_tapes, tmp_path) -> None:
    for src in list(example_jobs) + list(example_tapes)[:6]:
        iso = _em(em703_exe, "gcode", "--dialect", "iso-1970s", src)
        assert iso.returncode == 0, iso.stderr
        text = iso.stdout.decode("ascii")
        again = _em(em703_exe, "gcode", "--dialect", "iso-1970s", src)
        assert again.stdout == iso.stdout                       # byte-identical
        for line in text.splitlines():
            assert line == "%" or line.startswith("(") or BLOCK.match(line), (src, line)
        progs = iso_programs(text)
        for prog in progs:
            nums = [int(b[1:4]) for b in prog]
            assert nums == list(range(1, len(nums) + 1)) and len(nums) <= 999
            assert prog[-1].endswith(" M02")
        # the same points as the LinuxCNC program (the ISO one may split long moves)
        lin = _em(em703_exe, "gcode", src).stdout.decode("ascii")
        want, got = linuxcnc_points(lin), iso_points(text)
        it = iter(got)
        assert all(any(p == q for q in it) for p in want), src
        assert (got[-1] == want[-1]) if want else not got
        prog = tmp_path / "p.iso"
        prog.write_bytes(iso.stdout)
        ok = _em(em703_exe, "check", prog)
        assert ok.returncode == 0 and ok.stdout.decode().endswith(" no tape error\n"), ok.stderr
        for code in ("iso", "eia"):
            tape = tmp_path / f"p.{code}.ptp"
            assert _em(em703_exe, "punch", "--code", code, prog, "-o", tape).returncode == 0
        from_tape = _em(em703_exe, "check", tmp_path / "p.iso.ptp").stdout
        assert from_tape.split(b": ", 1)[1] == ok.stdout.split(b": ", 1)[1]


def test_long_program_is_cut_into_complete_programs(em703_exe, example_jobs) -> None:
    """The demo board's job runs past 999 blocks: it becomes several programs,
    each of at most 999 numbered blocks, each ending with M02; the tool state
    carries over (raised at a cut, lowered again in the next program)."""
    biggest = max(example_jobs, key=lambda j: len(_em(em703_exe, "gcode", "--dialect",
                                                        "iso-1970s", j).stdout))
    text = _em(em703_exe, "gcode", "--dialect", "iso-1970s", biggest).stdout.decode()
    progs = iso_programs(text)
    assert len(progs) >= 2
    for prog in progs:
        assert 1 <= len(prog) <= 999 and prog[0] == "N001 G17" and prog[-1].endswith(" M02")
        downs = sum(1 for b in prog if "Z-001000" in b) - sum(1 for b in prog if "Z+001000" in b)
        assert downs == 0                                        # every program ends raised


def test_each_program_of_a_cut_writes_its_feed_again(em703_exe, tmp_path) -> None:
    """DX1 CYC300 K20 KK DX1 K10 KK: raise, travel, lower, draw, 300 times;
    block 998 would be a travel, so the cut comes with the tool raised, and
    the next program's first feed block (the tool lowered) writes F76 again:
    each program starts from nothing in force."""
    from harness.tape import Frame, encode
    tape = tmp_path / "cut.ptp"
    tape.write_bytes(encode([Frame(dx=1, k=20, cyc=300), Frame(dx=1, k=10)]))
    progs = iso_programs(_em(em703_exe, "gcode", "--dialect", "iso-1970s", tape).stdout.decode())
    assert [len(p) for p in progs] == [998, 206]
    assert progs[0][-2:] == ["N997 G00 Z+001000", "N998 M02"]
    assert progs[1][:4] == ["N001 G17", "N002 G00 X+000010 Y+000000", "N003 G01 Z-001000 F76",
                            "N004 G01 X+000010 Y+000000"]


def test_the_feed_codes_of_the_geometric_series() -> None:
    """1.12**76 = 5503 (the lines' 5500 mm/min), 1.12**65 = 1582 (arcs' 1500:
    64.53 on the scale, nearest 65); 1.12**99 = 74573, the document's
    "до 75000 (1,12^99)"."""
    assert round(math.log(5500) / math.log(1.12)) == 76
    assert round(math.log(1500) / math.log(1.12)) == 65
    assert round(1.12 ** 99, -3) == 75000


def test_check_finds_codes_of_one_group(em703_exe, tmp_path) -> None:
    prog = tmp_path / "bad.iso"
    prog.write_text("%\nN001 G17\nN002 G01 G02 X+001000 Y+000000 F76\nN003 G02 G17 G45 G61 G83"
                    " X+000000 Y+000000\nN004 M03 M05\nN005 M07\nN006 X+1 Y+000000\n%\n")
    proc = _em(em703_exe, "check", prog)
    assert proc.returncode == 1 and proc.stdout == b""
    lines = proc.stderr.decode("utf-8").splitlines()
    assert lines == [
        f"{prog}: block N002 (line 3): ошибка перфоленты (tape error): G01 and G02 are of one group",
        f"{prog}: block N004 (line 5): ошибка перфоленты (tape error): M03 and M05 are of one group",
        f"{prog}: block N005 (line 6): M07 is not in the document's table (M00 M02 M03 M04 M05 "
        "M06 M38 M39 M40)",
        f"{prog}: block N006 (line 7): the word X+1 is not a sign and six digits"]
    # the document's own example block, G02 G17 G45 G61 G83, is one of each group


def test_a_fault_on_a_tape_names_the_tape_row_where_its_block_starts(em703_exe,
                                                                      tmp_path) -> None:
    """Read from a punched tape, a fault names the line of the text read from
    it and the tape's row where that line starts, on ISO and on EIA tape,
    with blank and delete rows among them (which the reader skips): the row
    `em703 view` shows as the block's N."""
    prog = tmp_path / "bad.iso"
    prog.write_text("%\nN001 G17\nN002 G01 G02 X+001000 Y+000000\nN003 M07\n%\n")
    for code, delete in (("iso", 0o377), ("eia", 0o177)):
        tape = tmp_path / f"bad.{code}.ptp"
        assert _em(em703_exe, "punch", "--code", code, prog, "-o", tape).returncode == 0
        data = tape.read_bytes()
        at = data.index(b"\n"[0] if code == "iso" else 0o200, 25)   # an end of block
        tape.write_bytes(data[:at] + bytes([0, delete, 0]) + data[at:])
        proc = _em(em703_exe, "check", tape)
        assert proc.returncode == 1, proc.stderr
        faults = proc.stderr.decode("utf-8").splitlines()
        found = [re.match(rf"{re.escape(str(tape))}: block (N00\d) \(line (\d), tape row "
                          r"(\d+)\): ", f) for f in faults]
        assert all(found) and [m[1] for m in found] == ["N002", "N003"], faults
        assert [m[2] for m in found] == ["3", "4"], faults
        view = _em(em703_exe, "view", tape).stdout.decode()
        n_rows = [int(r) for r in re.findall(r"^ +(\d+) \|.*\| \d{3}   N$", view, re.M)]
        assert [int(m[3]) for m in found] == n_rows[1:], (code, faults, n_rows)
        assert n_rows[1] == at + 3 + 2             # the three rows put in are counted


def test_check_finds_a_comment_that_is_not_closed(em703_exe, tmp_path) -> None:
    prog = tmp_path / "open.iso"
    prog.write_text("%\n(a comment\nN001 G17\nN002 M02\n%\n(closed)\n")
    proc = _em(em703_exe, "check", prog)
    assert (proc.returncode, proc.stdout) == (1, b"")
    assert proc.stderr.decode() == f"{prog}: line 2: a comment must end with )\n"


def test_check_of_a_tape_with_a_parity_error(em703_exe, tmp_path) -> None:
    prog = tmp_path / "p.iso"
    prog.write_text("%\nN001 G17\nN002 M02\n%\n")
    tape = tmp_path / "p.ptp"
    assert _em(em703_exe, "punch", "--code", "iso", prog, "-o", tape).returncode == 0
    data = bytearray(tape.read_bytes())
    data[25] ^= 1
    tape.write_bytes(bytes(data))
    proc = _em(em703_exe, "check", tape)
    assert proc.returncode == 1
    assert proc.stderr.decode() == f"{tape}: row 26: parity error (odd number of holes): not an " \
                                   "ISO tape, or a misread row\n"


def test_check_shows_control_characters_in_octal(em703_exe, tmp_path) -> None:
    """A byte of the program that is not a printable character reaches a
    message as its octal code in angle brackets (the code `em703 view`
    prints for its row), never raw: a delete, an ESC, a CR in the middle of
    a line, a TAB; nothing else below 32 is on standard error."""
    cases = [
        ("address", "N001 G17\x7f\x1b", 'block N001 (line 2): the word G17<177><033> is not two '
                                        "digits"),
        ("address", "N001 G17\rX+000000", "block N001 (line 2): the word G17<015> is not two digits"),
        ("address", "N001 \x1b[2J", 'block N001 (line 2): no address "<033>" in the block format'),
        ("address", "001\x07", 'line 2: a block begins with N and three digits, not "001<007>" '
                              "(no letter: a fixed or a variable frame? see --frame)"),
        ("variable", "N\x0c01", 'line 2: a variable frame begins with its number, three digits, '
                               'not "N<014>01" (a letter address: an address frame? see --frame)'),
        ("variable", "001\t0\x7f", 'block N001 (line 2): slot G00-G09 (2nd slot, columns 5-6) '
                                   '"0<177>" is not two digits (nor two spaces, no word)'),
        ("fixed", "001\t" + "0" * 44, 'block N001 (line 2): slot G00-G09 (columns 4-5) "<011>0" has '
                                    "a TAB in it (a TAB at column 4: a variable frame? see --frame)"),
    ]
    for frame, block, want in cases:
        prog = tmp_path / "c.iso"
        prog.write_bytes(f"%\n{block}\n%\n".encode("ascii"))
        proc = _em(em703_exe, "check", "--frame", frame, prog)
        assert proc.returncode == 1 and proc.stdout == b"", block
        assert proc.stderr == f"{prog}: {want}\n".encode("ascii"), (block, proc.stderr)


def test_check_skips_delete_rows(em703_exe, tmp_path) -> None:
    """A punch operator rubs out a row by punching every hole of the code over
    it: a delete row, all eight tracks on ISO tape (0377, DEL with its parity
    track), tracks 1-7 on EIA (0177), as `em703 view` names them. The reader
    skips it as it skips a blank row, on both tapes; a delete row of one code
    on the other's tape is still a parity error."""
    prog = tmp_path / "p.iso"
    prog.write_text("%\nN001 G17\nN002 M02\n%\n")
    for code, delete, other in (("iso", 0o377, 0o177), ("eia", 0o177, 0o377)):
        tape = tmp_path / f"p.{code}.ptp"
        assert _em(em703_exe, "punch", "--code", code, prog, "-o", tape).returncode == 0
        good = _em(em703_exe, "check", tape)
        assert good.returncode == 0, good.stderr
        data = bytearray(tape.read_bytes())
        # a wrong digit after the 1 of N001, rubbed out; two more delete rows
        # at the start of the program and inside N002
        data[26:26] = bytes([delete])
        data[22:22] = bytes([delete])
        data[33:33] = bytes([delete])
        tape.write_bytes(bytes(data))
        view = _em(em703_exe, "view", tape, "--code", code, "--rows", "27:28").stdout.decode()
        assert f"| {delete:03o}   delete" in view, view
        back = _em(em703_exe, "check", tape)
        assert back.returncode == 0, back.stderr
        assert back.stdout.split(b": ", 1)[1] == good.stdout.split(b": ", 1)[1] == \
            b"1 program, 2 blocks, no tape error\n"
        data[27] = other
        tape.write_bytes(bytes(data))
        bad = _em(em703_exe, "check", tape)
        assert bad.returncode == 1 and b"row 28: parity error" in bad.stderr, bad.stderr


def test_a_text_that_is_not_ascii_is_read_as_a_tape_and_says_why(em703_exe, tmp_path) -> None:
    """A byte above 127 is a row with track 8: a file that has one is read as
    a tape image, a text of UTF-8 letters too. Its fault then says so and
    where the first such byte is, as a row and as a line of text; a tape
    with its blank leader needs no such word."""
    prog = tmp_path / "ru.iso"
    prog.write_text("%\n(проверка)\nN001 G17\n%\n", encoding="utf-8")
    proc = _em(em703_exe, "check", prog)
    assert proc.returncode == 1 and proc.stdout == b""
    assert proc.stderr.decode() == (
        f"{prog}: row 2: parity error (even number of holes): not an EIA tape, or a misread row "
        "(read as a tape image for its bytes above 127, the first at row 4, line 2 as text: a "
        "program as text must be ASCII)\n")
    prog.write_text("%\nN001 G17 (é)\n%\n", encoding="utf-8")
    proc = _em(em703_exe, "check", prog)
    assert proc.returncode == 1
    assert proc.stderr.decode().endswith(": not an ISO tape, or a misread row (read as a tape image "
                                         "for its bytes above 127, the first at row 13, line 2 as "
                                         "text: a program as text must be ASCII)\n")


def test_an_arc_too_large_for_i_and_j_is_chords_and_says_so(em703_exe, tmp_path) -> None:
    """I and J hold 999.99 mm: a circle of that radius is one G02; one of
    1000.00 mm is G01 chords within 0.01 mm of it, after a comment that says
    so; --chords says so once at the top, and --z is refused (the dialect
    always moves Z)."""
    from harness.tape import Frame, encode
    for r in (99_999, 100_000):
        tape = tmp_path / f"c{r}.ptp"
        tape.write_bytes(encode([Frame(x=r, k=13)]))
        text = _em(em703_exe, "gcode", "--dialect", "iso-1970s", tape).stdout.decode()
        assert "(EM-703 tape, code 8, 1 frame, block format" in text
        blocks = [b for p in iso_programs(text) for b in p]
        if r == 99_999:
            assert "N003 G02 X+000000 Y+000000 I-999990 J+000000 F65" in blocks
            assert "chords" not in text
            continue
        assert ("(an arc of radius 1000.00 mm, too large for the six digits of I and J, as "
                "chords within 0.0100 mm)") in text.splitlines()
        assert not any(" G02" in b or " G03" in b for b in blocks)
        pts = iso_points(text)
        cx, cy = -r * 10, 0                                   # 0.001 mm
        assert pts[-1] == (0, 0) and len(pts) > 100
        for (ax, ay), (bx, by) in zip(pts, pts[1:]):
            for x, y in ((ax, ay), ((ax + bx) / 2, (ay + by) / 2)):
                assert abs(math.hypot(x - cx, y - cy) - r * 10) <= 10 + 8
    asked = _em(em703_exe, "gcode", "--dialect", "iso-1970s", "--chords", "0.5",
                tmp_path / "c99999.ptp").stdout.decode()
    assert asked.splitlines()[3] == "(arcs as chords within 0.5000 mm)"
    z = _em(em703_exe, "gcode", "--dialect", "iso-1970s", "--z", tmp_path / "c99999.ptp")
    assert z.returncode == 2 and b"--z is for linuxcnc and grbl" in z.stderr


def test_a_file_without_a_program_is_a_fault(em703_exe, tmp_path) -> None:
    for name, text in (("empty.iso", ""), ("blank.iso", "\n\n"), ("remark.iso", "(a remark)\n")):
        path = tmp_path / name
        path.write_text(text)
        proc = _em(em703_exe, "check", path)
        assert proc.returncode == 1 and proc.stdout == b""
        assert proc.stderr.decode() == (f'{path}: no program in it: a program is a line "%", '
                                        'its numbered blocks (N001 ...), and "%"\n')


def test_a_block_number_of_four_digits_is_quoted(em703_exe, tmp_path) -> None:
    path = tmp_path / "n4.iso"
    path.write_text("%\nN0001 G17\nN002 M02\n%\n")
    proc = _em(em703_exe, "check", path)
    assert proc.returncode == 1
    assert proc.stderr.decode() == (f'{path}: line 2: the block number has three digits, not '
                                    '"N0001" (a blank after them)\n')
