"""What the 1977 chain makes of a board: one line per tape (frames, metres of
tape, machine minutes) and, for a deck of gerber2deck with a drill package,
the drilling tour of TENZOR against the board's own order (docs/GERBER.md).

``python -m seeds tapereport DIR/NAME.job [--deck DECK.crd]``

NAME.job is the job sheet of a package; when NAME-DRILL.job lies beside it
(or NAME.job is itself a NAME-DRILL package), the drilling tour is reported
too. The job sheet is read as em703 reads it (docs/FILES.md): ``key = value``
lines, a name, and for each tape its file beside the sheet and its tool; a
size or SHA-256 it records must be its file's (harness.verify's check). The tapes are read back with
the harness's decoder and simulator (harness.tape.decode, harness.sim.simulate),
not taken on the job sheet's word. A row of tape is 2.54 mm (a tenth of an
inch). The travel of the board's own order is the tool's path, raised, from
the start point through the holes' centres in the order of the drill file and
back, on each of the two pad tapes (holes up to DMAX on the small one, the
others on the large one, as TENZOR splits them); TENZOR's is the raised travel
its two pad tapes make (from hole to hole, to the rim of each hole's first
circle).

Exit status: 0 reported; 1 a tape or the deck cannot be read for what it
holds; 2 a file cannot be opened or is not a job sheet.
"""
from __future__ import annotations

import argparse
import math
import re
import sys
from dataclasses import dataclass
from pathlib import Path

from harness.deck import CardError, parse_deck, sanitise
from harness.files import ascii_text
from harness.sim import simulate
from harness.tape import TapeError, decode
from harness.verify import VerifyError, package_files_agree

ROW_MM = 2.54
TAPES = ("small", "large", "cond")
#: A package's name as TENZOR writes it into file names: columns 1-18 of the
#: name card, sanitised (docs/FILES.md).
_NAME = re.compile(r"^[A-Za-z0-9_-]{1,18}$")
#: Millimetres with at most two decimals (a tool of the job sheet).
_MM = re.compile(r"^[0-9]+(\.[0-9]{1,2})?$")


class ReportError(Exception):
    """What cannot be reported, and why; ``status`` is the exit status."""

    def __init__(self, status: int, message: str) -> None:
        super().__init__(message)
        self.status = status


@dataclass(frozen=True)
class Job:
    """A job sheet's name and, for each tape, its path and its tool (as written)."""

    path: Path
    name: str
    tapes: dict[str, Path]
    tools: dict[str, str]


def _read(path: Path, what: str) -> bytes:
    try:
        return path.read_bytes()
    except OSError as exc:
        raise ReportError(2, f"{path}: {exc.strerror or exc}{what}") from None


def read_job(path: Path) -> Job:
    """The job sheet at ``path``, checked; ReportError names the line or the
    missing key."""
    text = _read(path, "").decode("latin-1")
    keys: dict[str, tuple[str, int]] = {}
    for no, line in enumerate(text.split("\n"), 1):
        line = line.removesuffix("\r")
        if not line.strip() or line.startswith("#"):
            continue
        if " = " not in line:
            raise ReportError(2, f"{path}: line {no}: not a \"key = value\" line: {line[:60]!r} "
                                 f"(is it a job sheet TENZOR wrote?)")
        key, value = line.split(" = ", 1)
        keys[key.strip()] = (value.strip(), no)

    def need(key: str, what: str) -> tuple[str, int]:
        if key not in keys:
            raise ReportError(2, f"{path}: the job sheet has no \"{key} = ...\" line ({what})")
        return keys[key]

    name, no = need("name", "the package's name")
    if not _NAME.match(name):
        raise ReportError(2, f"{path}: line {no}: name {name!r} is not a package's name as "
                             f"TENZOR writes it (1 to 18 letters, digits, - and _)")
    tapes, tools = {}, {}
    for t in TAPES:
        file, no = need(f"{t}.tape", f"the {t} tape's file")
        if not file or "/" in file or "\\" in file or "\0" in file or file in (".", ".."):
            raise ReportError(2, f"{path}: line {no}: {t}.tape must name a file beside the "
                                 f"job sheet, not {file!r}")
        tool, no = need(f"{t}.tool_mm", f"the {t} tape's tool")
        if not _MM.match(tool) or not 0 < float(tool) <= 1200:
            raise ReportError(2, f"{path}: line {no}: {t}.tool_mm must be a tool width in mm "
                                 f"(above 0, at most 1200, two decimals), not {tool!r}")
        tapes[t] = path.parent / file
        tools[t] = tool
    return Job(path, name, tapes, tools)


def tape_lines(job: Job) -> tuple[list[str], dict[str, float]]:
    """One line a tape of a job, and the raised travel (mm) of each tape."""
    tapes = {t: _read(job.tapes[t], f" (the {t} tape of {job.path})") for t in TAPES}
    # a size or SHA-256 the sheet records must be its file's (verify's check)
    try:
        package_files_agree(job.path.parent, job.path.stem)
    except VerifyError as exc:
        raise ReportError(1, str(exc)) from None
    lines, travel = [], {}
    for t in TAPES:
        path, data = job.tapes[t], tapes[t]
        try:
            tape = decode(data)
        except TapeError as exc:
            raise ReportError(1, f"{path}: {exc}") from None
        run = simulate(tape.frames)
        travel[t] = run.travel_mm
        lines.append(f"{job.name} {t:5s}: {len(tape.frames):7d} frames, "
                     f"{len(data) * ROW_MM / 1000:8.2f} m of tape, {run.minutes:7.2f} min "
                     f"(drawn {run.drawn_mm / 1000:7.2f} m, travel {run.travel_mm / 1000:6.2f} m, "
                     f"tool {job.tools[t]} mm)")
    return lines, travel


def own_order_travel(deck: Path, package: str) -> tuple[int, float]:
    """(holes, travel in mm) of a package's pads in deck order, split as
    TENZOR splits them onto the small and large tapes. ``package`` is the
    name as in file names (a name card is matched as TENZOR names its files)."""
    try:
        lines = ascii_text(_read(deck, ""), "card").split("\n")
    except ValueError as exc:
        raise ReportError(1, f"{deck}: {exc}: not a card deck") from None
    start = next((i for i, ln in enumerate(lines)
                  if ln[:1] not in ("*", "#") and ln[:72].strip()
                  and sanitise(ln[:18]) == package), None)
    if start is None:
        raise ReportError(1, f"{deck}: no package named {package} (its name card is "
                             f"wanted for the drill file's order)")
    end = next((i for i in range(start + 1, len(lines)) if lines[i][:1] in ("C", "E")
                and lines[i][1:72].strip() == ""), None)
    if end is None:
        raise ReportError(1, f"{deck}: card {start + 1}: package {package} has no C or E "
                             f"card after it")
    # blank lines before it keep the deck's card numbers in the reader's messages
    try:
        pkg = parse_deck("\n" * start + "\n".join([*lines[start:end], "E"]) + "\n")[0]
    except CardError as exc:
        raise ReportError(1, f"{deck}: {exc} (package {package})") from None
    total, holes = 0.0, 0
    for small in (True, False):
        x = y = 0
        for p in pkg.pads:
            if (p.size <= pkg.dmax) != small:
                continue
            for cx, cy in p.centres():
                total += math.hypot(cx - x, cy - y)
                x, y = cx, cy
                holes += 1
        total += math.hypot(x, y)
    return holes, total / 100.0


def report(path: Path, deck: Path | None) -> list[str]:
    """The lines of the report on the job sheet at ``path`` (see the module doc)."""
    job = read_job(path)
    out, travel = tape_lines(job)
    if job.name.endswith("-DRILL"):
        drill = job
    else:
        beside = path.with_name(f"{job.name}-DRILL.job")
        if not beside.exists():
            if deck is not None:
                print(f"tapereport: no {beside.name} beside {path}: no drilling tour to "
                      f"compare, --deck not used", file=sys.stderr)
            return out
        drill = read_job(beside)
        dl, travel = tape_lines(drill)
        out += dl
    tenzor = travel["small"] + travel["large"]
    if deck is None:
        out.append(f"{drill.name} drilling: travel in TENZOR's order {tenzor / 1000:.2f} m "
                   f"(give --deck for the drill file's order)")
        return out
    holes, own = own_order_travel(deck, drill.name)
    if own >= 1.5 * tenzor > 0:
        than = f"{own / tenzor:.1f} times shorter"
    elif own >= tenzor > 0:
        than = f"TENZOR's is {100 * (1 - tenzor / own):.0f} % shorter"
    elif own > tenzor:
        than = "no travel in TENZOR's"
    elif own > 0:
        than = f"TENZOR's is {100 * (tenzor / own - 1):.0f} % longer"
    else:
        than = "no travel in the drill file's"
    out.append(f"{drill.name} drilling: {holes} holes; travel in the drill file's order "
               f"{own / 1000:.2f} m, in TENZOR's order {tenzor / 1000:.2f} m ({than})")
    return out


def _run(args: argparse.Namespace) -> int:
    try:
        for line in report(Path(args.job), Path(args.deck) if args.deck else None):
            print(line)
    except ReportError as exc:
        print(f"tapereport: {exc}", file=sys.stderr)
        return exc.status
    return 0


def add_tapereport(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("tapereport", help="one line per tape of a job, and its drilling tour",
                       description=__doc__.split("\n\n")[0])
    p.add_argument("job", metavar="NAME.job", help="the job sheet of the copper package "
                                                   "(or of its NAME-DRILL package)")
    p.add_argument("--deck", metavar="DECK.crd",
                   help="the deck (for the drill file's own order of the NAME-DRILL package)")
    p.set_defaults(func=_run)
