"""Seed 003: a PC shell for a CNC: polylines to a binary program, sent in
128-byte blocks with a CRC and an acknowledgement per block.

Source: seed 003 (docs/SOURCES.md) (Russian paper on a PC
information-and-control shell for a CNC system; OCR text of its section on
Fig. 5 "Блок-схема алгоритма кодирования и вывода УП"; the figures are lost
and no byte values are given).  What it says, and what is built:

* A command of the program (УП) is one or three 16-bit words ("int").  A
  one-word command is technological or moves the tool (РИ) in z to a layer
  whose height is a parameter of the CNC.  A three-word command is a move in
  relative coordinates: the first word is the operation code ORed with the
  signs of the increments (block 6), the next two are |dx| and |dy|.
  (:func:`encode`, :func:`decode`.)
* The first command sets the tool's starting z; the last is "конец УП"
  (block 12).  Where the next point is "Const" (a transition between
  polylines) the tool is raised or lowered (block 9).
* An increment may not exceed int/2, 15 bits (blocks 7, 8); a longer line
  is cut into m parts (blocks 14-16).  The cut here is seed 004's
  (:func:`seeds.seed004.split_move` with at most 32767 pulses), so every
  division point stays within one pulse of the line.
* The program is cut into 128-byte blocks, each with a CRC; each block
  sent is acknowledged by the CNC; on a failed transfer the shell says
  "ошибка вывода" (output error, block 20) and stops: the whole process has
  to be started again.  (:func:`packets`, :class:`Controller`,
  :func:`send`.)  The documented improvement, resending a block the CNC
  refused up to N times, is the option ``resend``.

Decisions where the paper is silent (docs/SEED003-CNC-LINK.md): words are
little-endian (an x86 PC); operation codes are in the high byte; the packet
is XMODEM-CRC's (SOH, block number, its complement, 128 bytes, CRC-16 with
polynomial 0x1021, initial 0, high byte first), ACK 0x06 / NAK 0x15, EOT
ends the transfer and CAN abandons it; the last block is padded with zero
bytes.  The controller keeps the blocks in its program memory and runs
nothing until the whole program has arrived intact.
"""

from __future__ import annotations

import argparse
import socket
import struct
import sys
import threading
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

from harness.deck import parse_deck
from harness.files import write_whole

from .seed004 import split_move

#: Largest increment of a three-word command: int/2, 15 bits.
MAX_STEP = 0x7FFF
#: Operation codes (high byte of the first word).
OP_Z = 0x10          # one word: move the tool in z to layer (low byte)
OP_LINE = 0x20       # three words: low bits 1 = x negative, 0 = y negative
OP_END = 0xFF        # one word: end of the program ("конец УП")
SIGN_X, SIGN_Y = 0b10, 0b01
#: Z layers: the tool raised (travel) and lowered (working).
LAYER_UP, LAYER_DOWN = 0, 1

BLOCK = 128
SOH, EOT, ACK, NAK, CAN = 0x01, 0x04, 0x06, 0x15, 0x18
#: The shell's message for a failed transfer (block 20 of Fig. 5).
OUTPUT_ERROR = "ошибка вывода"

Point = tuple[int, int]


# ---------------------------------------------------------------------------
# The program.
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Command:
    """One command: ``op`` OP_Z (``layer``), OP_LINE (``dx``, ``dy``) or
    OP_END."""

    op: int
    layer: int = 0
    dx: int = 0
    dy: int = 0

    def words(self) -> list[int]:
        """The command's 16-bit words."""
        if self.op == OP_LINE:
            if max(abs(self.dx), abs(self.dy)) > MAX_STEP:
                raise ValueError(f"increment ({self.dx}, {self.dy}) exceeds {MAX_STEP}")
            signs = (SIGN_X if self.dx < 0 else 0) | (SIGN_Y if self.dy < 0 else 0)
            return [OP_LINE << 8 | signs, abs(self.dx), abs(self.dy)]
        if self.op == OP_Z:
            if not 0 <= self.layer <= 255:
                raise ValueError(f"layer {self.layer} is not 0..255")
            return [OP_Z << 8 | self.layer]
        if self.op == OP_END:
            return [OP_END << 8]
        raise ValueError(f"unknown operation {self.op:#x}")


def _moves(dx: int, dy: int) -> list[Command]:
    """A straight move as three-word commands, cut into m parts when an
    increment exceeds 15 bits (blocks 7, 8, 14-16)."""
    return [Command(OP_LINE, dx=a, dy=b) for a, b in split_move(dx, dy, MAX_STEP)]


def program(polylines: Sequence[Sequence[Point]], start: Point = (0, 0)) -> list[Command]:
    """The commands drawing the polylines in order from ``start``: the first
    command sets z (raised), each polyline is reached raised, drawn lowered,
    and left raised; the program ends back at the start, then "конец УП"."""
    cmds = [Command(OP_Z, LAYER_UP)]
    x, y = start
    for pl in polylines:
        if len(pl) < 2:
            raise ValueError(f"a polyline needs two points, not {len(pl)}")
        cmds += _moves(pl[0][0] - x, pl[0][1] - y)
        cmds.append(Command(OP_Z, LAYER_DOWN))
        x, y = pl[0]
        for px, py in pl[1:]:
            cmds += _moves(px - x, py - y)
            x, y = px, py
        cmds.append(Command(OP_Z, LAYER_UP))
    cmds += _moves(start[0] - x, start[1] - y)
    cmds.append(Command(OP_END))
    return cmds


def encode(cmds: Iterable[Command]) -> bytes:
    """The program as bytes: 16-bit little-endian words."""
    words = [w for c in cmds for w in c.words()]
    return struct.pack(f"<{len(words)}H", *words)


def decode(data: bytes) -> list[Command]:
    """Commands up to and including "конец УП"; bytes after it (a block's
    padding) are ignored.  ValueError naming the word (1-based) of a bad
    command or of a program without its end."""
    if len(data) % 2:
        data = data[:-1]
    words = struct.unpack(f"<{len(data) // 2}H", data)
    cmds: list[Command] = []
    i = 0
    while i < len(words):
        w = words[i]
        op, low = w >> 8, w & 0xFF
        if op == OP_END and low == 0:
            cmds.append(Command(OP_END))
            return cmds
        if op == OP_Z:
            cmds.append(Command(OP_Z, layer=low))
            i += 1
        elif op == OP_LINE and low <= 3:
            if i + 2 >= len(words):
                raise ValueError(f"word {i + 1}: a move without its two increments")
            ax, ay = words[i + 1], words[i + 2]
            if ax > MAX_STEP or ay > MAX_STEP:
                raise ValueError(f"word {i + 1}: increment over 15 bits")
            cmds.append(Command(OP_LINE, dx=-ax if low & SIGN_X else ax,
                                dy=-ay if low & SIGN_Y else ay))
            i += 3
        else:
            raise ValueError(f"word {i + 1}: unknown command {w:#06x}")
    raise ValueError(f"word {len(words)}: the program has no end command")


def execute(cmds: Sequence[Command], start: Point = (0, 0)) -> list[list[Point]]:
    """What the machine draws: the polylines traced with the tool lowered
    (consecutive moves joined), from ``start``."""
    x, y = start
    down = False
    drawn: list[list[Point]] = []
    for c in cmds:
        if c.op == OP_Z:
            new_down = c.layer != LAYER_UP
            if new_down and not down:
                drawn.append([(x, y)])
            down = new_down
        elif c.op == OP_LINE:
            x, y = x + c.dx, y + c.dy
            if down:
                drawn[-1].append((x, y))
        elif c.op == OP_END:
            break
    return [pl for pl in drawn if len(pl) > 1]


# ---------------------------------------------------------------------------
# Blocks and CRC.
# ---------------------------------------------------------------------------
def crc16(data: bytes, crc: int = 0) -> int:
    """CRC-16 with polynomial 0x1021, initial value 0, no reflection
    (XMODEM's; its check value for b"123456789" is 0x31C3)."""
    for byte in data:
        crc ^= byte << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1021) if crc & 0x8000 else crc << 1
            crc &= 0xFFFF
    return crc


def blocks(data: bytes) -> list[bytes]:
    """The program cut into 128-byte blocks, the last padded with zeros."""
    out = [data[i:i + BLOCK] for i in range(0, len(data), BLOCK)] or [b""]
    out[-1] = out[-1].ljust(BLOCK, b"\0")
    return out


def packet(number: int, block: bytes) -> bytes:
    """SOH, number mod 256, its complement, the block, CRC high, CRC low."""
    n = number & 0xFF
    crc = crc16(block)
    return bytes([SOH, n, 0xFF - n]) + block + bytes([crc >> 8, crc & 0xFF])


def packets(data: bytes) -> list[bytes]:
    """Every packet of a program, numbered from 1."""
    return [packet(i, b) for i, b in enumerate(blocks(data), 1)]


# ---------------------------------------------------------------------------
# The controller.
# ---------------------------------------------------------------------------
PACKET = BLOCK + 5


@dataclass
class Controller:
    """The CNC's side of the link: checks each packet, answers ACK or NAK,
    keeps good blocks in its program memory, and runs the program only after
    EOT, when every block arrived intact.  ``log``: one line per event."""

    memory: list[bytes] = field(default_factory=list)
    log: list[str] = field(default_factory=list)
    complete: bool = False
    abandoned: bool = False
    drawn: list[list[Point]] | None = None

    def receive(self, pkt: bytes) -> int:
        """One packet in, the answer out (ACK or NAK)."""
        expected = (len(self.memory) + 1) & 0xFF
        if len(pkt) != PACKET or pkt[0] != SOH or pkt[1] + pkt[2] != 0xFF:
            self.log.append(f"cnc: block {len(self.memory) + 1}: bad frame, NAK")
            return NAK
        block, crc = pkt[3:3 + BLOCK], pkt[-2] << 8 | pkt[-1]
        if crc16(block) != crc:
            self.log.append(f"cnc: block {len(self.memory) + 1}: CRC {crc16(block):#06x} "
                            f"!= {crc:#06x}, NAK")
            return NAK
        if pkt[1] == (expected - 1) & 0xFF and self.memory and block == self.memory[-1]:
            self.log.append(f"cnc: block {len(self.memory)} again, ACK")
            return ACK                      # a repeat whose ACK was lost
        if pkt[1] != expected:
            self.log.append(f"cnc: block number {pkt[1]}, expected {expected}, NAK")
            return NAK
        self.memory.append(block)
        self.log.append(f"cnc: block {len(self.memory)}: ACK")
        return ACK

    def end(self) -> int:
        """EOT: the program is complete; decode and run it."""
        self.complete = True
        self.drawn = execute(decode(b"".join(self.memory)))
        self.log.append(f"cnc: program of {len(self.memory)} blocks complete, run")
        return ACK

    def abandon(self) -> None:
        """CAN: forget the blocks; nothing runs."""
        self.abandoned = True
        self.memory.clear()
        self.log.append("cnc: transfer abandoned, program memory cleared")

    def serve(self, sock: socket.socket) -> None:
        """Answer packets arriving on a socket until EOT or CAN."""
        buf = b""
        while True:
            if not buf:
                chunk = sock.recv(4096)
                if not chunk:
                    return
                buf += chunk
            if buf[0] == EOT:
                sock.sendall(bytes([self.end()]))
                return
            if buf[0] == CAN:
                self.abandon()
                return
            while len(buf) < PACKET:
                chunk = sock.recv(4096)
                if not chunk:
                    return
                buf += chunk
            pkt, buf = buf[:PACKET], buf[PACKET:]
            sock.sendall(bytes([self.receive(pkt)]))


# ---------------------------------------------------------------------------
# The shell's side: sending over a link.
# ---------------------------------------------------------------------------
@dataclass
class Transfer:
    """The outcome of :func:`send`: ``ok``; the shell's ``message``; one
    ``log`` line per transmission; the controller (what it kept and ran)."""

    ok: bool
    message: str
    log: list[str]
    controller: Controller
    transmissions: int


def corrupt(pkt: bytes, transmission: int) -> bytes:
    """The packet with one bit flipped in transit (a data byte chosen by the
    transmission number, so runs are repeatable)."""
    i = 3 + (transmission * 37) % BLOCK
    return pkt[:i] + bytes([pkt[i] ^ 0x10]) + pkt[i + 1:]


def send(data: bytes, corrupt_at: Iterable[int] = (), resend: int = 0,
         timeout: float = 5.0) -> Transfer:
    """Send a program to a simulated controller over a loopback socket pair
    (the controller answering in its own thread).

    ``corrupt_at``: transmission numbers (1-based, counting resends) whose
    packet is damaged on the line.  ``resend``: how many times a refused
    block is sent again (0, the paper's shell: the first NAK stops the
    transfer with "ошибка вывода")."""
    bad = set(corrupt_at)
    ctl = Controller()
    ours, theirs = socket.socketpair()
    ours.settimeout(timeout)
    worker = threading.Thread(target=ctl.serve, args=(theirs,), daemon=True)
    worker.start()
    log: list[str] = []
    count = 0
    ok, message = True, ""
    try:
        pkts = packets(data)
        for number, pkt in enumerate(pkts, 1):
            for attempt in range(resend + 1):
                count += 1
                wire = corrupt(pkt, count) if count in bad else pkt
                ours.sendall(wire)
                answer = ours.recv(1)
                acked = answer == bytes([ACK])
                log.append(f"block {number}/{len(pkts)} transmission {count}"
                           f"{' (damaged on the line)' if wire != pkt else ''}: "
                           f"{'ACK' if acked else 'NAK' if answer == bytes([NAK]) else 'no answer'}")
                if acked:
                    break
            else:
                ok = False
                message = (f"{OUTPUT_ERROR} (output error): block {number} of {len(pkts)} "
                           f"not acknowledged after {resend + 1} transmission"
                           f"{'s' if resend else ''}; transfer stopped, nothing runs")
                ours.sendall(bytes([CAN]))
                break
        if ok:
            ours.sendall(bytes([EOT]))
            if ours.recv(1) != bytes([ACK]):
                ok, message = False, f"{OUTPUT_ERROR} (output error): end of transfer not acknowledged"
            else:
                message = f"program sent: {len(pkts)} blocks, {count} transmissions"
    except OSError as exc:
        ok, message = False, f"{OUTPUT_ERROR} (output error): {exc}"
    finally:
        worker.join(timeout)
        ours.close()
        theirs.close()
    return Transfer(ok, message, log, ctl, count)


# ---------------------------------------------------------------------------
# Input, and the command line.
# ---------------------------------------------------------------------------
def read_polylines(text: str) -> list[list[Point]]:
    """'x y' per line (whole pulses); a blank line ends a polyline; '#'
    starts a comment."""
    out: list[list[Point]] = [[]]
    for no, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            if raw.strip() == "" and out[-1]:
                out.append([])
            continue
        parts = line.split()
        try:
            x, y = (int(v) for v in parts)
        except ValueError:
            raise ValueError(f"line {no}: expected 'x y' in whole pulses, got {line!r}") from None
        out[-1].append((x, y))
    out = [pl for pl in out if pl]
    for pl in out:
        if len(pl) < 2:
            raise ValueError(f"polyline at {pl[0]} has one point")
    return out


def deck_polylines(text: str) -> list[list[Point]]:
    """The conductors (L/+ cards) of a card deck's packages as polylines in
    0.01 mm, one pulse each."""

    return [list(c.points) for pkg in parse_deck(text) for c in pkg.conductors]


def _run_cnclink(args: argparse.Namespace) -> int:
    if args.resend < 0:
        print(f"cnclink: --resend {args.resend}: a block can be sent again 0 or more times",
              file=sys.stderr)
        return 2
    try:
        text = sys.stdin.read() if args.input == "-" else open(args.input, encoding="ascii").read()
        pls = deck_polylines(text) if args.input.endswith(".crd") else read_polylines(text)
        data = encode(program(pls))
    except OSError as exc:
        print(f"cnclink: {args.input}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    except ValueError as exc:
        print(f"cnclink: {args.input}: {exc}", file=sys.stderr)
        return 1
    if args.output:
        try:
            write_whole(args.output, data, inputs=[args.input])
        except OSError as exc:
            print(f"cnclink: {args.output}: {exc.strerror or exc}", file=sys.stderr)
            return 2
    try:
        corrupt_at = [int(v) for v in args.corrupt.split(",") if v] if args.corrupt else []
    except ValueError:
        print(f"cnclink: --corrupt {args.corrupt!r}: expected N[,N...], whole numbers",
              file=sys.stderr)
        return 2
    result = send(data, corrupt_at, args.resend)
    for line in result.log:
        print(line)
    if not result.ok:
        print(result.message, file=sys.stderr)
        return 1
    drawn = result.controller.drawn or []
    print(result.message)
    print(f"cnc ran the program: {len(drawn)} polylines drawn in "
          f"{sum(len(p) - 1 for p in drawn)} moves")
    return 0


def add_cnclink(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "cnclink", help="send polylines to a simulated CNC in 128-byte CRC blocks (seed 003)",
        description="Encode polylines (a file of 'x y' lines in pulses, a blank line "
                    "between polylines, or the conductors of a .crd deck) as a program of "
                    "one- and three-word commands, send it in 128-byte blocks with a CRC to "
                    "a simulated CNC over a loopback link, and report each block's "
                    "acknowledgement.  A refused block stops the transfer with the paper's "
                    "'ошибка вывода' (output error) and exit status 1.")
    p.add_argument("input", metavar="POLYLINES", help="polyline text or .crd deck ('-' = stdin)")
    p.add_argument("-o", "--output", metavar="PROG.bin", help="also write the program's bytes")
    p.add_argument("--corrupt", metavar="N[,N...]",
                   help="damage these transmissions on the line (1-based, resends count)")
    p.add_argument("--resend", type=int, default=0, metavar="K",
                   help="send a refused block again up to K times (default 0: the paper's "
                        "shell stops at once)")
    p.set_defaults(func=_run_cnclink)
