"""FORTRAN 77 checker for ``legacy/`` (the rules: legacy/README.md).

Checks every ``*.f`` file under a directory (hidden and ``build``
directories are skipped) against the rules in ``RULES``; each message names
its rule.  Use ``check_dir(path)`` or ``python -m harness f77check [DIR]``.

FORTRAN 77 has no INCLUDE, so every routine carries its own copy of the
COMMON blocks it uses.  When the directory holds a master text
(``COMMON.inc``: each block under a ``C     ---- /NAME/ ...`` line, as the
FORTRAN statements themselves), every copy must be that text line for line
(``F77-COMMON``), and ``--write-common`` writes the copies from it.  Without
a master, copies of a block are compared with each other by their variables.

The reader follows fixed form (ANSI X3.9-1978, section 3): a line with C or *
in column 1 is a comment; columns 1-5 hold a label, column 6 a continuation
mark (anything but blank or zero), columns 7-72 the statement.  A statement
is its initial line joined with its continuation lines; blanks outside
character constants are insignificant, so keywords are matched on the
statement with blanks removed ("END DO" and "ENDDO" alike).  Character
constants are '...' with '' for a quote; Hollerith constants are not
supported (the re-creation does not use them).  Symbolic names are collected
from declarations (type, DIMENSION, COMMON, PARAMETER, EXTERNAL, INTRINSIC,
SAVE), program unit headers, CALL and ENTRY, and from the expressions of
assignments, IF conditions, DO controls and CALL arguments (the intrinsic
functions of Fortran 90 are looked for in every statement but FORMAT); the
gfortran step (``F77-DECL``) makes sure every variable is declared.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from .files import write_whole

#: The rules: id -> what it requires.  Every message names one of these ids.
RULES: dict[str, str] = {
    "F77-BLANK": "no blank lines: a card deck has no blank cards (use a C comment)",
    "F77-COL72": "nothing beyond column 72 (columns 73-80 are the sequence field)",
    "F77-TAB": "no tab characters",
    "F77-CHARSET": "only the FORTRAN 77 character set in statements; ASCII "
                   "printable characters only anywhere",
    "F77-LOWER": "no lower-case letters outside character constants and comments",
    "F77-COMMENT": "comment lines have C or * in column 1",
    "F77-LABEL": "columns 1-5 hold only a label (digits, not zero), and only "
                 "on an initial line",
    "F77-CONT": "continuation: a FORTRAN 77 character in column 6, after an "
                "initial line, at most 19 continuation lines",
    "F77-STMT": "an initial line has a statement in columns 7-72",
    "F77-F90": "no Fortran 90 constructs (::, !, ;, \", ==, /=, <, >, _, %, &, "
               "END DO, DO WHILE, labelless DO, MODULE, USE, CONTAINS, "
               "ALLOCATE, INTENT, INTERFACE, SELECT CASE, INCLUDE, EXIT, "
               "CYCLE, KIND=, END SUBROUTINE ...)",
    "F77-EXT": "no vendor extensions (INTEGER*4, REAL*8, DOUBLE COMPLEX, "
               "NAMELIST, ...); IMPLICIT NONE is the only extension",
    "F77-NAME": "symbolic names have at most 6 characters",
    "F77-IMPLICIT": "every program unit has IMPLICIT NONE and no other IMPLICIT",
    "F77-UNIT": "one named program unit per file, ending in END, in a file "
                "named after it in lower case (MTFILL in mtfill.f)",
    "F77-COMMON": "a named COMMON block is declared identically in every unit "
                  "that uses it: a copy of its master text in COMMON.inc, line "
                  "for line (without a master: the same variables, types and "
                  "dimensions)",
    "F77-BLKCOM": "no blank COMMON",
    "F77-PARAM": "a PARAMETER constant has the same type and value in every unit",
    "F77-INTRINSIC": "only the intrinsic functions of FORTRAN 77 (no FLOOR, "
                     "MODULO, IAND, IACHAR, SIZE, HUGE, ...: gfortran -std=legacy "
                     "takes them, so the checker looks for them)",
    "F77-DECL": "every variable is declared (gfortran: 'has no IMPLICIT type')",
    "F77-INDEX": "the index of the directory's README.md is the one the routines give",
    "F77-BLOCKDATA": "no BLOCK DATA (a BLOCK DATA in a library reaches the program only "
                     "if the linker pulls it in: GNU ld does, gold does not)",
    "F77-STOP": "no STOP or PAUSE: no routine stops the run (errors go through CMERR)",
    "F77-SAVE": "every COMMON block of the master text is SAVEd in its section",
    "F77-HEADER": "a routine's header (with a README index): 'C     NAME - what it "
                  "does (PROGRAM)' in its first lines, the program its prefix says, "
                  "SOURCE: and CHANGES:, and 'C     END OF NAME' before its END",
    "F77-LAYER": "a shared routine (CM) calls no routine of one program (TZ, MT, ML)",
    "F77-COMPILE": "the file compiles (other gfortran -fsyntax-only errors)",
}

MAX_NAME = 6
MAX_CONTINUATIONS = 19
STATEMENT_WIDTH = 66                       # columns 7-72
#: The FORTRAN 77 character set (X3.9-1978, 3.1.1), upper case.
F77_CHARS = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 =+-*/(),.$':")
#: Characters outside it that mark Fortran 90 (or later) source.
F90_CHARS: dict[str, str] = {
    ";": "';' statement separator",
    "<": "relational operator '<' (use .LT. or .LE.)",
    ">": "relational operator '>' (use .GT. or .GE.)",
    "_": "'_' in a name",
    "%": "'%' component selector",
    "&": "'&' continuation",
}
#: Intrinsic functions of Fortran 90 and later that FORTRAN 77 does not have
#: (its own are in table 5 of the standard); gfortran -std=legacy takes them
#: all, so the checker looks for them itself.
F90_INTRINSICS: frozenset[str] = frozenset("""
    ACHAR ADJUSTL ADJUSTR ALL ALLOCATED ANY ASSOCIATED BIT_SIZE BTEST CEILING
    COUNT CSHIFT DIGITS DOT_PRODUCT EOSHIFT EPSILON EXPONENT FLOOR FRACTION HUGE
    IACHAR IAND IBCLR IBITS IBSET IEOR IOR ISHFT ISHFTC KIND LBOUND LEN_TRIM
    LOGICAL MATMUL MAXEXPONENT MAXLOC MAXVAL MERGE MINEXPONENT MINLOC MINVAL
    MODULO NEAREST NOT NULL PACK PRECISION PRESENT PRODUCT RADIX RANGE REPEAT
    RESHAPE RRSPACING SCALE SCAN SELECTED_INT_KIND SELECTED_REAL_KIND
    SET_EXPONENT SHAPE SIZE SPACING SPREAD SUM TINY TRANSFER TRANSPOSE TRIM
    UBOUND UNPACK VERIFY ERF ERFC GAMMA HYPOT NORM2 POPCNT NEW_LINE
    """.split())
F90_PAIRS: dict[str, str] = {
    "::": "'::' in a declaration",
    "==": "relational operator '==' (use .EQ.)",
    "/=": "relational operator '/=' (use .NE.)",
}
#: Statements (blanks removed) that are Fortran 90: pattern -> construct.
F90_STATEMENTS: list[tuple[re.Pattern[str], str]] = [
    (re.compile(r"DO(\d+,?)?WHILE\("), "DO WHILE"),
    (re.compile(r"DO\d*$"), "DO without a loop control"),
    (re.compile(r"MODULE"), "MODULE"),
    (re.compile(r"USE"), "USE"),
    (re.compile(r"CONTAINS$"), "CONTAINS"),
    (re.compile(r"(DE)?ALLOCATE\("), "ALLOCATE"),
    (re.compile(r"INTENT\("), "INTENT"),
    (re.compile(r"(ABSTRACT)?INTERFACE"), "INTERFACE"),
    (re.compile(r"SELECTCASE\("), "SELECT CASE"),
    (re.compile(r"CASE(\(|DEFAULT$)"), "CASE"),
    (re.compile(r"INCLUDE\x01"), "INCLUDE"),
    (re.compile(r"EXIT([A-Z][A-Z0-9_]*)?$"), "EXIT"),
    (re.compile(r"CYCLE([A-Z][A-Z0-9_]*)?$"), "CYCLE"),
    (re.compile(r"WHERE\("), "WHERE"),
    (re.compile(r"FORALL\("), "FORALL"),
]
#: Statements (blanks removed) that are vendor extensions.
EXT_STATEMENTS: list[tuple[re.Pattern[str], str]] = [
    (re.compile(r"DOUBLECOMPLEX"), "DOUBLE COMPLEX"),
    (re.compile(r"NAMELIST/"), "NAMELIST"),
    (re.compile(r"BYTE[A-Z]"), "BYTE"),
    (re.compile(r"POINTER\("), "Cray POINTER"),
    (re.compile(r"STRUCTURE/"), "STRUCTURE"),
    (re.compile(r"RECORD/"), "RECORD"),
    (re.compile(r"(AUTOMATIC|STATIC)[A-Z]"), "AUTOMATIC/STATIC"),
]
_END_F90 = re.compile(r"END(DO|SUBROUTINE|FUNCTION|PROGRAM|BLOCKDATA|MODULE|"
                      r"INTERFACE|SELECT|TYPE|WHERE|FORALL)")
_NAME = r"[A-Z][A-Z0-9_]*"
_TYPE = re.compile(r"(INTEGER|REAL|DOUBLEPRECISION|COMPLEX|LOGICAL|CHARACTER)")
_LEN = re.compile(r"\*(\d+|\([^()]*\))")
_HEADERS: list[tuple[re.Pattern[str], str]] = [
    (re.compile(rf"PROGRAM({_NAME})$"), "PROGRAM"),
    (re.compile(rf"SUBROUTINE({_NAME})(\(.*\))?$"), "SUBROUTINE"),
    (re.compile(rf"(?:INTEGER|REAL|DOUBLEPRECISION|COMPLEX|LOGICAL|"
                rf"CHARACTER(?:\*(?:\d+|\(\*\)))?)?FUNCTION({_NAME})(\(.*\))$"),
     "FUNCTION"),
    (re.compile(rf"BLOCKDATA({_NAME})?$"), "BLOCK DATA"),
]
_DO = re.compile(rf"DO(\d*),?({_NAME})=")
_DOTTED = re.compile(r"\.[A-Z]+\.")
_EXPR_NAME = re.compile(r"(?<![A-Z0-9.])[A-Z][A-Z0-9_]*")
_GFORTRAN_MSG = re.compile(r"^(?P<file>.*?):(?P<line>\d+):(?P<col>\d+): "
                           r"(?P<kind>Fatal Error|Error|Warning): (?P<msg>.*)$")


@dataclass(frozen=True, order=True)
class Violation:
    """One broken rule at a place in a file (line and column 1-based)."""

    path: str
    line: int
    col: int
    rule: str
    message: str

    def __str__(self) -> str:
        return f"{self.path}:{self.line}:{self.col}: {self.rule}: {self.message}"


# ---------------------------------------------------------------------------
# Small text helpers on statements with blanks removed.
# ---------------------------------------------------------------------------
def _match_paren(s: str, i: int) -> int:
    """Index of the ')' closing the '(' at s[i], or -1."""
    depth = 0
    for j in range(i, len(s)):
        if s[j] == "(":
            depth += 1
        elif s[j] == ")":
            depth -= 1
            if depth == 0:
                return j
    return -1


def _split_top(s: str, start: int, end: int) -> list[tuple[int, int]]:
    """Ranges of s[start:end] between commas at parenthesis depth 0."""
    out: list[tuple[int, int]] = []
    depth, a = 0, start
    for j in range(start, end):
        if s[j] == "(":
            depth += 1
        elif s[j] == ")":
            depth -= 1
        elif s[j] == "," and depth == 0:
            out.append((a, j))
            a = j + 1
    out.append((a, end))
    return [(a, b) for a, b in out if b > a]


def _top_index(s: str, ch: str, start: int = 0) -> int:
    """Index of the first ``ch`` at parenthesis depth 0 from start, or -1."""
    depth = 0
    for j in range(start, len(s)):
        if s[j] == "(":
            depth += 1
        elif s[j] == ")":
            depth -= 1
        elif s[j] == ch and depth == 0:
            return j
    return -1


def _norm_len(text: str) -> str:
    """CHARACTER length: '(80)' -> '80', '(*)' and '(MAXL)' stay."""
    inner = text[1:-1] if text.startswith("(") and text.endswith(")") else text
    return inner if inner.isdigit() else text


# ---------------------------------------------------------------------------
# Statements and program units.
# ---------------------------------------------------------------------------
@dataclass
class _Statement:
    """One statement: its characters (columns 7-72 of its lines) and, after
    lexing, ``s``: upper case, blanks and string contents removed (each
    character constant is one \\x01)."""

    label: str
    line: int
    chars: list[str] = field(default_factory=list)
    pos: list[tuple[int, int]] = field(default_factory=list)
    last_line: int = 0
    last_len: int = 0
    continuations: int = 0
    s: str = ""
    smap: list[int] = field(default_factory=list)
    strings: dict[int, str] = field(default_factory=dict)

    def add(self, line: int, text: str) -> None:
        if self.chars or self.last_line:            # pad the previous line to col 72
            for j in range(self.last_len, STATEMENT_WIDTH):
                self.chars.append(" ")
                self.pos.append((self.last_line, 7 + j))
        for j, ch in enumerate(text):
            self.chars.append(ch)
            self.pos.append((line, 7 + j))
        self.last_line, self.last_len = line, len(text)

    def at(self, si: int) -> tuple[int, int]:
        """(line, column) of index ``si`` of ``s``."""
        if not self.smap:
            return self.line, 7
        return self.pos[self.smap[min(max(si, 0), len(self.smap) - 1)]]

    def text(self, a: int, b: int) -> str:
        """s[a:b] with its character constants put back."""
        return "".join(self.strings.get(j, self.s[j]) for j in range(a, b))


@dataclass
class _Unit:
    kind: str
    name: str | None
    line: int
    col: int
    implicit_none: bool = False
    types: dict[str, str] = field(default_factory=dict)
    dims: dict[str, str] = field(default_factory=dict)
    commons: dict[str, tuple[int, int, list[str]]] = field(default_factory=dict)
    common_lines: list[tuple[str, int]] = field(default_factory=list)  # block, line
    params: list[tuple[str, str, int, int]] = field(default_factory=list)


@dataclass
class _FileResult:
    display: str
    units: list[_Unit]
    violations: list[Violation]


class _FileChecker:
    """Checks one file; collects its units for the checks across files."""

    def __init__(self, path: Path, display: str) -> None:
        self.path = path
        self.display = display
        self.violations: list[Violation] = []
        self._seen: set[tuple[int, str, str]] = set()
        self._names: set[str] = set()
        self.units: list[_Unit] = []
        self.unit: _Unit | None = None

    def add(self, line: int, col: int, rule: str, message: str) -> None:
        key = (line, rule, message)
        if key not in self._seen:
            self._seen.add(key)
            self.violations.append(Violation(self.display, line, col, rule, message))

    # -- lines ---------------------------------------------------------------
    def run(self) -> _FileResult:
        text = self.path.read_bytes().decode("latin-1")
        lines = text.split("\n")
        if lines and lines[-1] == "":
            lines.pop()
        statements: list[_Statement] = []
        current: _Statement | None = None
        for n, raw in enumerate(lines, 1):
            if raw.strip(" ") == "":
                self.add(n, 1, "F77-BLANK", "blank line (use a comment line with C "
                                            "in column 1)")
                continue
            if len(raw) > 72:
                self.add(n, 73, "F77-COL72", f"line has {len(raw)} characters; "
                                             "columns 73-80 must be blank")
            if "\t" in raw:
                self.add(n, raw.index("\t") + 1, "F77-TAB", "tab character")
            for j, ch in enumerate(raw):
                if (ord(ch) < 32 and ch != "\t") or ord(ch) > 126:
                    self.add(n, j + 1, "F77-CHARSET",
                             f"character {ch!r} is not printable ASCII")
                    break
            c1 = raw[0]
            if c1 in "C*":
                continue
            if c1 in "c!":
                self.add(n, 1, "F77-COMMENT", f"comment line starts with {c1!r}; "
                                              "use C or * in column 1")
                continue
            card = raw[:72]
            labels, mark, body = card[:5], card[5:6] or " ", card[6:]
            if mark not in " 0":                       # continuation line
                if labels.strip(" \t"):
                    col = next(j for j, ch in enumerate(labels) if ch not in " \t") + 1
                    self.add(n, col, "F77-LABEL", "continuation line has text in "
                                                  "columns 1-5")
                if mark not in F77_CHARS:
                    self.add(n, 6, "F77-CONT", f"continuation mark {mark!r} is not "
                                               "a FORTRAN 77 character")
                if current is None:               # dropped: nothing to join it to
                    self.add(n, 6, "F77-CONT", "continuation line with no "
                                               "statement to continue")
                    continue
                else:
                    current.continuations += 1
                    if current.continuations == MAX_CONTINUATIONS + 1:
                        self.add(n, 6, "F77-CONT", "more than "
                                 f"{MAX_CONTINUATIONS} continuation lines")
                current.add(n, body)
                continue
            misplaced = False
            for j, ch in enumerate(labels):
                if ch not in " 0123456789\t":
                    self.add(n, j + 1, "F77-LABEL",
                             f"{ch!r} in column {j + 1}: columns 1-5 hold only a "
                             "label; statements start in column 7")
                    misplaced = True
                    break
            label = "".join(ch for ch in labels if ch.isdigit())
            if label and int(label) == 0:
                self.add(n, 1, "F77-LABEL", "label 0 is not allowed")
            if not body.strip(" \t") and not misplaced:
                self.add(n, 7, "F77-STMT", "initial line without a statement in "
                                           "columns 7-72")
            current = _Statement(label=label, line=n)
            current.add(n, body)
            statements.append(current)
        for st in statements:
            self._lex(st)
            self._statement(st)
        self._close_unit(at_eof=True)
        self._file_checks()
        return _FileResult(self.display, self.units, self.violations)

    # -- lexing --------------------------------------------------------------
    def _lex(self, st: _Statement) -> None:
        chars, pos = st.chars, st.pos
        out: list[str] = []
        lower_lines: set[int] = set()
        i, n = 0, len(chars)
        while i < n:
            ch = chars[i]
            line, col = pos[i]
            if ch == " ":
                i += 1
                continue
            if ch in "'\"":
                if ch == '"':
                    self.add(line, col, "F77-F90", "double-quoted string "
                                                   "(use '...')")
                j = i + 1
                while j < n:
                    if chars[j] == ch:
                        if j + 1 < n and chars[j + 1] == ch:
                            j += 2
                            continue
                        break
                    j += 1
                st.strings[len(out)] = "".join(chars[i:j + 1])
                out.append("\x01")
                st.smap.append(i)
                i = j + 1
                continue
            if ch == "!":
                self.add(line, col, "F77-F90", "'!' comment")
                while i < n and pos[i][0] == line:
                    i += 1
                continue
            up = ch
            if "a" <= ch <= "z":
                if line not in lower_lines:
                    lower_lines.add(line)
                    self.add(line, col, "F77-LOWER", f"lower-case letter {ch!r} "
                                                     "outside a character constant")
                up = ch.upper()
            elif ch in F90_CHARS:
                self.add(line, col, "F77-F90", F90_CHARS[ch])
            elif ch not in F77_CHARS:
                if 32 <= ord(ch) < 127:
                    self.add(line, col, "F77-CHARSET", f"character {ch!r} is not "
                                                       "in the FORTRAN 77 character set")
                i += 1                 # (non-printable: reported on its line)
                continue
            out.append(up)
            st.smap.append(i)
            i += 1
        st.s = "".join(out)
        for pair, message in F90_PAIRS.items():
            k = st.s.find(pair)
            while k >= 0:
                self.add(*st.at(k), "F77-F90", message)
                k = st.s.find(pair, k + len(pair))

    # -- names ---------------------------------------------------------------
    def _name(self, st: _Statement, si: int, name: str, what: str) -> None:
        if len(name) > MAX_NAME and name not in self._names:
            self._names.add(name)
            self.add(*st.at(si), "F77-NAME", f"{what} {name} has {len(name)} "
                                             f"characters (at most {MAX_NAME})")

    def _expr_names(self, st: _Statement, a: int, b: int, names: bool = True) -> None:
        """The names of s[a:b]: at most six characters (with ``names``), no
        intrinsic function of Fortran 90, no array constructor."""
        masked = _DOTTED.sub(lambda m: " " * len(m.group()), st.s[a:b])
        unit = self.unit
        for m in _EXPR_NAME.finditer(masked):
            name = m.group()
            if names:
                self._name(st, a + m.start(), name, "name")
            if (name in F90_INTRINSICS and masked[m.end():m.end() + 1] == "("
                    and unit is not None and name not in unit.types
                    and name not in unit.dims):
                self.add(*st.at(a + m.start()), "F77-INTRINSIC",
                         f"{name} is an intrinsic function of Fortran 90, not of "
                         "FORTRAN 77")
        k = masked.find("(/")
        if k >= 0:
            self.add(*st.at(a + k), "F77-F90", "array constructor (/ ... /)")

    # -- units ---------------------------------------------------------------
    def _open_unit(self, kind: str, name: str | None, st: _Statement) -> None:
        if self.unit is not None:
            self.add(st.line, 7, "F77-UNIT", f"{kind} starts before the END of "
                                             f"{self.unit.kind} {self.unit.name}")
            self._close_unit()
        line, col = st.at(0)
        self.unit = _Unit(kind=kind, name=name, line=line, col=col)
        self.units.append(self.unit)

    def _close_unit(self, at_eof: bool = False) -> None:
        unit = self.unit
        if unit is None:
            return
        if at_eof:
            self.add(unit.line, unit.col, "F77-UNIT",
                     f"{unit.kind} {unit.name or '(unnamed)'} has no END statement")
        if not unit.implicit_none:
            self.add(unit.line, unit.col, "F77-IMPLICIT",
                     f"{unit.kind} {unit.name or '(unnamed)'} has no IMPLICIT NONE")
        self.unit = None

    def _file_checks(self) -> None:
        if not self.units:
            self.add(1, 1, "F77-UNIT", "no program unit in this file")
            return
        for unit in self.units[1:]:
            self.add(unit.line, unit.col, "F77-UNIT",
                     f"second program unit {unit.name or '(unnamed)'} in this "
                     "file (one program unit per file)")
        first = self.units[0]
        if first.name is None:
            self.add(first.line, first.col, "F77-UNIT",
                     f"{first.kind} has no name, so the file cannot be named after it")
            return
        want = first.name.lower() + ".f"
        if self.path.name != want:
            self.add(first.line, first.col, "F77-UNIT",
                     f"file is named {self.path.name}; {first.kind} {first.name} "
                     f"belongs in {want}")

    # -- statements ----------------------------------------------------------
    def _statement(self, st: _Statement) -> None:
        s = st.s
        if not s:
            return
        for pattern, kind in _HEADERS:
            m = pattern.match(s)
            if m:
                name = m.group(1)
                self._open_unit(kind, name, st)
                if kind == "BLOCK DATA":
                    self.add(*st.at(0), "F77-BLOCKDATA", "BLOCK DATA: set the block's "
                             "values in a routine the program calls first (as TZCODE "
                             "sets the tape code)")
                if name:
                    self._name(st, m.start(1), name, kind)
                if m.lastindex and m.lastindex >= 2 and m.group(2):
                    a, b = m.start(2) + 1, m.end(2) - 1
                    for x, y in _split_top(s, a, b):
                        if re.fullmatch(_NAME, s[x:y]):
                            self._name(st, x, s[x:y], "dummy argument")
                return
        if self.unit is None:
            self._open_unit("main program", None, st)
        self._body(st, 0)

    def _body(self, st: _Statement, off: int) -> None:
        s = st.s
        t = s[off:]
        unit = self.unit
        assert unit is not None
        m = re.match(r"(ELSE)?IF\(", t)
        if m:
            p = off + m.end() - 1
            c = _match_paren(s, p)
            if c > 0 and (c + 1 == len(s) or s[c + 1] != "="):
                self._expr_names(st, p + 1, c)
                rest = s[c + 1:]
                if rest and rest != "THEN" and not rest[0].isdigit():
                    self._body(st, c + 1)
                return
        eq = _top_index(s, "=", off)
        if eq >= 0 and "::" not in t:
            target = re.compile(_NAME).match(s, off)
            declared = target is not None and target.group() in unit.types
            if t.startswith("PARAMETER") and not t.startswith("PARAMETER(") \
                    and not declared:
                self.add(*st.at(off), "F77-EXT", "PARAMETER without parentheses")
                return
            if _TYPE.match(t) and not declared:
                self.add(*st.at(off), "F77-F90", "initialisation in a type "
                                                "statement (use PARAMETER or DATA)")
                return
            m = _DO.match(t)
            if m and _top_index(s, ",", eq + 1) >= 0:
                if not m.group(1):
                    self.add(*st.at(off), "F77-F90", "DO without a statement label "
                                                    "(DO ... END DO)")
                self._expr_names(st, off + m.start(2), len(s))
                return
            self._expr_names(st, off, len(s))      # assignment or statement function
            return
        if t == "END":
            self._close_unit()
            return
        m = re.match(r"(STOP|PAUSE)(?![A-Z])", t)
        if m:
            self.add(*st.at(off), "F77-STOP", f"{m.group(1)}: a routine does not stop the "
                     "run; an error of the input goes through CMERR, and the package goes on "
                     "or is stopped by its caller")
            return
        m = _END_F90.match(t)
        if m:
            self.add(*st.at(off), "F77-F90", f"END {m.group(1)}")
            if m.group(1) in ("SUBROUTINE", "FUNCTION", "PROGRAM", "BLOCKDATA"):
                self._close_unit()
            return
        for pattern, construct in F90_STATEMENTS:
            if pattern.match(t):
                self.add(*st.at(off), "F77-F90", construct)
                return
        for pattern, construct in EXT_STATEMENTS:
            if pattern.match(t):
                self.add(*st.at(off), "F77-EXT", construct)
                return
        if t.startswith("IMPLICIT"):
            if t == "IMPLICITNONE":
                unit.implicit_none = True
            else:
                self.add(*st.at(off), "F77-IMPLICIT", "IMPLICIT other than "
                                                     "IMPLICIT NONE")
            return
        m = _TYPE.match(t)
        if m:
            self._type_statement(st, off, m.group(1))
            return
        for keyword, handler in (("DIMENSION", self._dimension),
                                 ("COMMON", self._common),
                                 ("PARAMETER(", self._parameter),
                                 ("EXTERNAL", self._name_list),
                                 ("INTRINSIC", self._name_list),
                                 ("SAVE", self._name_list),
                                 ("CALL", self._call),
                                 ("ENTRY", self._call)):
            if t.startswith(keyword):
                handler(st, off, off + len(keyword))
                return
        if not t.startswith("FORMAT("):     # READ, WRITE, PRINT, GO TO (...), ...:
            self._expr_names(st, off, len(s), names=False)    # their functions

    def _type_statement(self, st: _Statement, off: int, keyword: str) -> None:
        s = st.s
        unit = self.unit
        assert unit is not None
        type_name = "DOUBLE PRECISION" if keyword == "DOUBLEPRECISION" else keyword
        i = off + len(keyword)
        length = "1"
        if s.startswith("*", i):
            m = _LEN.match(s, i)
            if m:
                length = _norm_len(m.group(1))
                i = m.end()
                if keyword != "CHARACTER":
                    self.add(*st.at(off), "F77-EXT",
                             f"{type_name}*{length} is not FORTRAN 77")
        elif s.startswith("(", i):
            c = _match_paren(s, i)
            selector = s[i:c + 1] if c > 0 else s[i:]
            self.add(*st.at(i), "F77-F90", f"kind or length selector {selector}"
                     + (" (KIND=)" if "KIND=" in selector else ""))
            i = c + 1 if c > 0 else len(s)
        if "::" in s[i:]:
            attributes = s[i:s.index("::", i)]
            if "INTENT(" in attributes:
                self.add(*st.at(i), "F77-F90", "INTENT")
            i = s.index("::", i) + 2
        for a, b in _split_top(s, i, len(s)):
            self._entity(st, a, b, type_name, length)

    def _entity(self, st: _Statement, a: int, b: int, type_name: str | None,
                length: str = "1") -> str | None:
        """Declare one entity ``NAME[(dims)][*len]`` of s[a:b]; returns NAME."""
        s = st.s
        unit = self.unit
        assert unit is not None
        m = re.compile(_NAME).match(s, a, b)
        if not m:
            return None
        name = m.group()
        self._name(st, a, name, "name")
        i = m.end()
        if i < b and s[i] == "(":
            c = _match_paren(s[:b], i)
            if c > 0:
                unit.dims[name] = s[i:c + 1]
                i = c + 1
        if type_name is not None:
            if type_name == "CHARACTER":
                lm = _LEN.match(s[:b], i)
                if lm:
                    length = _norm_len(lm.group(1))
                unit.types[name] = f"CHARACTER*{length}"
            else:
                unit.types[name] = type_name
        return name

    def _dimension(self, st: _Statement, off: int, i: int) -> None:
        for a, b in _split_top(st.s, i, len(st.s)):
            self._entity(st, a, b, None)

    def _common(self, st: _Statement, off: int, i: int) -> None:
        s = st.s
        unit = self.unit
        assert unit is not None
        block = ""
        while i < len(s):
            if s[i] == "/":
                j = s.find("/", i + 1)
                if j < 0:
                    return
                block = s[i + 1:j]
                if block:
                    self._name(st, i + 1, block, "COMMON block")
                i = j + 1
            end = len(s)
            depth = 0
            for j in range(i, len(s)):
                depth += {"(": 1, ")": -1}.get(s[j], 0)
                if s[j] == "/" and depth == 0:
                    end = j
                    break
            if not block:
                self.add(*st.at(i), "F77-BLKCOM", "blank COMMON (name every "
                                                  "COMMON block)")
            line, col = st.at(off)
            if block:
                unit.common_lines.append((block, line))
            entry = unit.commons.setdefault(block, (line, col, []))
            for a, b in _split_top(s, i, end):
                name = self._entity(st, a, b, None)
                if name:
                    entry[2].append(name)
            i = end

    def _parameter(self, st: _Statement, off: int, i: int) -> None:
        s = st.s
        unit = self.unit
        assert unit is not None
        c = _match_paren(s, i - 1)
        end = c if c > 0 else len(s)
        for a, b in _split_top(s, i, end):
            eq = s.find("=", a, b)
            if eq < 0:
                continue
            name = s[a:eq]
            self._name(st, a, name, "PARAMETER")
            self._expr_names(st, eq + 1, b)
            line, col = st.at(a)
            unit.params.append((name, st.text(eq + 1, b), line, col))

    def _name_list(self, st: _Statement, off: int, i: int) -> None:
        s = st.s
        for a, b in _split_top(s, i, len(s)):
            if re.fullmatch(_NAME, s[a:b]):
                self._name(st, a, s[a:b], "name")

    def _call(self, st: _Statement, off: int, i: int) -> None:
        s = st.s
        m = re.compile(_NAME).match(s, i)
        if not m:
            return
        self._name(st, i, m.group(), "procedure")
        if m.end() < len(s) and s[m.end()] == "(":
            self._expr_names(st, m.end(), len(s))


# ---------------------------------------------------------------------------
# Checks across files.
# ---------------------------------------------------------------------------
def _signature(unit: _Unit, block: str) -> list[str]:
    return [f"{v} {unit.types.get(v, 'untyped')}{unit.dims.get(v, '')}"
            for v in unit.commons[block][2]]


def _cross_checks(results: list[_FileResult], commons: bool = True) -> list[Violation]:
    """PARAMETERs (and, with ``commons``, the COMMON blocks) of all files
    compared with the first file that has them."""
    out: list[Violation] = []
    seen: dict[str, tuple[str, int, list[str]]] = {}
    params: dict[str, tuple[str, int, str, str]] = {}
    for res in results:
        for unit in res.units:
            for block, (line, col, _vars) in unit.commons.items():
                if not block or not commons:
                    continue
                sig = _signature(unit, block)
                if block not in seen:
                    seen[block] = (res.display, line, sig)
                    continue
                where, ref_line, ref = seen[block]
                if sig != ref:
                    i = next((k for k, (p, q) in enumerate(zip(sig, ref)) if p != q),
                             None)
                    detail = (f"variable {i + 1} is {sig[i]} here, {ref[i]} there"
                              if i is not None else
                              f"{len(sig)} variables here, {len(ref)} there")
                    out.append(Violation(res.display, line, col, "F77-COMMON",
                                         f"COMMON /{block}/ differs from "
                                         f"{where}:{ref_line}: {detail}"))
            for name, value, line, col in unit.params:
                type_name = unit.types.get(name, "untyped")
                if name not in params:
                    params[name] = (res.display, line, value, type_name)
                    continue
                where, ref_line, ref_value, ref_type = params[name]
                if (value, type_name) != (ref_value, ref_type):
                    out.append(Violation(res.display, line, col, "F77-PARAM",
                                         f"PARAMETER {name} is {type_name} {value} "
                                         f"here, {ref_type} {ref_value} in "
                                         f"{where}:{ref_line}"))
    return out


# ---------------------------------------------------------------------------
# gfortran: every variable declared.
# ---------------------------------------------------------------------------
GFORTRAN_FLAGS: tuple[str, ...] = (
    "-fsyntax-only", "-ffixed-form", "-fimplicit-none", "-std=legacy", "-Wall",
    "-fdiagnostics-color=never", "-fno-diagnostics-show-caret")


def _gfortran(path: Path, display: str, exe: str) -> list[Violation]:
    """Run gfortran -fsyntax-only on a copy in a temporary directory (so no
    .mod or .o file is left anywhere); its errors become violations."""
    out: list[Violation] = []
    with tempfile.TemporaryDirectory(prefix="f77check-") as tmp:
        copy = Path(tmp) / path.name
        shutil.copyfile(path, copy)
        env = dict(os.environ, LC_ALL="C", LANG="C", LANGUAGE="C")
        proc = subprocess.run([exe, *GFORTRAN_FLAGS, copy.name], cwd=tmp, env=env,
                              capture_output=True, text=True, errors="replace",
                              timeout=300)
    for text in proc.stderr.splitlines():
        m = _GFORTRAN_MSG.match(text)
        if m:
            if m.group("kind") == "Warning":
                continue
            msg = m.group("msg")
            rule = "F77-DECL" if "has no IMPLICIT type" in msg else "F77-COMPILE"
            out.append(Violation(display, max(int(m.group("line")), 1),
                                 max(int(m.group("col")), 1), rule, f"gfortran: {msg}"))
        elif "Error:" in text:
            out.append(Violation(display, 1, 1, "F77-COMPILE", f"gfortran: {text}"))
    if proc.returncode != 0 and not out:
        first = proc.stderr.strip().splitlines()[:1] or [f"exit status {proc.returncode}"]
        out.append(Violation(display, 1, 1, "F77-COMPILE", f"gfortran: {first[0]}"))
    return out


# ---------------------------------------------------------------------------
# The master text of the COMMON blocks.
# ---------------------------------------------------------------------------
MASTER = "COMMON.inc"
_HEAD = re.compile(r"^C     ---- /([A-Z][A-Z0-9]*)/")
_DECL = re.compile(r"^      (INTEGER|REAL|DOUBLE ?PRECISION|CHARACTER|LOGICAL|PARAMETER|"
                   r"COMMON|SAVE|EQUIVALENCE)\b")
_COMMON_STMT = re.compile(r"^      COMMON */ *([A-Z][A-Z0-9]*) */")


def common_copies(lines: list[str]) -> list[tuple[str, int, int]]:
    """The COMMON copies of a file: (block of the header line, first line,
    last line), 0-based and inclusive.  A copy is a ``C     ---- /NAME/``
    line and the declarations that follow it (comment lines between them
    included), up to the next ``C     ----`` line, a ``C`` line alone or
    the first other statement."""
    out: list[tuple[str, int, int]] = []
    i = 0
    while i < len(lines):
        m = _HEAD.match(lines[i])
        if not m:
            i += 1
            continue
        j = end = i
        j += 1
        while j < len(lines):
            line = lines[j]
            if line.startswith("C     ----") or line.rstrip() == "C":
                break
            if line[:1] in "Cc*":
                j += 1
                continue
            if len(line) > 5 and line[:5].strip() == "" and line[5] not in " 0":
                end = j                                   # a continuation line
            elif _DECL.match(line):
                end = j
            else:
                break
            j += 1
        out.append((m.group(1), i, end))
        i = end + 1
    return out


def read_master(path: Path) -> dict[str, list[str]]:
    """The sections of a master text: block of the header line -> its lines
    (the header, the declarations; trailing comment lines dropped)."""
    lines = path.read_text(encoding="ascii").splitlines()
    return {name: lines[a:b + 1] for name, a, b in common_copies(lines)}


def _blocks_of(section: list[str]) -> set[str]:
    """The COMMON blocks a section declares (/TZPKG/ and /TZPKGC/, say)."""
    return {m.group(1) for line in section for m in [_COMMON_STMT.match(line)] if m}


def master_checks(paths: Iterable[Path], master: dict[str, list[str]],
                  master_name: str = MASTER,
                  results: list[_FileResult] | None = None) -> list[Violation]:
    """Every copy is its master section line for line; every COMMON
    statement (as the reader finds it in ``results``, those of ``paths``:
    blanks ignored, continuation lines joined) is inside a copy of the
    section that declares its block."""
    owner = {b: name for name, sec in master.items() for b in _blocks_of(sec)}
    out: list[Violation] = []
    paths = list(paths)
    if results is None:
        results = [_FileChecker(p, str(p)).run() for p in paths]
    for path, res in zip(paths, results):
        lines = path.read_text(encoding="ascii", errors="replace").splitlines()
        inside: set[int] = set()
        for name, a, b in common_copies(lines):
            inside.update(range(a, b + 1))
            want = master.get(name)
            if want is None:
                out.append(Violation(str(path), a + 1, 1, "F77-COMMON",
                                     f"COMMON /{name}/ has no master text in {master_name}"))
                continue
            got = lines[a:b + 1]
            if got != want:
                k = next((k for k, (p, q) in enumerate(zip(got, want)) if p != q),
                         min(len(got), len(want)))
                expect = want[k].strip() if k < len(want) else "the end of the copy"
                out.append(Violation(str(path), a + k + 1, 1, "F77-COMMON",
                                     f"copy of /{name}/ differs from {master_name} "
                                     f"(line {k + 1} of the section): expected {expect!r}"))
        for block, n in (x for unit in res.units for x in unit.common_lines):
            if n - 1 not in inside:
                where = f"/{owner[block]}/" if block in owner else "no section"
                out.append(Violation(str(path), n, 7, "F77-COMMON",
                                     f"COMMON /{block}/ outside a copy of its master "
                                     f"text ({where} of {master_name})"))
    return out


def save_problems(master: Path) -> list[Violation]:
    """Every COMMON block of the master text is SAVEd in its own section
    (TENZOR's caller, a modern main program, declares none of them, and a
    block declared only in subprograms may become undefined when they
    return: the standard's 17.3)."""
    lines = master.read_text(encoding="ascii", errors="replace").splitlines()
    out: list[Violation] = []
    for _name, a, b in common_copies(lines):
        saved = {blk for line in lines[a:b + 1] if re.match(r"^      SAVE\b", line)
                 for blk in re.findall(r"/ *([A-Z][A-Z0-9]*) */", line)}
        for n in range(a, b + 1):
            m = _COMMON_STMT.match(lines[n])
            if m and m.group(1) not in saved:
                out.append(Violation(str(master), n + 1, 7, "F77-SAVE",
                                     f"COMMON /{m.group(1)}/ is not SAVEd in its section: "
                                     f"add SAVE /{m.group(1)}/ after it"))
    return out


#: The program of each routine prefix (legacy/README.md, "The names").
PROGRAMS = {"TZ": "TENZOR", "MT": "M703T", "ML": "M703L", "CM": "SHARED"}


def header_problems(path: Path, units: set[str]) -> list[Violation]:
    """The header a routine of an indexed directory opens and ends with
    (legacy/README.md): its title comment in the first three lines naming
    the routine and its program, SOURCE:, CHANGES:, and ``C     END OF
    NAME`` before its END; and, for a shared (CM) routine, no call of a
    routine of one program."""
    shown = str(path)
    try:
        r = read_routine(path, units)
    except HeaderError as exc:
        return [Violation(shown, exc.line, 1, "F77-HEADER", exc.text)]
    lines = path.read_text(encoding="ascii").splitlines()
    out: list[Violation] = []
    name = r.name
    title = next((k for k, ln in enumerate(lines[:3]) if _TITLE.match(ln)), 0)
    if _TITLE.match(lines[title]).group(1) != name:
        out.append(Violation(shown, title + 1, 7, "F77-HEADER", f"the title comment names "
                             f"{_TITLE.match(lines[title]).group(1)}, the routine is {name}"))
    want = PROGRAMS.get(name[:2], name if name in ("TENZOR", "M703T", "M703L") else "")
    if want and r.program != want:
        out.append(Violation(shown, title + 1, 7, "F77-HEADER",
                             f"the header says ({r.program or 'no program'}): {name} is of "
                             f"{want}, as its name says"))
    for key in ("SOURCE:", "CHANGES:"):
        if not any(ln.startswith(f"C     {key}") for ln in lines):
            out.append(Violation(shown, title + 1, 1, "F77-HEADER",
                                 f"no 'C     {key}' line in the header"))
    end = max((k for k, ln in enumerate(lines) if ln.strip() == "END"), default=len(lines))
    if end == 0 or lines[end - 1] != f"C     END OF {name}":
        out.append(Violation(shown, end + 1 if end < len(lines) else len(lines), 1,
                             "F77-HEADER", f"the routine's END is not preceded by "
                             f"'C     END OF {name}'"))
    if name.startswith("CM"):
        for callee in r.calls:
            if PROGRAMS.get(callee[:2], "SHARED") != "SHARED" or \
                    callee in ("TENZOR", "M703T", "M703L"):
                n = next((k for k, ln in enumerate(lines)
                          if ln[:1] not in "Cc*" and re.search(rf"\b{callee}\b", ln[6:72])),
                         0)
                out.append(Violation(shown, n + 1, 7, "F77-LAYER",
                                     f"{name}, a shared routine, calls {callee} of "
                                     f"{PROGRAMS.get(callee[:2], callee)}: give it as an "
                                     "argument, as CMASSM is given MTITEM or MLITEM"))
    return out


def write_copies(paths: Iterable[Path], master: dict[str, list[str]]) -> list[Path]:
    """Rewrite every copy from the master text; the files that changed."""
    changed = []
    for path in paths:
        text = path.read_text(encoding="ascii")
        lines = text.splitlines()
        for name, a, b in reversed(common_copies(lines)):
            if name in master:
                lines[a:b + 1] = master[name]
        new = "\n".join(lines) + "\n"
        if new != text:
            write_whole(path, new)
            changed.append(path)
    return changed


# ---------------------------------------------------------------------------
# The index of legacy/README.md, written from the routines themselves.
# ---------------------------------------------------------------------------
INDEX_BEGIN = "<!-- index: written by `python -m harness f77check --index`; do not edit -->"
INDEX_END = "<!-- end of index -->"
_UNIT_LINE = re.compile(r"^      (?:(?:INTEGER|LOGICAL|REAL|DOUBLE PRECISION) +)?"
                        r"(PROGRAM|SUBROUTINE|FUNCTION|BLOCK DATA) +([A-Z][A-Z0-9]*)")
_TITLE = re.compile(r"^C     ([A-Z][A-Z0-9]*) *- (.*)$")
_TAG = re.compile(r"\((TENZOR|M703T|M703L|SHARED)\)\s*$")


@dataclass
class Routine:
    """One program unit of legacy/, as its header describes it."""

    name: str
    kind: str                       # PROGRAM, SUBROUTINE, FUNCTION, BLOCK DATA
    program: str                    # TENZOR, M703T, M703L or SHARED (the header's tag)
    purpose: str
    source: str                     # the first clause of the SOURCE line
    calls: list[str] = field(default_factory=list)     # in order of first call
    commons: list[str] = field(default_factory=list)   # the master sections it copies


def _first_sentence(text: str) -> str:
    """Text up to the first full stop, semicolon or colon outside
    parentheses and quotes: what a header's SOURCE paragraph names first."""
    depth, quoted = 0, False
    for k, ch in enumerate(text):
        if ch == '"':
            quoted = not quoted
        elif not quoted and ch == "(":
            depth += 1
        elif not quoted and ch == ")":
            depth -= 1
        elif not quoted and depth == 0 and ch in ".;:" and text[k + 1:k + 2] in (" ", ""):
            word = text[:k].split()[-1] if text[:k].split() else ""
            if ch == "." and word.isalpha() and len(word) <= 4 and text[k + 1:].strip():
                continue                  # an abbreviation: SYST. J., FIG. 1
            return text[:k]
    return text


class HeaderError(ValueError):
    """A file whose routine the index cannot read: ``path``, ``line``, ``text``."""

    def __init__(self, path: Path, line: int, text: str) -> None:
        super().__init__(f"{path}: line {line}: {text}")
        self.path, self.line, self.text = path, line, text


def read_routine(path: Path, units: set[str]) -> Routine:
    """The header, the calls (CALL, a function reference, a routine passed as
    an argument) and the COMMON copies of one file of legacy/."""
    data = path.read_bytes()
    try:
        lines = data.decode("ascii").splitlines()
    except UnicodeDecodeError as exc:
        raise HeaderError(path, data[:exc.start].count(b"\n") + 1,
                          f"byte {data[exc.start]:03o} (octal) is not ASCII, as a FORTRAN 77 "
                          "source is") from None
    title = next((m for m in map(_TITLE.match, lines[:3]) if m), None)
    if title is None:
        raise HeaderError(path, 1, "no title comment in lines 1-3 (the index wants "
                                   "'C     NAME - what it does')")
    purpose, program = title.group(2).strip(), ""
    tag = _TAG.search(purpose)
    if tag:
        purpose = purpose[:tag.start()].strip()
    else:
        tag = _TAG.search(lines[2]) if len(lines) > 2 else None
    program = tag.group(1) if tag else ""
    start = next((k for k, ln in enumerate(lines) if ln.startswith("C     SOURCE:")), None)
    para = []
    if start is not None:
        para.append(lines[start][len("C     SOURCE:"):].strip())
        for ln in lines[start + 1:]:
            if not ln.startswith("C              "):
                break
            para.append(ln.strip()[1:].strip())
    source = _first_sentence(" ".join(para))
    unit = next((m for m in map(_UNIT_LINE.match, lines) if m), None)
    if unit is None:
        raise HeaderError(path, 1, "no PROGRAM, SUBROUTINE or FUNCTION statement (every "
                                   "file of the index holds one routine)")
    calls: list[str] = []
    for line in lines:
        if line[:1] in "Cc*" or _UNIT_LINE.match(line):
            continue
        stmt = line[6:72] if len(line) > 6 else ""
        bare = re.sub(r"'[^']*'", "", stmt)
        devices = set(re.findall(r"CALL *(DV[A-Z0-9]*)", bare))
        for name in re.findall(r"[A-Z][A-Z0-9]*", bare):
            if (name in units or name in devices) and name != unit.group(2) \
                    and name not in calls:
                calls.append(name)
    commons = [name for name, _a, _b in common_copies(lines)]
    return Routine(unit.group(2), unit.group(1), program, purpose, source, calls, commons)


def legacy_index(root: Path) -> str:
    """The generated part of legacy/README.md: the call tree, the COMMON
    blocks with their users, and one line per routine."""
    files = find_sources(root)
    names = {p.stem.upper() for p in files}
    routines = {r.name: r for r in (read_routine(p, names) for p in files)}
    out = [INDEX_BEGIN, "", "### The call tree", "",
           "Each routine is shown under the first routine that calls it; a later",
           "call shows its name only, followed by `...`. `DV...` routines are the",
           "devices of `src/monitor/`.", "", "```"]
    shown: set[str] = set()

    def walk(name: str, depth: int) -> None:
        r = routines.get(name)
        kind = f" ({r.kind})" if r and r.kind not in ("SUBROUTINE", "PROGRAM") else ""
        again = name in shown
        out.append("  " * depth + name + kind + (" ..." if again and r and r.calls else ""))
        if again or r is None:
            return
        shown.add(name)
        for c in r.calls:
            walk(c, depth + 1)

    walk("TENZOR", 0)
    out += ["```", ""]
    lost = sorted(set(routines) - shown)
    if lost:
        out += ["Not called from TENZOR: " + ", ".join(lost) + ".", ""]
    out += ["### The COMMON blocks", "",
            "| section of COMMON.inc | copied into |", "|---|---|"]
    users: dict[str, list[str]] = {}
    for n, r in sorted(routines.items()):
        for c in r.commons:
            users.setdefault(c, []).append(n)
    for c in sorted(users):
        out.append(f"| /{c}/ | {', '.join(users[c])} |")
    out += ["", "### The routines", "",
            "| routine | program | what it does | source |", "|---|---|---|---|"]
    for n, r in sorted(routines.items()):
        out.append(f"| [{n}]({n.lower()}.f) | {r.program or r.kind} | {r.purpose} | "
                   f"{r.source.replace('|', '/')} |")
    out += ["", INDEX_END]
    return "\n".join(out) + "\n"


def index_problems(root: Path) -> list[str]:
    """What is wrong with the index in root/README.md (empty: it is current)."""
    readme = root / "README.md"
    if not readme.is_file():
        return [f"{readme}: missing"]
    try:
        text = readme.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        return [f"{readme}: not UTF-8 text ({exc.reason} at byte {exc.start})"]
    if INDEX_BEGIN not in text or INDEX_END not in text:
        return [f"{readme}: no generated index between its markers"]
    have = text[text.index(INDEX_BEGIN):text.index(INDEX_END) + len(INDEX_END)] + "\n"
    try:
        want = legacy_index(root)
    except HeaderError as exc:
        return [f"the index cannot be made until {exc.path.name}'s header is mended "
                "(F77-HEADER)"]
    if have != want:
        a, b = have.splitlines(), want.splitlines()
        k = next((i for i, (p, q) in enumerate(zip(a, b)) if p != q), min(len(a), len(b)))
        got = a[k] if k < len(a) else "(the end)"
        exp = b[k] if k < len(b) else "(the end)"
        return [f"{readme}: the index is out of date at its line {k + 1}: "
                f"{got!r}, the routines say {exp!r} (python -m harness f77check --index)"]
    return []


def write_index(root: Path) -> bool:
    """Write the index into root/README.md between its markers; True if it changed."""
    readme = root / "README.md"
    text = readme.read_text(encoding="utf-8")
    a, b = text.index(INDEX_BEGIN), text.index(INDEX_END) + len(INDEX_END) + 1
    new = text[:a] + legacy_index(root) + text[b:]
    if new != text:
        write_whole(readme, new, encoding="utf-8")
    return new != text


# ---------------------------------------------------------------------------
# Entry points.
# ---------------------------------------------------------------------------
def find_sources(root: str | os.PathLike[str]) -> list[Path]:
    """Every ``*.f`` file under root, sorted, skipping hidden and build dirs."""
    base = Path(root)
    found = []
    for p in base.rglob("*.f"):
        parts = p.relative_to(base).parts[:-1]
        if p.is_file() and not any(x.startswith(".") or x == "build" for x in parts):
            found.append(p)
    return sorted(found)


def check_files(paths: Iterable[Path], compiler: str | None = "gfortran",
                notes: list[str] | None = None,
                master: Path | None = None) -> list[Violation]:
    """Check the given files (names as given are used in messages); with a
    master COMMON text, every copy against it."""
    paths = list(paths)
    results = [_FileChecker(p, str(p)).run() for p in paths]
    violations = [v for r in results for v in r.violations]
    if master is not None:
        violations += master_checks(paths, read_master(master), str(master), results)
        violations += _cross_checks(results, commons=False)
    else:
        violations += _cross_checks(results)
    if compiler:
        exe = shutil.which(compiler)
        if exe is None:
            if notes is not None:
                notes.append(f"{compiler} is not on PATH: the F77-DECL step "
                             "(every variable declared) was skipped")
        else:
            for p in paths:
                violations += _gfortran(p, str(p), exe)
    return sorted(set(violations))


def check_dir(path: str | os.PathLike[str] = "legacy",
              compiler: str | None = "gfortran",
              notes: list[str] | None = None) -> list[Violation]:
    """Check every ``*.f`` under ``path``; returns the violations, sorted.

    ``compiler`` runs the F77-DECL step (None skips it); if it is not on PATH
    the step is skipped and a line saying so is appended to ``notes``.  The
    copies of COMMON blocks are checked against ``path/COMMON.inc`` when
    it exists.
    """
    master = Path(path) / MASTER
    files = find_sources(path)
    return sorted(set(check_files(files, compiler, notes, master if master.is_file() else None)
                      + directory_problems(Path(path), files)))


def directory_problems(root: Path, files: list[Path]) -> list[Violation]:
    """The rules of a directory as legacy/ is kept: with a master COMMON
    text, every block SAVEd in it; with a README.md, its index current and
    every routine's header as the index reads it."""
    out: list[Violation] = []
    if (root / MASTER).is_file():
        out += save_problems(root / MASTER)
    if (root / "README.md").is_file():
        out += [Violation(str(root / "README.md"), 1, 1, "F77-INDEX", p)
                for p in index_problems(root)]
        units = {p.stem.upper() for p in files}
        out += [v for p in files for v in header_problems(p, units)]
    return out


def main(directory: str = "legacy", write_common: bool = False, index: bool = False) -> int:
    """CLI: print violations and a summary; 0 clean, 1 violations, 2 no input.
    With ``write_common``, first rewrite the COMMON copies from the master;
    with ``index``, first rewrite the index of DIR/README.md."""
    root = Path(directory)
    if not root.is_dir():
        print(f"f77check: {directory}: "
              + ("not a directory" if root.exists() else "no such directory"), file=sys.stderr)
        return 2
    files = find_sources(root)
    if not files:
        print(f"f77check: no *.f files under {directory}", file=sys.stderr)
        return 2
    master = root / MASTER
    if write_common:
        if not master.is_file():
            print(f"f77check: {master}: no master COMMON text to write from",
                  file=sys.stderr)
            return 2
        for path in write_copies(files, read_master(master)):
            print(f"f77check: wrote the COMMON copies of {path}")
    if index:
        try:
            if write_index(root):
                print(f"f77check: wrote the index of {root / 'README.md'}")
        except (OSError, ValueError) as exc:
            print(f"f77check: {root / 'README.md'}: cannot write the index: {exc}",
                  file=sys.stderr)
            return 2
    notes: list[str] = []
    violations = check_files(files, notes=notes,
                             master=master if master.is_file() else None)
    violations += directory_problems(root, files)
    for v in violations:
        print(v)
    for note in notes:
        print(f"f77check: {note}", file=sys.stderr)
    if violations:
        bad = len({v.path for v in violations})
        print(f"f77check: {len(violations)} violations in {bad} of {len(files)} files")
        return 1
    print(f"f77check: {len(files)} files, no violations")
    return 0
