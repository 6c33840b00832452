"""The rules of legacy/README.md hold for every file of legacy/: the faithful
programs read as a 1977 listing (fixed form, six-character names, upper case,
every COMMON copy the master text of COMMON.inc, PARAMETERs alike everywhere,
every variable declared), and README's index is the one the routines give."""
from __future__ import annotations

import shutil
from pathlib import Path

from harness.f77check import check_dir, index_problems, legacy_index, write_index

LEGACY = Path(__file__).resolve().parents[3] / "legacy"


def test_legacy_sources_follow_the_rules():
    notes: list[str] = []
    violations = check_dir(LEGACY, notes=notes)
    assert not notes, notes  # gfortran must be there: the set-up installs it
    assert not violations, "\n".join(str(v) for v in violations)


def test_every_unit_names_its_source_and_ends_with_a_trailer():
    for path in sorted(LEGACY.glob("*.f")):
        text = path.read_text()
        unit = path.stem.upper()
        assert f"C     {unit}" in text.splitlines()[1] or f"C     {unit} " in text, path
        assert "C     SOURCE:" in text, path
        assert f"C     END OF {unit}" in text, path


def test_readme_index_is_the_one_the_routines_give():
    assert index_problems(LEGACY) == []


def test_every_routine_names_its_program_and_is_reached_from_tenzor():
    index = legacy_index(LEGACY)
    table = index.split("### The routines", 1)[1]
    rows = [line for line in table.splitlines() if line.startswith("| [")]
    assert len(rows) == len(list(LEGACY.glob("*.f")))
    for row in rows:
        assert row.split(" | ")[1] in {"TENZOR", "M703T", "M703L", "SHARED"}, row
    assert "Not called from TENZOR" not in index


def test_a_stale_index_is_caught(tmp_path):
    for name in ("README.md", "cmitoa.f", "cmtrim.f"):
        shutil.copy(LEGACY / name, tmp_path / name)
    write_index(tmp_path)
    assert index_problems(tmp_path) == []
    path = tmp_path / "cmtrim.f"
    path.write_text(path.read_text().replace("LENGTH OF A STRING", "THE LENGTH OF A TEXT"))
    problems = index_problems(tmp_path)
    assert len(problems) == 1 and "out of date" in problems[0] and "THE LENGTH OF A TEXT" \
        in problems[0], problems


def test_a_routine_tenzor_does_not_call_is_named(tmp_path):
    """The call tree starts at TENZOR; a routine it never reaches is named
    under the tree, so the index cannot hide it."""
    for name in ("README.md", "cmitoa.f", "cmtrim.f"):
        shutil.copy(LEGACY / name, tmp_path / name)
    index = legacy_index(tmp_path)
    assert "```\nTENZOR\n```\n\nNot called from TENZOR: CMITOA, CMTRIM.\n" in index, index


def test_an_index_whose_call_tree_is_in_another_order_is_stale(tmp_path):
    """The index is compared line for line, in order: the same lines in
    another order (TENZOR now calls CMITOA before CMTRIM) are out of date."""
    for name in ("README.md", "cmitoa.f", "cmtrim.f"):
        shutil.copy(LEGACY / name, tmp_path / name)
    calls = ["      CALL CMTRIM(STR, L)", "      CALL CMITOA(L, STR, L)"]
    tenzor = tmp_path / "tenzor.f"

    def write_tenzor(body):
        tenzor.write_text("\n".join([
            "C     TENZOR - THE ROOT OF THE TEST'S TREE   (TENZOR)",
            "C     SOURCE:  THE TESTS.", "C     CHANGES: SEE GIT.",
            "      SUBROUTINE TENZOR", "      IMPLICIT NONE", "      CHARACTER*8 STR",
            "      INTEGER L", "      STR = 'AB'", *body, "      RETURN",
            "C     END OF TENZOR", "      END", ""]))

    write_tenzor(calls)
    write_index(tmp_path)
    assert index_problems(tmp_path) == []
    assert "TENZOR\n  CMTRIM\n  CMITOA\n" in legacy_index(tmp_path)
    write_tenzor(calls[::-1])
    problems = index_problems(tmp_path)
    assert len(problems) == 1 and "out of date" in problems[0] and "'  CMTRIM'" in problems[0] \
        and "'  CMITOA'" in problems[0], problems
