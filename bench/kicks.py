"""The kicks' traces: how soon TENZOR's tour comes within 1 % of the optimum.

``python -m bench.kicks`` measures the search the way docs/PERFORMANCE.md's
trials of the kicks are measured ("Five more trials", "At 9982ddf"). It
builds a *traced* copy of a tree's TENZOR in a temporary directory (the tree
itself is not touched), whose ``CMKICK`` also

* takes its seed from the environment variable ``TZSEED`` (default 1977,
  TENZOR's own) and its window, the failed kicks in a row after which the
  kicks stop, as a multiple of TENZOR's own (a quarter of a kick an item,
  times the square root of N / 700 on a tape of N items, N over 700; at
  least 160 kicks where TENZOR's is: when the tour comes back from a far
  start point), from ``TZWIN`` (default 1, TENZOR's own);
* on a tape of more than 150 items (on a TSPLIB deck, the small-pad tape:
  the others are empty) appends to the file ``TZTRACE`` names a line when
  the kicks begin, one at each kick kept and one when they stop: the
  kick's number (negated on the last line), the process's CPU seconds so
  far and the tour's length in the tape's units; the first line also the
  least window CMKICK took (1, or 160).

The instrumentation uses GNU Fortran's ``GETENV``: it is a tool for
measuring, never part of TENZOR, whose legacy/ stays FORTRAN 77. It is put
in by replacing lines of ``legacy/cmkick.f`` (:data:`PATCH`); if that file
has changed so that a line is no longer there, the tool says which.

Each instance of ``bench/tsplib/`` is run once with each seed under a long
window (40 times TENZOR's own, ten kicks an item on a tape of up to 700
items, by default), so that every shorter window can be read off the same
trace: a window of W stops the kicks after W * N / 4 kicks in a row that
all failed (at least 160 where CMKICK's least window applies, which the
trace's first line says; times the square root of N / 700 where N is
over 700), and, as
CMKICK's window grows
with what the kept kicks have gained, three times as many more for each per
cent beyond the first half, up to 8 * W * N / 4 in all (read from the
trace's lengths, which may put a stop one kick off CMKICK's own sum of
gains), at a time found from the trace's own cost of a kick. The tour's
per cent over the proven optimum is that of its TSPLIB length
(:mod:`bench.tsplib`), each trace's lengths scaled by the ratio of the two
at the trace's end. Printed, per instance: the kicks to come within 1 %
with the first seed and with the others, the kicks a budget of a hundredth
of LKH-3's time allows (LKH-3's seconds read from the recorded TSPLIB run,
``--lkh``, as the hour of that run may not be this one's), the cost of a
kick; then the mean per cent over the optimum after 25 to 400 ms of CPU;
then, for windows of 1 to 20 times TENZOR's own (a quarter to five kicks
an item on a tape of up to 700 items),
the runs within 1 % and the first seed's CPU time to the end of the program
and per cent.

    python -m bench.kicks                                  # this tree, eleven instances, six seeds
    python -m bench.kicks --tree ../trial --names d493,pcb1173 --seeds 1977,12345
"""
from __future__ import annotations

import argparse
import csv
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from harness.files import quiet_when_output_closes

from . import measure, tsplib

ROOT = Path(__file__).resolve().parents[1]

#: The seeds of the trials in docs/PERFORMANCE.md; the first is TENZOR's.
SEEDS: tuple[int, ...] = (1977, 12345, 777, 4242, 99, 31337)
#: Times (ms of CPU) at which the mean per cent is read.
AT_MS: tuple[int, ...] = (25, 50, 100, 200, 400)
#: Windows (failed kicks in a row, as multiples of TENZOR's own) read off
#: each trace.
WINDOWS: tuple[int, ...] = (1, 2, 4, 8, 20)
#: Tapes of at most this many items are not traced.
TRACE_ABOVE = 150

#: The instrumentation of legacy/cmkick.f: (a line block of the file, what
#: replaces it). Each block must occur exactly once.
PATCH: tuple[tuple[str, str], ...] = (
    ("      DOUBLE PRECISION DIST, GKEPT, GPCT\n",
     "      DOUBLE PRECISION DIST, GKEPT, GPCT, CMTLEN\n"
     "      EXTERNAL CMTLEN\n"
     "      CHARACTER*80 ENVV\n"
     "      INTEGER ITRC, NWIN\n"
     "      REAL TCPU\n"),
    ("      ISEED = 1977\n",
     "      ISEED = 1977\n"
     "      CALL GETENV('TZSEED', ENVV)\n"
     "      IF (ENVV .NE. ' ') READ (ENVV, *) ISEED\n"
     "      NWIN = 1\n"
     "      CALL GETENV('TZWIN', ENVV)\n"
     "      IF (ENVV .NE. ' ') READ (ENVV, *) NWIN\n"
     "      ITRC = 0\n"
     "      CALL GETENV('TZTRACE', ENVV)\n"
     f"      IF (ENVV .NE. ' ' .AND. NITM .GT. {TRACE_ABOVE}) ITRC = 1\n"),
    ("      IF (MODE .EQ. 2) NBASE = MAX(NITM / 4, NLEAST)\n",
     "      IF (MODE .EQ. 2) NBASE = MAX(NWIN * NITM / 4, NLEAST)\n"),
    ("      NSTAG = NBASE\n      GKEPT = 0.0D0\n",
     "      NSTAG = NBASE\n"
     "      GKEPT = 0.0D0\n"
     "      IF (ITRC .EQ. 1) THEN\n"
     "         OPEN (77, FILE=ENVV, STATUS='UNKNOWN', POSITION='APPEND')\n"
     "         CALL CPU_TIME(TCPU)\n"
     "         WRITE (77, *) 0, TCPU, CMTLEN(), NLEAST\n"
     "      END IF\n"),
    ("            KLAST = KK\n",
     "            KLAST = KK\n"
     "            IF (ITRC .EQ. 1) THEN\n"
     "               CALL CPU_TIME(TCPU)\n"
     "               WRITE (77, *) KK, TCPU, CMTLEN()\n"
     "            END IF\n"),
    ("   60 CONTINUE\n      LJRN = 0\n",
     "   60 CONTINUE\n"
     "      IF (ITRC .EQ. 1) THEN\n"
     "         CALL CPU_TIME(TCPU)\n"
     "         WRITE (77, *) -NDONE, TCPU, CMTLEN()\n"
     "         CLOSE (77)\n"
     "      END IF\n"
     "      LJRN = 0\n"),
)


class KicksError(Exception):
    """The traced copy cannot be made or run."""


def traced_source(text: str) -> str:
    """legacy/cmkick.f with :data:`PATCH` put in; KicksError names the
    first block that is not in ``text`` exactly once."""
    for old, new in PATCH:
        n = text.count(old)
        if n != 1:
            first = old.splitlines()[0].strip()
            raise KicksError(f"legacy/cmkick.f holds {n} copies of the line {first!r}, not "
                             "one: the trace cannot be put in; update bench/kicks.py's PATCH")
        text = text.replace(old, new)
    return text


def build_traced(tree: Path, work: Path) -> Path:
    """Copy the Fortran of ``tree`` into ``work``, put the trace in, build
    it as the benchmark builds TENZOR; the executable's path."""
    if shutil.which("fpm") is None:
        raise KicksError("fpm is not on PATH: put .venv/bin on PATH (make setup)")
    for part in ("legacy", "src", "app", "test"):
        if (tree / part).is_dir():
            shutil.copytree(tree / part, work / part)
    shutil.copy2(tree / "fpm.toml", work / "fpm.toml")
    kick = work / "legacy" / "cmkick.f"
    kick.write_text(traced_source(kick.read_text(encoding="ascii")), encoding="ascii")
    try:
        return measure.release_binary(work)
    except subprocess.CalledProcessError as exc:
        out = (exc.stdout or b"") + (exc.stderr or b"")
        raise KicksError("fpm build of the traced copy failed:\n"
                         + out.decode(errors="replace")[-3000:]) from None


@dataclass
class Trace:
    """One traced run: ``points`` (kick, CPU s, per cent over the optimum),
    the first when the kicks begin, the last when they stop (its kick
    number the kicks made); ``cpu`` the whole process's CPU seconds;
    ``least`` the least window CMKICK took (1, or 160 where the tour came
    back from a far start point), read off the trace's first line."""
    items: int
    points: list[tuple[int, float, float]]
    cpu: float
    least: int = 1

    @property
    def kicks(self) -> int:
        return self.points[-1][0]

    def per_kick(self) -> float:
        """CPU seconds a kick, over the whole trace."""
        return (self.points[-1][1] - self.points[0][1]) / max(1, self.kicks)

    def after(self) -> float:
        """CPU seconds of the program after the kicks."""
        return max(0.0, self.cpu - self.points[-1][1])

    def at(self, ms: float) -> float:
        """Per cent over the optimum at ``ms`` of CPU (the first point's,
        before the kicks begin)."""
        pct = self.points[0][2]
        for _, t, p in self.points:
            if t * 1000 <= ms:
                pct = p
        return pct

    def kicks_to(self, pct: float = 1.0) -> int | None:
        """The kick after which the tour is first within ``pct`` per cent
        (0: before any kick), or None."""
        return next((k for k, _, p in self.points if p <= pct), None)

    def window(self, w: int) -> tuple[float, float]:
        """Stopped after ``w`` * items / 4 failed kicks in a row (at least
        ``least``, as CMKICK counts them; times the square root of items /
        700 on a tape of more than 700 items), a window that grows after
        each kept kick by three times itself for each per cent the kicks
        have taken off beyond the first half, up to eight times ``w`` *
        items / 4 (CMKICK's rule): (CPU seconds of the whole program, per
        cent). The trace's own window must be at least ``w``; past its end
        the run ends as it did."""
        t0, p0 = self.points[0][1], self.points[0][2]
        last = self.points[0]
        base = max(w * self.items // 4, self.least)
        cap = 8 * base
        if self.items > 700:
            base = int(base * math.sqrt(self.items / 700.0))
        stag = base
        for point in self.points[1:-1] + [(self.kicks + 10**9, 0.0, 0.0)]:
            if point[0] - last[0] > stag:
                stop = min(last[0] + stag, self.kicks)
                return t0 + self.per_kick() * stop + self.after(), last[2]
            last = point
            # the per cent of the first tour's length the kicks took off
            gained = 100.0 * (p0 - point[2]) / (100.0 + p0) - 0.5
            if gained > 0.0:
                stag = min(base + int(3.0 * base * gained), cap)
        return self.cpu, self.points[-1][2]


def read_trace(path: Path, items: int, pct_end: float, cpu: float) -> Trace:
    """A trace file, its lengths scaled so that the last is ``pct_end`` per
    cent over the optimum."""
    rows = [line.split() for line in path.read_text().splitlines() if line.strip()]
    if len(rows) < 2:
        raise KicksError(f"{path}: no trace (is the tape over {TRACE_ABOVE} items?)")
    # the first line's fourth number: the least window CMKICK took
    least = int(rows[0][3]) if len(rows[0]) > 3 else 1
    pts = [(abs(int(k)), float(t), float(x)) for k, t, x, *_ in rows]
    scale = (1 + pct_end / 100) / pts[-1][2]
    return Trace(items, [(k, t, 100 * (x * scale - 1)) for k, t, x in pts], cpu, least)


def run_traced(exe: Path, instance: str | tsplib.Instance, seed: int, window: int,
               scratch: Path) -> Trace:
    """One run of the traced TENZOR on a TSPLIB instance (by name, or as
    another deck of it, bench.variants)."""
    inst = tsplib.load(instance) if isinstance(instance, str) else instance
    deck = tsplib.write_deck(inst, scratch)
    trc = scratch / f"{inst.name}.{seed}.trc"
    trc.unlink(missing_ok=True)
    out = scratch / inst.name
    env = dict(os.environ, TZTRACE=str(trc), TZSEED=str(seed), TZWIN=str(window))
    try:
        _, cpu = measure.run_once(exe, deck, out, env)
    except RuntimeError as exc:
        raise KicksError(str(exc)) from None
    length = tsplib.tenzor_length(inst, out)
    return read_trace(trc, len(inst.nodes), 100 * (length / inst.optimum - 1), cpu)


def lkh_seconds(path: Path) -> dict[str, float]:
    """LKH-3's seconds per instance from a recorded tsplib.csv."""
    try:
        with path.open(newline="") as f:
            return {r["instance"]: float(r["lkh_s"]) for r in csv.DictReader(f) if r["lkh_s"]}
    except OSError:
        return {}


def _span(values: list[int | None]) -> str:
    got = sorted(v for v in values if v is not None)
    never = len(values) - len(got)
    text = (f"{got[0]}" if len(got) == 1 or got[0] == got[-1] else
            f"{got[0]}-{got[-1]}") if got else "-"
    return text + (f", never {never}" if never else "")


def report(runs: dict[str, list[Trace]], seeds: list[int], lkh: dict[str, float]) -> str:
    """The three tables described in the module's text."""
    lines = [f"instance  items  kicks to 1 %: seed {seeds[0]}  other seeds           "
             "kicks a 1/100 LKH-3 budget allows  us a kick"]
    for name, traces in runs.items():
        first = traces[0]
        allow = "-"
        if name in lkh:
            budget = lkh[name] / 100
            allow = _span([int(max(0.0, budget - tr.points[0][1] - tr.after())
                               / tr.per_kick()) for tr in traces])
        k1 = first.kicks_to()
        lines.append(f"{name:8s} {first.items:6d}  {'never' if k1 is None else k1:>20}  "
                     f"{_span([tr.kicks_to() for tr in traces[1:]]):22s}"
                     f"{allow:>34s}  {first.per_kick() * 1e6:9.1f}")
    every = [tr for traces in runs.values() for tr in traces]
    lines.append("")
    lines.append("mean % over the optimum after " + ", ".join(f"{ms}" for ms in AT_MS)
                 + " ms of CPU: " + ", ".join(f"{statistics.mean(tr.at(ms) for tr in every):.2f}"
                                            for ms in AT_MS))
    lines.append("")
    lines.append("window (times TENZOR's own: a quarter of a failed kick an item, "
                 "times sqrt(N/700) on a tape of N > 700 items)")
    lines.append(f"window  runs within 1 %   seed {seeds[0]}: CPU ms of the program / % "
                 "(* within a hundredth of LKH-3)")
    for w in WINDOWS:
        cells = []
        within = 0
        for name, traces in runs.items():
            stops = [tr.window(w) for tr in traces]
            within += sum(p <= 1.0 for _, p in stops)
            t, p = stops[0]
            mark = "*" if p <= 1.0 and name in lkh and t <= lkh[name] / 100 else " "
            cells.append(f"{name} {mark}{t * 1000:.0f}/{p:.2f}")
        lines.append(f"{w:6d}  {within:4d} of {len(every):<4d}   " + ", ".join(cells))
    return "\n".join(lines)


def build_parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="python -m bench.kicks", description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tree", type=Path, default=ROOT,
                    help="the tree whose TENZOR is traced (default this one)")
    ap.add_argument("--names", default=",".join(tsplib.NAMES),
                    help="TSPLIB instances (default all of bench/tsplib/)")
    ap.add_argument("--seeds", default=",".join(map(str, SEEDS)),
                    help="seeds, the first reported on its own (default the six of the trials)")
    ap.add_argument("--window", type=int, default=40,
                    help="the traced runs' window, as a multiple of TENZOR's own (default 40: "
                         "ten kicks an item on a tape of up to 700 items)")
    ap.add_argument("--lkh", type=Path, default=ROOT / "bench" / "results" / "tsplib.csv",
                    help="a tsplib.csv whose LKH-3 seconds set the budgets")
    ap.add_argument("--out", type=Path, default=Path("out/kicks"),
                    help="decks, tapes and traces (default out/kicks)")
    return ap


@quiet_when_output_closes
def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    names, problem = tsplib.parse_names("--names", args.names)
    try:
        seeds = [int(s) for s in args.seeds.split(",") if s]
    except ValueError:
        seeds = []
    if problem is None and not seeds:
        problem = f"--seeds {args.seeds!r}: give whole numbers separated by commas"
    elif problem is None and args.window < max(WINDOWS):
        problem = (f"--window {args.window}: at least {max(WINDOWS)}, so that every "
                   "window of the report can be read off the traces")
    if problem is not None:
        print(f"bench.kicks: {problem}", file=sys.stderr)
        return 2
    args.out.mkdir(parents=True, exist_ok=True)
    try:
        with tempfile.TemporaryDirectory(prefix="kicks-") as tmp:
            exe = build_traced(args.tree.resolve(), Path(tmp))
            runs = {n: [run_traced(exe, n, s, args.window, args.out) for s in seeds]
                    for n in names}
    except KicksError as exc:
        print(f"bench.kicks: {exc}", file=sys.stderr)
        return 2
    print(report(runs, seeds, lkh_seconds(args.lkh)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
