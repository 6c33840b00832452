"""Seed 003 (the PC shell for a CNC): one- and three-word commands,
increments split at 15 bits, 128-byte blocks with a CRC, and a loopback
transfer to a simulated controller that acknowledges each block."""
from __future__ import annotations

import struct
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from seeds import seed003 as s3
from harness.deck import parse_deck
from seeds.seed004 import line_distance

ROOT = Path(__file__).resolve().parents[2]

coord = st.integers(-60000, 60000)      # every increment within m x 0x7FFF
st_polylines = st.lists(st.lists(st.tuples(coord, coord), min_size=2, max_size=6),
                        min_size=1, max_size=5)


def test_command_words() -> None:
    """Block 6: operation code ORed with the signs; then |dx|, |dy|."""
    assert s3.Command(s3.OP_LINE, dx=-5, dy=7).words() == [0x2002, 5, 7]
    assert s3.Command(s3.OP_LINE, dx=5, dy=-7).words() == [0x2001, 5, 7]
    assert s3.Command(s3.OP_LINE, dx=-32767, dy=-1).words() == [0x2003, 0x7FFF, 1]
    assert s3.Command(s3.OP_Z, layer=1).words() == [0x1001]
    assert s3.Command(s3.OP_END).words() == [0xFF00]
    with pytest.raises(ValueError):
        s3.Command(s3.OP_LINE, dx=32768).words()
    assert s3.encode([s3.Command(s3.OP_LINE, dx=-5, dy=7)]) == bytes([0x02, 0x20, 5, 0, 7, 0])


def test_long_increments_are_split_at_15_bits() -> None:
    """Blocks 7, 8, 14-16: a line of 100000 x 3 pulses becomes m = 4 moves
    (the machine's fixed ratio); so does one of 40000 x 0, and with m = 10
    it is 10 moves; one longer than m x 0x7FFF is refused, naming it."""
    assert [c.dx for c in s3.program([[(0, 0), (40000, 0)]])[2:6]] == [10000] * 4
    assert len([c for c in s3.program([[(0, 0), (40000, 0)]], ratio=10)
                if c.op == s3.OP_LINE]) == 10 + 10           # drawn, and the way back
    with pytest.raises(ValueError, match=r"polyline 1 segment 1 from \(0, 0\) to "
                                         r"\(131069, 0\): increment of 131069 pulses "
                                         r"is more than the machine's largest, "
                                         r"m x 32767 = 131068 \(m = 4; the parameter m "
                                         r"would have to be at least 5\)"):
        s3.program([[(0, 0), (131069, 0)]])
    cmds = s3.program([[(0, 0), (100000, 3)]])
    moves = [c for c in cmds if c.op == s3.OP_LINE]
    drawn = moves[:4]          # from the start point (0, 0) the first move is the line
    assert [c.dx for c in drawn] == [25000] * 4
    assert sum(c.dy for c in drawn) == 3
    assert all(abs(c.dx) <= s3.MAX_STEP and abs(c.dy) <= s3.MAX_STEP for c in moves)


def test_the_longest_increments_of_one_and_of_m_parts() -> None:
    """0x7FFF pulses is still one move (int/2 is the limit, not beyond it);
    m x 0x7FFF = 131068 is still m moves, each of 0x7FFF; one pulse more
    is refused."""
    assert s3.program([[(0, 0), (32767, -32767)]])[2] == s3.Command(s3.OP_LINE, dx=32767,
                                                                    dy=-32767)
    assert s3.program([[(0, 0), (32767, -32767)]])[3] == s3.Command(s3.OP_Z, s3.LAYER_UP)
    cmds = s3.program([[(0, 0), (0, 131068)]])
    assert cmds[2:7] == [s3.Command(s3.OP_LINE, dx=0, dy=32767)] * 4 + [
        s3.Command(s3.OP_Z, s3.LAYER_UP)]
    with pytest.raises(ValueError, match="increment of 131069 pulses"):
        s3.program([[(0, 0), (0, 131069)]])


def test_program_shape() -> None:
    """First command sets z (raised), the last is 'конец УП'."""
    cmds = s3.program([[(10, 10), (20, 10)], [(30, 30), (30, 40), (40, 40)]])
    assert cmds[0] == s3.Command(s3.OP_Z, s3.LAYER_UP)
    assert cmds[-1] == s3.Command(s3.OP_END)
    kinds = [c.op for c in cmds]
    assert kinds.count(s3.OP_Z) == 1 + 2 * 2
    assert s3.decode(s3.encode(cmds)) == cmds


@given(pls=st_polylines)
@example(pls=[[(0, 0), (0, 0)], [(5, 5), (5, 5), (70000, -70000)]])
def test_program_round_trip_draws_the_polylines(pls) -> None:
    cmds = s3.program(pls)
    assert s3.decode(s3.encode(cmds) + b"\0" * 7) == cmds     # padding ignored
    x = y = 0
    for c in cmds:
        if c.op == s3.OP_LINE:
            x, y = x + c.dx, y + c.dy
    assert (x, y) == (0, 0)                                  # back at the start
    drawn = s3.execute(cmds)
    want = [pl for pl in pls if any(p != pl[0] for p in pl)]
    assert len(drawn) == len(want)
    for got, pl in zip(drawn, want):
        assert got[0] == pl[0] and got[-1] == pl[-1]
        pos = 0
        for p in pl:                                         # every vertex, in order
            pos = got.index(p, pos)


def test_extra_points_stay_on_the_line() -> None:
    (pl,) = s3.execute(s3.program([[(0, 0), (98132, 87647)]]))
    assert pl[0] == (0, 0) and pl[-1] == (98132, 87647) and len(pl) == 5   # m = 4, fixed
    assert all(abs(line_distance(x, y, 98132, 87647)) < 1 for x, y in pl)


def test_decode_names_the_word() -> None:
    data = s3.encode([s3.Command(s3.OP_Z, 0)]) + struct.pack("<H", 0x3000)
    with pytest.raises(ValueError, match="word 2: unknown command 0x3000"):
        s3.decode(data)
    with pytest.raises(ValueError, match="no end command"):
        s3.decode(s3.encode([s3.Command(s3.OP_Z, 0)]))


# ---------------------------------------------------------------------------
# Blocks, CRC, the controller.
# ---------------------------------------------------------------------------
def test_crc_check_value() -> None:
    assert s3.crc16(b"123456789") == 0x31C3
    assert s3.crc16(b"") == 0


def test_blocks_and_packets() -> None:
    data = bytes(range(256)) + b"xyz"
    bl = s3.blocks(data)
    assert [len(b) for b in bl] == [128, 128, 128]
    assert bl[2] == b"xyz" + b"\0" * 125
    pk = s3.packets(data)
    assert pk[1][:3] == bytes([s3.SOH, 2, 253]) and len(pk[1]) == 133
    crc = s3.crc16(bl[1])
    assert pk[1][-2:] == bytes([crc >> 8, crc & 0xFF])


def test_block_numbers_wrap_after_255() -> None:
    """The block number is one byte, mod 256 (XMODEM's): block 256 is 0 and
    block 257 is 1, each with its complement; a program of 300 blocks goes
    through whole."""
    block = bytes(128)
    assert [s3.packet(n, block)[:3] for n in (255, 256, 257)] == [
        bytes([s3.SOH, 255, 0]), bytes([s3.SOH, 0, 255]), bytes([s3.SOH, 1, 254])]
    data = bytes((k * 7 + k // 128) & 0xFF for k in range(300 * 128))
    result = s3.send(data)
    assert result.ok and result.transmissions == 300
    assert result.message == "program sent: 300 blocks, 300 transmissions"
    assert b"".join(result.controller.memory) == data


@given(block=st.binary(min_size=128, max_size=128), start=st.integers(0, 132 * 8 - 1),
       length=st.integers(1, 16), pattern=st.integers(1, 2 ** 16 - 1))
def test_controller_refuses_every_burst_error(block, start, length, pattern) -> None:
    """A CRC-16 catches every burst of up to 16 bits: such a damaged packet
    is refused and never stored."""
    pkt = bytearray(s3.packet(1, block))
    bits = (pattern & ((1 << length) - 1)) | 1 << (length - 1) | 1   # a burst from start
    for k in range(length):
        if bits >> k & 1:
            bit = 8 + start + k                  # past the SOH byte
            if bit < len(pkt) * 8:
                pkt[bit // 8] ^= 0x80 >> (bit % 8)
    ctl = s3.Controller()
    if bytes(pkt) == s3.packet(1, block):
        return
    assert ctl.receive(bytes(pkt)) == s3.NAK
    assert ctl.memory == []


def test_loopback_transfer_runs_the_program() -> None:
    (pkg,) = [p for p in parse_deck((ROOT / "examples" / "demo.crd").read_text())]
    pls = [list(c.points) for c in pkg.conductors]
    data = s3.encode(s3.program(pls))
    result = s3.send(data)
    assert result.ok and result.transmissions == len(s3.blocks(data)) > 1
    assert all(line.endswith("ACK") for line in result.log)
    assert result.controller.complete
    assert b"".join(result.controller.memory)[:len(data)] == data
    assert result.controller.program == data
    assert result.controller.drawn == s3.execute(s3.program(pls))


def test_a_damaged_block_is_an_output_error_and_nothing_runs() -> None:
    data = s3.encode(s3.program([[(0, 0), (i * 1000, (i % 7) * 300)] for i in range(1, 40)]))
    n = len(s3.blocks(data))
    assert n >= 3
    result = s3.send(data, corrupt_at=[2])
    assert not result.ok
    assert result.message.startswith("ошибка вывода (output error): block 2 of")
    assert result.transmissions == 2 and result.log[-1].endswith("NAK")
    ctl = result.controller
    assert ctl.abandoned and not ctl.complete and ctl.drawn is None and ctl.memory == []


def test_resending_recovers() -> None:
    """The improvement: a refused block is sent again (here twice damaged,
    then intact)."""
    data = s3.encode(s3.program([[(0, 0), (i * 1000, (i % 7) * 300)] for i in range(1, 40)]))
    n = len(s3.blocks(data))
    result = s3.send(data, corrupt_at=[2, 3], resend=2)
    assert result.ok and result.transmissions == n + 2
    assert [line.split(": ")[-1] for line in result.log[1:4]] == ["NAK", "NAK", "ACK"]
    assert result.controller.drawn == s3.execute(s3.program(
        [[(0, 0), (i * 1000, (i % 7) * 300)] for i in range(1, 40)]))
    worse = s3.send(data, corrupt_at=[2, 3, 4], resend=2)
    assert not worse.ok and "after 3 transmissions" in worse.message


@settings(max_examples=15, deadline=None)
@given(pls=st_polylines, damaged=st.sets(st.integers(1, 12), max_size=3),
       resend=st.integers(0, 3))
def test_transfer_never_runs_a_damaged_program(pls, damaged, resend) -> None:
    data = s3.encode(s3.program(pls))
    result = s3.send(data, corrupt_at=damaged, resend=resend)
    ctl = result.controller
    if result.ok:
        assert ctl.drawn == s3.execute(s3.program(pls))
        assert b"".join(ctl.memory)[:len(data)] == data
    else:
        assert ctl.drawn is None and "ошибка вывода" in result.message


def test_cnclink_command(tmp_path: Path) -> None:
    text = "# two polylines\n0 0\n40000 0\n40000 100\n\n5 5\n6 9\n"
    src = tmp_path / "pl.txt"
    src.write_text(text)
    prog = tmp_path / "prog.bin"
    ok = subprocess.run([sys.executable, "-m", "seeds", "cnclink", str(src), "-o", str(prog)],
                        cwd=ROOT, capture_output=True, text=True)
    assert ok.returncode == 0, ok.stderr
    assert "it draws 2 polylines" in ok.stdout
    assert s3.decode(prog.read_bytes()) == s3.program(s3.read_polylines(text))
    bad = subprocess.run([sys.executable, "-m", "seeds", "cnclink", str(src), "--corrupt", "1"],
                         cwd=ROOT, capture_output=True)
    assert bad.returncode == 1
    assert "ошибка вывода" in bad.stderr.decode("utf-8")
