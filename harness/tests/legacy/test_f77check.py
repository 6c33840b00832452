"""Tests of harness.f77check on small synthetic files, one rule at a time.

The real legacy/ tree is checked by another test; these files are written
to tmp_path.
"""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest

from harness.__main__ import main
from harness.f77check import RULES, Violation, check_dir, read_master

HAVE_GFORTRAN = shutil.which("gfortran") is not None
needs_gfortran = pytest.mark.skipif(not HAVE_GFORTRAN, reason="gfortran not on PATH")

def write(directory: Path, name: str, lines: list[str]) -> Path:
    path = directory / name
    path.write_text("".join(line + "\n" for line in lines), encoding="utf-8")
    return path


def subroutine(name: str, body: list[str], end: str = "      END") -> list[str]:
    """A small correct subroutine around ``body``."""
    return ["C     " + name + " - TEST UNIT",
            f"      SUBROUTINE {name}",
            "      IMPLICIT NONE",
            "      INTEGER I, J",
            "      CHARACTER*8 S",
            *body,
            "      RETURN",
            end]


def headed(name: str, body: list[str]) -> list[str]:
    """A shared routine with the header of an indexed directory (legacy/README.md)."""
    return (["C     " + name + " - TEST UNIT   (SHARED)", "C     SOURCE:  THE TESTS.",
             "C     CHANGES: SEE GIT."] + subroutine(name, body)[1:-1]
            + ["C     END OF " + name, "      END"])


def rules(directory: Path, compiler: str | None = None) -> set[str]:
    return {v.rule for v in check_dir(directory, compiler=compiler)}


def only(directory: Path, rule: str) -> list[Violation]:
    """The violations, asserting they are all of ``rule`` (and some exist)."""
    found = check_dir(directory, compiler=None)
    assert found, f"{rule} not flagged"
    assert {v.rule for v in found} == {rule}, "\n".join(map(str, found))
    return found


# ---------------------------------------------------------------------------
# Clean files.
# ---------------------------------------------------------------------------
CLEAN_MAIN = [
    "C=======================================================================",
    "C     TZMAIN - TEST PROGRAM: COMMON AND PARAMETER SHARED WITH CMADD",
    "C=======================================================================",
    "      PROGRAM TZMAIN",
    "      IMPLICIT NONE",
    "      INTEGER MAXPAD",
    "      PARAMETER (MAXPAD = 500)",
    "      CHARACTER*8 NAME",
    "      CHARACTER*(*) TITLE",
    "      PARAMETER (TITLE = 'It''s; \"ok\" ! <>')",
    "      INTEGER NPAD, IPX(MAXPAD), I",
    "      REAL SCALE",
    "      DOUBLE PRECISION D",
    "      LOGICAL DONE",
    "      COMMON /CMPAD/ NPAD, IPX",
    "      COMMON /CMNAM/ NAME, SCALE",
    "      EXTERNAL CMADD",
    "      DATA DONE /.FALSE./",
    "      NPAD = 0",
    "      NAME = 'lower ok'",
    "      SCALE = 1.0E+2 * .5E1",
    "      D = 1.5D0",
    "      DO 10, I = 1, MAXPAD",
    "         IPX(I) = 0",
    "   10 CONTINUE",
    "      IF (NPAD .EQ. 0 .AND. SCALE .GT. 1.5) CALL CMADD(10)",
    "      IF (NPAD .GT. 0) THEN",
    "         WRITE (*, '(A, I5)') 'pads: ', NPAD",
    "      ELSE IF (NPAD .LT. 0) THEN",
    "         GO TO 20",
    "      ELSE",
    "         DONE = .TRUE.",
    "      END IF",
    "      WRITE (*, 100) NAME(1:4), TITLE, 'a string that goes on and on acr",
    "     1oss a continuation line', NPAD",
    "   20 CONTINUE",
    "  100 FORMAT (1X, A4, A, A/1X, I5)",
    "      END",
]
CLEAN_SUB = [
    "C     CMADD - ADD ONE PAD",
    "*     (A STAR COMMENT CARD)",
    "      SUBROUTINE CMADD(IX)",
    "      IMPLICIT NONE",
    "      INTEGER IX",
    "      INTEGER MAXPAD",
    "      PARAMETER (MAXPAD = 500)",
    "      INTEGER NPAD, IPX",
    "      DIMENSION IPX(MAXPAD)",
    "      COMMON /CMPAD/ NPAD,",
    "     1               IPX",
    "      IF (NPAD .GE. MAXPAD) RETURN",
    "      NPAD = NPAD + 1",
    "      IPX(NPAD) = IX",
    "      RETURN",
    "      END",
]


def test_clean_files_pass(tmp_path: Path) -> None:
    write(tmp_path, "tzmain.f", CLEAN_MAIN)
    write(tmp_path, "cmadd.f", CLEAN_SUB)
    assert check_dir(tmp_path, compiler=None) == []


@needs_gfortran
def test_clean_files_pass_gfortran_and_leave_no_files(tmp_path: Path) -> None:
    write(tmp_path, "tzmain.f", CLEAN_MAIN)
    write(tmp_path, "cmadd.f", CLEAN_SUB)
    before = sorted(tmp_path.iterdir())
    assert check_dir(tmp_path) == []
    assert sorted(tmp_path.iterdir()) == before


def test_clean_function_and_block_data(tmp_path: Path) -> None:
    """A clean function passes; a BLOCK DATA, standard FORTRAN 77 as it is,
    is the one rule it breaks: the project keeps none (the linkers)."""
    write(tmp_path, "iadd.f", [
        "      INTEGER FUNCTION IADD(I, J)",
        "      IMPLICIT NONE",
        "      INTEGER I, J",
        "      IADD = I + J",
        "      END"])
    write(tmp_path, "cminit.f", [
        "      BLOCK DATA CMINIT",
        "      IMPLICIT NONE",
        "      INTEGER NPAD",
        "      COMMON /CMCNT/ NPAD",
        "      DATA NPAD /0/",
        "      END"])
    found = check_dir(tmp_path)
    assert [(Path(v.path).name, v.line, v.rule) for v in found] == [
        ("cminit.f", 1, "F77-BLOCKDATA")], found


@pytest.mark.parametrize("stmt", ["      STOP", "      STOP 'TABLE FULL'", "      PAUSE 7",
                                  "      IF (I .GT. 1) STOP"])
def test_no_routine_stops_the_run(tmp_path: Path, stmt: str) -> None:
    write(tmp_path, "cmone.f", subroutine("CMONE", ["      I = 1", stmt]))
    found = only(tmp_path, "F77-STOP")
    assert found[0].line == 7 and "goes through CMERR" in found[0].message


def test_a_variable_named_stop_is_not_a_stop(tmp_path: Path) -> None:
    write(tmp_path, "cmone.f", subroutine("CMONE", ["      INTEGER STOPS", "      STOPS = 1"]))
    assert check_dir(tmp_path, compiler=None) == []


LEGACY = Path(__file__).resolve().parents[3] / "legacy"


def legacy_copy(tmp_path: Path) -> Path:
    """legacy/ as it is, to break one rule in."""
    shutil.copytree(LEGACY, tmp_path / "leg")
    return tmp_path / "leg"


def test_a_block_the_master_does_not_save_is_named(tmp_path: Path) -> None:
    root = legacy_copy(tmp_path)
    master = root / "COMMON.inc"
    text = master.read_text()
    line = text[:text.index("      COMMON /CMFRT/")].count("\n") + 1
    master.write_text(text.replace("      SAVE /CMFRT/\n", "", 1))
    assert main(["f77check", "--write-common", str(root)]) == 1
    found = [v for v in check_dir(root, compiler=None) if v.rule == "F77-SAVE"]
    assert [(Path(v.path).name, v.line) for v in found] == [("COMMON.inc", line)], found
    assert found[0].message == ("COMMON /CMFRT/ is not SAVEd in its section: add SAVE "
                                "/CMFRT/ after it")


@pytest.mark.parametrize("edit, rule, at, says", [
    (lambda t: t.replace("C     CHANGES:", "C     HISTORY:"), "F77-HEADER", "title",
     "no 'C     CHANGES:' line in the header"),
    (lambda t: t.replace("C     END OF CMTRIM\n", ""), "F77-HEADER", "end",
     "the routine's END is not preceded by 'C     END OF CMTRIM'"),
    (lambda t: t.replace("(SHARED)", "(TENZOR)", 1), "F77-HEADER", "title",
     "the header says (TENZOR): CMTRIM is of SHARED, as its name says"),
    (lambda t: t.replace("      RETURN\n", "      CALL TZGCLR\n      RETURN\n", 1),
     "F77-LAYER", "call", "CMTRIM, a shared routine, calls TZGCLR of TENZOR: give it as "
                         "an argument, as CMASSM is given MTITEM or MLITEM"),
    (lambda t: t.replace("C     SOURCE:", "C     ORIGIN:"), "F77-HEADER", "title",
     "no 'C     SOURCE:' line in the header"),
    (lambda t: t.replace("(SHARED)", "", 1), "F77-HEADER", "title",
     "the header says (no program): CMTRIM is of SHARED, as its name says"),
    (lambda t: t.replace("C     CMTRIM - ", "C     CMITOA - "), "F77-HEADER", "title",
     "the title comment names CMITOA, the routine is CMTRIM"),
    (lambda t: t.replace("C     END OF CMTRIM", "C     END OF CMITOA"), "F77-HEADER", "end",
     "the routine's END is not preceded by 'C     END OF CMTRIM'"),
    (lambda t: t.replace("      RETURN\n", "      CALL M703T\n      RETURN\n", 1),
     "F77-LAYER", "call", "CMTRIM, a shared routine, calls M703T of M703T: give it as "
                         "an argument, as CMASSM is given MTITEM or MLITEM"),
])
def test_the_header_and_the_layers_of_an_indexed_directory(tmp_path, edit, rule, at,
                                                           says) -> None:
    """With a README index, each routine's header is checked as the index
    reads it, and a shared routine may not call a routine of one program."""
    root = legacy_copy(tmp_path)
    path = root / "cmtrim.f"
    path.write_text(edit(path.read_text()))
    lines = path.read_text().splitlines()
    title = next(k for k, ln in enumerate(lines, 1) if re.match(r"C     CM[A-Z]+ - ", ln))
    end = next(k for k, ln in enumerate(lines, 1) if ln == "      END")
    call = next((k for k, ln in enumerate(lines, 1) if re.search(r"CALL (TZGCLR|M703T)", ln)),
                0)
    line = {"title": title, "end": end, "call": call}[at]
    found = [(Path(v.path).name, v.line, v.rule, v.message)
             for v in check_dir(root, compiler=None) if v.rule in ("F77-HEADER", "F77-LAYER")]
    assert found == [("cmtrim.f", line, rule, says)], found


# ---------------------------------------------------------------------------
# One rule at a time.
# ---------------------------------------------------------------------------
def test_blank_line(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["", "   "]))
    found = only(tmp_path, "F77-BLANK")
    assert [(v.line, v.col) for v in found] == [(6, 1), (7, 1)]


def test_column_73(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["      I = 1".ljust(72) + "SUB00010",
                                                "C" + "-" * 72]))
    found = only(tmp_path, "F77-COL72")
    assert [(v.line, v.col) for v in found] == [(6, 73), (7, 73)]


def test_tab(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["      I = 1\t", "C\tCOMMENT"]))
    found = only(tmp_path, "F77-TAB")
    assert [(v.line, v.col) for v in found] == [(6, 12), (7, 2)]


def test_charset(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["      I = 1 @ 2",
                                                "C     ПРИМЕР 1"]))
    found = only(tmp_path, "F77-CHARSET")
    assert [(v.line, v.col) for v in found] == [(6, 13), (7, 7)]


def test_every_lower_case_letter_is_lower_case(tmp_path: Path) -> None:
    """a to z, not a to y: a lower-case letter outside a string is F77-LOWER,
    whichever it is."""
    write(tmp_path, "sub.f", subroutine("SUB", [f"      {ch.upper()}{ch} = 1"
                                                for ch in "abyz"]))
    found = only(tmp_path, "F77-LOWER")
    assert [(v.line, v.col) for v in found] == [(6, 8), (7, 8), (8, 8), (9, 8)]
    assert found[3].message == "lower-case letter 'z' outside a character constant"


def test_delete_is_not_printable(tmp_path: Path) -> None:
    """DEL (octal 177) is no printable ASCII character, in a comment or a statement."""
    write(tmp_path, "sub.f", subroutine("SUB", ["C     A RUBOUT \x7f HERE", "      I = 1 \x7f"]))
    found = only(tmp_path, "F77-CHARSET")
    assert [(v.line, v.col) for v in found] == [(6, 16), (7, 13)]
    assert all("is not printable ASCII" in v.message for v in found)


def test_lower_case(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["      i = 1", "      S = 'ok' // 'OK'",
                                                "C     comments may be lower case"]))
    found = only(tmp_path, "F77-LOWER")
    assert [(v.line, v.col) for v in found] == [(6, 7)]


@pytest.mark.parametrize("mark", ["c", "!"])
def test_comment_mark(tmp_path: Path, mark: str) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", [mark + "     A COMMENT"]))
    assert [(v.line, v.col) for v in only(tmp_path, "F77-COMMENT")] == [(6, 1)]


@pytest.mark.parametrize("line,col", [
    ("  1A  CONTINUE", 4),
    ("   00 CONTINUE", 1),
    ("I = 1", 1),
])
def test_label_field(tmp_path: Path, line: str, col: int) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", [line]))
    assert [(v.line, v.col) for v in only(tmp_path, "F77-LABEL")] == [(6, col)]


def test_label_on_continuation(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["      I = 1 +", "   10+    2"]))
    assert [(v.line, v.col) for v in only(tmp_path, "F77-LABEL")] == [(7, 4)]


def test_zero_in_column_6_is_an_initial_line(tmp_path: Path) -> None:
    """A zero in column 6 marks an initial line, as a blank does (X3.9-1978,
    3.2.2): it may carry a label, and it continues nothing."""
    write(tmp_path, "sub.f", ["     0SUBROUTINE SUB", *subroutine("SUB", [
        "      I = 1", "   200J = 2"])[2:]])
    assert check_dir(tmp_path, compiler=None) == []


def test_continuation_mark_not_f77(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["      I = 1 +", "     #    2"]))
    assert [(v.line, v.col) for v in only(tmp_path, "F77-CONT")] == [(7, 6)]


def test_continuation_without_statement(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", ["     1C NOT A COMMENT", *subroutine("SUB", [])])
    found = only(tmp_path, "F77-CONT")
    assert [(v.line, v.col) for v in found] == [(1, 6)]
    assert "no statement to continue" in found[0].message


def test_twenty_continuation_lines(tmp_path: Path) -> None:
    body = ["      I = 1"] + ["     +  + 1"] * 20
    write(tmp_path, "sub.f", subroutine("SUB", body))
    found = only(tmp_path, "F77-CONT")
    assert [(v.line, v.col) for v in found] == [(26, 6)]
    assert "more than 19" in found[0].message


def test_label_without_statement(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["   30"]))
    assert [(v.line, v.col) for v in only(tmp_path, "F77-STMT")] == [(6, 7)]


F90_SNIPPETS: list[tuple[list[str], str]] = [
    (["      INTEGER :: K"], "'::'"),
    (["      I = 1 ! NOTE"], "'!' comment"),
    (["      I = 1; J = 2"], "';'"),
    (["      IF (I == 1) J = 2"], "'=='"),
    (["      IF (I /= 1) J = 2"], "'/='"),
    (["      IF (I < 1) J = 2"], "'<'"),
    (["      IF (I >= 1) J = 2"], "'>'"),
    (["      DO 10 WHILE (I .LT. 3)", "   10 CONTINUE"], "DO WHILE"),
    (["      DO WHILE (I .LT. 3)", "      I = I + 1", "      END DO"], "DO WHILE"),
    (["      DO I = 1, 3", "      END DO"], "DO without a statement label"),
    (["      DO 10 I = 1, 3", "   10 ENDDO"], "END DO"),
    (["      DO", "   10 CONTINUE"], "DO without a loop control"),
    (["      MODULE M"], "MODULE"),
    (["      USE M"], "USE"),
    (["      CONTAINS"], "CONTAINS"),
    (["      ALLOCATE (J(10))"], "ALLOCATE"),
    (["      INTENT (IN) I"], "INTENT"),
    (["      INTERFACE"], "INTERFACE"),
    (["      SELECT CASE (I)"], "SELECT CASE"),
    (["      INCLUDE 'COMMON.INC'"], "INCLUDE"),
    (["      EXIT"], "EXIT"),
    (["      IF (I .GT. 1) CYCLE"], "CYCLE"),
    (["      S = \"DQ\""], "double-quoted"),
    (["      INTEGER(KIND=4) K"], "KIND="),
    (["      A_B = 1"], "'_'"),
    (["      I = J%K"], "'%'"),
    (["      INTEGER K = 1"], "initialisation in a type statement"),
]


@pytest.mark.parametrize("body,what", F90_SNIPPETS, ids=[s[1] for s in F90_SNIPPETS])
def test_fortran_90(tmp_path: Path, body: list[str], what: str) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", body))
    found = only(tmp_path, "F77-F90")
    assert any(what in v.message for v in found), "\n".join(map(str, found))


def test_end_subroutine_is_fortran_90(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", [], end="      END SUBROUTINE SUB"))
    found = only(tmp_path, "F77-F90")
    assert [v.message for v in found] == ["END SUBROUTINE"]


def test_end_function_is_fortran_90(tmp_path: Path) -> None:
    write(tmp_path, "ione.f", ["      INTEGER FUNCTION IONE(I)", "      IMPLICIT NONE",
                               "      INTEGER I", "      IONE = I", "      END FUNCTION IONE"])
    found = only(tmp_path, "F77-F90")
    assert [(v.line, v.message) for v in found] == [(5, "END FUNCTION")]


def test_blanks_do_not_hide_keywords(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["      DO 10 I = 1, 3", "   10 E N D D O"]))
    assert [v.message for v in only(tmp_path, "F77-F90")] == ["END DO"]


def test_strings_and_substrings_are_not_fortran_90(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", [
        "      S = 'A == B; C /= D :: E ! <> \"Q\" _ % &'",
        "      S = S(1:2) // 'it''s'",
        "      J = I / (I + 1)",
    ]))
    assert check_dir(tmp_path, compiler=None) == []


@pytest.mark.parametrize("line", ["      INTEGER*4 K", "      REAL*8 X",
                                  "      DOUBLE COMPLEX Z",
                                  "      PARAMETER K = 1", "      LOGICAL*1 L",
                                  "      COMPLEX*16 Z", "      NAMELIST /NL/ I, J",
                                  "      BYTE K"])
def test_extensions(tmp_path: Path, line: str) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", [line]))
    assert len(only(tmp_path, "F77-EXT")) == 1


@pytest.mark.parametrize("body,name", [
    (["      INTEGER TOOLONG"], "TOOLONG"),
    (["      INTEGER IPADX", "      COMMON /CMPADS1/ IPADX"], "CMPADS1"),
    (["      INTEGER MAXPADS", "      PARAMETER (MAXPADS = 5)"], "MAXPADS"),
    (["      CALL CMPUNCH(1)"], "CMPUNCH"),
    (["      S = CMADJST(S)"], "CMADJST"),
    (["      IF (LENTRIM(S) .GT. 0) I = 1"], "LENTRIM"),
    (["      DO 10 I = 1, NUMBERS", "   10 CONTINUE"], "NUMBERS"),
])
def test_names_longer_than_six(tmp_path: Path, body: list[str], name: str) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", body))
    found = only(tmp_path, "F77-NAME")
    assert [v.message.split()[-7] for v in found] == [name]


def test_unit_name_longer_than_six(tmp_path: Path) -> None:
    write(tmp_path, "toolong.f", subroutine("TOOLONG", []))
    found = only(tmp_path, "F77-NAME")
    assert [(v.line, v.col) for v in found] == [(2, 18)]


def test_missing_implicit_none(tmp_path: Path) -> None:
    lines = subroutine("SUB", [])
    lines.remove("      IMPLICIT NONE")
    write(tmp_path, "sub.f", lines)
    found = only(tmp_path, "F77-IMPLICIT")
    assert [(v.line, v.col) for v in found] == [(2, 7)]


def test_other_implicit(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["      IMPLICIT INTEGER (A-Z)"]))
    assert len(only(tmp_path, "F77-IMPLICIT")) == 1


def test_two_units_in_one_file(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", []) + subroutine("SUB2", []))
    found = only(tmp_path, "F77-UNIT")
    assert [(v.line, v.col) for v in found] == [(9, 7)]
    assert "SUB2" in found[0].message


@pytest.mark.parametrize("file_name", ["other.f", "SUB.f"])
def test_file_named_after_unit(tmp_path: Path, file_name: str) -> None:
    write(tmp_path, file_name, subroutine("SUB", []))
    found = only(tmp_path, "F77-UNIT")
    assert "belongs in sub.f" in found[0].message


def test_unnamed_main_program(tmp_path: Path) -> None:
    write(tmp_path, "main.f", ["      IMPLICIT NONE", "      CONTINUE", "      END"])
    assert "has no name" in only(tmp_path, "F77-UNIT")[0].message


def test_missing_end(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", [])[:-1])
    assert "has no END" in only(tmp_path, "F77-UNIT")[0].message


def test_common_blocks_must_agree(tmp_path: Path) -> None:
    write(tmp_path, "suba.f", subroutine("SUBA", [
        "      INTEGER NPAD, IPX(500)", "      COMMON /CMPAD/ NPAD, IPX"]))
    write(tmp_path, "subb.f", subroutine("SUBB", [
        "      INTEGER NPAD, IPX(400)", "      COMMON /CMPAD/ NPAD, IPX"]))
    write(tmp_path, "subc.f", subroutine("SUBC", [
        "      INTEGER NPAD", "      REAL IPX(500)", "      COMMON /CMPAD/ NPAD, IPX"]))
    write(tmp_path, "subd.f", subroutine("SUBD", [
        "      INTEGER NPAD", "      COMMON /CMPAD/ NPAD"]))
    write(tmp_path, "sube.f", subroutine("SUBE", [
        "      INTEGER NPAD, IPX", "      COMMON /CMPAD/ NPAD, IPX(500)"]))
    found = only(tmp_path, "F77-COMMON")
    assert [(Path(v.path).name, v.line) for v in found] == [
        ("subb.f", 7), ("subc.f", 8), ("subd.f", 7)]
    assert found[0].message == (f"COMMON /CMPAD/ differs from {tmp_path}/suba.f:7: "
                                "variable 2 is IPX INTEGER(400) here, "
                                "IPX INTEGER(500) there")
    assert "1 variables here, 2 there" in found[2].message


@pytest.mark.parametrize("line", ["      COMMON I, J", "      COMMON // I, J",
                                  "      COMMON /CMA/ I, // J"])
def test_blank_common(tmp_path: Path, line: str) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", [line]))
    assert len(only(tmp_path, "F77-BLKCOM")) == 1


def test_parameters_must_agree(tmp_path: Path) -> None:
    write(tmp_path, "suba.f", subroutine("SUBA", [
        "      INTEGER MAXPAD", "      PARAMETER (MAXPAD = 500)"]))
    write(tmp_path, "subb.f", subroutine("SUBB", [
        "      INTEGER MAXPAD", "      PARAMETER (MAXPAD=500)"]))
    write(tmp_path, "subc.f", subroutine("SUBC", [
        "      INTEGER MAXPAD", "      PARAMETER (MAXPAD = 400)"]))
    write(tmp_path, "subd.f", subroutine("SUBD", [
        "      REAL MAXPAD", "      PARAMETER (MAXPAD = 500)"]))
    found = only(tmp_path, "F77-PARAM")
    assert [Path(v.path).name for v in found] == ["subc.f", "subd.f"]
    assert found[0].message == (f"PARAMETER MAXPAD is INTEGER 400 here, "
                                f"INTEGER 500 in {tmp_path}/suba.f:7")


@needs_gfortran
def test_undeclared_variable(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["      K = 1"]))
    found = check_dir(tmp_path)
    assert [(v.rule, v.line, v.col) for v in found] == [("F77-DECL", 6, 7)]
    assert "'k'" in found[0].message and "IMPLICIT type" in found[0].message


@needs_gfortran
def test_compile_error(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["      I = (1"]))
    found = check_dir(tmp_path)
    assert {v.rule for v in found} == {"F77-COMPILE"}
    assert found[0].line == 6


def test_missing_compiler_is_noted(tmp_path: Path) -> None:
    write(tmp_path, "sub.f", subroutine("SUB", ["      K = 1"]))
    notes: list[str] = []
    assert check_dir(tmp_path, compiler="no-such-f77-compiler", notes=notes) == []
    assert notes == ["no-such-f77-compiler is not on PATH: the F77-DECL step "
                     "(every variable declared) was skipped"]


def test_violation_format() -> None:
    v = Violation("legacy/mtfill.f", 12, 73, "F77-COL72", "line has 80 characters")
    assert str(v) == "legacy/mtfill.f:12:73: F77-COL72: line has 80 characters"


def test_subdirectories_and_build_are_walked_correctly(tmp_path: Path) -> None:
    (tmp_path / "sub").mkdir()
    (tmp_path / "build").mkdir()
    write(tmp_path / "sub", "sub.f", subroutine("SUB", ["      i = 1"]))
    write(tmp_path / "build", "junk.f", ["junk"])
    assert [(Path(v.path).name, v.rule) for v in check_dir(tmp_path, compiler=None)] \
        == [("sub.f", "F77-LOWER")]


# ---------------------------------------------------------------------------
# Command line.
# ---------------------------------------------------------------------------
def test_cli(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    write(tmp_path, "tzmain.f", CLEAN_MAIN)
    write(tmp_path, "cmadd.f", CLEAN_SUB)
    assert main(["f77check", str(tmp_path)]) == 0
    assert capsys.readouterr().out == "f77check: 2 files, no violations\n"
    write(tmp_path, "cmadd.f", CLEAN_SUB + [""])
    assert main(["f77check", str(tmp_path)]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out == [f"{tmp_path}/cmadd.f:17:1: F77-BLANK: blank line (use a comment "
                   "line with C in column 1)",
                   "f77check: 1 violations in 1 of 2 files"]
    assert main(["f77check", str(tmp_path / "nowhere")]) == 2
    (tmp_path / "empty").mkdir()
    assert main(["f77check", str(tmp_path / "empty")]) == 2


def test_every_rule_is_tested() -> None:
    """Every rule id of RULES is asserted by some test in this file."""
    source = Path(__file__).read_text(encoding="utf-8")
    asserted = set(re.findall(r'"(F77-[A-Z0-9]+)"', source))
    assert asserted == set(RULES), sorted(set(RULES) ^ asserted)


# ---------------------------------------------------------------------------
# The master COMMON text: every copy is it, line for line.
# ---------------------------------------------------------------------------
MASTER_TEXT = ["C     THE MASTER TEXT",
               "C     ---- /CMPAD/ THE PADS ------------------------------------------",
               "      INTEGER MXPAD",
               "      PARAMETER (MXPAD = 500)",
               "      INTEGER NPAD, IPX(MXPAD)",
               "      COMMON /CMPAD/ NPAD, IPX",
               "      SAVE /CMPAD/",
               "C"]
COPY = MASTER_TEXT[1:7]


def master_tree(directory: Path, copy: list[str]) -> Path:
    write(directory, "COMMON.inc", MASTER_TEXT)
    return write(directory, "cmuse.f", subroutine("CMUSE", [*copy, "      NPAD = 0"]))


def test_copies_equal_to_the_master_pass(tmp_path: Path) -> None:
    master_tree(tmp_path, COPY)
    assert check_dir(tmp_path, compiler=None) == []


@pytest.mark.parametrize("k, changed", [
    (1, "      INTEGER  MXPAD"),                     # one blank more: same meaning, other text
    (2, "      PARAMETER (MXPAD = 400)"),
    (4, "      COMMON /CMPAD/ NPAD, IPX, IPY"),
])
def test_a_copy_differing_from_the_master_is_caught(tmp_path: Path, k: int, changed: str) -> None:
    copy = list(COPY)
    copy[k] = changed
    master_tree(tmp_path, copy)
    found = only(tmp_path, "F77-COMMON")
    assert any(f"differs from {tmp_path / 'COMMON.inc'} (line {k + 1} of the section)"
               in v.message and v.line == 6 + k for v in found), found


@pytest.mark.parametrize("copy, line, expect", [
    (COPY[:5], 11, "'SAVE /CMPAD/'"),                            # the SAVE left out
    ([*COPY, "      INTEGER NXTRA"], 12, "'the end of the copy'"),  # a line more
])
def test_a_copy_shorter_or_longer_than_the_master_is_caught(tmp_path: Path, copy: list[str],
                                                            line: int, expect: str) -> None:
    """Line for line means as many lines: a copy that stops before the
    master's SAVE (the block may become undefined, legacy/README.md) or
    goes on after it is not the master."""
    master_tree(tmp_path, copy)
    found = only(tmp_path, "F77-COMMON")
    assert [(v.line, v.message) for v in found] == [
        (line, f"copy of /CMPAD/ differs from {tmp_path / 'COMMON.inc'} (line "
               f"{line - 5} of the section): expected {expect}")], found


@pytest.mark.parametrize("stmt", ["      COMMON /CMPAD/ NPAD, IPX",
                                  "      COMMON/CMPAD/NPAD,IPX",
                                  "      COMMON / CMPAD / NPAD, IPX",
                                  "      COMMON\n     1   /CMPAD/ NPAD, IPX"])
def test_a_common_outside_a_copy_is_caught_however_it_is_spaced(tmp_path: Path,
                                                                stmt: str) -> None:
    """Blanks are insignificant in FORTRAN 77: a COMMON statement spelt
    without them is still outside a copy of its master text."""
    write(tmp_path, "COMMON.inc", MASTER_TEXT)
    write(tmp_path, "cmtwo.f", subroutine("CMTWO", [
        "      INTEGER NPAD, IPX(400)", *stmt.split("\n"), "      NPAD = 0"]))
    found = only(tmp_path, "F77-COMMON")
    assert [(v.line, v.col, v.message) for v in found] == [
        (7, 7, f"COMMON /CMPAD/ outside a copy of its master text (/CMPAD/ of "
               f"{tmp_path / 'COMMON.inc'})")], found


@pytest.mark.parametrize("was, spelt", [("/CMPAD/", "/ CMPAD /"),
                                        ("COMMON /CMPAD/", "COMMON/CMPAD/")])
def test_a_master_block_spelt_with_blanks_must_be_saved_too(tmp_path: Path, was: str,
                                                            spelt: str) -> None:
    """F77-SAVE reads the master's COMMON statements with the blanks FORTRAN
    ignores: / CMPAD / and COMMON/CMPAD/ are /CMPAD/, unsaved, and SAVE /
    CMPAD / saves it."""
    text = [ln.replace(was, spelt) if ln.startswith("      ") else ln for ln in MASTER_TEXT]
    write(tmp_path, "COMMON.inc", [ln for ln in text if not ln.startswith("      SAVE")])
    write(tmp_path, "cmuse.f", subroutine("CMUSE", ["      NPAD = 0"]))
    found = [v for v in check_dir(tmp_path, compiler=None) if v.rule == "F77-SAVE"]
    assert [(Path(v.path).name, v.line) for v in found] == [("COMMON.inc", 6)], found
    write(tmp_path, "COMMON.inc", text)
    assert [v for v in check_dir(tmp_path, compiler=None) if v.rule == "F77-SAVE"] == []


def test_a_block_without_master_and_a_common_outside_a_copy_are_caught(tmp_path: Path) -> None:
    write(tmp_path, "COMMON.inc", MASTER_TEXT)
    write(tmp_path, "cmone.f", subroutine("CMONE", [
        "C     ---- /CMNEW/ NOT IN THE MASTER ----------------------------------",
        "      INTEGER NNEW", "      COMMON /CMNEW/ NNEW", "      NNEW = 0"]))
    write(tmp_path, "cmtwo.f", subroutine("CMTWO", [
        "      INTEGER NPAD, IPX(500)", "      COMMON /CMPAD/ NPAD, IPX", "      NPAD = 0"]))
    messages = sorted(v.message for v in only(tmp_path, "F77-COMMON"))
    assert any("COMMON /CMNEW/ has no master text" in m for m in messages), messages
    assert any("COMMON /CMPAD/ outside a copy of its master text (/CMPAD/ of" in m
               for m in messages), messages


def test_write_common_writes_the_copies_from_the_master(tmp_path: Path, capsys) -> None:
    copy = list(COPY)
    copy[2] = "      PARAMETER (MXPAD = 400)"
    path = master_tree(tmp_path, copy)
    assert main(["f77check", str(tmp_path)]) == 1
    assert main(["f77check", "--write-common", str(tmp_path)]) == 0
    assert "      PARAMETER (MXPAD = 500)" in path.read_text().splitlines()
    assert "wrote the COMMON copies of" in capsys.readouterr().out


def test_legacy_has_a_master_for_every_block_it_uses() -> None:
    legacy = Path(__file__).resolve().parents[3] / "legacy"
    master = read_master(legacy / "COMMON.inc")
    used = {m for p in legacy.glob("*.f")
            for m in re.findall(r"^      COMMON */([A-Z0-9]+)/", p.read_text(), re.M)}
    declared = {b for sec in master.values()
                for b in re.findall(r"^      COMMON */([A-Z0-9]+)/", "\n".join(sec), re.M)}
    assert used == declared, used ^ declared


def test_a_readme_whose_index_is_stale_fails_the_check(tmp_path: Path, capsys) -> None:
    write(tmp_path, "cmone.f", headed("CMONE", ["      I = 1"]))
    (tmp_path / "README.md").write_text(
        "# test\n\n<!-- index: written by `python -m harness f77check --index`; "
        "do not edit -->\nstale\n<!-- end of index -->\n", encoding="utf-8")
    assert main(["f77check", str(tmp_path)]) == 1
    assert "F77-INDEX" in capsys.readouterr().out
    assert main(["f77check", "--index", str(tmp_path)]) == 0
    assert "| [CMONE](cmone.f) |" in (tmp_path / "README.md").read_text()


@pytest.mark.parametrize("text, says", [
    (b"      PROGRAM X\n      END\n", "line 1: no title comment in lines 1-3"),
    (b"", "line 1: no title comment in lines 1-3"),
    (b"C     ZZ - a routine\n      I = 1\n",
     "line 1: no PROGRAM, SUBROUTINE or FUNCTION statement"),
    (b"C     ZZ - caf\xc3\xa9\n      PROGRAM X\n      END\n",
     "line 1: byte 303 (octal) is not ASCII"),
])
def test_a_file_the_index_cannot_read_is_named(tmp_path: Path, capsys, text, says) -> None:
    """The index is made from each file's title comment and its routine:
    a file without them is a violation naming it, never a traceback."""
    write(tmp_path, "cmone.f", subroutine("CMONE", ["      I = 1"]))
    (tmp_path / "README.md").write_text(
        "# test\n\n<!-- index: written by `python -m harness f77check --index`; "
        "do not edit -->\nstale\n<!-- end of index -->\n", encoding="utf-8")
    (tmp_path / "zz.f").write_bytes(text)
    assert main(["f77check", str(tmp_path)]) == 1
    out = capsys.readouterr()
    line, text = says.split(": ", 1)
    assert f"{tmp_path / 'zz.f'}:{line[5:]}:1: F77-HEADER: {text}" in out.out, out.out
    assert "F77-INDEX: the index cannot be made until zz.f's header is mended" in out.out
    assert "Traceback" not in out.err
    assert main(["f77check", "--index", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert f"cannot write the index: {tmp_path / 'zz.f'}: {says}" in err, err


@pytest.mark.parametrize("expr", ["MODULO(I, 2)", "IAND(I, 3)", "IACHAR(S(1:1))", "SIZE(J)",
                                  "HUGE(I)", "INT(FLOOR(1.5))"])
def test_fortran_90_intrinsics_are_caught(tmp_path: Path, expr: str) -> None:
    write(tmp_path, "cmone.f", subroutine("CMONE", [f"      I = {expr}"]))
    found = only(tmp_path, "F77-INTRINSIC")
    assert found[0].line == 6 and "not of FORTRAN 77" in found[0].message


@pytest.mark.parametrize("expr", ["TRIM(S)", "ACHAR(65)", "REPEAT(S, 2)", "SCAN(S, 'A')",
                                  "VERIFY(S, 'A')"])
def test_fortran_90_character_intrinsics_are_caught(tmp_path: Path, expr: str) -> None:
    """The string functions of Fortran 90 that a FORTRAN 77 routine is most
    tempted by (CMTRIM is there because LEN_TRIM and TRIM are not); gfortran
    -std=legacy takes them all, so nothing but F77-INTRINSIC would see them."""
    write(tmp_path, "cmone.f", subroutine("CMONE", [f"      S = S // {expr}"]))
    found = only(tmp_path, "F77-INTRINSIC")
    assert [(v.line, v.col) for v in found] == [(6, 16)]
    assert found[0].message == f"{expr[:expr.index('(')]} is an intrinsic function of " \
                               "Fortran 90, not of FORTRAN 77"


@pytest.mark.parametrize("body, line, col", [
    (["      WRITE (*, '(A)') TRIM(S)"], 6, 24),
    (["      PRINT *, IACHAR(S(1:1))"], 6, 16),
    (["      READ (*, *) J", "      WRITE (*, *) IAND(J, 7)"], 7, 20),
    (["      IF (I .GT. 0) WRITE (*, *) ACHAR(I)"], 6, 34),
    (["      GO TO (10, 20), MODULO(I, 2) + 1", "   10 CONTINUE", "   20 CONTINUE"], 6, 23),
])
def test_fortran_90_intrinsics_are_caught_in_every_statement(tmp_path: Path, body, line,
                                                             col) -> None:
    """Not only in assignments, IF conditions, DO controls and CALLs: an
    output list, a computed GO TO (gfortran -std=legacy takes them all)."""
    write(tmp_path, "cmone.f", subroutine("CMONE", body))
    found = only(tmp_path, "F77-INTRINSIC")
    assert [(v.line, v.col) for v in found] == [(line, col)], found


def test_a_format_is_not_an_array_constructor(tmp_path: Path) -> None:
    write(tmp_path, "cmone.f", subroutine("CMONE", ["      WRITE (*, 100) I",
                                                    "  100 FORMAT (/1X, I5, 2(1X, I3)/)"]))
    assert check_dir(tmp_path, compiler=None) == []


def test_a_long_fortran_90_intrinsic_is_an_intrinsic_not_only_a_long_name(tmp_path) -> None:
    write(tmp_path, "cmone.f", subroutine("CMONE", ["      S = ADJUSTL(S)"]))
    assert rules(tmp_path) == {"F77-INTRINSIC", "F77-NAME"}


def test_a_declared_function_of_the_same_name_is_not_an_intrinsic(tmp_path: Path) -> None:
    write(tmp_path, "cmone.f", subroutine("CMONE", ["      INTEGER HUGE", "      I = HUGE(1)"]))
    assert check_dir(tmp_path, compiler=None) == []


def test_an_array_constructor_is_fortran_90(tmp_path: Path) -> None:
    write(tmp_path, "cmone.f", subroutine("CMONE", ["      INTEGER K(2)", "      K = (/ 1, 2 /)"]))
    found = only(tmp_path, "F77-F90")
    assert "array constructor" in found[0].message


def test_a_directory_that_is_not_there_is_named_so(tmp_path: Path, capsys) -> None:
    assert main(["f77check", str(tmp_path / "gone")]) == 2
    assert capsys.readouterr().err == f"f77check: {tmp_path / 'gone'}: no such directory\n"
    (tmp_path / "file.f").write_text("")
    assert main(["f77check", str(tmp_path / "file.f")]) == 2
    assert capsys.readouterr().err == f"f77check: {tmp_path / 'file.f'}: not a directory\n"
