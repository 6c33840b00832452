"""What the seeds' commands share in reading their options: the parser, and
``X,Y`` and ``W1,W2,W3`` lists of millimetres."""
from __future__ import annotations

import argparse
import math


class Parser(argparse.ArgumentParser):
    """argparse's parser with its abbreviations off (``--tol`` is not
    ``--tolerance``): an option is taken only by its whole name, as em703
    takes them, so an option added later cannot change what a command line
    meant.  The subcommands' parsers are of the same class."""

    def __init__(self, *args, **kwargs) -> None:
        kwargs.setdefault("allow_abbrev", False)
        super().__init__(*args, **kwargs)


def mm_list(text: str, option: str, n: int) -> tuple[float, ...]:
    """``n`` finite numbers of mm separated by commas; ValueError naming the
    option otherwise."""
    try:
        vals = tuple(float(v) for v in text.split(","))
    except ValueError:
        vals = ()
    if len(vals) != n or not all(math.isfinite(v) for v in vals):
        raise ValueError(f"{option} {text}: {n} finite numbers of mm separated by commas")
    return vals
