"""TENZOR punches the same bytes whichever linker builds it.

The FORTRAN 77 of legacy/ is built here from scratch with gfortran: every
routine compiled on its own and put into a static library, as fpm does, with
the device layer and the shell beside it, then linked twice, by GNU ld (bfd)
and by gold. Each program runs every deck of examples/; every file it writes
(tapes, frame text, listing, job sheet) must be byte for byte what the
tenzor under test writes. A code table that reaches the program only
through one linker's rules (gold does not pull an archive member to define a
COMMON block) would punch blank tapes here; and a build whose code table is
never set must stop with a message, not punch blank tapes.
"""
from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from harness.tests.helpers import DECKS, ROOT

#: The modern sources tenzor needs, in the order their modules need them.
SHELL = ["src/base/base_os.f90", "src/monitor/monitor_devices.f90", "src/monitor/devices.f90",
         "src/base/base_args.f90", "app/tenzor.f90"]
LINKERS = ["bfd", "gold"]


def _have_linker(name: str) -> bool:
    return shutil.which(f"ld.{name}") is not None


@pytest.fixture(scope="module")
def parts(tmp_path_factory) -> tuple[Path, list[str]]:
    """legacy/ compiled into a static library, and the shell's objects."""
    gfortran = shutil.which("gfortran")
    if gfortran is None:
        pytest.fail("gfortran is not on PATH: the set-up installs it", pytrace=False)
    work = tmp_path_factory.mktemp("linkers")
    objects = []
    for src in sorted((ROOT / "legacy").glob("*.f")):
        obj = work / (src.stem + ".o")
        subprocess.run([gfortran, "-c", "-ffixed-form", "-fimplicit-none", str(src), "-o",
                        str(obj)], check=True, capture_output=True)
        objects.append(str(obj))
    subprocess.run(["ar", "rcs", str(work / "liblegacy.a"), *objects], check=True)
    shell = []
    for src in SHELL:
        obj = work / (Path(src).stem + ".o")
        subprocess.run([gfortran, "-c", f"-J{work}", str(ROOT / src), "-o", str(obj)],
                       check=True, capture_output=True)
        shell.append(str(obj))
    return work, shell


@pytest.fixture(scope="module")
def built(parts) -> dict[str, Path]:
    """tenzor linked by each linker: linker -> program."""
    gfortran = shutil.which("gfortran")
    work, shell = parts
    programs = {}
    for linker in LINKERS:
        if not _have_linker(linker):
            continue
        exe = work / f"tenzor-{linker}"
        subprocess.run([gfortran, f"-fuse-ld={linker}", *shell, str(work / "liblegacy.a"),
                        "-o", str(exe)], check=True, capture_output=True)
        programs[linker] = exe
    return programs


def _outputs(exe: Path, deck: Path, out: Path) -> dict[str, bytes]:
    proc = subprocess.run([str(exe), str(deck), "-o", str(out)], capture_output=True,
                          timeout=120)
    files = {p.name: p.read_bytes() for p in sorted(out.iterdir())} if out.exists() else {}
    files["exit status"] = str(proc.returncode).encode()
    return files


@pytest.mark.parametrize("linker", LINKERS)
def test_every_linker_builds_a_tenzor_that_punches_the_same_bytes(built, linker, tenzor_exe,
                                                                  tmp_path):
    if linker not in built:
        pytest.fail(f"ld.{linker} is not installed (Debian package binutils)", pytrace=False)
    for n, deck in enumerate(DECKS):
        want = _outputs(tenzor_exe, deck, tmp_path / f"want{n}")
        got = _outputs(built[linker], deck, tmp_path / f"got{n}")
        assert got.keys() == want.keys(), (deck, sorted(got), sorted(want))
        differ = [name for name in want if got[name] != want[name]]
        assert not differ, f"{deck.relative_to(ROOT)}: linked by {linker}, {differ} differ"
        tapes = [name for name in want if name.endswith(".ptp")]
        assert tapes and all(any(want[t][20:]) for t in tapes), "blank tapes"


def test_a_build_without_its_code_table_stops_with_a_message(parts, tmp_path):
    """TZCODE replaced by a routine that sets nothing: TENZOR must refuse to
    punch (exit 2, a message naming the table), not write blank tapes."""
    work, shell = parts
    stub = tmp_path / "tzcode.f"
    stub.write_text("      SUBROUTINE TZCODE\n      RETURN\n      END\n")
    obj = tmp_path / "tzcode.o"
    subprocess.run(["gfortran", "-c", str(stub), "-o", str(obj)], check=True,
                   capture_output=True)
    exe = tmp_path / "tenzor-unset"
    subprocess.run(["gfortran", *shell, str(obj), str(work / "liblegacy.a"), "-o", str(exe)],
                   check=True, capture_output=True)
    out = tmp_path / "out"
    proc = subprocess.run([str(exe), str(DECKS[0]), "-o", str(out)], capture_output=True,
                          text=True, timeout=60)
    assert proc.returncode == 2, proc.stderr
    assert "CODE TABLE /CMCOD/ IS NOT SET" in proc.stderr
    assert not (out.exists() and any(out.glob("*.ptp"))), "tapes punched"
