"""Seed 004's three kinds of frame: `em703 gcode --dialect iso-1970s --frame
fixed|variable|address` and `em703 check --frame`.

For every example job the three programs carry the same blocks: each is read
back here (by this file's own reading of the layout, not em703's) into the
same sequence of resolved blocks (N, the G codes in force, the increments X Y
Z I J, F and T in force, the block's M); the variable program with each empty
slot filled from the block before is the fixed program, slot by slot; the
variable frames are shorter than the fixed ones; each program punched on ISO
and on EIA tape reads back through `em703 check` without a tape error. A
variable frame with a TAB missing, a slot out of form or a TAB too many, and a
fixed frame of the wrong width, are refused with the block, the line, the slot
and what was wanted."""

from __future__ import annotations

import subprocess

from harness.tests.helpers import iso_programs

#: The slots of fixed and variable frames and their widths (em703_iso.f90).
SLOTS = [("N", 3), ("G", 2), ("G", 2), ("X", 7), ("Y", 7), ("Z", 7), ("I", 7), ("J", 7),
         ("F", 2), ("T", 2), ("M", 2)]
FIXED = sum(w for _, w in SLOTS)
TAB = "\t"


def _em(exe, *args):
    return subprocess.run([str(exe), *map(str, args)], capture_output=True)


def _gcode(exe, src, frame=None) -> str:
    args = ["gcode", "--dialect", "iso-1970s", src]
    if frame:
        args += ["--frame", frame]
    proc = _em(exe, *args)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout.decode("ascii")


def _empty(k: int) -> str:
    return "+000000" if 3 <= k <= 7 else " " * SLOTS[k][1]


def resolved_address(prog: list[str]) -> list[tuple]:
    """The address blocks of a program as slot values: G, F, T carried from
    the block that set them, increments 0 when absent, M the block's own."""
    state = [_empty(k) for k in range(len(SLOTS))]
    out = []
    for block in prog:
        words = block.split(" ")
        assert words[0][0] == "N"
        for k in range(3, 8):
            state[k] = "+000000"
        state[10] = "  "
        state[0] = words[0][1:]
        for w in words[1:]:
            if w[0] == "G":
                state[1 if int(w[1:]) < 10 else 2] = w[1:]
            else:
                state["NGGXYZIJFTM".index(w[0])] = w[1:]
        out.append(tuple(state))
    return out


def fixed_slots(block: str) -> tuple:
    assert len(block) == FIXED, block
    out, c = [], 0
    for _, w in SLOTS:
        out.append(block[c:c + w])
        c += w
    return tuple(out)


def expanded_variable(prog: list[str]) -> list[tuple]:
    """A variable program's frames with every empty or dropped slot filled
    from the frame before (the first frame of a program: from nothing)."""
    prev = [_empty(k) for k in range(len(SLOTS))]
    out = []
    for block in prog:
        fields = block.split(TAB)
        assert 1 <= len(fields) <= len(SLOTS), block
        cur = list(prev)
        for k, v in enumerate(fields):
            if v:
                assert len(v) == SLOTS[k][1], (block, k, v)
                cur[k] = v
        assert fields[0] and fields[-1] or len(fields) == 1, block   # ends at a value
        out.append(tuple(cur))
        prev = cur
    return out


def moves(slots: list[tuple]) -> list[tuple]:
    """(N, G codes, X, Y, Z, I, J, F, T, M) with numbers, None for no word."""
    def num(v):
        return None if v.strip() == "" else int(v)
    return [tuple(num(v) for v in s) for s in slots]


def test_three_frames_carry_the_same_blocks(em703_exe, example_jobs, example_tapes, tmp_path):
    sizes = {}
    for src in list(example_jobs) + list(example_tapes)[:6]:
        plain = _em(em703_exe, "gcode", "--dialect", "iso-1970s", src).stdout
        address = _gcode(em703_exe, src, "address")
        assert address.encode() == plain                    # --frame address is today's
        fixed = _gcode(em703_exe, src, "fixed")
        variable = _gcode(em703_exe, src, "variable")
        pa, pf, pv = iso_programs(address), iso_programs(fixed), iso_programs(variable)
        assert len(pa) == len(pf) == len(pv) >= 1
        for a, f, v in zip(pa, pf, pv):
            assert len(a) == len(f) == len(v)
            fs = [fixed_slots(b) for b in f]
            assert expanded_variable(v) == fs, src          # TABs expanded = the fixed frames
            assert moves(resolved_address(a)) == moves(fs), src
            for b in v:
                assert not b.endswith(TAB)
        # the same comments and % lines, the fixed and variable ones with one more
        # comment (the layout) after the two of the head
        rest = [[ln for ln in t.split("\n") if ln[:1] in ("%", "(")] for t in (address, fixed,
                                                                              variable)]
        assert rest[1][:3] == rest[0][:3] and rest[1][4:] == rest[0][3:]
        assert rest[2][:3] == rest[0][:3] and rest[2][4:] == rest[0][3:]
        assert rest[1][3].startswith("(fixed frames of 48 characters")
        assert rest[2][3].startswith("(variable frames")
        sizes[src.name] = (len(address), len(fixed), len(variable))
        for frame, text in (("address", address), ("fixed", fixed), ("variable", variable)):
            prog = tmp_path / f"p.{frame}"
            prog.write_text(text)
            ok = _em(em703_exe, "check", "--frame", frame, prog)
            assert ok.returncode == 0 and ok.stdout.endswith(b" no tape error\n"), ok.stderr
            for code in ("iso", "eia"):
                tape = tmp_path / f"p.{frame}.{code}.ptp"
                assert _em(em703_exe, "punch", "--code", code, prog, "-o", tape).returncode == 0
                back = _em(em703_exe, "check", "--frame", frame, tape)
                assert back.returncode == 0, back.stderr
                assert back.stdout.split(b": ", 1)[1] == ok.stdout.split(b": ", 1)[1]
    # variable frames are shorter than fixed ones, on every job and on the demo board
    for name, (a, f, v) in sizes.items():
        assert v < f, name
    board = max(sizes.values())
    assert board[2] < 0.6 * board[1]


def test_the_variable_frame_leaves_out_what_is_unchanged(em703_exe, example_jobs):
    """EXAMPLE3: the layout of docs/TOOLS.md, a TAB for every unchanged slot."""
    job = next(j for j in example_jobs if j.name == "EXAMPLE3.job")
    variable = iso_programs(_gcode(em703_exe, job, "variable"))[0]
    fixed = iso_programs(_gcode(em703_exe, job, "fixed"))[0]
    assert variable[0] == "001\t\t17"
    assert fixed[0] == "001  17" + "+000000" * 5 + "      "
    # T02 M06 after T01 M06: only the T slot changes, M06 stays in store
    assert variable[1:3] == ["002" + TAB * 9 + "01\t06", "003" + TAB * 9 + "02"]
    # the arc after the tool went down: Z back to +000000, F65 after F76
    assert variable[5] == "006\t02\t\t-020000\t-020000\t+000000\t-020000\t\t65"
    # a block after a tool change: M cleared (two spaces), not left in store
    assert variable[4].endswith("\t76\t\t  ")


def _write(path, blocks: list[str]):
    path.write_text("%\n" + "".join(b + "\n" for b in blocks) + "%\n")


def test_variable_frames_at_fault(em703_exe, tmp_path):
    prog = tmp_path / "v.iso"
    good = ["001\t\t17", "002\t01\t\t+001000\t+000000\t\t\t\t76", "003\t\t\t\t+002000"]
    _write(prog, good)
    ok = _em(em703_exe, "check", "--frame", "variable", prog)
    assert ok.returncode == 0 and ok.stdout == f"{prog}: 1 program, 3 blocks, no tape error\n".encode()
    cases = {
        # the TAB between X and Y missing
        "002\t01\t\t+001000+000000\t\t\t\t76":
            'block N002 (line 3): slot X (4th slot, columns 9-22) "+001000+000000" is not a sign '
            'and six digits (14 characters, 7 wanted: a TAB missing?)',
        # the TAB of the empty G10-G39 slot missing: X lands in that slot
        "002\t01\t+001000\t+000000\t\t\t\t76":
            'block N002 (line 3): slot G10-G39 (3rd slot, columns 8-14) "+001000" is not two '
            'digits (nor two spaces, no word) (7 characters, 2 wanted: a TAB missing?)',
        "002\t01\t\t+0010x0\t+000000":
            'block N002 (line 3): slot X (4th slot, columns 9-15) "+0010x0" is not a sign and six '
            'digits',
        "002\t17":
            'block N002 (line 3): slot G00-G09 (2nd slot, columns 5-6) "17" is G17, not of '
            'G00-G09, the codes this slot takes',
        "002" + TAB * 11:
            "block N002 (line 3): a variable frame has at most 11 slots (N G G X Y Z I J F T M, "
            "10 TABs), this one more: a TAB too many (the 11th TAB, column 14)",
        "\t01":
            "line 3: slot N is empty: every frame begins with its number, three digits",
        "N002 G01":
            'line 3: a variable frame begins with its number, three digits, not '
            '"N002" (a letter address: an address frame? see --frame)',
    }
    for bad, want in cases.items():
        _write(prog, [good[0], bad, good[2]])
        proc = _em(em703_exe, "check", "--frame", "variable", prog)
        assert proc.returncode == 1 and proc.stdout == b"", bad
        got = proc.stderr.decode("utf-8").splitlines()
        assert got[0] == f"{prog}: {want}", (bad, got)


def test_a_slot_of_megabytes_is_refused_at_once_in_one_short_line(em703_exe, tmp_path):
    """A message shows at most 20 characters of the program, then "...": a
    variable frame whose slot holds 2 MB of digits (its TABs lost), and an
    address block of one such word, are each refused with one short line.
    (The slot was once copied into the message a character at a time, which
    took minutes; the timeout makes such a regression fail, not hang.)"""
    digits = "1" * 2_000_000
    cases = [
        ("variable", "001\t" + digits,
         'block N001 (line 2): slot G00-G09 (2nd slot, columns 5-2000004) "' + "1" * 20 +
         '..." is not two digits (nor two spaces, no word) (2000000 characters, 2 wanted: a TAB '
         'missing?)'),
        ("address", "N001 X" + digits,
         "block N001 (line 2): the word X" + "1" * 19 + "... is not a sign and six digits"),
        ("fixed", "001  17" + "+000000" * 5 + "      " + digits,
         'block N001 (line 2): a fixed frame has 48 characters, this one 2000048: "' + "1" * 20 +
         '..." after slot M (from column 49)'),
    ]
    for frame, block, want in cases:
        prog = tmp_path / f"long.{frame}"
        _write(prog, [block])
        proc = subprocess.run([str(em703_exe), "check", "--frame", frame, str(prog)],
                              capture_output=True, timeout=60)
        assert proc.returncode == 1 and proc.stdout == b"", frame
        assert proc.stderr.decode("ascii") == f"{prog}: {want}\n", frame
        assert len(proc.stderr) < 300 + len(str(prog))


def test_variable_slots_resolve_before_the_group_check(em703_exe, tmp_path):
    """An empty slot is the previous block's value: the checks run on the
    resolved block (M03 in store and M05 cannot clash: one M slot), and the
    block numbers must still increase."""
    prog = tmp_path / "v.iso"
    # M03, then M05 in the M slot (M03 is replaced, not added), then an empty
    # M slot (M05 again): no clash of the spindle's group
    _write(prog, ["001\t\t17", "002" + TAB * 10 + "03", "003" + TAB * 10 + "05", "004\t01"])
    ok = _em(em703_exe, "check", "--frame", "variable", prog)
    assert ok.returncode == 0 and ok.stdout == f"{prog}: 1 program, 4 blocks, no tape error\n".encode()
    # written as address blocks, the resolved blocks: M03 and M05 never meet
    _write(prog, ["N001 G17", "N002 G17 M03", "N003 G17 M05", "N004 G01 G17 M05"])
    assert _em(em703_exe, "check", prog).returncode == 0
    _write(prog, ["N001 G17", "N002 M03 M05"])
    clash = _em(em703_exe, "check", prog)
    assert clash.returncode == 1 and b"M03 and M05 are of one group" in clash.stderr
    _write(prog, ["001\t\t17", "002\t01\t\t\t\t\t\t\t\t\t07", "002\t00"])
    proc = _em(em703_exe, "check", "--frame", "variable", prog)
    assert proc.returncode == 1
    assert proc.stderr.decode("utf-8").splitlines() == [
        f"{prog}: block N002 (line 3): M07 is not in the document's table (M00 M02 M03 M04 M05 "
        "M06 M38 M39 M40)",
        # the next frame leaves M empty: M07 again, from the block before
        f"{prog}: block N002 (line 4): block numbers must increase (N002 before)",
        f"{prog}: block N002 (line 4): M07 is not in the document's table (M00 M02 M03 M04 M05 "
        "M06 M38 M39 M40)"]


def test_fixed_frames_of_the_wrong_width_are_refused(em703_exe, tmp_path):
    prog = tmp_path / "f.iso"
    good = "002" + "01" + "17" + "+001000" + "+000000" * 4 + "76" + "  " + "  "
    assert len(good) == FIXED
    _write(prog, ["001  17" + "+000000" * 5 + "      ", good])
    ok = _em(em703_exe, "check", "--frame", "fixed", prog)
    assert ok.returncode == 0, ok.stderr
    cases = {
        good[:10] + good[11:]:       # a digit of X dropped: 47 characters
            'block N002 (line 3): slot X (columns 8-14) "+00000+" is not a sign and six digits; '
            'the frame has 47 characters, a fixed frame 48',
        good + "0":
            'block N002 (line 3): a fixed frame has 48 characters, this one 49: "0" after slot M '
            "(from column 49)",
        good[:-2]:                   # the trailing M slot lost (an editor's trim)
            "block N002 (line 3): a fixed frame has 48 characters, this one 46: slot M (columns "
            "47-48) is missing",
        good[:-4]:                   # T and M lost
            "block N002 (line 3): a fixed frame has 48 characters, this one 44: slots T to M "
            "(columns 45-48) are missing",
        good[:-1]:                   # half of M lost
            "block N002 (line 3): a fixed frame has 48 characters, this one 47: it ends in slot M "
            "(columns 47-48), which is cut short",
        good[:3] + "\t" + good[3:]:
            'block N002 (line 3): slot G00-G09 (columns 4-5) "<011>0" has a TAB in it; the frame '
            "has 49 characters, a fixed frame 48 (a TAB at column 4: a variable frame? see --frame)",
        good[:3] + "17" + good[5:]:
            'block N002 (line 3): slot G00-G09 (columns 4-5) "17" is G17, not of G00-G09, the '
            "codes this slot takes",
        "N002 G01 X+001000":
            'line 3: slot N (columns 1-3) "N00" is not three digits; the frame has 17 characters, '
            "a fixed frame 48 (a letter address: an address frame? see --frame)",
    }
    for bad, want in cases.items():
        _write(prog, ["001  17" + "+000000" * 5 + "      ", bad])
        proc = _em(em703_exe, "check", "--frame", "fixed", prog)
        assert proc.returncode == 1 and proc.stdout == b"", bad
        assert proc.stderr.decode("utf-8").splitlines() == [f"{prog}: {want}"], bad


def test_a_program_checked_in_the_wrong_frame_says_so_at_its_first_block(em703_exe, example_jobs,
                                                                       tmp_path):
    """docs/TOOLS.md: "A program checked in the wrong kind of frame says so at
    its first block", for each of the six pairs of kinds."""
    job = next(j for j in example_jobs if j.name == "EXAMPLE3.job")
    want = {
        ("address", "fixed"):
            'line 4: slot N (columns 1-3) "N00" is not three digits; the frame has 8 characters, a '
            "fixed frame 48 (a letter address: an address frame? see --frame)",
        ("address", "variable"):
            'line 4: a variable frame begins with its number, three digits, not "N001" (a letter '
            "address: an address frame? see --frame)",
        ("fixed", "address"):
            'line 5: a block begins with N and three digits, not "001 " (no letter: a fixed or a '
            "variable frame? see --frame)",
        ("fixed", "variable"):
            'block N001 (line 5): slot N (1st slot, columns 1-48) "001  17+000000+00000..." is not '
            "three digits (48 characters and no TAB, a fixed frame's width: a fixed frame? see "
            "--frame)",
        ("variable", "address"):
            'line 5: a block begins with N and three digits, not "001<011>" (no letter: a fixed or '
            "a variable frame? see --frame)",
        ("variable", "fixed"):
            'block N001 (line 5): slot G00-G09 (columns 4-5) "<011><011>" has a TAB in it; the frame '
            "has 7 characters, a fixed frame 48 (a TAB at column 4: a variable frame? see --frame)",
    }
    for (written, checked), message in want.items():
        prog = tmp_path / f"p.{written}"
        prog.write_text(_gcode(em703_exe, job, written))
        proc = _em(em703_exe, "check", "--frame", checked, prog)
        assert proc.returncode == 1 and proc.stdout == b"", (written, checked)
        first = proc.stderr.decode().splitlines()[0]
        assert first == f"{prog}: {message}", (written, checked, first)


def test_tab_on_iso_and_eia_tape(em703_exe, tmp_path):
    """TAB punches on both tapes (ISO: HT, 011 octal; EIA RS-244: 2-3-4-5-6,
    076 octal) and em703 view names it."""
    prog = tmp_path / "t.iso"
    prog.write_text("%\n001\t\t17\n%\n")
    for code, octal in (("iso", "011"), ("eia", "076")):
        tape = tmp_path / f"t.{code}.ptp"
        assert _em(em703_exe, "punch", "--code", code, prog, "-o", tape).returncode == 0
        rows = tape.read_bytes()
        assert rows[20 + 5] == int(octal, 8) and rows[20 + 6] == int(octal, 8)
        view = _em(em703_exe, "view", tape, "--code", code, "--rows", "26:27").stdout.decode()
        tabs = [ln for ln in view.splitlines() if ln.rstrip().endswith(f"| {octal}   tab")]
        assert len(tabs) == 2, view
        back = _em(em703_exe, "check", "--frame", "variable", tape)
        assert back.returncode == 0 and back.stdout.endswith(b"1 program, 1 block, no tape error\n")


def test_check_of_an_eia_tape_with_a_parity_error(em703_exe, tmp_path):
    prog = tmp_path / "p.iso"
    prog.write_text("%\nN001 G17\nN002 M02\n%\n")
    tape = tmp_path / "p.ptp"
    assert _em(em703_exe, "punch", "--code", "eia", prog, "-o", tape).returncode == 0
    assert _em(em703_exe, "check", tape).returncode == 0
    data = bytearray(tape.read_bytes())
    assert data[25] == 0o001                # the 1 of N001, one hole
    data[25] ^= 2                           # a hole too many on track 2
    tape.write_bytes(bytes(data))
    proc = _em(em703_exe, "check", tape)
    assert proc.returncode == 1
    assert proc.stderr.decode() == f"{tape}: row 26: parity error (even number of holes): not an " \
                                   "EIA tape, or a misread row\n"


def test_frame_on_the_command_line(em703_exe, example_tapes, tmp_path):
    tape = list(example_tapes)[0]
    bad = _em(em703_exe, "gcode", tape, "--frame", "fixed")
    assert bad.returncode == 2 and b"--frame is for --dialect iso-1970s" in bad.stderr
    bad = _em(em703_exe, "gcode", "--dialect", "iso-1970s", tape, "--frame", "tab")
    assert bad.returncode == 2
    assert b'--frame takes address, fixed or variable, not "tab"' in bad.stderr
    prog = tmp_path / "p.iso"
    prog.write_text("%\nN001 G17\n%\n")
    assert _em(em703_exe, "check", prog, "--frame", "address").returncode == 0
    bad = _em(em703_exe, "check", prog, "--frame", "")
    assert bad.returncode == 2 and bad.stdout == b""
    assert bad.stderr == b'em703 check: --frame takes address, fixed or variable, not "" (see em703 ' \
                         b"check --help)\n"
    for sub in ("gcode", "check"):
        assert b"--frame" in _em(em703_exe, sub, "--help").stdout
    assert b"[--frame address|fixed|variable]" in _em(em703_exe, "--help").stdout
