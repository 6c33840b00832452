"""Valid TENZOR cards, built column by column.

Lengths are given as ``int`` (units of 0.01 mm) or ``Decimal`` (mm, at
most two decimals); ``None`` leaves a field blank (its default).  Real
fields are always written WITH a decimal point, right-justified, so they
read the same under every Fortran blank mode.  Layout: docs/CARDS.md.

The writer only: the random boards that the tests draw from are in the
tests (``harness/tests/strategies.py``), so that the writer needs no test
library.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from decimal import Decimal
from typing import Union

Length = Union[int, Decimal]


# ---------------------------------------------------------------------------
# Fields and cards.
# ---------------------------------------------------------------------------
def units(v: Length) -> int:
    """A length as an integer number of 0.01 mm."""
    if isinstance(v, bool):
        raise TypeError("a length cannot be a bool")
    if isinstance(v, int):
        return v
    if isinstance(v, Decimal):
        u = v * 100
        if u != u.to_integral_value():
            raise ValueError(f"{v} mm is not a whole number of 0.01 mm")
        return int(u)
    raise TypeError(f"a length is an int (0.01 mm) or a Decimal (mm), not {type(v).__name__}")


def real_field(v: Length | None, width: int) -> str:
    """Fw.2 field: e.g. 1250 -> '     12.50' for width 10; None -> blanks."""
    if v is None:
        return " " * width
    u = units(v)
    text = f"{'-' if u < 0 else ''}{abs(u) // 100}.{abs(u) % 100:02d}"
    if len(text) > width:
        raise ValueError(f"{text} does not fit in {width} columns")
    return text.rjust(width)


def int_field(v: int | None, width: int) -> str:
    """Iw field, right-justified; None -> blanks."""
    if v is None:
        return " " * width
    text = str(int(v))
    if len(text) > width:
        raise ValueError(f"{text} does not fit in {width} columns")
    return text.rjust(width)


def _card(*parts: tuple[int, str]) -> str:
    """A card from (first column, text) parts; trailing blanks removed."""
    cols = [" "] * 72
    for col, text in parts:
        for n, ch in enumerate(text):
            if cols[col - 1 + n] != " " and ch != " ":
                raise ValueError(f"column {col + n} written twice")
            cols[col - 1 + n] = ch
    return "".join(cols).rstrip()


def name_card(name: str) -> str:
    """Package name in columns 1-18."""
    if not name.strip() or len(name) > 18 or name[0] in "*# ":
        raise ValueError(f"bad package name {name!r}")
    if name.rstrip() in ("C", "E"):
        raise ValueError(f"package name {name!r}: a bare C or E ends a package, it is no name")
    return _card((1, name))


def p_card(x0: Length | None = None, y0: Length | None = None,
           w1: Length | None = None, w2: Length | None = None, w3: Length | None = None,
           dmax: Length | None = None, scale: tuple[int, int] | None = None,
           code: str | None = None, order: str | None = None) -> str:
    """P card: start point, tools, Dmax, scale, code (8/K), order (O/D)."""
    if code not in (None, "8", "K") or order not in (None, "O", "D"):
        raise ValueError(f"code {code!r} / order {order!r}")
    n, d = scale if scale is not None else (None, None)
    return _card((1, "P"), (11, real_field(x0, 10)), (21, real_field(y0, 10)),
                 (31, real_field(w1, 8)), (39, real_field(w2, 8)),
                 (47, real_field(w3, 8)), (55, real_field(dmax, 8)),
                 (63, int_field(n, 3)), (66, int_field(d, 3)),
                 (70, code or " "), (71, order or " "))


def d_card(x: Length, y: Length, w: Length, h: Length | None = None, n: int | None = None,
           sx: Length | None = None, sy: Length | None = None) -> str:
    """D card: a pad (round if h is None), or a row of n pads at steps sx, sy."""
    return _card((1, "D"), (11, real_field(x, 10)), (21, real_field(y, 10)),
                 (31, real_field(w, 8)), (39, real_field(h, 8)), (47, int_field(n, 4)),
                 (51, real_field(sx, 10)), (61, real_field(sy, 10)))


def l_card(x: Length, y: Length, w: Length | None = None) -> str:
    """L card: first vertex of a conductor of width w (None = w3)."""
    return _card((1, "L"), (11, real_field(x, 10)), (21, real_field(y, 10)),
                 (31, real_field(w, 8)))


def plus_card(x: Length, y: Length) -> str:
    """+ card: next vertex of the open conductor."""
    return _card((1, "+"), (11, real_field(x, 10)), (21, real_field(y, 10)))


def o_card(direction: str, x: Length, y: Length, r: Length) -> str:
    """O card: a circle; direction '+' (clockwise) or '-'."""
    if direction not in ("+", "-"):
        raise ValueError(f"direction {direction!r}")
    return _card((1, "O"), (2, direction), (11, real_field(x, 10)),
                 (21, real_field(y, 10)), (31, real_field(r, 10)))


def a_card(direction: str, xc: Length, yc: Length, xs: Length, ys: Length,
           xe: Length, ye: Length) -> str:
    """A card: an arc about (xc, yc) from (xs, ys) to (xe, ye)."""
    if direction not in ("+", "-"):
        raise ValueError(f"direction {direction!r}")
    return _card((1, "A"), (2, direction),
                 *[(c, real_field(v, 10)) for c, v in
                   zip((11, 21, 31, 41, 51, 61), (xc, yc, xs, ys, xe, ye))])


def m_card(tape: str = "L", x: Length | None = None, y: Length | None = None,
           dx: Length | None = None, dy: Length | None = None,
           cyc: int | None = None, k: int = 10) -> str:
    """M card: one frame for tape 'S', 'B' or 'L' (or ' ', meaning L)."""
    if tape not in ("S", "B", "L", " "):
        raise ValueError(f"tape {tape!r}")
    return _card((1, "M"), (2, tape), (11, real_field(x, 10)), (21, real_field(y, 10)),
                 (31, real_field(dx, 10)), (41, real_field(dy, 10)),
                 (51, int_field(cyc, 5)), (56, int_field(k, 5)))


@dataclass
class CardPackage:
    """A package to punch: its name and its data cards (no C/E card)."""

    name: str
    cards: list[str] = field(default_factory=list)


def deck(packages: list[CardPackage], envelope: bool = True, job: str = "HARNESS") -> str:
    """A whole deck: optional job envelope, the packages separated by C
    cards, the final E, and *END FILE; one card per line."""
    lines: list[str] = []
    if envelope:
        lines += [f"*NAME {job}", "*MAIN TENZOR", "*EXECUTE"]
    for n, pkg in enumerate(packages):
        lines.append(name_card(pkg.name))
        lines += pkg.cards
        lines.append("E" if n == len(packages) - 1 else "C")
    if envelope:
        lines.append("*END FILE")
    for no, line in enumerate(lines, 1):
        if len(line) > 72:
            raise ValueError(f"card {no} is longer than 72 columns")
    return "\n".join(lines) + "\n"
