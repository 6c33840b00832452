"""TENZOR punches the same bytes whichever linker builds it.

scripts/judges.sh builds TENZOR with gfortran as fpm does (every routine of
legacy/ compiled on its own and put into a static library, the device layer
and the shell beside it), then links it twice, by GNU ld (bfd) and by gold.
Each program runs every deck of examples/; every file it writes (tapes, frame
text, listing, job sheet) must be byte for byte what the tenzor under test
writes. A code table that reaches the program only through one linker's rules
(gold does not pull an archive member to define a COMMON block) would punch
blank tapes here; and a build whose code table is never set must stop with a
message, not punch blank tapes.
"""
from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from harness.tests.helpers import DECKS, ROOT

LINKERS = ["bfd", "gold"]


def build(linker: str) -> Path:
    """build/gfortran-LINKER/, made afresh by scripts/judges.sh."""
    if shutil.which(f"ld.{linker}") is None:
        pytest.fail(f"ld.{linker} is not installed (Debian package binutils)", pytrace=False)
    proc = subprocess.run(["bash", str(ROOT / "scripts" / "judges.sh"), "gfortran", linker],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    return ROOT / "build" / f"gfortran-{linker}"


@pytest.fixture(scope="module")
def built() -> dict[str, Path]:
    """linker -> its build directory."""
    return {linker: build(linker) for linker in LINKERS}


def _outputs(exe: Path, deck: Path, out: Path) -> dict[str, bytes]:
    proc = subprocess.run([str(exe), str(deck), "-o", str(out)], capture_output=True,
                          timeout=120)
    files = {p.name: p.read_bytes() for p in sorted(out.iterdir())} if out.exists() else {}
    files["exit status"] = str(proc.returncode).encode()
    return files


@pytest.mark.parametrize("linker", LINKERS)
def test_every_linker_builds_a_tenzor_that_punches_the_same_bytes(built, linker, tenzor_exe,
                                                                  tmp_path):
    for n, deck in enumerate(DECKS):
        want = _outputs(tenzor_exe, deck, tmp_path / f"want{n}")
        got = _outputs(built[linker] / "tenzor", deck, tmp_path / f"got{n}")
        assert got.keys() == want.keys(), (deck, sorted(got), sorted(want))
        differ = [name for name in want if got[name] != want[name]]
        assert not differ, f"{deck.relative_to(ROOT)}: linked by {linker}, {differ} differ"
        tapes = [name for name in want if name.endswith(".ptp")]
        assert tapes and all(any(want[t][20:]) for t in tapes), "blank tapes"


def test_a_build_without_its_code_table_stops_with_a_message(built, tmp_path):
    """TZCODE replaced by a routine that sets nothing: TENZOR must refuse to
    punch (exit 2, a message naming the table), not write blank tapes."""
    parts = built["bfd"]
    stub = tmp_path / "tzcode.f"
    stub.write_text("      SUBROUTINE TZCODE\n      RETURN\n      END\n")
    obj = tmp_path / "tzcode.o"
    subprocess.run(["gfortran", "-c", str(stub), "-o", str(obj)], check=True,
                   capture_output=True)
    exe = tmp_path / "tenzor-unset"
    subprocess.run(["gfortran", *map(str, sorted((parts / "shell").glob("*.o"))), str(obj),
                    str(parts / "liblegacy.a"), "-o", str(exe)], check=True,
                   capture_output=True)
    out = tmp_path / "out"
    proc = subprocess.run([str(exe), str(DECKS[0]), "-o", str(out)], capture_output=True,
                          text=True, timeout=60)
    assert proc.returncode == 2, proc.stderr
    assert "CODE TABLE /CMCOD/ IS NOT SET" in proc.stderr
    assert not (out.exists() and any(out.glob("*.ptp"))), "tapes punched"
