"""Two tools that others trust judge the FORTRAN 77 of legacy/, besides the
project's own checker (f77check):

* f2c -A -u, the classic FORTRAN 77 to C translator (AT&T/Bell Labs),
  translates every file without an error;
* ftnchek -f77 (Moniot), the FORTRAN 77 checker, finds no nonstandard syntax
  but IMPLICIT NONE (the one extension the rules allow) and no subprogram
  that is not defined, but the DV... devices of src/monitor/.

scripts/setup.sh installs both (Debian packages f2c and ftnchek); a machine
without them fails here, it does not skip.
"""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from harness.tests.helpers import ROOT

SOURCES = sorted((ROOT / "legacy").glob("*.f"))


def _tool(name: str) -> str:
    path = shutil.which(name)
    if path is None:
        pytest.fail(f"{name} is not installed: `make setup` installs it (Debian "
                    f"package {name})", pytrace=False)
    return path


def f2c_errors(source: Path, out: Path) -> list[str]:
    """What f2c -A -u says is wrong with a file (empty: it translates it)."""
    proc = subprocess.run([_tool("f2c"), "-A", "-u", f"-d{out}", str(source)],
                          capture_output=True, text=True, timeout=60)
    errors = [line for line in proc.stderr.splitlines() if "Error" in line]
    if proc.returncode != 0 and not errors:
        errors = [proc.stderr.strip() or f"exit status {proc.returncode}"]
    return errors


@pytest.mark.parametrize("source", SOURCES, ids=[p.name for p in SOURCES])
def test_f2c_translates_the_file(source, tmp_path):
    assert f2c_errors(source, tmp_path) == []


def test_the_f2c_gate_catches_what_it_is_for(tmp_path):
    bad = tmp_path / "cmbad.f"
    bad.write_text("C     CMBAD - FORTRAN 90 IN DISGUISE\n"
                   "      SUBROUTINE CMBAD(S, X)\n"
                   "      IMPLICIT NONE\n"
                   "      CHARACTER*(*) S\n"
                   "      DOUBLE PRECISION X\n"
                   "      INTEGER I\n"
                   "      I = FLOOR(X)\n"
                   "      CALL DVERR('CMBAD: ' // S)\n"
                   "      RETURN\n"
                   "      END\n")
    errors = f2c_errors(bad, tmp_path)
    assert any("floor" in e for e in errors), errors
    assert any("concatenation" in e for e in errors), errors


def ftnchek_findings(directory: Path) -> list[str]:
    """ftnchek's warnings on every file of a directory that the rules forbid."""
    proc = subprocess.run([_tool("ftnchek"), "-f77", "-declare", "-quiet",
                           *sorted(p.name for p in directory.glob("*.f"))],
                          cwd=directory, capture_output=True, text=True, timeout=300)
    text = proc.stdout + proc.stderr
    found = []
    lines = text.splitlines()
    for k, line in enumerate(lines):
        m = re.match(r"Warning near line (\d+) col (\d+) file (\S+): Nonstandard syntax(.*)", line)
        if m:
            source = (directory / m.group(3)).read_text().splitlines()
            stmt = source[int(m.group(1)) - 1].strip() if int(m.group(1)) <= len(source) else ""
            if stmt != "IMPLICIT NONE":
                found.append(f"{m.group(3)}:{m.group(1)}: nonstandard syntax{m.group(4)}: {stmt}")
        m = re.match(r"Warning: Subprogram (\S+) never defined", line)
        if m and not m.group(1).startswith("DV"):
            where = lines[k + 1].strip() if k + 1 < len(lines) else ""
            found.append(f"{m.group(1)} is called but never defined ({where})")
    return found


def test_ftnchek_finds_only_implicit_none_and_the_devices(tmp_path):
    for source in SOURCES:
        shutil.copy(source, tmp_path / source.name)
    assert ftnchek_findings(tmp_path) == []


def test_the_ftnchek_gate_catches_what_it_is_for(tmp_path):
    (tmp_path / "cmbad.f").write_text(
        "C     CMBAD - A UNIT THAT BREAKS THE RULES\n"
        "      SUBROUTINE CMBAD(X)\n"
        "      IMPLICIT NONE\n"
        "      DOUBLE PRECISION X\n"
        "      INTEGER I\n"
        "      I = FLOOR(X)\n"
        "      DO WHILE (I .GT. 0)\n"
        "         I = I - 1\n"
        "      END DO\n"
        "      CALL CMNONE(I)\n"
        "      CALL DVPRNT('A DEVICE IS FINE')\n"
        "      RETURN\n"
        "      END\n")
    found = ftnchek_findings(tmp_path)
    assert any("nonstandard syntax" in f and "DO WHILE" in f for f in found), found
    assert any(f.startswith("CMNONE is called but never defined") for f in found), found
    assert not any("DVPRNT" in f for f in found), found
