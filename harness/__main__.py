"""Command line of the oracle: ``python -m harness decode|verify|f77check ...``.

The neighbouring systems have their own (``python -m seeds``), and so have
the benchmarks (``python -m bench``).

Subcommands are listed in ``SUBCOMMANDS``: name -> function that adds the
subparser to argparse and sets ``func`` (the runner, returning an exit
status).  To add one, write ``_add_NAME(sub)`` and a runner, and add it to
the dict.  Exit status: 0 done, 1 the input had errors, 2 usage or I/O.
"""

from __future__ import annotations

import argparse
import functools
import sys
from collections.abc import Callable, Sequence
from pathlib import Path

from . import f77check, tape, verify
from .files import quiet_when_output_closes


def _write(text: str, stream=None) -> None:
    """Write UTF-8 whatever the locale says (the utf8 text has Cyrillic)."""
    stream = stream or sys.stdout
    stream.flush()
    buffer = getattr(stream, "buffer", None)
    if buffer is not None:
        buffer.write(text.encode("utf-8"))
        buffer.flush()
    else:
        stream.write(text)


def _run_decode(args: argparse.Namespace) -> int:
    path = Path(args.tape)
    try:
        data = path.read_bytes()
    except OSError as exc:
        print(f"{args.tape}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    try:
        decoded = tape.decode(data, args.code)
    except tape.TapeError as exc:
        print(f"{args.tape}: {exc}", file=sys.stderr)
        return 1
    _write(tape.tape_text(decoded, utf8=args.utf8))
    return 0


def _add_decode(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("decode", help="decode and check an EM-703 tape image",
                       description="Print the frame text of a .ptp tape image, "
                                   "or the first error with its row number. Exit "
                                   "status: 0 decoded, 1 a tape error, 2 usage or I/O.")
    p.add_argument("tape", metavar="TAPE.ptp", help="tape image, one byte per row")
    p.add_argument("--code", choices=("8", "K", "auto"), default="auto",
                   help="code variant: 8 plain, K with control, auto (default)")
    p.add_argument("--utf8", action="store_true",
                   help="print the report's symbols (ΔX ΔY Ц К КК ГМ)")
    p.set_defaults(func=_run_decode)


def _run_f77check(args: argparse.Namespace) -> int:
    return f77check.main(args.dir, write_common=args.write_common, index=args.index)


def _add_f77check(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("f77check", help="check the FORTRAN 77 sources (legacy/README.md)",
                       description="Check every *.f file under DIR against the FORTRAN 77 "
                                   "rules of legacy/README.md, and, when DIR/COMMON.inc "
                                   "exists, every COMMON copy against it.")
    p.add_argument("dir", nargs="?", default="legacy", metavar="DIR",
                   help="directory to check (default: legacy)")
    p.add_argument("--write-common", action="store_true",
                   help="first write every COMMON copy from DIR/COMMON.inc")
    p.add_argument("--index", action="store_true",
                   help="first write the index of DIR/README.md from the routines")
    p.set_defaults(func=_run_f77check)


def _run_verify(args: argparse.Namespace) -> int:
    return verify.main(args.deck, args.tapedir, args.tolerance, args.code)


def _add_verify(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("verify", help="check anyone's tapes against a deck",
                       description="Check the tapes NAME-small.ptp, NAME-large.ptp and "
                                   "NAME-cond.ptp of each package of DECK, found in "
                                   "TAPEDIR, against the deck's geometry: decoding, "
                                   "the return to the start point, the field, and the "
                                   "drawing within the tolerance. Prints PASS, or FAIL "
                                   "with each reason. Exit status: 0 PASS, 1 FAIL, "
                                   "2 usage or I/O.")
    p.add_argument("deck", metavar="DECK", help="the card deck (.crd)")
    p.add_argument("tapedir", metavar="TAPEDIR", help="directory holding the tapes")
    p.add_argument("--tolerance", default="0.05", metavar="MM",
                   help="coverage tolerance in mm (default 0.05, the machine's accuracy)")
    p.add_argument("--code", choices=("8", "K", "auto"), default="auto",
                   help="require this code variant (default: detect it from each tape)")
    p.set_defaults(func=_run_verify)


#: name -> function adding the subcommand's parser.
SUBCOMMANDS: dict[str, Callable[[argparse._SubParsersAction], None]] = {
    "decode": _add_decode,
    "f77check": _add_f77check,
    "verify": _add_verify,
}


def build_parser() -> argparse.ArgumentParser:
    """The argument parser with every subcommand of ``SUBCOMMANDS``."""
    # abbreviations off (--tol is not --tolerance): an option is its whole name
    parser = argparse.ArgumentParser(prog="python -m harness", allow_abbrev=False,
                                     description="The EM-703 oracle: decode a tape, verify tapes against a deck, check the FORTRAN 77 of legacy/")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True,
                                parser_class=functools.partial(argparse.ArgumentParser,
                                                               allow_abbrev=False))
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
