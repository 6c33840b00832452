"""Option values the seeds' commands share: ``X,Y`` and ``W1,W2,W3`` lists of
millimetres."""
from __future__ import annotations

import math


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
