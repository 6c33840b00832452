"""`make mutants`: how many realistic small faults in legacy/ and src/ the
tests catch (mutation testing; not run by CI: it takes a while).

Each mutant below is one change a programmer could make by mistake: a
comparison off by one, a constant slightly wrong, a rule's limit moved. For
each, the file is changed in place, the programs are rebuilt (fpm rebuilds
only what changed; scripts/fpm_build.sh links the test programs again), and
the tests that run TENZOR and em703 (`pytest -m "tenzor or em703" -x`) and
the Fortran unit tests run against them; the
mutant is killed when any test fails, and the table names the first test
that failed (pytest's ``FAILED path::test`` line). The file is always restored, also when
the run is interrupted; the script refuses to start on a tree whose legacy/
or src/ has uncommitted changes. It prints a table and the score; the table
is kept in docs/ROBUSTNESS.md.

A mutant that changes no output (an equivalent mutant) cannot be killed and
is marked so in the list, with the reason; the score counts the others.
"""
from __future__ import annotations

import re
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: fpm build with the test programs linked again (scripts/fpm_build.sh): with
#: a plain `fpm build`, `fpm test` ran the test programs as they were linked
#: before the mutant, and only pytest could catch it
BUILD = ["bash", "scripts/fpm_build.sh"]


@dataclass(frozen=True)
class Mutant:
    path: str
    old: str
    new: str
    what: str
    equivalent: str = ""            # why no output can change, if so


MUTANTS = [
    # the four boundaries the first mutation run found untested
    Mutant("legacy/cmfold.f", "      IF (NC .GE. 2) THEN", "      IF (NC .GE. 3) THEN",
           "a pair repeated twice is no longer a cycle"),
    Mutant("legacy/mtbody.f", "            ISMAX = MAX(1, IT - IOVL)",
           "            ISMAX = MAX(1, IT - IOVL + 1)",
           "round-pad circles step one unit over T - OVL"),
    Mutant("legacy/mlbody.f", "      IF (R1 .LT. 1.0D0) THEN", "      IF (R1 .LE. 1.0D0) THEN",
           "a conductor 0.02 mm wider than its tool gets one pass"),
    Mutant("legacy/cmspl1.f", "IF (IFMAX .GT. 0) N = (MAX(ABS(IDX), ABS(IDY)) + IFMAX - 1)",
           "IF (IFMAX .GT. 0) N = (MAX(ABS(IDX), ABS(IDY)) + IFMAX)",
           "a move of exactly k FMAX is cut into k + 1 frames"),
    # more of the same kind
    Mutant("legacy/mtbody.f", "         IR = (IW - IT) / 2", "         IR = (IW - IT + 1) / 2",
           "round pad's first circle half a unit out"),
    Mutant("legacy/mtbody.f", "      IOVL = MAX(1, MIN(10, IT / 4))",
           "      IOVL = MAX(1, MIN(9, IT / 4))", "pad overlap limit 0.09 mm"),
    Mutant("legacy/mlbody.f", "      IOVL = MAX(1, MIN(10, IT / 4))",
           "      IOVL = MAX(1, MIN(10, IT / 5))", "conductor overlap T/5"),
    Mutant("legacy/mtpads.f", "         IF (MAX(KPW(I), KPH(I)) .GT. IDMAX) IC = 2",
           "         IF (MAX(KPW(I), KPH(I)) .GE. IDMAX) IC = 2",
           "a pad of exactly Dmax goes to the large-pad tape"),
    Mutant("legacy/cmstat.f", "NROWT(IU) * 2.54D0 / 1.0D3", "NROWT(IU) * 2.50D0 / 1.0D3",
           "tape length 2.50 mm a row"),
    Mutant("legacy/cmfdp.f", "      NR = INT(R * 100.0D0 + 0.5D0)",
           "      NR = INT(R * 100.0D0 + 0.4D0)", "listing decimals rounded at 0.4"),
    Mutant("legacy/tzpbeg.f", "         IF (CMSAME(PKNAMS(I), PKFILE)) THEN",
           "         IF (PKNAMS(I) .EQ. PKFILE) THEN", "names differing in case not duplicates"),
    Mutant("legacy/cmerr.f", "      IF (NERR .GT. MXERR + 1) RETURN",
           "      IF (NERR .GT. MXERR + 2) RETURN", "one error message past the limit"),
    Mutant("legacy/tzdcrd.f",
           "         IF (ABS(DBLE(IX) + DBLE(N - 1) * ISX) .GT. 12000000.0D0) THEN",
           "         IF (ABS(DBLE(IX) + DBLE(N - 1) * ISX) .GT. 12000100.0D0) THEN",
           "a row of pads 1 mm past the coordinate limit accepted"),
    Mutant("legacy/cmpnum.f", "      IF (IVAL .EQ. 0) RETURN", "      IF (IVAL .EQ. 1) RETURN",
           "the number 1 is not punched"),
    Mutant("legacy/cmsim.f", "      PARAMETER (FLD = 120000.0D0, BIG = 999999999.0D0)",
           "      PARAMETER (FLD = 120100.0D0, BIG = 999999999.0D0)",
           "the field 1 mm larger"),
    Mutant("legacy/tenzor.f",
           "      IF (ICGM .NE. 31 .OR. ICX .EQ. ICY .OR. ICDIG(9, 1) .NE. 9) THEN",
           "      IF (ICGM .NE. 31 .OR. ICX .EQ. ICY) THEN",
           "the code table check without the digits", "the table TZCODE sets always "
           "passes both checks; only a build without TZCODE reaches them (test_linkers)"),
    # src/: the tools and the monitor
    Mutant("src/em703/em703_sim.f90",
           "LINE_SPEED = 5500.0_real64, ARC_SPEED = 1500.0_real64",
           "LINE_SPEED = 5500.0_real64, ARC_SPEED = 1600.0_real64", "arcs at 1.6 m/min"),
    Mutant("src/em703/em703_sim.f90", "TRAVEL_SPEED = 5500.0_real64",
           "TRAVEL_SPEED = 5000.0_real64", "travel at 5.0 m/min"),
    Mutant("src/monitor/monitor_devices.f90",
           "call sheet%line(trim(tape_suffix(i)) // '.bytes = ' // itoa(tape(i)%n))",
           "call sheet%line(trim(tape_suffix(i)) // '.bytes = ' // itoa(tape(i)%n + 1))",
           "the job sheet records a tape one byte long"),
    Mutant("src/base/base_sha256.f90", "            w(t) = iand(w(t-16) + s0 + w(t-7) + s1, m32)",
           "            w(t) = iand(w(t-16) + s0 + w(t-6) + s1, m32)", "SHA-256 schedule"),
    Mutant("src/base/base_files.c", "    if (tmp[0] == '\\0') return 0;  /* written straight",
           "    if (tmp[0] != '\\0') return 0;  /* written straight",
           "staged files never renamed into place"),
    Mutant("src/em703/em703_commands.f90", "            if (same_file(out, inputs(i)%path)) then",
           "            if (.false.) then", "outputs over inputs allowed"),
    Mutant("src/em703/em703_jobsheet.f90",
           "        ok = a >= 1 .and. a <= 100 .and. b >= 1 .and. b <= 100",
           "        ok = a >= 1 .and. a <= 100 .and. b >= 1 .and. b <= 99",
           "scale 1:100 refused"),
    Mutant("src/monitor/monitor_devices.f90",
           "            if (deck(last:last) == achar(13)) last = last - 1",
           "            if (deck(last:last) == achar(10)) last = last - 1",
           "card reader keeps the CR of a CRLF deck"),
    # the tour: faults that leave every tape valid and only the order worse or
    # different, which the recorded tours (seven TSPLIB instances, the demo deck) catch
    Mutant("legacy/cmkick.f", "      LMAX = MIN(50, NITM / 3)", "      LMAX = MIN(40, NITM / 3)",
           "kicks swap runs of up to 40 items, not 50"),
    Mutant("legacy/cmkick.f", "IF (MODE .EQ. 2) LM = MIN(450, MAX(LMAX, NITM / 3))",
           "IF (MODE .EQ. 2) LM = MIN(400, MAX(LMAX, NITM / 3))",
           "kicks on a small tape swap runs of up to 400 items, not 450"),
    Mutant("legacy/cmkick.f", "         IF (DGAIN .LE. 1.0D-6) THEN",
           "         IF (DGAIN .LT. -1.0D-6) THEN",
           "a kick that leaves the tour no shorter is kept"),
    Mutant("legacy/cmkick.f", "IF (MODE .EQ. 2) NBASE = MAX(NITM / 4, NLEAST)",
           "IF (MODE .EQ. 2) NBASE = MAX(NITM / 2, NLEAST)",
           "the kicks of a small tape give up after half a failure an item in a row, "
           "not a quarter"),
    Mutant("legacy/cmorop.f", "      DO 50 K = 1, 3", "      DO 50 K = 1, 2",
           "Or-opt moves runs of one or two items only"),
    Mutant("legacy/cmknn.f", "PARAMETER (MXQ = 2, MXRING = 30, MXQEN = 4000)",
           "PARAMETER (MXQ = 1, MXRING = 30, MXQEN = 4000)",
           "one near end per quadrant, not two"),
    Mutant("legacy/cmopt2.f", "                  IE4 = KOUT(ITOUR(J - 1))",
           "                  IE4 = KIN(ITOUR(J - 1))",
           "2-opt looks at the wrong end of the item before a candidate"),
    Mutant("legacy/cmtrev.f", "      IF (I .EQ. J) THEN", "      IF (I .EQ. -J) THEN",
           "the middle item of an odd reversal keeps its direction"),
    Mutant("legacy/cmtrev.f", "            DO 4 IP = KJHI + 1, I2", "            DO 4 IP = KJHI + 2, I2",
           "a kick's first place past the saved run is not saved"),
    Mutant("legacy/cmkick.f", "            KWORK = KWORK + KJWK", "            KWORK = KWORK + 0",
           "an undone kick's reversals not counted in the work bound"),
    Mutant("legacy/cmknn.f", "            IF (KQX(IP) .EQ. KQX(IP - 1) .AND.",
           "            IF (KQX(IP) .EQ. KQX(IP - 1) .OR.",
           "an exit takes its entry's near ends when the two share only x"),
    Mutant("legacy/cmecho.f", "         LINE(9-LS:8) = S(1:LS)", "         LINE(10-LS:9) = S(1:LS)",
           "the card number echoed one column to the right"),
    Mutant("legacy/cmknn.f", "                     ELSE IF (D .LE. NBD(MXNB)) THEN",
           "                     ELSE IF (D .LT. NBD(MXNB)) THEN",
           "a near end tied with the sixteenth is never offered to the list"),
    Mutant("legacy/cmtour.f", "         NJ = MIN(MAX(NITM, NJOB), 20000)",
           "         NJ = MIN(NITM, 20000)",
           "the kicks' bound of a tape counts its own items, not its package's"),
    Mutant("legacy/cmopt2.f", "      IF (IP .EQ. NITM) THEN", "      IF (IP .EQ. -1) THEN",
           "the last move is never tried from the start point's side"),
    Mutant("legacy/cmopt2.f", "LIMP .EQ. 0 .AND. NJOB .LE. 20000)", "LIMP .EQ. 0 .AND. NJOB .LE. 0)",
           "neither Lin and Kernighan's chain nor Or-3opt ever tried"),
    Mutant("legacy/cmopt2.f", "      IF (IP .EQ. 1) THEN", "      IF (IP .EQ. -1) THEN",
           "the first move is never tried from the tool's start's side"),
    Mutant("legacy/cmlk3.f", "            IF (KADD(IT5) .EQ. ICHN) GOTO 270",
           "            IF (KADD(IT5) .EQ. -1) GOTO 270",
           "the chain's step that goes on may take out a move the chain changed"),
    Mutant("legacy/cmlk3.f", "      NBRD = 8\n", "      NBRD = 7\n",
           "the chain tries the 7 nearest ends of t2 and t4, not 8"),
    Mutant("legacy/cmkick.f", "            DO 32 J = NDJ, 1, -1", "            DO 32 J = NDJ, 2, -1",
           "a failed kick puts back all but the first move length it changed"),
    Mutant("legacy/cmtrev.f", "         CALL CMDMV(I2)", "         CALL CMDMV(I1)",
           "a reversal keeps the length of the move into it, not the one out of it"),
    # the kicks' window that grows with what they gain (caught by where the
    # kicks stop on traced runs, test_kicks.py: u1060's first shuffled deck
    # and d1291 mirrored; d1291's, pcb3038's and fl1400's recorded tours
    # caught them before their kicks came to stop at the work bound)
    Mutant("legacy/cmkick.f", "GKEPT / TLEN0 - 0.5D0", "GKEPT / TLEN0 - 1.0D0",
           "the kicks' window grows only beyond the first per cent they gained, "
           "not the first half per cent"),
    Mutant("legacy/cmkick.f", "NSTAG = MIN(NBASE + INT(3.0D0 *", "NSTAG = MIN(NBASE + INT(2.0D0 *",
           "the kicks' window grows by half a kick an item for each per cent gained, "
           "not three quarters"),
    Mutant("legacy/cmkick.f", "      NCAP = 8 * NBASE", "      NCAP = 16 * NBASE",
           "the kicks' window grows up to four kicks an item, not two"),
    Mutant("legacy/cmkick.f", "     1   NLEAST = 160", "     1   NLEAST = 100",
           "the kicks' least window is 100 failed kicks, not 160"),
    Mutant("legacy/cmkick.f", ".GT. 0.125D0 * TLEN0)", ".GT. 0.25D0 * TLEN0)",
           "the least window only where the start point's two moves make over a quarter "
           "of the tour, not an eighth"),
    # the chain's breadth of 16 on a tape of more than 2000 items (caught
    # by d2103's recorded tour; the first also leaves pcb3038's, of 3038
    # items, as it is)
    Mutant("legacy/cmlk3.f", "IF (NITM .GT. 2000) NBRD = 16", "IF (NITM .GT. 3000) NBRD = 16",
           "the chain tries 16 near ends only on a tape of more than 3000 items, not 2000"),
    Mutant("legacy/cmlk3.f", "IF (NITM .GT. 2000) NBRD = 16", "IF (NITM .GT. 2000) NBRD = 12",
           "the chain tries 12 near ends on a tape of more than 2000 items, not 16"),
    # the chain passes by a t5 that can neither close shorter nor be the
    # best step, by the triangle t5-t1 <= t5-t6 + t6-t1: the bound must
    # count the move t5-t6, else steps that would close are lost
    Mutant("legacy/cmlk3.f", "               D51 = G4 + DMV(IT5) + 1.0D-6",
           "               D51 = G4 + 1.0D-6",
           "the chain's bound on t5-t1 leaves out the move of t5, and passes by t5 "
           "whose step could close shorter"),
    # the kicks' window that grows with the tape beyond 700 items (caught by
    # pcb1173's recorded tour and the window's own test)
    Mutant("legacy/cmkick.f", "IF (MODE .EQ. 2 .AND. NITM .GT. 700)",
           "IF (MODE .EQ. 2 .AND. NITM .GT. 1200)",
           "the kicks' window grows with the tape only beyond 1200 items, not 700"),
    # the card reader's numbers, limits and rules (found by a hand mutation run
    # of the deck's reading and checking; caught by test_bad_decks,
    # test_boundaries and test_unread_columns)
    Mutant("legacy/cmnum.f", "         IF (ID .GT. 9) ID = -1", "         IF (ID .GT. 10) ID = -1",
           "':' (the code after '9') is read as the digit 10"),
    Mutant("legacy/cmnum.f", "            IF (IACC .GT. MAXV10) THEN",
           "            IF (IACC .GE. MAXV10) THEN", "9999999.9 is too large to read"),
    Mutant("legacy/cmnum.f", "(CH .EQ. '+' .OR. CH .EQ. '-') .AND. I .EQ. IA)",
           "(CH .EQ. '+' .OR. CH .EQ. '-'))",
           "a sign inside or after a number makes it negative, not an error"),
    Mutant("legacy/tzpcrd.f", "IF (I .LE. 2 .AND. (IV(I) .LT. 0 .OR. IV(I) .GT. MXFLD))",
           "IF (I .LE. 2 .AND. (IV(I) .LT. 0 .OR. IV(I) .GE. MXFLD))",
           "a start point on the field's edge (1200.00 mm) refused"),
    Mutant("legacy/tzpcrd.f", "(IV(I) .LE. 0 .OR. IV(I) .GT. MXTOOL)) THEN",
           "(IV(I) .LE. 0 .OR. IV(I) .GE. MXTOOL)) THEN", "a tool of 20.00 mm refused"),
    Mutant("legacy/tzpcrd.f", "IF (I .EQ. 6 .AND. (IV(I) .LE. 0 .OR. IV(I) .GT. MXFLD))",
           "IF (I .EQ. 6 .AND. (IV(I) .LE. 0 .OR. IV(I) .GT. MXFLD+1))",
           "a DMAX of 1200.01 mm taken"),
    Mutant("legacy/tzpcrd.f", "1,1, 2,1, 5,1, 50,1, 100,1 /", "1,1, 2,1, 5,1, 20,1, 100,1 /",
           "the scale 20:1 taken, 50:1 refused"),
    Mutant("legacy/tzdcrd.f", "IF (N .GT. 1 .AND. ISX .EQ. 0 .AND. ISY .EQ. 0) THEN",
           "IF (N .GT. 2 .AND. ISX .EQ. 0 .AND. ISY .EQ. 0) THEN",
           "a row of two pads without a step taken (both on one place)"),
    Mutant("legacy/tzdcrd.f", "      IF (MAX(IW, IH) .GT. IDMAX) IU = 2",
           "      IF (IW .GT. IDMAX) IU = 2",
           "a pad large by its height only is checked against W1, not W2"),
    Mutant("legacy/tzdcrd.f", "IF (IH .GT. 0 .AND. IH .LT. IT .AND. ICOL .EQ. 0) ICOL = 39",
           "IF (IH .GT. 0 .AND. IH .LE. IT .AND. ICOL .EQ. 0) ICOL = 39",
           "a pad exactly as high as its tool refused"),
    Mutant("legacy/tzdcrd.f", "CARD, 47, 50, 0, 1, 'N'", "CARD, 48, 50, 0, 1, 'N'",
           "N of a D card read in cols 48-50: a row of 1234 pads is 234"),
    Mutant("legacy/tzacrd.f", "      IF (RS .GT. MXRAD) THEN", "      IF (RS .GE. MXRAD) THEN",
           "a circle or arc of exactly 10 m refused"),
    Mutant("legacy/tzcard.f", "IF (IC .LT. 32 .OR. IC .GT. 126) THEN",
           "IF (IC .LT. 32 .OR. IC .GT. 127) THEN", "DEL (byte 127) taken as a card character"),
    Mutant("legacy/tzwarn.f", "         CARET(9+I:9+I) = '^'", "         CARET(10+I:10+I) = '^'",
           "a warning's carets one column right of the columns it names"),
]

TESTS = ["python", "-m", "pytest", "-q", "-x", "--tb=no", "-rf", "-p", "no:cacheprovider", "-m",
         "tenzor or em703"]


def _run(cmd: list[str], timeout: int = 1800) -> bool:
    return _output(cmd, timeout)[0]


def _output(cmd: list[str], timeout: int = 1800) -> tuple[bool, str]:
    proc = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=timeout)
    return proc.returncode == 0, proc.stdout + proc.stderr


def first_failure(output: str, runner: str) -> str:
    """The first failing test named in pytest's or fpm test's output
    (``FAILED path::test`` of ``-x -q``; fpm test's ``FAIL name`` or
    ``ERROR STOP`` line), else the runner's name alone."""
    m = re.search(r"^(?:FAILED|ERROR) (\S+::.+?)(?: - .*)?$", output, re.M)
    if m:
        return f"{runner}: `{m.group(1)}`"
    m = re.search(r"^.*\b(?:FAIL|ERROR STOP)\b.*$", output, re.M)
    if m and runner == "fpm test":
        return f"{runner}: {m.group(0).strip()[:100]}"
    return runner


def killed(m: Mutant) -> tuple[bool, str]:
    """Apply m, rebuild, test; restore. (killed, by what)."""
    path = ROOT / m.path
    text = path.read_text()
    if text.count(m.old) != 1:
        return False, f"NOT APPLIED: the text is not in {m.path} exactly once"
    try:
        path.write_text(text.replace(m.old, m.new))
        if not _run(BUILD):
            return True, "the build"
        ok, out = _output(["fpm", "test"])
        if not ok:
            return True, first_failure(out, "fpm test")
        ok, out = _output(TESTS)
        if not ok:
            return True, first_failure(out, "pytest")
        return False, "survived"
    finally:
        path.write_text(text)


def main(argv: list[str]) -> int:
    """`scripts/mutants.py [N ...]`: every mutant, or only those numbered N
    (1-based, as the table numbers them), e.g. to re-run the survivors."""
    try:
        chosen = {int(a) for a in argv} or set(range(1, len(MUTANTS) + 1))
    except ValueError:
        print("usage: scripts/mutants.py [N ...]  (mutant numbers, 1-based)", file=sys.stderr)
        return 2
    dirty = subprocess.run(["git", "status", "--porcelain", "legacy", "src"], cwd=ROOT,
                           capture_output=True, text=True).stdout
    if dirty.strip():
        print("mutants: legacy/ or src/ has uncommitted changes; commit or stash them "
              "first (each mutant edits a file in place)", file=sys.stderr)
        return 2
    rows, kills, counted = [], 0, 0
    start = time.monotonic()
    try:
        for n, m in enumerate(MUTANTS, 1):
            if n not in chosen:
                continue
            t = time.monotonic()
            dead, by = killed(m)
            if not m.equivalent:
                counted += 1
                kills += dead
            verdict = "killed" if dead else ("equivalent" if m.equivalent else "SURVIVED")
            rows.append((m, verdict, by))
            print(f"{n:2d}/{len(MUTANTS)} {verdict:10s} {m.path}: {m.what} "
                  f"({by}, {time.monotonic() - t:.0f} s)", flush=True)
    finally:
        _run(BUILD)
    print()
    print("| file | mutant | verdict | caught by |")
    print("|---|---|---|---|")
    for m, verdict, by in rows:
        print(f"| `{m.path}` | {m.what} | {verdict} | {m.equivalent or by} |")
    score = 100.0 * kills / counted if counted else 0.0
    equivalent = sum(1 for _, verdict, _ in rows if verdict == "equivalent")
    print(f"\n{kills} of {counted} non-equivalent mutants killed ({score:.1f} %), "
          f"{equivalent} equivalent; {time.monotonic() - start:.0f} s")
    return 0 if score >= 95.0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
