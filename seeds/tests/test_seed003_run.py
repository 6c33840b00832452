"""Seed 003, the line and the run: lost and stray bytes survived with
resends, the program the CNC accepted equal to the one sent, the run mode's
conversation (Пуск, ready, Кадр, Сбой, КП, Стоп), the parameter message with
its CRC byte, the panel, the picture."""
from __future__ import annotations

import struct
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from seeds import seed003 as s3

ROOT = Path(__file__).resolve().parents[2]
DATA = s3.encode(s3.program([[(0, 0), (i * 1000, (i % 7) * 300)] for i in range(1, 40)]))
TWO = "# two polylines\n0 0\n40000 0\n40000 100\n\n5 5\n6 9\n"


def cnclink(*args: str, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "seeds", "cnclink", *args], cwd=cwd,
                          capture_output=True, text=True, encoding="utf-8")


# ---------------------------------------------------------------------------
# The line.
# ---------------------------------------------------------------------------
def test_a_lost_byte_was_fatal_now_recovered() -> None:
    """The reported failure: one dropped byte with three resends allowed."""
    result = s3.send(DATA, drop_at=[2], resend=3)
    assert result.ok and result.controller.program == DATA
    assert result.log[1] == "block 2/7 transmission 2 (byte 119 lost): NAK"
    assert "cnc: block 2: 132 of 133 bytes, then 1 s of silence: timeout, NAK" \
        in result.controller.log
    paper = s3.send(DATA, drop_at=[2])
    assert not paper.ok and paper.message.startswith("ошибка вывода (output error): block 2 of 7")
    assert paper.controller.memory == [] and paper.controller.program == b""


def test_lost_soh_and_stray_bytes_are_hunted_past() -> None:
    pkt = s3.packet(1, DATA[:128])
    ctl = s3.Controller()
    ctl.feed(pkt[1:])                       # SOH lost: the block number 0x01 looks like one
    assert ctl.answers == []
    ctl.quiet()
    assert ctl.answers == [s3.NAK] and ctl.memory == []
    ctl.answers.clear()
    ctl.feed(b"\x55\xaa" + pkt)             # noise before the packet
    assert ctl.answers == [s3.ACK] and ctl.memory == [DATA[:128]]
    assert "cnc: 2 stray bytes before SOH discarded" in ctl.log
    bad = bytearray(s3.packet(2, DATA[128:256]))
    bad[-1] ^= 0xFF                         # damaged CRC byte
    ctl.answers.clear()
    ctl.feed(bytes(bad[:60]) + b"\x01" + bytes(bad[60:]))   # and a stray byte inside
    assert ctl.answers == []                # it waits for the line to fall quiet
    ctl.quiet()
    assert ctl.answers == [s3.NAK] and len(ctl.memory) == 1
    assert "cnc: 1 more byte discarded until the line fell quiet" in ctl.log


def test_eot_inside_a_hunt_is_not_an_end() -> None:
    """A 0x04 met while hunting for SOH is a data byte, not EOT."""
    ctl = s3.Controller()
    ctl.feed(b"\x33\x04")
    assert not ctl.complete


transmission = st.integers(1, 24)


@settings(max_examples=60, deadline=None)
@given(drop=st.sets(transmission, max_size=3), noise=st.sets(transmission, max_size=3),
       flip=st.sets(transmission, max_size=3), resend=st.integers(0, 7))
@example(drop={1, 2, 3}, noise={4}, flip={5}, resend=3)
def test_any_fault_pattern(drop, noise, flip, resend) -> None:
    """Whatever the line does: either the CNC holds exactly the program sent,
    or the shell says "ошибка вывода" and the CNC holds nothing.  A fault
    costs one transmission: with a resend budget at least the number of
    damaged transmissions, the transfer completes."""
    result = s3.send(DATA, flip, resend, drop, noise)
    ctl = result.controller
    if result.ok:
        assert ctl.complete and ctl.program == DATA
    else:
        assert result.message.startswith("ошибка вывода")
        assert not ctl.complete and ctl.memory == [] and ctl.program == b""
    if resend >= len(drop | noise | flip):
        assert result.ok, result.log


def test_survival_table_in_the_docs_is_current() -> None:
    data = s3.encode(s3.program(s3.deck_polylines((ROOT / "examples" / "demo.crd").read_text())))
    table = "\n".join(s3.survival_table(data))
    assert table in (ROOT / "docs" / "SEED003-CNC-LINK.md").read_text()


def test_cnclink_received_equals_output(tmp_path: Path) -> None:
    src = tmp_path / "pl.txt"
    src.write_text(TWO)
    out, got = tmp_path / "p.bin", tmp_path / "r.bin"
    run = cnclink(str(src), "-o", str(out), "--received", str(got), "--drop", "1",
                  "--noise", "2", "--corrupt", "3", "--resend", "3")
    assert run.returncode == 0, run.stderr
    assert run.stdout.splitlines()[:4] == [
        "block 1/1 transmission 1 (byte 60 lost): NAK",
        "block 1/1 transmission 2 (stray byte 0xc3 before byte 9): NAK",
        "block 1/1 transmission 3 (bit flipped in byte 115): NAK",
        "block 1/1 transmission 4: ACK"]
    assert got.read_bytes() == out.read_bytes() == s3.encode(s3.program(s3.read_polylines(TWO)))
    paper = cnclink(str(src), "--drop", "1", "--received", str(tmp_path / "none.bin"))
    assert paper.returncode == 1 and "ошибка вывода (output error)" in paper.stderr
    assert not (tmp_path / "none.bin").exists()
    assert "Traceback" not in paper.stderr


@pytest.mark.parametrize("args, message", [
    (["--drop", "x"], "cnclink: --drop 'x': expected transmission numbers like 2,5,9"),
    (["--noise", "0"], "cnclink: --noise '0': transmissions are numbered from 1"),
    # an empty item was skipped: 1,,2 taken as 1,2
    (["--drop", "1,,2"], "cnclink: --drop '1,,2': item 2 is empty; expected transmission "
                         "numbers like 2,5,9"),
    (["--corrupt", "3,"], "cnclink: --corrupt '3,': item 2 is empty"),
    (["--limits", "5"], "cnclink: --limits '5': expected X,Y in whole pulses"),
    (["--resend", "-1"], "cnclink: --resend -1: expected a whole number from 0"),
    (["--stop-at", "0"], "cnclink: --stop-at 0: expected a whole number from 1"),
])
def test_bad_options_are_named(tmp_path: Path, args, message) -> None:
    src = tmp_path / "pl.txt"
    src.write_text(TWO)
    run = cnclink(str(src), *args)
    assert run.returncode == 2 and run.stderr.startswith(message), run.stderr


def test_bad_input_is_named(tmp_path: Path) -> None:
    src = tmp_path / "pl.txt"
    src.write_text("0 0\n1 x\n")
    run = cnclink(str(src))
    assert run.returncode == 1
    assert run.stderr == (f"cnclink: {src}: line 2: expected 'x y' in whole pulses, "
                          f"got '1 x'\n")
    src.write_text("0 0\n200000 0\n")
    run = cnclink(str(src))
    assert run.returncode == 1 and "polyline 1 segment 1 from (0, 0) to (200000, 0)" in run.stderr
    src.write_text("0 0\n\n5 5\n6 6\n")
    run = cnclink(str(src))
    assert run.stderr == (f"cnclink: {src}: line 1: polyline at (0, 0) has one point; "
                          f"a polyline needs two\n")


# ---------------------------------------------------------------------------
# Parameters.
# ---------------------------------------------------------------------------
def test_crc8_and_the_parameter_message() -> None:
    assert s3.crc8(b"123456789") == 0xF4
    msg = s3.param_message(s3.defaults())
    buf = struct.pack("<BBI8H", 3, 4, 60000, 500, 0, 0, 0, 0, 0, 0, 0)
    assert msg == bytes([s3.CMD_PARAMS, len(buf)]) + buf + bytes([s3.crc8(buf)])
    four = dict(s3.defaults(), axes=4)
    assert len(s3.param_buffer(four)) == len(buf) + 4          # φ's long
    assert len(s3.param_buffer(dict(s3.defaults(), axes=2))) == 6
    machine = s3.Machine()
    assert machine.load_params(s3.param_message(dict(four, z3=77))) == s3.ACK
    assert machine.params["z3"] == 77 and machine.params["axes"] == 4
    assert machine.load_params(msg[:-1] + bytes([msg[-1] ^ 1])) == s3.NAK
    assert machine.params["z3"] == 77                          # kept the old ones


def test_parameter_entry_checks_ranges() -> None:
    values, notes = s3.read_params("axes = 2\nm = 300\nz1 = 5\nfoo=1\nfeed = x\nm 3\n", "p.txt")
    assert values["m"] == 4 and values["feed"] == 60000 and values["z1"] == 0
    assert notes == [
        "p.txt: line 2: m = 300 is out of range 1..255; set to the default 4",
        "p.txt: line 4: unknown parameter 'foo'; the parameters are axes, m, feed, z0, z1, "
        "z2, z3, z4, z5, z6, z7, phi",
        "p.txt: line 5: feed = 'x' is not a whole number 1..10000000; set to the default 60000",
        "p.txt: line 6: expected 'name = value', got 'm 3'",
        "p.txt: line 3: z1 is not a parameter of a 2-axis machine; ignored",
    ]


def test_both_ends_of_every_range_are_taken() -> None:
    """A value at either end of its parameter's range is taken as given,
    with no message; one past an end gets the default."""
    low = "\n".join(f"{p.name} = {p.low}" for p in s3.PARAMS) + "\naxes = 4\n"
    high = "\n".join(f"{p.name} = {p.high}" for p in s3.PARAMS) + "\n"
    for text, end in ((low, "low"), (high, "high")):
        values, notes = s3.read_params(text, "p.txt")
        assert notes == []
        assert values == {p.name: 4 if p.name == "axes" else getattr(p, end) for p in s3.PARAMS}
    values, notes = s3.read_params("axes = 4\nphi = 10000001\nz7 = 32768\n", "p.txt")
    assert values["phi"] == 3600 and values["z7"] == 0 and len(notes) == 2


def test_a_bad_value_of_another_axis_group_is_said_to_be_unused() -> None:
    # "z0 = -1 is out of range 0..32767; set to the default 500" on a machine
    # of 2 axes, which has no z0
    values, notes = s3.read_params("z0 = -1\nz5 = x\naxes = 2\nm = 0\n", "p.txt")
    assert values["z0"] == 500 and values["m"] == 4
    assert notes == [
        "p.txt: line 1: z0 = -1 is out of range 0..32767, and z0 is not a parameter of a "
        "2-axis machine; ignored",
        "p.txt: line 2: z5 = 'x' is not a whole number 0..32767, and z5 is not a parameter "
        "of a 2-axis machine; ignored",
        "p.txt: line 4: m = 0 is out of range 1..255; set to the default 4",
    ]


def test_cnclink_params(tmp_path: Path) -> None:
    src, par = tmp_path / "pl.txt", tmp_path / "p.txt"
    src.write_text(TWO)
    par.write_text("m = 2\nz0 = 800\nz1 = 20\n")
    run = cnclink(str(src), "--params", str(par), "--run", "--stop-at", "3")
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert lines[0] == "parameters: 25 bytes, CRC-8 0x3e: ACK"
    assert "panel: Z          20         20          0" in lines     # lowered to z1
    assert "panel: X       20000      20000          0" in lines     # m = 2: 40000 in 2
    bad = cnclink(str(src), "--params", str(par), "--corrupt-params")
    assert bad.returncode == 1
    assert "ошибка загрузки параметров (parameter load error)" in bad.stderr


# ---------------------------------------------------------------------------
# The run.
# ---------------------------------------------------------------------------
def test_run_conversation_exact(tmp_path: Path) -> None:
    src = tmp_path / "pl.txt"
    src.write_text("0 0\n100 0\n100 50\n")
    run = cnclink(str(src), "--run")
    assert run.returncode == 0, run.stderr
    assert run.stdout == """\
block 1/1 transmission 1: ACK
EOT: ACK
program sent: 1 blocks, 1 transmissions
Пуск: the program's picture is drawn in the view; start command 0x12 sent
ЧПУ: 0x01: готова (ready); the program runs
Кадр 1
Кадр 2
Кадр 3
Кадр 4
Кадр 5
Кадр 6
КП: программа выполнена (the program ran to its end)
panel: axis        set     actual   mismatch
panel: X           0          0          0
panel: Y           0          0          0
panel: Z         500        500          0
panel: φ     (not active on a 3-axis machine)
"""


def test_stop_limits_and_faults(tmp_path: Path) -> None:
    src = tmp_path / "pl.txt"
    src.write_text(TWO)
    stop = cnclink(str(src), "--run", "--stop-at", "4")
    assert stop.returncode == 0
    assert stop.stdout.splitlines()[-7:-5] == [
        "Кадр 4", "Стоп pressed: stop command 0x14 sent; the picture is removed from the "
                  "view; back to the start"]
    edge = cnclink(str(src), "--run", "--limits", "30000,30000")
    assert edge.returncode == 1
    assert ("Сбой 1: выход за пределы стола (a move past the table's limits); back to the "
            "start (frame 6, word 12 of the program)") in edge.stdout.splitlines()
    assert cnclink(str(src), "--run", "--limits", "40000,30000").returncode == 0
    panel = cnclink(str(src), "--run", "--panel-stop", "2")
    assert "Сбой 3: останов с пульта ЧПУ (stopped by the operator at the CNC's panel); " \
           "back to the start (frame 3, word 3 of the program)" in panel.stdout
    words = [0x1000, 0x1009, 0xFF00]
    prog = tmp_path / "layer9.bin"
    prog.write_bytes(struct.pack("<3H", *words))
    layer = cnclink(str(prog), "--run")
    assert "Сбой 4: нет высоты слоя в таблице (a z layer with no height in the table); " \
           "back to the start (frame 2, word 2 of the program)" in layer.stdout
    prog.write_bytes(struct.pack("<3H", 0x1000, 0x3000, 0xFF00))
    unknown = cnclink(str(prog), "--run")
    assert "Сбой 2: неизвестная команда (a command the CNC does not know); back to the " \
           "start (frame 2, word 2 of the program)" in unknown.stdout
    failed = cnclink(str(src), "--run", "--corrupt", "1")
    assert failed.returncode == 1
    assert failed.stdout.splitlines()[-1] == (
        "ЧПУ: 0x00: не готова к работе (not ready: no program in memory); back to the start")


def test_svg_and_view(tmp_path: Path) -> None:
    src = tmp_path / "pl.txt"
    src.write_text(TWO)
    pics = []
    for k in range(2):
        pic = tmp_path / f"run{k}.svg"
        assert cnclink(str(src), "--run", "--stop-at", "7", "--svg", str(pic)).returncode == 0
        pics.append(pic.read_text())
    assert pics[0] == pics[1]                               # byte-identical run to run
    assert pics[0].count('stroke="#d00000"') == 5           # 4 parts of 40000, the 100
    assert pics[0].count('stroke="#000000"') == 1           # (5, 5)-(6, 9) still to do
    data = s3.encode(s3.program(s3.read_polylines(TWO)))
    assert s3.view(data)[:3] == ["    1  1000            z layer 0",
                                 "    2  1001            z layer 1",
                                 "    3  2000 2710 0000  move +10000 +0"]
    assert s3.view(data)[-1] == "   17  FF00            конец УП (end)"


def test_a_file_that_is_not_a_whole_program_or_draws_nothing_is_said(tmp_path: Path) -> None:
    """Random bytes, a program cut short, an empty file and a deck of pads
    only were all "sent" with exit 0 and "it draws 0 polylines"."""
    from harness import cards
    whole = s3.encode(s3.program(s3.read_polylines(TWO)))
    cases = {
        "noise.bin": (bytes((k * 151 + 7) % 256 for k in range(300)),
                      "noise.bin: not a whole program: word 1: unknown command 0x9e07"),
        "cut.bin": (whole[:-2], f"cut.bin: not a whole program: word {len(whole) // 2 - 1}: "
                                f"the program has no end command"),
        "empty.txt": (b"", "empty.txt: nothing to draw: no polyline of two points or more in "
                           "it; nothing sent"),
        "pads.crd": (cards.deck([cards.CardPackage("PADS", [cards.p_card(1000, 1000, 80, 80, 40),
                                                            cards.d_card(100, 100, 160)])])
                     .encode("ascii"),
                     "pads.crd: nothing to draw: the deck has no conductors (L and + cards), "
                     "the only cards cnclink draws; nothing sent"),
    }
    for name, (data, words) in cases.items():
        (tmp_path / name).write_bytes(data)
        proc = cnclink(str(tmp_path / name))
        assert proc.returncode == 1, (name, proc.stdout, proc.stderr)
        assert words in proc.stderr, (name, proc.stderr)
        assert "draws 0 polylines" not in proc.stdout and "Traceback" not in proc.stderr
        if name.endswith(".bin"):
            assert "EOT: ACK" in proc.stdout            # sent as it is: the CNC judges it
        else:
            assert proc.stdout == ""                    # nothing sent
    (tmp_path / "ok.bin").write_bytes(whole)
    assert cnclink(str(tmp_path / "ok.bin")).returncode == 0
    # a whole program that draws nothing is the CNC's to run (a z layer only)
    (tmp_path / "z.bin").write_bytes(struct.pack("<3H", 0x1000, 0x1001, 0xFF00))
    z = cnclink(str(tmp_path / "z.bin"))
    assert z.returncode == 0 and "z.bin: the program draws nothing (no move with the tool " \
        "lowered)" in z.stderr, z.stderr
