"""Other decks of the same boards: how much TENZOR's TSPLIB tours owe to the deck.

``python -m bench.variants`` runs each instance of ``bench/tsplib/`` as its
TSPLIB file gives it (``as``) and as seven other decks of the same board:
mirrored left to right (``mx``), and with its pads in six shuffled orders
(``sh1`` to ``sh6``, from Python's random with seeds 1 to 6; node 1, the
start point, stays first). Each has the proven optimum of the published
one: a mirror keeps every distance, and the order of the D cards only
changes which pad has which number. TENZOR's tour is not bound to stay the
same: its searches look at the items in the order of their numbers and
break ties (many, on a drilling board's rows of equally spaced pads) by the
smaller number; so a tour within 1 % on the published deck may not be on
another. The benchmark's TSPLIB table is one deck of each board; this is
eight. (Mirroring top to bottom or transposing gave the tours of ``mx`` on
all eleven boards, turning a quarter those of ``as``: one mirror stands for
them, and the shuffles, which change more, are most of the eight.)

Printed: per instance, the per cent over the optimum of each deck and the
CPU milliseconds of the slowest; then the runs within 1 %, the mean, and
the worst. Written into ``--out``: ``variants.csv`` (one row a run),
``variants.txt`` (what was printed) and the decks and tapes (``scratch/``).

    python -m bench.variants                                  # this tree's release build
    python -m bench.variants --tenzor ../trial/tenzor --names d198,d2103
"""
from __future__ import annotations

import argparse
import csv
import io
import random
import statistics
import subprocess
import sys
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from harness.files import quiet_when_output_closes, write_whole

from . import measure, tsplib

ROOT = Path(__file__).resolve().parents[1]

#: the decks of a board, in the order they are reported
TAGS = ("as", "mx", "sh1", "sh2", "sh3", "sh4", "sh5", "sh6")


@dataclass(frozen=True)
class Variant:
    """One deck of a board: ``instance`` (its nodes moved or renumbered,
    the same name and optimum) and ``origin``, the published instance's
    number of each of its nodes."""
    tag: str
    instance: tsplib.Instance
    origin: tuple[int, ...]


def variants(inst: tsplib.Instance) -> Iterator[Variant]:
    """The eight decks of ``inst``, in the order of :data:`TAGS`."""
    nodes = inst.nodes
    same = tuple(range(len(nodes)))
    yield Variant("as", inst, same)
    yield Variant("mx", tsplib.Instance(inst.name, inst.kind, inst.optimum,
                                        tuple((-x, y) for x, y in nodes)), same)
    for seed in range(1, 7):
        rest = list(range(1, len(nodes)))
        random.Random(seed).shuffle(rest)
        order = (0, *rest)
        pts = tuple(nodes[k] for k in order)
        yield Variant(f"sh{seed}", tsplib.Instance(inst.name, inst.kind, inst.optimum, pts),
                      order)


@dataclass(frozen=True)
class Run:
    name: str
    tag: str
    length: int
    pct: float
    cpu_ms: float


def run_variant(exe: Path, v: Variant, scratch: Path) -> Run:
    """TENZOR once on the variant's deck: its tour's length and CPU time."""
    where = scratch / f"{v.instance.name}-{v.tag}"
    where.mkdir(parents=True, exist_ok=True)
    deck = tsplib.write_deck(v.instance, where)
    _, cpu = measure.run_once(exe, deck, where / "out")
    length = tsplib.tenzor_length(v.instance, where / "out")
    return Run(v.instance.name, v.tag, length,
               100.0 * (length / v.instance.optimum - 1), 1000.0 * cpu)


def report(runs: list[Run]) -> str:
    """The table of per cents, one line an instance, and the summary."""
    names = list(dict.fromkeys(r.name for r in runs))
    out = io.StringIO()
    out.write(f"{'instance':9s}" + "".join(f"{t:>7s}" for t in TAGS)
              + "   within 1 %   mean   worst   max CPU ms\n")
    for name in names:
        rs = {r.tag: r for r in runs if r.name == name}
        pcts = [r.pct for r in rs.values()]
        out.write(f"{name:9s}"
                  + "".join(f"{rs[t].pct:7.2f}" if t in rs else f"{'-':>7s}" for t in TAGS)
                  + f"   {sum(p <= 1.0 for p in pcts):4d} of {len(pcts):<3d}"
                  + f"{statistics.mean(pcts):7.2f} {max(pcts):7.2f}"
                  + f" {max(r.cpu_ms for r in rs.values()):10.1f}\n")
    pcts = [r.pct for r in runs]
    published = [r.pct for r in runs if r.tag == "as"]
    out.write(f"\nwithin 1 % of the optimum: {sum(p <= 1.0 for p in pcts)} of {len(pcts)} "
              f"decks ({sum(p <= 1.0 for p in published)} of {len(published)} as published); "
              f"mean {statistics.mean(pcts):.2f} % (as published {statistics.mean(published):.2f} %); "
              f"worst {max(pcts):.2f} %\n")
    return out.getvalue()


def write_csv(runs: list[Run]) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["instance", "deck", "length", "pct", "cpu_ms"])
    for r in runs:
        w.writerow([r.name, r.tag, r.length, f"{r.pct:.4f}", f"{r.cpu_ms:.2f}"])
    return buf.getvalue()


def build_parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="python -m bench.variants",
                                 description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tenzor", type=Path, metavar="EXE",
                    help="the TENZOR binary to run (default: this tree's release build, "
                         "as make release makes it)")
    ap.add_argument("--names", default=",".join(tsplib.NAMES),
                    help="TSPLIB instances (default all of bench/tsplib/)")
    ap.add_argument("--out", type=Path, default=Path("out/variants"),
                    help="the results, decks and tapes (default out/variants)")
    return ap


@quiet_when_output_closes
def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    names, problem = tsplib.parse_names("--names", args.names)
    if problem is not None:
        print(f"bench.variants: {problem}", file=sys.stderr)
        return 2
    if args.tenzor is not None and not args.tenzor.is_file():
        print(f"bench.variants: --tenzor {args.tenzor}: no such file", file=sys.stderr)
        return 2
    try:
        exe = args.tenzor.resolve() if args.tenzor else measure.release_binary(ROOT)
    except subprocess.CalledProcessError as exc:
        print(f"bench.variants: the release build failed:\n{exc.stderr.decode(errors='replace')}",
              file=sys.stderr)
        return 2
    runs = []
    for name in names:
        for v in variants(tsplib.load(name)):
            runs.append(run_variant(exe, v, args.out / "scratch"))
        print(f"{name}: " + " ".join(f"{r.tag} {r.pct:.2f}" for r in runs[-len(TAGS):]),
              file=sys.stderr, flush=True)
    text = report(runs)
    args.out.mkdir(parents=True, exist_ok=True)
    write_whole(args.out / "variants.csv", write_csv(runs))
    write_whole(args.out / "variants.txt", text)
    print(text, end="")              # after the files, which a closed output must not lose
    return 0


if __name__ == "__main__":
    sys.exit(main())
