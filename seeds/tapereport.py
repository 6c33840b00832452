"""What the 1977 chain makes of a board: one line per tape (frames, metres of
tape, machine minutes) and, for a deck of gerber2deck with a drill package,
the drilling tour of TENZOR against the board's own order (docs/GERBER.md).

``python -m seeds tapereport DIR/NAME.job [--deck DECK.crd]``

The tapes are read back with the harness's decoder and simulator
(harness.tape.decode, harness.sim.simulate), not taken on the job sheet's
word. A row of tape is 2.54 mm (a tenth of an inch). The travel of the
board's own order is the tool's path, raised, from the start point through
the holes' centres in the order of the drill file and back, on each of the
two pad tapes (holes up to DMAX on the small one, the others on the large
one, as TENZOR splits them); TENZOR's is the raised travel its two pad
tapes make (from hole to hole, to the rim of each hole's first circle).
"""
from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

from harness.deck import parse_deck
from harness.sim import simulate
from harness.tape import TapeError, decode

ROW_MM = 2.54
TAPES = ("small", "large", "cond")


def job_keys(path: Path) -> dict[str, str]:
    keys = {}
    for line in path.read_text(encoding="ascii", errors="replace").splitlines():
        if "=" in line and not line.startswith("#"):
            k, v = line.split("=", 1)
            keys[k.strip()] = v.strip()
    return keys


def tape_lines(job: Path) -> tuple[list[str], dict[str, float]]:
    """One line a tape of a job, and the raised travel (mm) of each tape."""
    keys = job_keys(job)
    lines, travel = [], {}
    for t in TAPES:
        data = (job.parent / keys[f"{t}.tape"]).read_bytes()
        tape = decode(data)
        run = simulate(tape.frames)
        travel[t] = run.travel_mm
        lines.append(f"{keys['name']} {t:5s}: {len(tape.frames):7d} frames, "
                     f"{len(data) * ROW_MM / 1000:8.2f} m of tape, {run.minutes:7.2f} min "
                     f"(drawn {run.drawn_mm / 1000:7.2f} m, travel {run.travel_mm / 1000:6.2f} m, "
                     f"tool {keys[f'{t}.tool_mm']} mm)")
    return lines, travel


def own_order_travel(deck_text: str, package: str) -> tuple[int, float]:
    """(holes, travel in mm) of a package's pads in deck order, split as
    TENZOR splits them onto the small and large tapes."""
    lines = deck_text.splitlines()
    start = next(i for i, ln in enumerate(lines) if ln[:18].rstrip() == package)
    end = next(i for i in range(start + 1, len(lines)) if lines[i][:1] in ("C", "E")
               and lines[i][1:72].strip() == "")
    pkg = parse_deck("\n".join([*lines[start:end], "E"]) + "\n")[0]
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


def report(job: Path, deck: Path | None) -> list[str]:
    out, _ = tape_lines(job)
    drill = job.with_name(f"{job_keys(job)['name']}-DRILL.job")
    if drill.exists():
        dl, travel = tape_lines(drill)
        out += dl
        tenzor = travel["small"] + travel["large"]
        if deck is not None:
            holes, own = own_order_travel(deck.read_text(encoding="ascii"),
                                          job_keys(drill)["name"])
            ratio = own / tenzor if tenzor else float("inf")
            out.append(f"{job_keys(drill)['name']} drilling: {holes} holes; travel in the "
                       f"drill file's order {own / 1000:.2f} m, in TENZOR's order "
                       f"{tenzor / 1000:.2f} m ({ratio:.1f} times shorter)")
        else:
            out.append(f"{job_keys(drill)['name']} drilling: travel in TENZOR's order "
                       f"{tenzor / 1000:.2f} m (give --deck for the drill file's order)")
    return out


def _run(args: argparse.Namespace) -> int:
    job = Path(args.job)
    try:
        for line in report(job, Path(args.deck) if args.deck else None):
            print(line)
    except OSError as exc:
        print(f"tapereport: {exc.filename or job}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    except (KeyError, StopIteration) as exc:
        print(f"tapereport: {job}: not a job sheet of TENZOR with its tapes beside it, or the "
              f"deck has no such package ({exc})", file=sys.stderr)
        return 2
    except (TapeError, ValueError) as exc:
        print(f"tapereport: {job}: a tape cannot be read: {exc}", file=sys.stderr)
        return 1
    return 0


def add_tapereport(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("tapereport", help="one line per tape of a job, and its drilling tour",
                       description=__doc__.split("\n\n")[0])
    p.add_argument("job", metavar="NAME.job", help="the job sheet of the copper package")
    p.add_argument("--deck", metavar="DECK.crd",
                   help="the deck (for the drill file's own order of the NAME-DRILL package)")
    p.set_defaults(func=_run)
