C=======================================================================
C     TZHEAD - THE HEADING OF A PACKAGE'S LISTING             (TENZOR)
C     SOURCE:  RECONSTRUCTED, DOCS/FILES.MD: THE JOB NAME FROM *NAME,
C              THE ENVELOPE CARDS ECHOED, THE PACKAGE, A COLUMN RULER.
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZHEAD
      IMPLICIT NONE
C     ---- /TZJOB/ THE JOB: CARD COUNT, ENVELOPE, PACKAGE NAMES ------
      INTEGER MXENV, MXPKG
      PARAMETER (MXENV = 20, MXPKG = 10000)
      INTEGER NCARD, JOBERR, ICODEO, NENV, NPKG, IRCJOB, LEXEC, LENV,
     1        LSTRCT
      COMMON /TZJOB/ NCARD, JOBERR, ICODEO, NENV, NPKG, IRCJOB, LEXEC,
     1               LENV, LSTRCT
      CHARACTER*80 ENVC(MXENV)
      CHARACTER*24 PKNAMS(MXPKG)
      CHARACTER*40 JOBNAM
      CHARACTER*80 CURC
      COMMON /TZJOBC/ ENVC, PKNAMS, JOBNAM, CURC
      SAVE /TZJOB/, /TZJOBC/
C     ---- /TZPKG/ THE PACKAGE: P CARD PARAMETERS, ITS CARD IMAGES ---
      INTEGER MXCRD
      PARAMETER (MXCRD = 200000)
      INTEGER LPKG, ICFST, NPCRD, NPERR, LECHO, IPCRD, LGEOM,
     1        IX0, IY0, IWT(3), IDMAX, ISCN, ISCD, ICODE, IORD, IFMAX,
     2        NPWRN
      COMMON /TZPKG/ LPKG, ICFST, NPCRD, NPERR, LECHO, IPCRD, LGEOM,
     1               IX0, IY0, IWT, IDMAX, ISCN, ISCD, ICODE, IORD,
     2               IFMAX, NPWRN
      CHARACTER*18 PKNAME
      CHARACTER*24 PKFILE
      CHARACTER*80 CIMG(MXCRD)
      COMMON /TZPKGC/ PKNAME, PKFILE, CIMG
      SAVE /TZPKG/, /TZPKGC/
C     ---- LOCAL -------------------------------------------------------
      INTEGER I, L, L1
      CHARACTER*12 S1
C
      CALL DVPRNT(' EM-703 TAPE SUBSYSTEM  TENZOR / M703T / M703L'
     1   // '      JINR P11-10356 (1977), RECONSTRUCTION')
      CALL DVPRNT(' ')
      CALL CMTRIM(JOBNAM, L)
      IF (L .GT. 0) THEN
         CALL DVPRNT(' JOB      ' // JOBNAM(1:L))
      ELSE
         CALL DVPRNT(' JOB      (NO *NAME CARD)')
      END IF
      CALL CMTRIM(PKFILE, L)
      CALL DVPRNT(' PACKAGE  ' // PKNAME // '    FILES ' // PKFILE(1:L)
     1   // '-SMALL, -LARGE, -COND')
      DO 10 I = 1, NENV
         CALL DVPRNT(' ENVELOPE ' // ENVC(I))
   10 CONTINUE
      IF (JOBERR .GT. 0) THEN
         CALL CMITOA(JOBERR, S1, L1)
         CALL DVPRNT(' *** THE JOB HAS ' // S1(1:L1) // ' ERROR(S) '
     1      // 'OUTSIDE ITS PACKAGES (SEE THE CONSOLE): NO TAPES ARE '
     2      // 'PUNCHED')
      END IF
      CALL DVPRNT(' ')
      CALL DVPRNT('    CARD ----+----1----+----2----+----3----+----4'
     1   // '----+----5----+----6----+----7--!-+----8')
      RETURN
C     END OF TZHEAD
      END
