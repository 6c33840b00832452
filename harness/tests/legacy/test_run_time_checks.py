"""The run-time checks of the build that `make test-checks` and `make fuzz`
test (the Makefile's CHECKS, on top of fpm's debug profile) catch what
docs/ROBUSTNESS.md says they catch.

A small FORTRAN 77 program is built with gfortran and exactly those flags. Told
to do nothing wrong, it runs to its end; told to do one wrong thing (a signed
integer overflow of each operation and kind, an index out of its array, a
floating-point invalid operation, division by zero or overflow), it must stop
with gfortran's report instead of going on with a wrong number. Every operand
is read at run time, so that no check is folded away at compile time. A flag
dropped or misspelt in the Makefile, or a compiler that ignores one, fails
here: the suites run against that build could then pass while checking
nothing.
"""
from __future__ import annotations

import re
import shlex
import shutil
import subprocess
from pathlib import Path

import pytest

from harness.tests.helpers import ROOT

PROGRAM = """\
      PROGRAM CHKS
      IMPLICIT NONE
      INTEGER K, I, J, IA(10)
      INTEGER*8 L
      DOUBLE PRECISION X, Y
      READ (*, *) K, J, X
      I = 2147483647
      L = 9223372036854775807_8
      Y = 1.0D0
      IA(1) = 0
      IF (K .EQ. 1) I = I + J
      IF (K .EQ. 2) I = -I - 1 - J
      IF (K .EQ. 3) I = I * J
      IF (K .EQ. 4) I = -(-I - J)
      IF (K .EQ. 5) I = (-I - J) / (-J)
      IF (K .EQ. 6) L = L + J
      IF (K .EQ. 7) I = IA(J + 10)
      IF (K .EQ. 8) Y = SQRT(X)
      IF (K .EQ. 9) Y = Y / X
      IF (K .EQ. 10) Y = X * X
      WRITE (*, '(A, I12, I21, F8.3)') 'END', I, L, Y
      END
"""

#: case -> (what it does wrong, its input: K J X)
CASES = {
    1: ("INTEGER + overflows", "1 1 1.0"),
    2: ("INTEGER - overflows", "2 1 1.0"),
    3: ("INTEGER * overflows", "3 2 1.0"),
    4: ("INTEGER negation overflows", "4 1 1.0"),
    5: ("INTEGER division overflows", "5 1 1.0"),
    6: ("INTEGER*8 + overflows", "6 1 1.0"),
    7: ("an index past its array", "7 1 1.0"),
    8: ("a floating-point invalid operation", "8 1 -1.0"),
    9: ("a floating-point division by zero", "9 1 0.0"),
    10: ("a floating-point overflow", "10 1 1.0D300"),
}


def checks() -> list[str]:
    """The Makefile's CHECKS, its continuation lines joined."""
    text = (ROOT / "Makefile").read_text().replace("\\\n", " ")
    m = re.search(r"^CHECKS\s*:=\s*(.*)$", text, re.M)
    assert m, "the Makefile defines no CHECKS"
    return shlex.split(m.group(1))


@pytest.fixture(scope="module")
def program(tmp_path_factory: pytest.TempPathFactory) -> Path:
    gfortran = shutil.which("gfortran")
    if gfortran is None:
        pytest.fail("gfortran is not installed: `make setup` installs it", pytrace=False)
    work = tmp_path_factory.mktemp("checks")
    (work / "chks.f").write_text(PROGRAM)
    # fpm's debug profile compiles at -O0 with -g and -fbacktrace; the same here
    proc = subprocess.run([gfortran, "-g", "-fbacktrace", *checks(), "chks.f", "-o", "chks"],
                          cwd=work, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    return work / "chks"


def run(program: Path, given: str) -> subprocess.CompletedProcess:
    return subprocess.run([str(program)], input=given + "\n", capture_output=True, text=True,
                          timeout=60)


def test_the_program_runs_to_its_end_when_nothing_is_wrong(program):
    for given in ("0 1 1.0", "1 -1 1.0", "3 1 1.0", "5 -1 1.0", "7 -5 1.0", "9 1 2.0"):
        proc = run(program, given)
        assert proc.returncode == 0 and proc.stdout.startswith("END"), (given, proc.stderr)


@pytest.mark.parametrize("case", sorted(CASES), ids=[CASES[c][0] for c in sorted(CASES)])
def test_each_check_trips(program, case):
    proc = run(program, CASES[case][1])
    assert proc.returncode != 0 and "END" not in proc.stdout, (
        f"{CASES[case][0]}: the program went on ({proc.stdout.strip()!r})")
    assert re.search(r"Fortran runtime error|Program received signal", proc.stderr), proc.stderr
