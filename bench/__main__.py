"""``python -m bench [--quick] [--out DIR] ...``: run the benchmarks.

Builds TENZOR's release build (``make release``: fpm's release profile
with :data:`bench.measure.RELEASE_FLAGS`) unless ``--tenzor`` names a
binary, runs every board, prints the table and the targets, and
writes ``bench.csv``, ``bench.txt`` (the table and the targets),
``bench.md`` (the table in Markdown) and ``bench.svg`` into ``--out``
(default ``out/bench``; the decks and tapes go to ``--out``/scratch).
Then the TSPLIB drilling problems of ``bench/tsplib/`` (:mod:`bench.tsplib`):
TENZOR's tour against the proven optimum, LKH-3's single run and OR-Tools,
into ``tsplib.csv``, ``tsplib.svg`` and the same text files (``--tsplib``,
``--no-tsplib``). ``--report CSV`` re-renders an earlier run without running
anything, byte for byte as the run wrote it (the CSV keeps every digit).
Exit status 0, or 2 for a usage or build problem.
"""

from __future__ import annotations

import argparse
import platform
import subprocess
import sys
import time
from collections.abc import Sequence
from pathlib import Path

from harness.files import quiet_when_output_closes, write_whole

from . import boards, measure, report, run_board, tours, tsplib

ROOT = Path(__file__).resolve().parents[1]


def _dists(text: str) -> list[str]:
    dists = [d.strip() for d in text.split(",") if d.strip()]
    bad = [d for d in dists if d not in boards.DISTRIBUTIONS]
    if bad or not dists:
        raise argparse.ArgumentTypeError(f"distributions are {', '.join(boards.DISTRIBUTIONS)}")
    return dists


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m bench", description=__doc__.split("\n\n")[1],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--quick", action="store_true",
                   help="boards of 100 and 1 000 pads only, 2 timed runs each")
    p.add_argument("--out", type=Path, default=ROOT / "out" / "bench", metavar="DIR",
                   help="output directory (default out/bench)")
    p.add_argument("--sizes", type=boards.sizes_argument, metavar="N,N,...",
                   help="board sizes in pads (default 100,1000,10000,100000)")
    p.add_argument("--dists", type=_dists, default=list(boards.DISTRIBUTIONS), metavar="D,D,...",
                   help="distributions (default uniform,clustered,grid)")
    p.add_argument("--repeats", type=int, metavar="N",
                   help="timed runs of TENZOR per board, the minimum is kept (default 5)")
    p.add_argument("--min-seconds", type=float, default=1.0, metavar="S",
                   help="repeat short runs until they add up to S seconds, at most 30 runs "
                        "(default 1)")
    p.add_argument("--lkh-max", type=int, default=10000, metavar="N",
                   help="largest board given to LKH-3 (default 10000)")
    p.add_argument("--nn-max", type=int, default=100000, metavar="N",
                   help="largest board given to the Python nearest neighbour (default 100000)")
    p.add_argument("--verify-dists", type=_dists, default=["uniform"], metavar="D,D,...",
                   help="distributions whose boards are also checked by `python -m harness "
                        "verify`, timed (default uniform)")
    p.add_argument("--verify-min", type=int, default=10000, metavar="N",
                   help="smallest board checked by verify (default 10000)")
    p.add_argument("--tenzor", type=Path, metavar="EXE",
                   help="the TENZOR binary to time (default: build the release build, as make release does)")
    p.add_argument("--tsplib", metavar="NAME,...",
                   help="TSPLIB instances to run (default: all of "
                        + ",".join(tsplib.NAMES) + "; --quick: d198,pcb442)")
    p.add_argument("--no-tsplib", action="store_true", help="run no TSPLIB instance")
    p.add_argument("--no-tsplib-refs", action="store_true",
                   help="TSPLIB: TENZOR only, no LKH-3 or OR-Tools (their time dominates)")
    p.add_argument("--report", type=Path, metavar="CSV",
                   help="run nothing: print the table and targets of an earlier bench.csv "
                        "(and of the tsplib.csv beside it) and write its bench.txt, "
                        "bench.md, bench.svg (and tsplib.svg) into --out")
    return p


def write_outputs(rows: Sequence[dict], out: Path,
                  tsp_rows: Sequence[dict] = ()) -> str:
    """bench.txt, bench.md and bench.svg of the rows, and tsplib.svg of the
    TSPLIB rows if any (bench.csv and tsplib.csv are the caller's); returns
    the text of bench.txt."""
    text = report.table(rows) + "\n" + report.targets_text(rows)
    md = report.table(rows, markdown=True)
    if tsp_rows:
        text += ("\nTSPLIB drilling problems (% over the proven optimum)\n\n"
                 + report.tsplib_table(tsp_rows) + "\n" + report.tsplib_targets_text(tsp_rows))
        md += "\n" + report.tsplib_table(tsp_rows, markdown=True)
    write_whole(out / "bench.txt", text)
    write_whole(out / "bench.md", md)
    write_whole(out / "bench.svg", report.svg(rows))
    if tsp_rows:
        write_whole(out / "tsplib.svg", report.tsplib_svg(tsp_rows))
    return text


@quiet_when_output_closes
def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if args.report:
        try:
            rows = report.read_csv(args.report)
        except OSError as exc:
            print(f"{args.report}: {exc.strerror or exc}", file=sys.stderr)
            return 2
        args.out.mkdir(parents=True, exist_ok=True)
        tsp_csv = args.report.with_name("tsplib.csv")
        tsp_rows = report.read_csv(tsp_csv) if tsp_csv.exists() else []
        print(write_outputs(rows, args.out, tsp_rows), end="")
        return 0
    sizes = args.sizes or ([100, 1000] if args.quick else list(boards.SIZES))
    repeats = args.repeats or (2 if args.quick else 5)
    if repeats < 1:
        print("--repeats must be at least 1", file=sys.stderr)
        return 2
    try:
        exe = args.tenzor.resolve() if args.tenzor else measure.release_binary(ROOT)
    except subprocess.CalledProcessError as exc:
        print(f"building TENZOR failed: {exc.stderr.decode(errors='replace')}", file=sys.stderr)
        return 2
    if not exe.exists():
        print(f"no TENZOR binary at {exe}", file=sys.stderr)
        return 2
    out = args.out
    scratch = out / "scratch"
    scratch.mkdir(parents=True, exist_ok=True)
    if not tours.lkh_available():
        print("elkai (LKH-3) is not installed: no reference tours", file=sys.stderr)
    print(f"TENZOR {exe}; {platform.processor() or platform.machine()}, "
          f"{len(sizes) * len(args.dists)} boards, {repeats} timed runs each (minimum kept)",
          flush=True)
    rows = []
    started = time.perf_counter()
    for size in sizes:
        for dist in args.dists:
            t = time.perf_counter()
            board = boards.make_board(dist, size)
            check = dist in args.verify_dists and size >= args.verify_min
            row = run_board(board, exe, scratch, repeats, args.lkh_max, args.nn_max,
                            args.min_seconds, verify=check)
            rows.append(row)
            checked = (f"; verify {row['verify_s']:.1f} s, {row['verify_rss_mb']:.0f} MB"
                       if check else "")
            print(f"  {row['board']}: TENZOR {row['tenzor_s']:.3f} s, "
                  f"{row['peak_rss_mb']:.1f} MB{checked}; board done in "
                  f"{time.perf_counter() - t:.0f} s", flush=True)
    tsp_rows = []
    names = ([] if args.no_tsplib else
             [n for n in (args.tsplib or ("d198,pcb442" if args.quick else
                                          ",".join(tsplib.NAMES))).split(",") if n])
    for name in names:
        t = time.perf_counter()
        row = tsplib.run_instance(name, exe, scratch, repeats, args.min_seconds,
                                  refs=not args.no_tsplib_refs)
        tsp_rows.append(row)
        print(f"  {name}: TENZOR {row['tenzor_pct']:.2f} % over the optimum, "
              f"{row['tenzor_s']:.3f} s; done in {time.perf_counter() - t:.0f} s", flush=True)
    report.write_csv(rows, out / "bench.csv")
    if tsp_rows:
        report.write_tsplib_csv(tsp_rows, out / "tsplib.csv")
    text = write_outputs(rows, out, tsp_rows)
    print()
    print(text, end="")
    print(f"\n{len(rows)} boards in {time.perf_counter() - started:.0f} s; "
          f"wrote {out / 'bench.csv'}, bench.txt, bench.md, bench.svg"
          + (", tsplib.csv, tsplib.svg" if tsp_rows else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
