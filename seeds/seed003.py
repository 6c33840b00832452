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
  is cut into m parts, m being the machine's fixed ratio of its largest
  increment to int/2 (blocks 14-16), the parameter ``m``.
* The program is cut into 128-byte blocks, each with a CRC; each block
  sent is acknowledged by the CNC; on a failed transfer the shell says
  "ошибка вывода" (output error, block 20) and stops: the whole process has
  to be started again.  (:func:`packets`, :class:`Controller`,
  :func:`send`.)  The documented improvement, resending a block the CNC
  refused up to N times, is the option ``resend``; with it the shell and
  the CNC resynchronise after a lost or a stray byte (the CNC's timeout,
  its NAK, its hunt for SOH).
* Parameters are entered with range checks (a wrong value gets the
  default and a message), grouped by the number of axes, converted to
  long, int or char and loaded in one message with one CRC byte
  (:func:`read_params`, :func:`param_message`, :meth:`Machine.load_params`).
* "Работа по программе": Пуск, the start command, the CNC's ready (or
  zero, not ready) reply, then its messages "Кадр" (a frame done), "Сбой"
  (with an error number) and "КП" (done); the Стоп button (:func:`run`);
  the panel with set and actual positions of X, Y, Z, φ
  (:meth:`Machine.panel`); the view of the program (:func:`svg`,
  :func:`view`).

Decisions where the paper is silent (docs/SEED003-CNC-LINK.md): words are
little-endian (an x86 PC); operation codes are in the high byte; the packet
is XMODEM-CRC's (SOH, block number, its complement, 128 bytes, CRC-16 with
polynomial 0x1021, initial 0, high byte first), ACK 0x06 / NAK 0x15, EOT
ends the transfer and CAN abandons it; the last block is padded with zero
bytes.  The serial line is simulated with a virtual clock (9600 baud, the
CNC's 1 s timeout, the shell's 10 s), so every run is repeatable.
"""

from __future__ import annotations

import argparse
import struct
import sys
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass, field

from harness.deck import parse_deck
from harness.files import write_whole

from .seed004 import division_point

#: Largest increment of a three-word command: int/2, 15 bits.
MAX_STEP = 0x7FFF
#: The machine's fixed ratio m (a parameter, ``m``): a segment with an
#: increment over MAX_STEP is cut into m parts, so no increment of the
#: machine may exceed m * MAX_STEP (131068 pulses, 1.31 m at 0.01 mm).
DEFAULT_RATIO = 4
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


def _moves(dx: int, dy: int, ratio: int = DEFAULT_RATIO) -> list[Command]:
    """A straight move as three-word commands (block 10); when an increment
    exceeds 15 bits, m = ``ratio`` parts, the machine's fixed ratio
    (blocks 7, 8, 14-16).  Part k ends at the pulse nearest k/m of the move,
    so every division point is within one pulse of the line."""
    if dx == 0 and dy == 0:
        return []
    longest = max(abs(dx), abs(dy))
    if longest <= MAX_STEP:
        return [Command(OP_LINE, dx=dx, dy=dy)]
    if longest > ratio * MAX_STEP:
        raise ValueError(f"increment of {longest} pulses is more than the machine's largest, "
                         f"m x {MAX_STEP} = {ratio * MAX_STEP} (m = {ratio}; the parameter m "
                         f"would have to be at least {-(-longest // MAX_STEP)})")
    pts = [(division_point(dx, k, ratio), division_point(dy, k, ratio))
           for k in range(ratio + 1)]
    return [Command(OP_LINE, dx=b[0] - a[0], dy=b[1] - a[1]) for a, b in zip(pts, pts[1:])]


def program(polylines: Sequence[Sequence[Point]], start: Point = (0, 0),
            ratio: int = DEFAULT_RATIO) -> list[Command]:
    """The commands drawing the polylines in order from ``start``: the first
    command sets z (raised), each polyline is reached raised, drawn lowered,
    and left raised; the program ends back at the start, then "конец УП".
    ``ratio``: the machine's m.  ValueError naming the polyline and segment
    of an increment longer than m x 0x7FFF."""
    cmds = [Command(OP_Z, LAYER_UP)]
    x, y = start

    def moves(tx: int, ty: int, what: str) -> list[Command]:
        try:
            return _moves(tx - x, ty - y, ratio)
        except ValueError as exc:
            raise ValueError(f"{what} from ({x}, {y}) to ({tx}, {ty}): {exc}") from None

    for n, pl in enumerate(polylines, 1):
        if len(pl) < 2:
            raise ValueError(f"polyline {n}: a polyline needs two points, not {len(pl)}")
        cmds += moves(pl[0][0], pl[0][1], f"the move to polyline {n}")
        cmds.append(Command(OP_Z, LAYER_DOWN))
        x, y = pl[0]
        for k, (px, py) in enumerate(pl[1:], 1):
            cmds += moves(px, py, f"polyline {n} segment {k}")
            x, y = px, py
        cmds.append(Command(OP_Z, LAYER_UP))
    cmds += moves(start[0], start[1], "the move back to the start")
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
# The line between the PC and the CNC.
# ---------------------------------------------------------------------------
PACKET = BLOCK + 5
#: The serial line: 9600 baud, 8 data bits, 1 stop bit: 10 bit times a byte.
BAUD = 9600
#: The CNC's timeout: a packet that stops short is given up after this much
#: silence, and after a refused packet the CNC waits for this much silence
#: (discarding what still arrives) before its NAK.  Seconds.
CNC_TIMEOUT = 1.0
#: How long the shell waits for an answer to a packet.  Seconds.
SHELL_TIMEOUT = 10.0


@dataclass(frozen=True)
class Faults:
    """What the line does to some transmissions (1-based, resends and the
    parameter message not counted): ``corrupt`` flips one bit of a data
    byte, ``drop`` loses one byte, ``noise`` inserts one stray byte.  The
    byte and the value are chosen from the transmission's number, so a run
    is repeatable; several faults may hit one transmission."""

    corrupt: frozenset[int] = frozenset()
    drop: frozenset[int] = frozenset()
    noise: frozenset[int] = frozenset()

    def apply(self, pkt: bytes, n: int) -> tuple[bytes, list[str]]:
        """The bytes that arrive for transmission ``n`` of ``pkt``, and what
        happened to them."""
        wire, what = pkt, []
        if n in self.corrupt:
            wire = corrupt(wire, n)
            what.append(f"bit flipped in byte {3 + (n * 37) % BLOCK + 1}")
        if n in self.drop:
            i = (n * 59) % len(wire)
            wire = wire[:i] + wire[i + 1:]
            what.append(f"byte {i + 1} lost")
        if n in self.noise:
            i, v = (n * 71) % (len(wire) + 1), (n * 97 + 1) & 0xFF
            wire = wire[:i] + bytes([v]) + wire[i:]
            what.append(f"stray byte {v:#04x} before byte {i + 1}")
        return wire, what


def corrupt(pkt: bytes, transmission: int) -> bytes:
    """The packet with one bit flipped in transit (a data byte chosen by the
    transmission number, so runs are repeatable)."""
    i = 3 + (transmission * 37) % BLOCK
    return pkt[:i] + bytes([pkt[i] ^ 0x10]) + pkt[i + 1:]


def program_bytes(memory: bytes) -> bytes:
    """The program in the CNC's memory: up to and including its first
    "конец УП" word (no other command word or increment can be 0xFF00);
    without one, the memory less its zero padding."""
    for i in range(0, len(memory) - 1, 2):
        if memory[i] == 0x00 and memory[i + 1] == OP_END:
            return memory[:i + 2]
    return memory.rstrip(b"\0")


# ---------------------------------------------------------------------------
# The controller: receiving.
# ---------------------------------------------------------------------------
@dataclass
class Controller:
    """The CNC's side of the link, fed the bytes as they arrive.

    It hunts for SOH (discarding anything else), collects a packet of 133
    bytes, checks its frame, number and CRC and answers ACK, or, for a bad
    packet, waits for the line to fall quiet (discarding the rest of what
    the shell sent) and answers NAK; a packet cut short by a lost byte is
    given up after :data:`CNC_TIMEOUT` of silence with a NAK.  EOT and CAN
    count only as the first byte after an answer.  Good blocks go to the
    program memory; nothing runs until EOT, when the whole program has
    arrived.  ``log``: one line per event."""

    memory: list[bytes] = field(default_factory=list)
    log: list[str] = field(default_factory=list)
    complete: bool = False
    abandoned: bool = False
    answers: list[int] = field(default_factory=list)
    _buf: bytearray | None = None
    _fresh: bool = True
    _purging: int = -1
    _stray: int = 0

    @property
    def program(self) -> bytes:
        """The program bytes the CNC accepted (empty until EOT)."""
        return program_bytes(b"".join(self.memory)) if self.complete else b""

    @property
    def drawn(self) -> list[list[Point]] | None:
        """What the accepted program draws; None before EOT or when it
        cannot be decoded."""
        if not self.complete:
            return None
        try:
            return execute(decode(self.program))
        except ValueError:
            return None

    def _answer(self, byte: int) -> None:
        self.answers.append(byte)
        self._fresh = True

    def feed(self, data: bytes) -> None:
        """Bytes arriving back to back."""
        for b in data:
            if self._purging >= 0:
                self._purging += 1
            elif self._buf is not None:
                self._buf.append(b)
                if len(self._buf) == PACKET:
                    pkt, self._buf = bytes(self._buf), None
                    if self.receive(pkt) == ACK:
                        self._answer(ACK)
                    else:
                        self._purging = 0
            elif self._fresh and b == EOT:
                self._answer(self.end())
            elif self._fresh and b == CAN:
                self.abandon()
                self._fresh = True
            elif b == SOH:
                if self._stray:
                    self.log.append(f"cnc: {self._stray} stray byte{'s' if self._stray > 1 else ''}"
                                    f" before SOH discarded")
                    self._stray = 0
                self._buf = bytearray([b])
                self._fresh = False
            else:
                self._stray += 1
                self._fresh = False

    def quiet(self) -> None:
        """The line has been silent for :data:`CNC_TIMEOUT`."""
        if self._buf is not None:
            self.log.append(f"cnc: block {len(self.memory) + 1}: {len(self._buf)} of {PACKET} "
                            f"bytes, then {CNC_TIMEOUT:g} s of silence: timeout, NAK")
            self._buf = None
            self._answer(NAK)
        elif self._purging >= 0:
            if self._purging:
                self.log.append(f"cnc: {self._purging} more byte{'s' if self._purging > 1 else ''}"
                                f" discarded until the line fell quiet")
            self._purging = -1
            self._answer(NAK)
        elif self._stray:
            self.log.append(f"cnc: {self._stray} bytes without SOH discarded: timeout, NAK")
            self._stray = 0
            self._answer(NAK)

    def receive(self, pkt: bytes) -> int:
        """One whole packet checked: ACK (stored) or NAK."""
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
        """EOT: the program is complete and stays in memory."""
        self.complete = True
        self.log.append(f"cnc: program of {len(self.memory)} blocks complete")
        return ACK

    def abandon(self) -> None:
        """CAN: forget the blocks; nothing runs."""
        self.abandoned = True
        self.memory.clear()
        self.log.append("cnc: transfer abandoned, program memory cleared")


# ---------------------------------------------------------------------------
# The shell's side: sending.
# ---------------------------------------------------------------------------
@dataclass
class Transfer:
    """The outcome of :func:`send`: ``ok``; the shell's ``message``; one
    ``log`` line per transmission; the controller (what it kept);
    ``seconds`` on the line at :data:`BAUD`, timeouts included."""

    ok: bool
    message: str
    log: list[str]
    controller: Controller
    transmissions: int
    seconds: float = 0.0


def send(data: bytes, corrupt_at: Iterable[int] = (), resend: int = 0,
         drop_at: Iterable[int] = (), noise_at: Iterable[int] = (),
         controller: Controller | None = None) -> Transfer:
    """Send a program to a simulated controller over a simulated serial
    line (a virtual clock: runs are repeatable and take no real time).

    ``corrupt_at``, ``drop_at``, ``noise_at``: transmission numbers (1-based,
    counting resends) that the line damages (:class:`Faults`).  After each
    transmission the shell waits for the answer: ACK, NAK, or none within
    :data:`SHELL_TIMEOUT`.  ``resend``: how many times a block that was not
    acknowledged is sent again (0, the paper's shell: the first failure
    stops the transfer with "ошибка вывода")."""
    faults = Faults(frozenset(corrupt_at), frozenset(drop_at), frozenset(noise_at))
    ctl = controller if controller is not None else Controller()
    log: list[str] = []
    count = 0
    clock = 0.0
    ok, message = True, ""
    pkts = packets(data)
    for number, pkt in enumerate(pkts, 1):
        for _attempt in range(resend + 1):
            count += 1
            wire, what = faults.apply(pkt, count)
            ctl.answers.clear()                   # the shell flushes its input
            ctl.feed(wire)
            clock += len(wire) * 10 / BAUD
            if not ctl.answers:
                ctl.quiet()
                clock += CNC_TIMEOUT
            if ctl.answers:
                answer = "ACK" if ctl.answers[0] == ACK else "NAK"
                clock += 10 / BAUD
            else:
                answer = f"no answer in {SHELL_TIMEOUT:g} s"
                clock += SHELL_TIMEOUT - CNC_TIMEOUT
            note = f" ({'; '.join(what)})" if what else ""
            log.append(f"block {number}/{len(pkts)} transmission {count}{note}: {answer}")
            if answer == "ACK":
                break
        else:
            ok = False
            message = (f"{OUTPUT_ERROR} (output error): block {number} of {len(pkts)} "
                       f"not acknowledged after {resend + 1} transmission"
                       f"{'s' if resend else ''}; transfer stopped, nothing runs")
            ctl.feed(bytes([CAN]))
            break
    if ok:
        for _attempt in range(resend + 1):       # EOT, again after a NAK (a stray byte)
            ctl.answers.clear()
            ctl.feed(bytes([EOT]))
            clock += 10 / BAUD
            if not ctl.answers:
                ctl.quiet()
                clock += CNC_TIMEOUT
            clock += 10 / BAUD
            log.append(f"EOT: {'ACK' if ctl.answers[:1] == [ACK] else 'NAK'}")
            if ctl.answers[:1] == [ACK]:
                message = f"program sent: {len(pkts)} blocks, {count} transmissions"
                break
        else:
            ok, message = False, f"{OUTPUT_ERROR} (output error): end of transfer not acknowledged"
            ctl.feed(bytes([CAN]))
    return Transfer(ok, message, log, ctl, count, clock)


def survival_table(data: bytes, budgets: Sequence[int] = (0, 1, 2, 3),
                   bursts: Sequence[int] = (1, 2, 3)) -> list[str]:
    """A Markdown table: for b consecutive damaged transmissions (b in
    ``bursts``), starting at each transmission of the undamaged transfer,
    each losing a byte, gaining a stray byte, having a bit flipped, or the
    three in turn, how many transfers of ``data`` complete with each resend
    budget K."""
    n = len(packets(data))
    names = {"drop": "a lost byte", "noise": "a stray byte", "corrupt": "a flipped bit",
             "mix": "lost, stray, flipped in turn"}
    out = ["| damaged transmissions in a row | " + " | ".join(f"K = {k}" for k in budgets)
           + " |", "|---" * (1 + len(budgets)) + "|"]
    for kind, name in names.items():
        for b in bursts:
            cells = []
            for k in budgets:
                done = 0
                for first in range(1, n + 1):
                    sets: dict[str, list[int]] = {"drop": [], "noise": [], "corrupt": []}
                    for j, t in enumerate(range(first, first + b)):
                        sets[("drop", "noise", "corrupt")[j % 3] if kind == "mix"
                             else kind].append(t)
                    result = send(data, sets["corrupt"], k, sets["drop"], sets["noise"])
                    done += result.ok and result.controller.program == data
                cells.append(f"{done}/{n}")
            out.append(f"| {b}, each {name} | " + " | ".join(cells) + " |")
    return out


# ---------------------------------------------------------------------------
# Parameters: entered, range-checked, loaded in one message with a CRC byte.
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Param:
    """One parameter: its binary ``kind`` ("char" 1 byte, "int" 2, "long"
    4), its range, its default, and the axis counts it belongs to."""

    name: str
    kind: str
    low: int
    high: int
    default: int
    axes: tuple[int, ...]
    meaning: str


#: The CNC's parameters in the order they are loaded.
PARAMS: tuple[Param, ...] = (
    Param("axes", "char", 2, 4, 3, (2, 3, 4), "number of driven axes"),
    Param("m", "char", 1, 255, 4, (2, 3, 4),
          "parts a segment longer than 0x7FFF pulses is cut into (the machine's "
          "largest increment / int/2)"),
    Param("feed", "long", 1, 10_000_000, 60_000, (2, 3, 4), "feed, pulses per minute"),
    *(Param(f"z{k}", "int", 0, 32767, 500 if k == 0 else 0, (3, 4),
            f"height of z layer {k}, pulses") for k in range(8)),
    Param("phi", "long", 1, 10_000_000, 3600, (4,), "pulses per turn of the φ axis"),
)
PARAM_BY_NAME = {p.name: p for p in PARAMS}
SIZES = {"char": 1, "int": 2, "long": 4}
#: Shell to CNC: the parameter message's first byte; start and stop.
CMD_PARAMS, CMD_START, CMD_STOP = 0x10, 0x12, 0x14
#: CNC to shell: ready (the paper's non-zero readiness), not ready (zero),
#: "Кадр" (+ 16-bit frame number), "Сбой" (+ error number), "КП".
READY, NOT_READY, MSG_KADR, MSG_SBOI, MSG_KP = 0x01, 0x00, 0x0B, 0x0F, 0x0E
PARAM_ERROR = "ошибка загрузки параметров"


def crc8(data: bytes, crc: int = 0) -> int:
    """CRC-8, polynomial 0x07, initial 0, not reflected (check value of
    b"123456789": 0xF4)."""
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = ((crc << 1) ^ 0x07) & 0xFF if crc & 0x80 else crc << 1
    return crc


def defaults() -> dict[str, int]:
    """Every parameter at its default."""
    return {p.name: p.default for p in PARAMS}


def read_params(text: str, where: str = "parameters") -> tuple[dict[str, int], list[str]]:
    """``name = value`` lines ('#' comments).  A value that is not a whole
    number or is out of range gets the parameter's default with a message,
    as the shell's editors did; so does a parameter of another axis group.
    Returns the values (defaults for the ones not given) and the messages."""
    values = defaults()
    given: dict[str, tuple[int, int]] = {}
    notes: list[str] = []
    refused: list[tuple[int, str]] = []      # (index in notes, name) of a value not taken
    for no, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        name, eq, value = (part.strip() for part in line.partition("="))
        if not eq or not name:
            notes.append(f"{where}: line {no}: expected 'name = value', got {line!r}")
            continue
        param = PARAM_BY_NAME.get(name)
        if param is None:
            notes.append(f"{where}: line {no}: unknown parameter {name!r}; the parameters "
                         f"are {', '.join(PARAM_BY_NAME)}")
            continue
        try:
            number = int(value)
        except ValueError:
            refused.append((len(notes), name))
            notes.append(f"{where}: line {no}: {name} = {value!r} is not a whole number "
                         f"{param.low}..{param.high}")
            continue
        if not param.low <= number <= param.high:
            refused.append((len(notes), name))
            notes.append(f"{where}: line {no}: {name} = {number} is out of range "
                         f"{param.low}..{param.high}")
            continue
        values[name] = number
        given[name] = (no, number)
    for k, name in refused:          # the machine's axes are known only at the end
        if values["axes"] in PARAM_BY_NAME[name].axes:
            notes[k] += f"; set to the default {PARAM_BY_NAME[name].default}"
        else:
            notes[k] += (f", and {name} is not a parameter of a {values['axes']}-axis "
                         f"machine; ignored")
    for name, (no, _) in given.items():
        if values["axes"] not in PARAM_BY_NAME[name].axes:
            notes.append(f"{where}: line {no}: {name} is not a parameter of a "
                         f"{values['axes']}-axis machine; ignored")
            values[name] = PARAM_BY_NAME[name].default
    return values, notes


def param_buffer(values: dict[str, int]) -> bytes:
    """The parameters of the machine's axis group, each as its binary type,
    little-endian, in :data:`PARAMS` order."""
    fmt = {"char": "<B", "int": "<H", "long": "<I"}
    return b"".join(struct.pack(fmt[p.kind], values[p.name]) for p in PARAMS
                    if values["axes"] in p.axes)


def param_message(values: dict[str, int]) -> bytes:
    """CMD_PARAMS, the buffer's length, the buffer, one CRC-8 byte."""
    buf = param_buffer(values)
    return bytes([CMD_PARAMS, len(buf)]) + buf + bytes([crc8(buf)])


def unpack_params(buf: bytes) -> dict[str, int]:
    """The parameter buffer read back (the CNC's side)."""
    axes = buf[0]
    fmt = {"char": "<B", "int": "<H", "long": "<I"}
    values, i = defaults(), 0
    values["axes"] = axes
    for p in PARAMS:
        if axes in p.axes:
            (values[p.name],) = struct.unpack_from(fmt[p.kind], buf, i)
            i += SIZES[p.kind]
    return values


# ---------------------------------------------------------------------------
# The CNC running the program ("Работа по программе").
# ---------------------------------------------------------------------------
#: "Сбой" numbers and their meanings.
FAULTS: dict[int, str] = {
    1: "выход за пределы стола (a move past the table's limits)",
    2: "неизвестная команда (a command the CNC does not know)",
    3: "останов с пульта ЧПУ (stopped by the operator at the CNC's panel)",
    4: "нет высоты слоя в таблице (a z layer with no height in the table)",
}


@dataclass
class Machine:
    """The CNC with its program memory, its parameters (in PROM until a
    parameter message replaces them) and its axes: set and actual positions
    of X, Y, Z, φ in pulses.  ``limits``: the table reaches 0..X, 0..Y
    (None: any position a program can reach)."""

    link: Controller = field(default_factory=Controller)
    params: dict[str, int] = field(default_factory=defaults)
    limits: tuple[int, int] | None = None
    set_pos: list[int] = field(default_factory=lambda: [0, 0, 0, 0])
    actual: list[int] = field(default_factory=lambda: [0, 0, 0, 0])
    log: list[str] = field(default_factory=list)

    def load_params(self, message: bytes) -> int:
        """A parameter message in: ACK when its CRC byte is right."""
        if len(message) < 3 or message[0] != CMD_PARAMS or len(message) != message[1] + 3:
            self.log.append("cnc: parameter message malformed, NAK")
            return NAK
        buf, crc = message[2:-1], message[-1]
        if crc8(buf) != crc:
            self.log.append(f"cnc: parameter CRC {crc8(buf):#04x} != {crc:#04x}, NAK")
            return NAK
        self.params = unpack_params(buf)
        self.log.append(f"cnc: {len(buf)} bytes of parameters stored, ACK")
        return ACK

    def start(self) -> int:
        """The start command: ready when a whole program is in memory."""
        return READY if self.link.complete and self.link.program else NOT_READY

    def frames(self, panel_stop: int | None = None) -> Iterator[tuple[bytes, int, int]]:
        """Run the program: for each message sent, its bytes and the word
        span (first word, words) of the command it reports."""
        words_ = self.link.program
        words = struct.unpack(f"<{len(words_) // 2}H", words_[:len(words_) // 2 * 2])
        i = frame = 0
        while True:
            if i >= len(words):
                yield bytes([MSG_SBOI, 2]), i, 0
                return
            w = words[i]
            op, low = w >> 8, w & 0xFF
            frame += 1
            if op == OP_END and low == 0:
                yield bytes([MSG_KP]), i, 1
                return
            if panel_stop is not None and frame > panel_stop:
                yield bytes([MSG_SBOI, 3]), i, 0
                return
            if op == OP_Z:
                if low > 7:
                    yield bytes([MSG_SBOI, 4]), i, 1
                    return
                if self.params["axes"] >= 3:     # a 2-axis machine only switches the tool
                    self.set_pos[2] = self.actual[2] = self.params[f"z{low}"]
                yield bytes([MSG_KADR]) + struct.pack("<H", frame & 0xFFFF), i, 1
                i += 1
            elif op == OP_LINE and low <= 3 and i + 2 < len(words) \
                    and max(words[i + 1], words[i + 2]) <= MAX_STEP:
                dx = -words[i + 1] if low & SIGN_X else words[i + 1]
                dy = -words[i + 2] if low & SIGN_Y else words[i + 2]
                x, y = self.set_pos[0] + dx, self.set_pos[1] + dy
                if self.limits and not (0 <= x <= self.limits[0] and 0 <= y <= self.limits[1]):
                    yield bytes([MSG_SBOI, 1]), i, 3
                    return
                self.set_pos[0] = self.actual[0] = x
                self.set_pos[1] = self.actual[1] = y
                yield bytes([MSG_KADR]) + struct.pack("<H", frame & 0xFFFF), i, 3
                i += 3
            else:
                yield bytes([MSG_SBOI, 2]), i, 1
                return

    def panel(self) -> list[str]:
        """The manual panel: set and actual positions and their mismatch."""
        axes = self.params["axes"]
        out = ["panel: axis        set     actual   mismatch"]
        for k, name in enumerate("XYZφ"):
            if k >= axes:
                out.append(f"panel: {name}     (not active on a {axes}-axis machine)")
            else:
                out.append(f"panel: {name}  {self.set_pos[k]:10d} {self.actual[k]:10d} "
                           f"{self.set_pos[k] - self.actual[k]:10d}")
        return out


@dataclass
class Run:
    """The run as the operator saw it: ``lines`` (one a message), how it
    ended (``outcome``: "КП", "Сбой N", "Стоп" or "не готова"), and the
    frames completed (word offsets of their commands)."""

    lines: list[str]
    outcome: str
    done: list[int]


def run(machine: Machine, stop_at: int | None = None, panel_stop: int | None = None) -> Run:
    """The shell's "Работа по программе": Пуск, the start command, the
    ready reply, then the CNC's messages until "КП" or "Сбой"; ``stop_at``:
    the operator presses Стоп after that frame; ``panel_stop``: the CNC's
    own panel stops it after that frame (a "Сбой")."""
    lines = ["Пуск: the program's picture is drawn in the view; "
             f"start command {CMD_START:#04x} sent"]
    ready = machine.start()
    if ready == NOT_READY:
        lines.append(f"ЧПУ: {NOT_READY:#04x}: не готова к работе (not ready: no program "
                     f"in memory); back to the start")
        return Run(lines, "не готова", [])
    lines.append(f"ЧПУ: {READY:#04x}: готова (ready); the program runs")
    done: list[int] = []
    for msg, first, _ in machine.frames(panel_stop):
        if msg[0] == MSG_KADR:
            (n,) = struct.unpack("<H", msg[1:3])
            lines.append(f"Кадр {n}")
            done.append(first)
            if stop_at is not None and len(done) >= stop_at:
                lines.append(f"Стоп pressed: stop command {CMD_STOP:#04x} sent; the "
                             f"picture is removed from the view; back to the start")
                return Run(lines, "Стоп", done)
        elif msg[0] == MSG_SBOI:
            lines.append(f"Сбой {msg[1]}: {FAULTS[msg[1]]}; back to the start "
                         f"(frame {len(done) + 1}, word {first + 1} of the program)")
            return Run(lines, f"Сбой {msg[1]}", done)
        else:
            lines.append("КП: программа выполнена (the program ran to its end)")
            return Run(lines, "КП", done)
    raise AssertionError("the CNC ended without a message")    # pragma: no cover


def view(data: bytes) -> list[str]:
    """The file view: the program's commands one a line with their frame
    numbers, as far as they can be read."""
    words = struct.unpack(f"<{len(data) // 2}H", data[:len(data) // 2 * 2])
    out, i, frame = [], 0, 0
    while i < len(words):
        w, frame = words[i], frame + 1
        op, low = w >> 8, w & 0xFF
        if op == OP_END and low == 0:
            out.append(f"{frame:5d}  {w:04X}            конец УП (end)")
            break
        if op == OP_Z:
            out.append(f"{frame:5d}  {w:04X}            z layer {low}")
            i += 1
        elif op == OP_LINE and low <= 3 and i + 2 < len(words):
            dx = -words[i + 1] if low & SIGN_X else words[i + 1]
            dy = -words[i + 2] if low & SIGN_Y else words[i + 2]
            out.append(f"{frame:5d}  {w:04X} {words[i + 1]:04X} {words[i + 2]:04X}  "
                       f"move {dx:+d} {dy:+d}")
            i += 3
        else:
            out.append(f"{frame:5d}  {w:04X}            unknown command")
            break
    return out


def svg(data: bytes, done: Sequence[int] = (), width: int = 720) -> str:
    """The program's picture: moves with the tool lowered in black, those
    whose frames completed in red, travel moves dotted grey.  ``done``:
    word offsets of completed commands (:attr:`Run.done`)."""
    words = struct.unpack(f"<{len(data) // 2}H", data[:len(data) // 2 * 2])
    finished = set(done)
    segs: list[tuple[int, int, int, int, str]] = []
    x = y = 0
    down = False
    i = 0
    while i < len(words):
        op, low = words[i] >> 8, words[i] & 0xFF
        if op == OP_Z:
            down = low != LAYER_UP
            i += 1
        elif op == OP_LINE and low <= 3 and i + 2 < len(words):
            dx = -words[i + 1] if low & SIGN_X else words[i + 1]
            dy = -words[i + 2] if low & SIGN_Y else words[i + 2]
            kind = "done" if i in finished else "draw" if down else "travel"
            segs.append((x, y, x + dx, y + dy, kind))
            x, y = x + dx, y + dy
            i += 3
        else:
            break
    xs = [v for s in segs for v in (s[0], s[2])] or [0]
    ys = [v for s in segs for v in (s[1], s[3])] or [0]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    span = max(x1 - x0, y1 - y0, 1)
    scale = (width - 20) / span
    height = int((y1 - y0) * scale) + 20
    style = {"draw": 'stroke="#000000"', "done": 'stroke="#d00000"',
             "travel": 'stroke="#a0a0a0" stroke-dasharray="4 4"'}
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'viewBox="0 0 {width} {height}">',
           f'<rect width="{width}" height="{height}" fill="#ffffff"/>']
    for ax, ay, bx, by, kind in segs:
        out.append(f'<line x1="{10 + (ax - x0) * scale:.2f}" y1="{10 + (y1 - ay) * scale:.2f}" '
                   f'x2="{10 + (bx - x0) * scale:.2f}" y2="{10 + (y1 - by) * scale:.2f}" '
                   f'{style[kind]} stroke-width="1.5"/>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------------------
# Input, and the command line.
# ---------------------------------------------------------------------------
def read_polylines(text: str) -> list[list[Point]]:
    """'x y' per line (whole pulses); a blank line ends a polyline; '#'
    starts a comment."""
    out: list[list[Point]] = [[]]
    starts: list[int] = [1]
    for no, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            if raw.strip() == "" and out[-1]:
                out.append([])
                starts.append(no + 1)
            continue
        if not out[-1]:
            starts[-1] = no
        parts = line.split()
        try:
            x, y = (int(v) for v in parts)
        except ValueError:
            raise ValueError(f"line {no}: expected 'x y' in whole pulses, got {line!r}") from None
        out[-1].append((x, y))
    for pl, no in zip(out, starts):
        if len(pl) == 1:
            raise ValueError(f"line {no}: polyline at {pl[0]} has one point; "
                             f"a polyline needs two")
    return [pl for pl in out if pl]


def deck_polylines(text: str) -> list[list[Point]]:
    """The conductors (L/+ cards) of a card deck's packages as polylines in
    0.01 mm, one pulse each."""

    return [list(c.points) for pkg in parse_deck(text) for c in pkg.conductors]


def _numbers(text: str | None, option: str) -> list[int]:
    """The transmission numbers of a fault option, 1 or more, comma-separated;
    ValueError naming the option for anything else (an empty item too:
    ``1,,2`` is a slip, not two numbers)."""
    if text is None:
        return []
    items = text.split(",")
    empty = next((k for k, v in enumerate(items, 1) if not v.strip()), None)
    if empty is not None:
        raise ValueError(f"{option} {text!r}: item {empty} is empty; expected transmission "
                         f"numbers like 2,5,9")
    try:
        out = [int(v) for v in items]
    except ValueError:
        raise ValueError(f"{option} {text!r}: expected transmission numbers "
                         f"like 2,5,9") from None
    if any(n < 1 for n in out):
        raise ValueError(f"{option} {text!r}: transmissions are numbered from 1")
    return out


def _run_cnclink(args: argparse.Namespace) -> int:
    def err(msg: str) -> None:
        print(f"cnclink: {msg}", file=sys.stderr)

    try:
        faults = {o: _numbers(getattr(args, o), f"--{o}") for o in ("corrupt", "drop", "noise")}
        limits = None
        if args.limits:
            try:
                lx, ly = (int(v) for v in args.limits.split(","))
            except ValueError:
                raise ValueError(f"--limits {args.limits!r}: expected X,Y in whole "
                                 f"pulses, like 120000,120000") from None
            if lx < 0 or ly < 0:
                raise ValueError(f"--limits {args.limits!r}: the table reaches 0..X, "
                                 f"0..Y; X and Y cannot be negative")
            limits = (lx, ly)
        for name in ("resend", "stop_at", "panel_stop"):
            value = getattr(args, name)
            if value is not None and value < (0 if name == "resend" else 1):
                raise ValueError(f"--{name.replace('_', '-')} {value}: expected a whole "
                                 f"number from {0 if name == 'resend' else 1}")
        # options of the run and of the parameters, given without them
        for name, needs, given in (("--stop-at", "--run", args.stop_at is not None),
                                   ("--panel-stop", "--run", args.panel_stop is not None),
                                   ("--corrupt-params", "--params", bool(args.corrupt_params))):
            if given and not getattr(args, needs[2:]):
                raise ValueError(f"{name} is an option of {needs}, which is not given")
    except ValueError as exc:
        err(str(exc))
        return 2
    values, notes = defaults(), []
    if args.params:
        try:
            with open(args.params, encoding="utf-8") as f:
                values, notes = read_params(f.read(), args.params)
        except OSError as exc:
            err(f"{args.params}: {exc.strerror or exc}")
            return 2
        except UnicodeDecodeError as exc:
            err(f"{args.params}: not UTF-8 text (byte {exc.start + 1})")
            return 1
    for note in notes:
        print(f"cnclink: {note}", file=sys.stderr)
    try:
        if args.input.endswith(".bin"):
            with open(args.input, "rb") as f:
                data = f.read()
            if not data:
                raise ValueError("the program is empty")
        else:
            raw = sys.stdin.buffer.read() if args.input == "-" else open(args.input, "rb").read()
            try:
                text = raw.decode("ascii")
            except UnicodeDecodeError as exc:
                raise ValueError(f"byte {exc.start + 1}: not ASCII text; POLYLINES is "
                                 f"'x y' lines, a .crd deck or a .bin program") from None
            deck = args.input.endswith(".crd")
            pls = deck_polylines(text) if deck else read_polylines(text)
            if not pls:
                raise ValueError("nothing to draw: " + (
                    "the deck has no conductors (L and + cards), the only cards cnclink "
                    "draws" if deck else "no polyline of two points or more in it")
                    + "; nothing sent")
            data = encode(program(pls, ratio=values["m"]))
    except OSError as exc:
        err(f"{args.input}: {exc.strerror or exc}")
        return 2
    except ValueError as exc:
        err(f"{args.input}: {exc}")
        return 1
    try:
        if args.output:
            write_whole(args.output, data, inputs=[args.input])
    except OSError as exc:
        err(f"{args.output}: {exc.strerror or exc}")
        return 2
    if args.view:
        for line in view(data):
            print(line)
    machine = Machine(limits=limits)
    if args.params:
        message = param_message(values)
        if args.corrupt_params:
            message = message[:-1] + bytes([message[-1] ^ 0x01])
        answer = machine.load_params(message)
        print(f"parameters: {len(message)} bytes, CRC-8 {message[-1]:#04x}: "
              f"{'ACK' if answer == ACK else 'NAK'}")
        if answer != ACK:
            err(f"{PARAM_ERROR} (parameter load error): the CNC refused the parameter "
                f"message; nothing sent")
            return 1
    result = send(data, faults["corrupt"], args.resend or 0, faults["drop"],
                  faults["noise"], controller=machine.link)
    for line in result.log:
        print(line)
    if not result.ok:
        err(result.message)
        if args.run:
            for line in run(machine).lines:
                print(line)
        return 1
    print(result.message)
    if args.received:
        try:
            write_whole(args.received, machine.link.program, inputs=[args.input])
        except OSError as exc:
            err(f"{args.received}: {exc.strerror or exc}")
            return 2
    if not args.run:
        try:                       # a .bin is sent as it is: the CNC judges it at Пуск
            drawn = execute(decode(data))
        except ValueError as exc:
            err(f"{args.input}: not a whole program: {exc}; the CNC holds it, but Пуск would "
                f"stop with Сбой 2")
            return 1
        print(f"program in the CNC's memory: it draws {len(drawn)} polylines in "
              f"{sum(len(p) - 1 for p in drawn)} moves")
        if not drawn:
            err(f"{args.input}: the program draws nothing (no move with the tool lowered)")
        return 0 if _write_svg(args, machine.link.program, []) else 2
    outcome = run(machine, args.stop_at, args.panel_stop)
    for line in outcome.lines:
        print(line)
    for line in machine.panel():
        print(line)
    if not _write_svg(args, machine.link.program, outcome.done):
        return 2
    return 0 if outcome.outcome in ("КП", "Стоп") else 1


def _write_svg(args: argparse.Namespace, data: bytes, done: Sequence[int]) -> bool:
    if not args.svg:
        return True
    try:
        write_whole(args.svg, svg(data, done), inputs=[args.input])
    except OSError as exc:
        print(f"cnclink: {args.svg}: {exc.strerror or exc}", file=sys.stderr)
        return False
    return True


def add_cnclink(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "cnclink", help="send polylines to a simulated CNC in 128-byte CRC blocks and run "
                        "them (seed 003)",
        description="Encode polylines (a file of 'x y' lines in pulses, a blank line "
                    "between polylines, the conductors of a .crd deck, or a .bin program "
                    "sent as it is) as a program of one- and three-word commands, send it "
                    "in 128-byte blocks with a CRC to a simulated CNC over a simulated "
                    "serial line, and report each block's acknowledgement.  A block not "
                    "acknowledged stops the transfer with the paper's 'ошибка вывода' "
                    "(output error) and exit status 1.  --run then runs it.")
    p.add_argument("input", metavar="POLYLINES",
                   help="polyline text, .crd deck or .bin program ('-' = stdin text)")
    p.add_argument("-o", "--output", metavar="PROG.bin", help="also write the program's bytes")
    p.add_argument("--corrupt", metavar="N[,N...]",
                   help="flip a bit in these transmissions (1-based, resends count)")
    p.add_argument("--drop", metavar="N[,N...]", help="lose a byte of these transmissions")
    p.add_argument("--noise", metavar="N[,N...]",
                   help="insert a stray byte into these transmissions")
    p.add_argument("--resend", type=int, default=0, metavar="K",
                   help="send a block not acknowledged again up to K times (default 0: "
                        "the paper's shell stops at once)")
    p.add_argument("--received", metavar="FILE",
                   help="write the program bytes the CNC accepted (equal to -o's)")
    p.add_argument("--params", metavar="FILE",
                   help="'name = value' lines: load the CNC's parameters first")
    p.add_argument("--corrupt-params", action="store_true",
                   help="damage the parameter message's CRC byte on the line")
    p.add_argument("--run", action="store_true",
                   help="press Пуск: run the program and print the CNC's messages")
    p.add_argument("--stop-at", type=int, metavar="N", help="press Стоп after frame N")
    p.add_argument("--panel-stop", type=int, metavar="N",
                   help="the operator stops the CNC from its own panel after frame N")
    p.add_argument("--limits", metavar="X,Y",
                   help="the table reaches 0..X, 0..Y pulses (default: no limit)")
    p.add_argument("--svg", metavar="FILE",
                   help="the part as the shell's view drew it; with --run, completed frames in red")
    p.add_argument("--view", action="store_true",
                   help="print the program's commands one a line (the file view)")
    p.set_defaults(func=_run_cnclink)
