"""Command line of the neighbouring systems: ``python -m seeds SUBCOMMAND ...``.

Each seed module adds its own subcommands (``add_NAME(sub)`` functions,
listed in ``SUBCOMMANDS``).  Exit status: 0 done, 1 the input had errors,
2 usage or I/O.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Sequence

from harness.files import quiet_when_output_closes

from . import gerber, seed001, seed001_dmc, seed002, seed003, seed004, tapereport, ural1
from .options import Parser

#: name -> function adding the subcommand's parser, in the documents' order.
SUBCOMMANDS: dict[str, Callable[[argparse._SubParsersAction], None]] = {
    "dxf2deck": seed001.add_dxf2deck,
    "dxf2dmc": seed001_dmc.add_dxf2dmc,
    "dxfboard": seed001.add_dxfboard,
    "gerber2deck": gerber.add_gerber2deck,
    "tapereport": tapereport.add_tapereport,
    "profile": seed002.add_profile,
    "equidistant": seed002.add_equidistant,
    "punch5121": seed002.add_punch5121,
    "ural1": ural1.add_ural1,
    "cnclink": seed003.add_cnclink,
    "split": seed004.add_split,
    "dda": seed004.add_dda,
}


def build_parser() -> argparse.ArgumentParser:
    """The argument parser with every subcommand of ``SUBCOMMANDS``."""
    parser = Parser(
        prog="python -m seeds",
        description="The neighbouring systems of seeds 001-004 (docs/SOURCES.md)")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for add in SUBCOMMANDS.values():
        add(sub)
    return parser


@quiet_when_output_closes
def main(argv: Sequence[str] | None = None) -> int:
    """Run one subcommand; returns the exit status (2 on a usage error)."""
    parser = build_parser()
    try:
        args, extra = parser.parse_known_args(argv)
        if extra:                      # said by the subcommand, with its own usage line
            sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
            sub.choices[args.command].error(f"unrecognized arguments: {' '.join(extra)}")
    except SystemExit as exc:          # argparse: --help (0) or usage error (2)
        return int(exc.code or 0)
    return int(args.func(args))


if __name__ == "__main__":
    sys.exit(main())
